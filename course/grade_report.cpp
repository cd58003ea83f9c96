#include "course/grade_report.h"

#include "course/assignment.h"
#include "course/rational.h"
#include "course/xml_text.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

namespace vplab {

using Json = nlohmann::ordered_json;

namespace {

// ---------------------------------------------------------------- text helpers

std::string shortNumber(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// A number of points as a German or English reader writes it: "7,5" in German.
std::string pointsNumber(double v, Language lang) {
  std::string t = shortNumber(v);
  if (lang == Language::de)
    if (const size_t dot = t.find('.'); dot != std::string::npos) t[dot] = ',';
  return t;
}

// "1 of 2 points", "1 von 1 Punkt", "1 von 2 Punkten" (the dative after "von").
std::string pointsOf(double earned, double of, Language lang) {
  const bool one = of == 1;
  return pointsNumber(earned, lang) + (lang == Language::de ? " von " : " of ") + pointsNumber(of, lang) +
         (lang == Language::de ? (one ? " Punkt" : " Punkten") : (one ? " point" : " points"));
}

// A value's text as JSON: numbers and strings as they are, "5 entries" (a list of another length)
// as a string.
Json asJson(const std::string& text) {
  Json j = Json::parse(text, nullptr, false);
  return j.is_discarded() ? Json(text) : j;
}

// " of 3 values" / " von 3 Werten" (German takes the dative after "von").
std::string ofValues(size_t n, Language lang) {
  if (lang == Language::de) return " von " + std::to_string(n) + (n == 1 ? " Wert" : " Werten");
  return " of " + std::to_string(n) + (n == 1 ? " value" : " values");
}

std::string values(size_t n, Language lang) {
  return std::to_string(n) + (lang == Language::de ? (n == 1 ? " Wert" : " Werte") : (n == 1 ? " value" : " values"));
}

// ---------------------------------------------------------------- numbers: cases

// A reference value as the sheet prints it: an exact fraction or 4 decimals ("-3/10", "0.7071"),
// never floating-point noise ("1.7500000000000004").
std::string sheetValue(const std::string& json) {
  const Json j = Json::parse(json, nullptr, false);
  return j.is_number_float() ? plainNumber(j.get<double>(), 4) : json;
}

std::string valueLine(const GradedValue& v, Language lang) {
  if (v.malformed()) return v.path + ": " + v.student + " — " + (lang == Language::de ? v.problemDe : v.problem);
  if (v.count && v.reference.empty()) return v.path + ": " + v.student + std::string(inLanguage(lang, " vertices", " Ecken"));
  if (v.count)
    return v.path + ": " + v.student + std::string(inLanguage(lang, " vertices, expected ", " Ecken, erwartet ")) + v.reference;
  if (v.reference.empty()) return v.path + ": " + v.student + (v.rounded ? std::string(inLanguage(lang, " (rounded)", " (gerundet)")) : "");
  std::string line = v.path + ": " + v.student + std::string(inLanguage(lang, ", expected ", ", erwartet ")) + sheetValue(v.reference);
  if (v.rounded) line += std::string(inLanguage(lang, " (rounded)", " (gerundet)"));
  return line;
}

GradeCase itemCase(const ItemGrade& item, const NumbersGrade& g, Language lang) {
  GradeCase c;
  c.name = item.title == item.path ? item.path : item.title + " (" + item.path + ")";
  c.points = item.earned;
  c.maxPoints = item.points;
  const std::string points = pointsOf(item.earned, item.points, lang);
  if (item.missing()) {
    c.passed = !item.required;
    c.message = item.required ? std::string(inLanguage(lang, "not given (required): ", "nicht angegeben (verlangt): ")) + points
                              : std::string(inLanguage(lang, "not given (optional): ", "nicht angegeben (freiwillig): ")) + points;
    return c;
  }
  c.passed = item.right();
  c.message = item.right() ? values(item.values, lang) + std::string(inLanguage(lang, " right: ", " richtig: ")) + points
              : item.withdrawnFor
                  ? std::to_string(item.wrong) + ofValues(item.values, lang) +
                        std::string(inLanguage(lang, " wrong; they follow from your earlier values, but the mistake ",
                                               " falsch; sie folgen aus Ihren früheren Werten, aber der Fehler ")) +
                        quoted(mistakeModel(*item.withdrawnFor).key, lang) +
                        std::string(inLanguage(lang, " removes what this task asks (no follow-through credit): ",
                                               " nimmt dieser Aufgabe ihren Gegenstand (kein Folgefehler): ")) + points
              : item.followsThrough
                  ? std::to_string(item.wrong) + ofValues(item.values, lang) +
                        std::string(inLanguage(lang, " wrong, but they follow from your earlier values: ",
                                               " falsch, folgen aber aus Ihren früheren Werten: ")) + points
                  : std::to_string(item.wrong) + ofValues(item.values, lang) +
                        std::string(inLanguage(lang, " wrong: ", " falsch: ")) + points;
  for (const GradedValue& v : g.values)
    if (!v.right && isWithin(v.path, item.path)) c.details.push_back(valueLine(v, lang));
  c.total = c.details.size();
  return c;
}

// One case per vector or matrix the student gave outside every item (all of them without an
// assignment), in the order of the student's file.
std::vector<GradeCase> groupCases(const NumbersGrade& g, Language lang, Json& groups) {
  std::vector<std::string> order;
  std::map<std::string, GradeCase> cases;
  std::map<std::string, std::pair<size_t, size_t>> counts;  // wrong, total
  for (const GradedValue& v : g.values) {
    bool inItem = false;
    for (const ItemGrade& i : g.items) inItem |= isWithin(v.path, i.path);
    if (inItem) continue;
    if (!cases.count(v.group)) order.push_back(v.group), cases[v.group].name = v.group;
    auto& [wrong, total] = counts[v.group];
    ++total;
    if (!v.right) {
      ++wrong;
      cases[v.group].passed = false;
      cases[v.group].details.push_back(valueLine(v, lang));
    }
  }
  std::vector<GradeCase> out;
  for (const std::string& name : order) {
    GradeCase& c = cases[name];
    const auto [wrong, total] = counts[name];
    c.total = wrong;
    c.message = c.passed ? values(total, lang) + std::string(inLanguage(lang, " right", " richtig"))
                         : std::to_string(wrong) + ofValues(total, lang) +
                               std::string(inLanguage(lang, " wrong", " falsch"));
    Json wrongValues = Json::array();
    for (const GradedValue& v : g.values)
      if (v.group == name && !v.right)
        wrongValues.push_back({{"path", v.path}, {"student", asJson(v.student)},
                               {"reference", v.reference.empty() ? Json() : asJson(v.reference)},
                               {"rounded", v.rounded}, {"problem", v.problem}, {"vertex_count", v.count}});
    groups.push_back({{"path", name}, {"values", total}, {"wrong", wrong}, {"wrong_values", wrongValues}});
    out.push_back(c);
  }
  return out;
}

// ---------------------------------------------------------------- numbers: diagnosis

std::string modelName(Mistake m, Language lang) {
  const MistakeModel& model = mistakeModel(m);
  return quoted(model.key, lang) + " (" + std::string(model.descriptionIn(lang)) + ")";
}

std::vector<std::string> diagnosis(const NumbersGrade& g, Language lang) {
  std::vector<std::string> d;
  const bool de = lang == Language::de;
  std::string missing;
  for (const ItemGrade& i : g.items)
    if (i.required && i.missing()) missing += (missing.empty() ? "" : ", ") + i.title;
  if (!missing.empty())
    d.push_back((de ? "Nicht angegeben, aber verlangt: " : "Required but not given: ") + missing + ".");
  if (g.rounded > 0) {
    const int needed = g.tolerance > 0 ? int(std::ceil(std::log10(0.5 / g.tolerance) - 1e-9)) : 15;
    const std::string to = std::to_string(std::max(g.roundedDecimals, 0)) +
                           (de ? (g.roundedDecimals == 1 ? " Nachkommastelle" : " Nachkommastellen")
                               : (g.roundedDecimals == 1 ? " decimal" : " decimals"));
    const bool one = g.rounded == 1;
    d.push_back(de ? values(g.rounded, lang) + (one ? " weicht" : " weichen") + " nur durch Rundung (auf " + to +
                         ") vom Ergebnis ab: die Toleranz verlangt |Δ| ≤ " + shortNumber(g.tolerance) +
                         " · max(1, |x|); geben Sie mindestens " + std::to_string(needed) + " Nachkommastellen an."
                   : values(g.rounded, lang) + (one ? " differs" : " differ") + " from the reference only by rounding (to " + to +
                         "): the tolerance asks for |Δ| ≤ " + shortNumber(g.tolerance) +
                         " · max(1, |x|); give at least " + std::to_string(needed) + " decimals.");
  }
  for (const std::string& w : de ? g.warningsDe : g.warnings) d.push_back((de ? "Hinweis: " : "Note: ") + w + ".");
  if (g.rowVectorForm)
    d.push_back(de ? "Alle Matrizen sind in der Zeilenvektor-Form des Skripts (p' = p · M) geschrieben: als Schreibweise "
                     "akzeptiert und transponiert bewertet."
                   : "Every matrix is written in the lecture notes' row-vector form (p' = p · M): accepted as a notation "
                     "and graded transposed.");
  if (g.firstStage)
    d.push_back((de ? "Die erste Stufe, in der Ihre Zahlen vom Ergebnis abweichen: "
                    : "The first stage where your numbers depart from the reference: ") +
                std::string(stageName(*g.firstStage, lang)) + ".");
  const size_t unexplained = g.wrong - g.rounded - g.consequent;  // wrong values of their own
  if (g.mistake) {
    const MistakeModel& m = mistakeModel(*g.mistake);
    d.push_back((de ? "Ihre Zahlen sind die des Fehlermodells " : "Your numbers are those of the mistake model ") +
                quoted(m.key, lang) + ": " + std::string(m.descriptionIn(lang)) + (de ? ". Siehe " : ". See ") +
                std::string(m.hintIn(lang)) + ".");
    return d;
  }
  if (g.fitting.size() > 1) {
    std::string names;
    for (size_t i = 0; i < g.fitting.size(); ++i)
      names += (i ? (i + 1 == g.fitting.size() ? (de ? " und " : " and ") : ", ") : "") + modelName(g.fitting[i], lang);
    d.push_back((de ? "Ihre Zahlen passen gleichermaßen zu den Fehlermodellen " : "Your numbers fit the mistake models ") +
                names + (de ? "; die angegebenen Werte unterscheiden sie nicht." : " alike; the values you gave cannot tell them apart."));
    return d;
  }
  if (unexplained == 0) return d;
  const ModelMatch* best = nullptr;
  for (const ModelMatch& m : g.models)
    if (m.explained > 0 && (!best || m.explained > best->explained)) best = &m;
  // A hint only when the model explains most of what is wrong: "explains 1 of 35" misleads.
  if (best && 2 * best->explained > unexplained) {
    if (best->explained >= unexplained)
      d.push_back(de ? "Das Fehlermodell " + modelName(best->mistake, lang) + " erklärt alle " + std::to_string(unexplained) +
                           " falschen Werte, würde aber auch " + values(best->contradicted, lang) +
                           " ändern, die Sie richtig haben: Sie haben diesen Fehler in einem Teil Ihrer Rechnung gemacht."
                     : "The mistake model " + modelName(best->mistake, lang) + " explains all " + std::to_string(unexplained) +
                           " wrong values, but it would also change " + values(best->contradicted, lang) +
                           " you got right: you made this mistake in a part of your work.");
    else
      d.push_back(de ? "Das Fehlermodell " + modelName(best->mistake, lang) + " erklärt " + std::to_string(best->explained) +
                           " von " + std::to_string(unexplained) + " falschen Werten; die übrigen " +
                           std::to_string(unexplained - best->explained) + " haben eine andere Ursache."
                     : "The mistake model " + modelName(best->mistake, lang) + " explains " + std::to_string(best->explained) +
                           " of the " + std::to_string(unexplained) + " wrong values; the other " +
                           std::to_string(unexplained - best->explained) + " have another cause.");
  } else {
    d.push_back(de ? "Keines der Fehlermodelle erklärt Ihre Zahlen." : "None of the mistake models explains your numbers.");
  }
  return d;
}

}  // namespace

std::string fixed(double v, int places) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", places, v);
  return buf;
}

std::string quoted(std::string_view s, Language lang) {
  return lang == Language::de ? "„" + std::string(s) + "“" : "\"" + std::string(s) + "\"";
}

std::string studentIdOf(const std::string& file) { return std::filesystem::path(file).stem().string(); }

namespace {

// The grade with what `reveal` hides taken out: the reference values, and with none the stage and
// the mistake models too.
NumbersGrade revealed(NumbersGrade g, Reveal reveal) {
  if (reveal == Reveal::values) return g;
  for (GradedValue& v : g.values) v.reference.clear();
  if (reveal == Reveal::none) {
    g.firstStage.reset();
    g.mistake.reset();
    g.fitting.clear();
    g.models.clear();
    for (ItemGrade& i : g.items) i.withdrawnFor.reset();
  }
  return g;
}

}  // namespace

GradeReport numbersReport(const NumbersGrade& graded, const std::string& student, const std::string& scene, Language lang,
                          Reveal reveal) {
  const NumbersGrade g = revealed(graded, reveal);
  GradeReport r;
  r.kind = "numbers";
  r.student = student;
  r.id = studentIdOf(student);
  r.scene = scene;
  r.lang = lang;
  r.passed = g.passed();
  r.passMark = g.passMark;
  r.header.push_back(lang == Language::de
                         ? "Toleranz: |Student − Ergebnis| ≤ " + shortNumber(g.tolerance) +
                               " · max(1, |Ergebnis|); ganze Zahlen, Namen und die Einordnung der Polygone (angenommen, verworfen, geclippt) exakt; ein geclipptes Polygon "
                               "darf an jeder Ecke beginnen und in beide Richtungen laufen"
                         : "tolerance: |student − reference| ≤ " + shortNumber(g.tolerance) +
                               " · max(1, |reference|); integers, names and fates exactly; a clipped polygon may start at "
                               "any vertex and run either way round");
  Json items = Json::array();
  for (const ItemGrade& i : g.items) {
    r.cases.push_back(itemCase(i, g, lang));
    items.push_back({{"path", i.path},
                     {"title", i.title},
                     {"required", i.required},
                     {"points", i.points},
                     {"earned", i.earned},
                     {"values", i.values},
                     {"wrong", i.wrong},
                     {"status", i.missing() ? "missing" : i.right() ? "right" : i.followsThrough ? "follows" : i.withdrawnFor ? "withdrawn" : "wrong"}});
  }
  Json groups = Json::array();
  for (GradeCase& c : groupCases(g, lang, groups)) r.cases.push_back(std::move(c));
  r.graded = !g.items.empty();
  r.points = g.points;
  r.maxPoints = g.maxPoints;
  Json models = Json::array();
  for (const ModelMatch& m : g.models)
    models.push_back({{"mistake", mistakeModel(m.mistake).key},
                      {"explains_wrong_values", m.explained},
                      {"contradicted_values", m.contradicted},
                      {"matches", m.contradicted == 0 && m.explained > 0}});
  r.diagnosis = diagnosis(g, lang);
  Json fitting = Json::array();
  for (Mistake m : g.fitting) fitting.push_back(mistakeModel(m).key);
  r.json = {{"kind", "numbers"},
            {"student", student},
            {"id", r.id},
            {"scene", scene},
            {"lang", lang == Language::de ? "de" : "en"},
            {"passed", g.passed()},
            {"tolerance", g.tolerance},
            {"values", g.values.size()},
            {"wrong", g.wrong},
            {"rounded", g.rounded},
            {"points", r.graded ? Json(g.points) : Json()},
            {"max_points", r.graded ? Json(g.maxPoints) : Json()},
            {"first_departing_stage",
             g.firstStage ? Json{{"stage", *g.firstStage}, {"name", stageName(*g.firstStage, lang)}} : Json()},
            {"mistake", g.mistake ? Json{{"key", mistakeModel(*g.mistake).key},
                                         {"description", mistakeModel(*g.mistake).descriptionIn(lang)},
                                         {"hint", mistakeModel(*g.mistake).hintIn(lang)}}
                                  : Json()},
            {"fitting_models", fitting},
            {"models", models},
            {"items", items},
            {"groups", groups},
            {"diagnosis", r.diagnosis}};
  return r;
}

GradeReport errorReport(const std::string& kind, const std::string& student, const std::string& scene,
                        const std::string& error, Language lang) {
  GradeReport r;
  r.kind = kind;
  r.student = student;
  r.id = studentIdOf(student);
  r.scene = scene;
  r.lang = lang;
  r.passed = false;
  r.error = error;
  r.diagnosis.push_back(std::string(inLanguage(lang, "Your answer could not be graded: ",
                                               "Ihre Antwort konnte nicht bewertet werden: ")) + error);
  r.json = {{"kind", kind},   {"student", student}, {"id", r.id},       {"scene", scene},
            {"lang", lang == Language::de ? "de" : "en"}, {"passed", false}, {"error", error},
            {"diagnosis", r.diagnosis}};
  return r;
}

// ---------------------------------------------------------------- text and JUnit

std::string reportText(const GradeReport& r) {
  const bool de = r.lang == Language::de;
  std::string out = "vplab grade " + r.kind + ": " + r.student + (de ? " gegen " : " against ") + r.scene + "\n";
  for (const std::string& h : r.header) out += "  " + h + "\n";
  out += "\n";
  size_t failed = 0;
  constexpr size_t kShown = 8;
  for (const GradeCase& c : r.cases) {
    failed += !c.passed;
    out += std::string(c.passed ? "  ok     " : (de ? "  FALSCH " : "  WRONG  ")) + c.name + ": " + c.message + "\n";
    if (!c.passed || r.kind == "image")
      for (size_t i = 0; i < c.details.size() && i < kShown; ++i) out += "           " + c.details[i] + "\n";
    const size_t shown = std::min(c.details.size(), kShown);
    if (!c.passed && c.total > shown)
      out += "           " + std::string(de ? "… und " : "… and ") + std::to_string(c.total - shown) +
             (de ? " weitere\n" : " more\n");
  }
  if (!r.cases.empty()) out += "\n";
  for (const std::string& d : r.diagnosis) out += d + "\n";
  if (r.graded)
    out += (de ? "Punkte: " : "Points: ") + pointsNumber(r.points, r.lang) + (de ? " von " : " of ") +
           pointsNumber(r.maxPoints, r.lang) + "\n";
  if (!r.error.empty()) return out + (de ? "NICHT BEWERTET\n" : "NOT GRADED\n");
  const std::string mark = r.passMark ? (de ? " (bestanden ab " : " (the pass mark is ") + pointsOf(*r.passMark, r.maxPoints, r.lang) + ")" : "";
  if (r.passed) return out + (de ? "BESTANDEN" : "PASSED") + mark + "\n";
  if (r.passMark) return out + (de ? "NICHT BESTANDEN" : "FAILED") + mark + "\n";
  out += (de ? "NICHT BESTANDEN: " : "FAILED: ") + std::to_string(failed) + (de ? " von " : " of ") +
         std::to_string(r.cases.size()) + (de ? " Prüfungen falsch\n" : " checks wrong\n");
  return out;
}

std::string reportJunit(const GradeReport& r) {
  size_t failures = 0;
  for (const GradeCase& c : r.cases) failures += !c.passed;
  const size_t errors = r.error.empty() ? 0 : 1;
  const size_t tests = r.cases.size() + errors;
  std::string diagnosis;
  for (const std::string& d : r.diagnosis) diagnosis += d + "\n";
  if (r.graded)
    diagnosis += std::string(inLanguage(r.lang, "Points: ", "Punkte: ")) + shortNumber(r.points) +
                 std::string(inLanguage(r.lang, " of ", " von ")) + shortNumber(r.maxPoints) + "\n";
  // The time of the whole grade, shared out over its cases (JUnit readers sum them).
  const std::string time = fixed(tests ? r.seconds / double(tests) : 0, 3);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<testsuites tests=\"" + std::to_string(tests) + "\" failures=\"" + std::to_string(failures) + "\" errors=\"" +
         std::to_string(errors) + "\" time=\"" + fixed(r.seconds, 3) + "\">\n";
  out += "  <testsuite name=\"vplab grade " + r.kind + ": " + xmlEscape(r.student) + "\" tests=\"" + std::to_string(tests) +
         "\" failures=\"" + std::to_string(failures) + "\" errors=\"" + std::to_string(errors) + "\" time=\"" +
         fixed(r.seconds, 3) + "\">\n";
  const std::string open = "    <testcase classname=\"" + xmlEscape(r.id) + "\" name=\"";
  if (errors)
    out += open + xmlEscape(std::string(inLanguage(r.lang, "answer file", "Antwortdatei"))) + "\" time=\"" + time +
           "\">\n      <error message=\"" + xmlEscape(r.error) + "\">" + xmlEscape(diagnosis) + "</error>\n    </testcase>\n";
  for (const GradeCase& c : r.cases) {
    out += open + xmlEscape(c.name) + "\" time=\"" + time + "\"";
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
