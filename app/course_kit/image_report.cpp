#include "app/course_kit/image_report.h"

namespace vplab {

using Json = nlohmann::ordered_json;

GradeReport imageReport(const ImageGrade& g, const std::string& student, const std::string& scene,
                        const std::string& differenceFile, Language lang) {
  const bool de = lang == Language::de;
  GradeReport r;
  r.kind = "image";
  r.student = student;
  r.id = studentIdOf(student);
  r.scene = scene;
  r.lang = lang;
  r.passed = g.passed();
  const ImageThresholds& t = g.thresholds;
  r.header.push_back(de ? "Schwellen: ein Pixel ist falsch, wenn ein Kanal um mehr als " + std::to_string(t.maxDiff) +
                              " abweicht (--max-diff); bestanden bei mittlerer Kanalabweichung ≤ " + fixed(t.meanDiff, 2) +
                              " (--mean-diff) und höchstens " + fixed(100 * t.maxShare, 2) + " % falschen Pixeln"
                        : "thresholds: a pixel is wrong when a channel differs by more than " + std::to_string(t.maxDiff) +
                              " (--max-diff); pass when the mean channel difference ≤ " + fixed(t.meanDiff, 2) +
                              " (--mean-diff) and at most " + fixed(100 * t.maxShare, 2) + " % of the pixels are wrong");
  r.header.push_back(de ? "ein um höchstens " + std::to_string(t.maxShift) +
                              " Pixel je Achse verschobenes Bild wird an seiner Verschiebung verglichen (--max-shift)"
                        : "a picture shifted by at most " + std::to_string(t.maxShift) +
                              " px on each axis is compared at its shift (--max-shift)");
  const ImageComparison& c = g.comparison;
  GradeCase image{de ? "Bild" : "image", g.passed(), "", {}};
  if (c.sizeMismatch) {
    image.message = (de ? "Größe " : "size ") + std::to_string(c.actualWidth) + " × " + std::to_string(c.actualHeight) +
                    (de ? ", das Ergebnis " : ", the reference ") + std::to_string(c.expectedWidth) + " × " +
                    std::to_string(c.expectedHeight);
  } else {
    image.message = std::to_string(c.differingPixels) + (de ? " von " : " of ") + std::to_string(c.pixelCount) +
                    (de ? " Pixeln falsch (" : " pixels wrong (") + fixed(100 * c.differingShare, 3) +
                    (de ? " %), größte Kanalabweichung " : " %), max channel difference ") + std::to_string(c.maxChannelDelta) +
                    (de ? ", Mittel " : ", mean ") + fixed(c.meanChannelDelta, 3);
    image.total = c.differingPixels;
    for (const PixelDelta& p : c.worst)
      image.details.push_back((de ? "Pixel (" : "pixel (") + std::to_string(p.x) + ", " + std::to_string(p.y) +
                              (de ? "): Ihres (" : "): yours (") + std::to_string(p.actual.r) + ", " +
                              std::to_string(p.actual.g) + ", " + std::to_string(p.actual.b) +
                              (de ? "), Ergebnis (" : "), reference (") + std::to_string(p.expected.r) + ", " +
                              std::to_string(p.expected.g) + ", " + std::to_string(p.expected.b) + ")");
  }
  r.cases.push_back(image);
  if (!differenceFile.empty())
    r.header.push_back((de ? "Differenzbild: " : "difference image: ") + differenceFile);
  Json models = Json::array();
  for (const ImageModelResult& m : g.models)
    models.push_back({{"mistake", m.key},
                      {"matches", m.matches},
                      {"mean_diff", m.comparison.meanChannelDelta},
                      {"wrong_share", m.comparison.differingShare}});
  if (!(g.shift == ImageShift{})) {
    const std::string by = "(" + std::to_string(g.shift.dx) + ", " + std::to_string(g.shift.dy) + ") px";
    r.diagnosis.push_back(
        g.shiftTolerated
            ? (de ? "Ihr Bild ist um " + by + " verschoben; es wurde an dieser Verschiebung verglichen."
                  : "Your picture is shifted by " + by + "; it was compared at that shift.")
            : (de ? "Ihr Bild ist um " + by + " verschoben; höchstens " + std::to_string(t.maxShift) +
                        " Pixel werden toleriert: zeichnen Sie es dort, wo DC es hinlegt (Ursprung oben links, Skript 15.2.5)."
                  : "Your picture is shifted by " + by + "; at most " + std::to_string(t.maxShift) +
                        " px are tolerated: draw it where DC puts it (origin top left, lecture notes 15.2.5)."));
  }
  if (g.mistake) {
    const ImageModelResult& m = g.models[*g.mistake];
    r.diagnosis.push_back((de ? "Ihr Bild ist das des Fehlermodells " : "Your picture is that of the mistake model ") +
                          quoted(m.key, lang) + ": " + (de ? m.descriptionDe : m.description) + (de ? ". Siehe " : ". See ") +
                          (de ? m.hintDe : m.hint) + ".");
  } else if (!g.passed() && g.shiftTolerated) {
    r.diagnosis.push_back(de ? "Keines der Fehlermodelle für Bilder (auf dem Kopf, gespiegelt, erst dividieren) passt zu Ihrem Bild."
                             : "None of the image mistake models (upside down, mirrored, divide first) matches your picture.");
  }
  r.json = {{"kind", "image"},
            {"student", student},
            {"id", r.id},
            {"scene", scene},
            {"lang", de ? "de" : "en"},
            {"passed", g.passed()},
            {"thresholds", {{"max_diff", t.maxDiff}, {"mean_diff", t.meanDiff}, {"max_share", t.maxShare}, {"max_shift", t.maxShift}}},
            {"shift", {g.shift.dx, g.shift.dy}},
            {"shift_tolerated", g.shiftTolerated},
            {"size", {c.actualWidth, c.actualHeight}},
            {"size_mismatch", c.sizeMismatch},
            {"wrong_pixels", c.differingPixels},
            {"wrong_share", c.differingShare},
            {"max_diff", c.maxChannelDelta},
            {"mean_diff", c.meanChannelDelta},
            {"difference_image", differenceFile},
            {"mistake", g.mistake ? Json(g.models[*g.mistake].key) : Json()},
            {"models", models},
            {"diagnosis", r.diagnosis}};
  return r;
}

}  // namespace vplab
