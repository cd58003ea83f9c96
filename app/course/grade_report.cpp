#include "app/course/grade_report.h"

#include <cstdio>
#include <map>

namespace vplab {

using Json = nlohmann::ordered_json;

namespace {

std::string fixed(double v, int places) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", places, v);
  return buf;
}

std::string xmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// A value's text as JSON: numbers and strings as they are, "5 entries" (a list of another length)
// as a string.
Json asJson(const std::string& text) {
  Json j = Json::parse(text, nullptr, false);
  return j.is_discarded() ? Json(text) : j;
}

}  // namespace

GradeReport numbersReport(const NumbersGrade& g, const std::string& student, const std::string& scene) {
  GradeReport r;
  r.kind = "numbers";
  r.student = student;
  r.scene = scene;
  r.passed = g.passed();
  char tol[32];
  std::snprintf(tol, sizeof tol, "%g", g.tolerance);
  r.header.push_back("tolerance: |student − reference| ≤ " + std::string(tol) +
                     " · max(1, |reference|); integers, names and fates exactly; a clipped polygon may start at any vertex");
  // One case per vector or matrix, in the order of the student's file.
  std::vector<std::string> order;
  std::map<std::string, GradeCase> cases;
  std::map<std::string, std::pair<size_t, size_t>> counts;  // wrong, total
  for (const GradedValue& v : g.values) {
    if (!cases.count(v.group)) order.push_back(v.group), cases[v.group].name = v.group;
    auto& [wrong, total] = counts[v.group];
    ++total;
    if (!v.right) {
      ++wrong;
      cases[v.group].passed = false;
      cases[v.group].details.push_back(v.path + ": " + v.student + ", expected " + v.reference);
    }
  }
  Json groups = Json::array();
  for (const std::string& name : order) {
    GradeCase& c = cases[name];
    const auto [wrong, total] = counts[name];
    c.message = c.passed ? std::to_string(total) + (total == 1 ? " value right" : " values right")
                         : std::to_string(wrong) + " of " + std::to_string(total) + " values wrong";
    Json wrongValues = Json::array();
    for (const GradedValue& v : g.values)
      if (v.group == name && !v.right)
        wrongValues.push_back({{"path", v.path}, {"student", asJson(v.student)}, {"reference", asJson(v.reference)}});
    groups.push_back({{"path", name}, {"values", total}, {"wrong", wrong}, {"wrong_values", wrongValues}});
    r.cases.push_back(c);
  }
  Json models = Json::array();
  for (const ModelMatch& m : g.models)
    models.push_back({{"mistake", mistakeModel(m.mistake).key},
                      {"explains_wrong_values", m.explained},
                      {"contradicted_values", m.contradicted},
                      {"matches", m.contradicted == 0}});
  if (g.firstStage)
    r.diagnosis.push_back("The first stage where your numbers depart from the reference: " +
                          std::string(stageName(*g.firstStage)) + ".");
  if (g.mistake) {
    const MistakeModel& m = mistakeModel(*g.mistake);
    r.diagnosis.push_back("Your numbers are those of the mistake model \"" + std::string(m.key) + "\": " +
                          std::string(m.description) + ". See " + std::string(m.hint) + ".");
  } else if (!g.passed()) {
    const ModelMatch* best = nullptr;
    for (const ModelMatch& m : g.models)
      if (m.explained > 0 && (!best || m.explained > best->explained)) best = &m;
    if (best)
      r.diagnosis.push_back("No mistake model explains all your numbers; \"" + std::string(mistakeModel(best->mistake).key) +
                            "\" (" + std::string(mistakeModel(best->mistake).description) + ") explains " +
                            std::to_string(best->explained) + " of the " + std::to_string(g.wrong) + " wrong values.");
    else
      r.diagnosis.push_back("None of the mistake models explains your numbers.");
  }
  r.json = {{"kind", "numbers"},
            {"student", student},
            {"scene", scene},
            {"passed", g.passed()},
            {"tolerance", g.tolerance},
            {"values", g.values.size()},
            {"wrong", g.wrong},
            {"first_departing_stage", g.firstStage ? Json{{"stage", *g.firstStage}, {"name", stageName(*g.firstStage)}} : Json()},
            {"mistake", g.mistake ? Json{{"key", mistakeModel(*g.mistake).key},
                                         {"description", mistakeModel(*g.mistake).description},
                                         {"hint", mistakeModel(*g.mistake).hint}}
                                  : Json()},
            {"models", models},
            {"groups", groups},
            {"diagnosis", r.diagnosis}};
  return r;
}

GradeReport imageReport(const ImageGrade& g, const std::string& student, const std::string& scene,
                        const std::string& differenceFile) {
  GradeReport r;
  r.kind = "image";
  r.student = student;
  r.scene = scene;
  r.passed = g.passed();
  const ImageThresholds& t = g.thresholds;
  r.header.push_back("thresholds: a pixel is wrong when a channel differs by more than " + std::to_string(t.maxDiff) +
                     " (--max-diff); pass when the mean channel difference ≤ " + fixed(t.meanDiff, 2) +
                     " (--mean-diff) and at most " + fixed(100 * t.maxShare, 2) + " % of the pixels are wrong");
  const ImageComparison& c = g.comparison;
  GradeCase image{"image", g.passed(), "", {}};
  if (c.sizeMismatch) {
    image.message = "size " + std::to_string(c.actualWidth) + " × " + std::to_string(c.actualHeight) + ", the reference " +
                    std::to_string(c.expectedWidth) + " × " + std::to_string(c.expectedHeight);
  } else {
    image.message = std::to_string(c.differingPixels) + " of " + std::to_string(c.pixelCount) + " pixels wrong (" +
                    fixed(100 * c.differingShare, 3) + " %), max channel difference " + std::to_string(c.maxChannelDelta) +
                    ", mean " + fixed(c.meanChannelDelta, 3);
    for (const PixelDelta& p : c.worst)
      image.details.push_back("pixel (" + std::to_string(p.x) + ", " + std::to_string(p.y) + "): yours (" +
                              std::to_string(p.actual.r) + ", " + std::to_string(p.actual.g) + ", " +
                              std::to_string(p.actual.b) + "), reference (" + std::to_string(p.expected.r) + ", " +
                              std::to_string(p.expected.g) + ", " + std::to_string(p.expected.b) + ")");
  }
  if (!differenceFile.empty()) image.details.push_back("difference image: " + differenceFile);
  r.cases.push_back(image);
  Json models = Json::array();
  for (const ImageModelResult& m : g.models)
    models.push_back({{"mistake", m.key},
                      {"matches", m.matches},
                      {"mean_diff", m.comparison.meanChannelDelta},
                      {"wrong_share", m.comparison.differingShare}});
  if (g.mistake) {
    const ImageModelResult& m = g.models[*g.mistake];
    r.diagnosis.push_back("Your picture is that of the mistake model \"" + m.key + "\": " + m.description + ". See " +
                          m.hint + ".");
  } else if (!g.passed()) {
    r.diagnosis.push_back("None of the image mistake models (upside down, mirrored, divide first) matches your picture.");
  }
  r.json = {{"kind", "image"},
            {"student", student},
            {"scene", scene},
            {"passed", g.passed()},
            {"thresholds", {{"max_diff", t.maxDiff}, {"mean_diff", t.meanDiff}, {"max_share", t.maxShare}}},
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

std::string reportText(const GradeReport& r) {
  std::string out = "vplab grade " + r.kind + ": " + r.student + " against " + r.scene + "\n";
  for (const std::string& h : r.header) out += "  " + h + "\n";
  out += "\n";
  size_t failed = 0;
  for (const GradeCase& c : r.cases) {
    failed += !c.passed;
    out += std::string(c.passed ? "  ok     " : "  WRONG  ") + c.name + ": " + c.message + "\n";
    if (!c.passed || r.kind == "image")
      for (size_t i = 0; i < c.details.size() && i < 8; ++i) out += "           " + c.details[i] + "\n";
    if (!c.passed && c.details.size() > 8) out += "           … and " + std::to_string(c.details.size() - 8) + " more\n";
  }
  out += "\n";
  for (const std::string& d : r.diagnosis) out += d + "\n";
  out += r.passed ? "PASSED\n" : "FAILED: " + std::to_string(failed) + " of " + std::to_string(r.cases.size()) +
                                     (r.kind == "numbers" ? " vectors or matrices wrong\n" : " checks wrong\n");
  return out;
}

std::string reportJunit(const GradeReport& r) {
  size_t failures = 0;
  for (const GradeCase& c : r.cases) failures += !c.passed;
  std::string diagnosis;
  for (const std::string& d : r.diagnosis) diagnosis += d + "\n";
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<testsuites tests=\"" + std::to_string(r.cases.size()) + "\" failures=\"" + std::to_string(failures) + "\">\n";
  out += "  <testsuite name=\"vplab grade " + r.kind + ": " + xmlEscape(r.student) + "\" tests=\"" +
         std::to_string(r.cases.size()) + "\" failures=\"" + std::to_string(failures) + "\" errors=\"0\">\n";
  for (const GradeCase& c : r.cases) {
    out += "    <testcase classname=\"" + xmlEscape(r.student) + "\" name=\"" + xmlEscape(c.name) + "\"";
    if (c.passed) {
      out += "/>\n";
      continue;
    }
    std::string text;
    for (const std::string& d : c.details) text += d + "\n";
    out += ">\n      <failure message=\"" + xmlEscape(c.message) + "\">" + xmlEscape(text + diagnosis) + "</failure>\n";
    out += "    </testcase>\n";
  }
  out += "    <system-out>" + xmlEscape(diagnosis) + "</system-out>\n  </testsuite>\n</testsuites>\n";
  return out;
}

}  // namespace vplab
