#include "course/moodle_bank.h"

#include "course/rational.h"
#include "course/xml_text.h"
#include "base/error.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <optional>

namespace vplab {

using Json = nlohmann::ordered_json;

namespace {

/// A value as the key gives it, snapped to its small fraction where it is one (6.1e-17 → 0).
double cleanValue(double x) {
  if (const auto r = Rational::approximate(x, 1000, 1e-9)) return r->toDouble();
  return x;
}

std::string labelOf(const std::string& title, std::string_view subPath) {
  std::string label = title;
  if (subPath.empty()) return label;
  label += " ";
  size_t at = 1;
  while (at <= subPath.size()) {
    const size_t end = std::min(subPath.find('/', at), subPath.size());
    const std::string_view key = subPath.substr(at, end - at);
    size_t index = 0;
    const auto [p, ec] = std::from_chars(key.data(), key.data() + key.size(), index);
    label += ec == std::errc() && p == key.data() + key.size() ? "[" + std::to_string(index + 1) + "]" : "." + std::string(key);
    at = end + 1;
  }
  return label;
}

/// Every number below `j`, with its JSON pointer relative to `j`, in document order.
void numbersOf(const Json& j, const std::string& at, std::vector<std::pair<std::string, const Json*>>& out) {
  if (j.is_number()) {
    out.emplace_back(at, &j);
  } else if (j.is_array()) {
    for (size_t i = 0; i < j.size(); ++i) numbersOf(j[i], at + "/" + std::to_string(i), out);
  } else if (j.is_object()) {
    for (const auto& [k, v] : j.items()) numbersOf(v, at + "/" + k, out);
  }
}

const Json* valueAt(const Json& j, const std::string& pointer) {
  try {
    const Json::json_pointer p(pointer);
    return j.contains(p) ? &j.at(p) : nullptr;
  } catch (const std::exception&) {
    return nullptr;
  }
}

std::string mistakeFeedback(const MistakeModel& m, Language lang) {
  return std::string(inLanguage(lang, "Mistake: ", "Fehler: ")) + std::string(m.descriptionIn(lang)) + " (" +
         std::string(m.hintIn(lang)) + ")";
}

/// Text inside CDATA: "]]>" cannot appear in it, so it is split across two sections.
std::string cdata(std::string_view s) {
  std::string out = "<![CDATA[";
  for (size_t i = 0; i < s.size(); ++i) {
    if (s.substr(i, 3) == "]]>") {
      out += "]]]]><![CDATA[>";
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out + "]]>";
}

std::string htmlEscape(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      default: out += c;
    }
  }
  return out;
}

/// One line of Markdown text as HTML: **bold**, $math$ → \(math\).
std::string inlineHtml(std::string_view line) {
  std::string out;
  bool bold = false;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '$') {
      const size_t end = line.find('$', i + 1);
      if (end != std::string_view::npos) {
        out += "\\(" + htmlEscape(line.substr(i + 1, end - i - 1)) + "\\)";
        i = end;
        continue;
      }
    }
    if (line.substr(i, 2) == "**") {
      out += bold ? "</strong>" : "<strong>";
      bold = !bold;
      ++i;
      continue;
    }
    out += htmlEscape(line.substr(i, 1));
  }
  if (bold) out += "</strong>";
  return out;
}

bool isNumberedItem(std::string_view line, size_t& textAt) {
  size_t i = 0;
  while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
  if (i == 0 || line.substr(i, 2) != ". ") return false;
  textAt = i + 2;
  return true;
}

bool validFigureName(std::string_view name) {
  if (name.empty() || name.size() > 64 || name[0] == '.') return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') return false;
  return true;
}

/// Points as a fraction (denominator up to 1000).
Rational pointsFraction(double points) {
  const std::optional<Rational> r = Rational::approximate(points, 1000, 1e-9);
  if (!r || r->num() < 0)
    throw Error("Moodle bank: " + std::to_string(points) + " points: a fraction with a denominator up to 1000 expected");
  return *r;
}

int64_t lcm64(int64_t a, int64_t b) {
  const int64_t l = a / std::gcd(a, b);
  if (l > INT64_MAX / b) throw Error("Moodle bank: the weights' common factor overflows");
  return l * b;
}

}  // namespace

int64_t clozeWeightFactor(const std::vector<std::pair<double, size_t>>& items) {
  int64_t equal = 1, denominators = 1;
  bool any = false;
  for (const auto& [points, count] : items) {
    const Rational p = pointsFraction(points);
    if (p.num() == 0 || count == 0) continue;
    any = true;
    // a·F / (b·n) an integer: F a multiple of b·n / gcd(a, b·n).
    const int64_t bn = p.den() * int64_t(count);
    equal = std::min(lcm64(equal, bn / std::gcd(p.num(), bn)), kMaxEqualWeightFactor + 1);
    denominators = lcm64(denominators, p.den());
  }
  if (!any) return 0;
  if (equal <= kMaxEqualWeightFactor) return equal;
  // Every value at least 1: a·F / b ≥ n.
  int64_t f = denominators;
  for (const auto& [points, count] : items) {
    const Rational p = pointsFraction(points);
    if (p.num() == 0 || count == 0) continue;
    const int64_t least = (int64_t(count) * p.den() + p.num() - 1) / p.num();
    f = std::max(f, (least + denominators - 1) / denominators * denominators);
  }
  return f;
}

std::vector<ClozeValue> clozeValues(const Assignment& assignment, const Json& key,
                                    const std::vector<std::pair<Mistake, Json>>& models, Language lang) {
  std::vector<ClozeValue> values;
  std::vector<std::pair<double, size_t>> counts;  // per item: points, values
  for (const AssignmentItem& item : assignment.items) {
    const Json* at = valueAt(key, item.path);
    if (!at) throw Error("Moodle bank: the answer key has no value at " + item.path + " (" + item.title + ")");
    std::vector<std::pair<std::string, const Json*>> numbers;
    numbersOf(*at, "", numbers);
    if (pointsFraction(item.points).num() == 0) numbers.clear();  // worth nothing: not asked
    counts.emplace_back(item.points, numbers.size());
    for (const auto& [sub, number] : numbers) {
      ClozeValue v;
      v.item = item.path;
      v.path = item.path + sub;
      v.label = labelOf(item.title, sub);
      v.value = number->is_number_integer() ? number->get<double>() : cleanValue(number->get<double>());
      v.tolerance = number->is_number_integer() ? 0 : assignment.tolerance * std::max(1.0, std::abs(v.value));
      for (const auto& [mistake, dump] : models) {
        const Json* predicted = valueAt(dump, v.path);
        if (!predicted || !predicted->is_number()) continue;
        const double m = number->is_number_integer() ? predicted->get<double>() : cleanValue(predicted->get<double>());
        if (!std::isfinite(m) || std::abs(m - v.value) <= v.tolerance) continue;
        const std::string feedback = mistakeFeedback(mistakeModel(mistake), lang);
        bool shared = false;
        for (ClozeDistractor& d : v.mistakes)
          if (std::abs(d.value - m) <= v.tolerance) {
            d.feedback += "; " + feedback;
            shared = true;
            break;
          }
        if (!shared) v.mistakes.push_back({m, feedback});
      }
      values.push_back(std::move(v));
    }
  }
  // Each item's points × F over its values, as evenly as integers allow (clozeWeightFactor).
  const int64_t factor = clozeWeightFactor(counts);
  int64_t sum = 0;
  size_t at = 0;
  for (const auto& [points, count] : counts) {
    if (count == 0) continue;
    const Rational p = pointsFraction(points);
    const int64_t total = p.num() * factor / p.den();  // an integer: F is a multiple of the denominators
    for (size_t k = 0; k < count; ++k) {
      const int64_t w = total / int64_t(count) + (int64_t(k) < total % int64_t(count) ? 1 : 0);
      values[at++].weight = int(w);
    }
    sum += total;
    // Moodle stores the question's mark, the sum of its weights, as a decimal below 100 000.
    if (sum > 99999) throw Error("Moodle bank: the sub-questions' weights add up to more than Moodle's 99999 marks");
  }
  return values;
}

bool isPolygonItem(std::string_view itemPath) {
  auto endsWith = [&](std::string_view tail) {
    return itemPath.size() >= tail.size() && itemPath.substr(itemPath.size() - tail.size()) == tail;
  };
  return endsWith("/clipped_dc") || (endsWith("/polygon") && itemPath.find("/clip_steps/") != std::string_view::npos);
}

std::string vertexOrderRule(Language lang) {
  return std::string(inLanguage(
      lang,
      "Order of a polygon's vertices: the order Sutherland–Hodgman writes them. Moodle compares value by value, so "
      "another first vertex or the other direction counts as wrong. A pass walks the edges of its input polygon "
      "\\(Q_1 \\ldots Q_n\\) in order, starting with the closing edge from the last vertex to the first, "
      "\\(Q_n \\to Q_1\\), then \\(Q_1 \\to Q_2\\), \\(Q_2 \\to Q_3\\), …; for each edge \\(S \\to P\\) it writes: "
      "entering (\\(S\\) outside, \\(P\\) inside) the intersection, then \\(P\\); both inside \\(P\\); leaving "
      "(\\(S\\) inside, \\(P\\) outside) the intersection; both outside nothing. So the result starts with what "
      "the closing edge \\(Q_n \\to Q_1\\) writes (entering: its intersection, then \\(Q_1\\); both inside: "
      "\\(Q_1\\); leaving: its intersection; both outside: nothing, and the first vertex a later edge writes comes "
      "first), and it goes round in the input's direction. The left plane's input is \\(P_1 \\ldots P_n\\), "
      "each further plane's the result of the plane before (a plane with no vertex outside leaves it as it is); "
      "a vertex on the plane counts as inside and is not written twice.",
      "Reihenfolge der Eckpunkte eines Polygons: die, in der Sutherland–Hodgman sie ausgibt. Moodle vergleicht Wert "
      "für Wert, ein anderer erster Punkt oder der andere Umlaufsinn zählt als falsch. Ein Durchlauf geht die Kanten "
      "seines Eingabepolygons \\(Q_1 \\ldots Q_n\\) der Reihe nach durch, beginnend mit der schließenden Kante vom "
      "letzten zum ersten Punkt, \\(Q_n \\to Q_1\\), dann \\(Q_1 \\to Q_2\\), \\(Q_2 \\to Q_3\\), …; für jede Kante "
      "\\(S \\to P\\) schreibt er: eintretend (\\(S\\) außen, \\(P\\) innen) den Schnittpunkt, dann \\(P\\); beide "
      "innen \\(P\\); austretend (\\(S\\) innen, \\(P\\) außen) den Schnittpunkt; beide außen nichts. Das Ergebnis "
      "beginnt also mit dem, was die schließende Kante \\(Q_n \\to Q_1\\) schreibt (eintretend: ihren Schnittpunkt, "
      "dann \\(Q_1\\); beide innen: \\(Q_1\\); austretend: ihren Schnittpunkt; beide außen: nichts, und zuerst kommt "
      "der erste Punkt, den eine spätere Kante schreibt), und läuft im Umlaufsinn der Eingabe. Die Eingabe der linken "
      "Ebene ist \\(P_1 \\ldots P_n\\), die jeder weiteren das Ergebnis der Ebene davor (eine Ebene ohne Punkt außen "
      "lässt es, wie es ist); ein Punkt auf der Ebene zählt als innen und wird nicht doppelt geschrieben."));
}

std::string vertexOrderNote(std::string_view itemPath, Language lang) {
  if (!isPolygonItem(itemPath)) return "";
  if (itemPath.substr(itemPath.size() - 11) == "/clipped_dc")
    return std::string(inLanguage(lang,
                                  "Vertices in the order of the polygon after the front plane (the same first vertex, "
                                  "the same direction), each divided by \\(w\\) and mapped to DC.",
                                  "Eckpunkte in der Reihenfolge des Polygons nach der vorderen Ebene (derselbe erste "
                                  "Punkt, derselbe Umlaufsinn), jeder durch \\(w\\) dividiert und auf DC abgebildet."));
  const bool first = itemPath.find("/clip_steps/0/") != std::string_view::npos;
  return first ? std::string(inLanguage(lang,
                                        "Vertices in the order this pass writes them (above): first the vertex it "
                                        "writes first, then on in the direction of \\(P_1, P_2, \\ldots\\).",
                                        "Eckpunkte in der Reihenfolge, in der dieser Durchlauf sie schreibt (oben): "
                                        "zuerst der Punkt, den er zuerst schreibt, dann weiter im Umlaufsinn von "
                                        "\\(P_1, P_2, \\ldots\\)."))
               : std::string(inLanguage(lang,
                                        "Vertices in the order this pass writes them (above): first the vertex it "
                                        "writes first, then on in the direction of its input, the polygon after the "
                                        "plane before.",
                                        "Eckpunkte in der Reihenfolge, in der dieser Durchlauf sie schreibt (oben): "
                                        "zuerst der Punkt, den er zuerst schreibt, dann weiter im Umlaufsinn seiner "
                                        "Eingabe, des Polygons nach der Ebene davor."));
}

std::string clozeNumber(double x) {
  if (!std::isfinite(x)) throw Error("Moodle bank: " + std::to_string(x) + " is not a number a cloze answer can hold");
  if (x == 0) return "0";
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  if (ec != std::errc()) throw Error("Moodle bank: cannot write the number " + std::to_string(x));
  return std::string(buf, end);
}

std::string clozeFeedbackText(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '}': out += "\\}"; break;
      case '#': out += "\\#"; break;
      case '~': out += "&#126;"; break;
      case '{': out += "&#123;"; break;
      case '\\': out += "&#92;"; break;
      case '&': out += "&amp;amp;"; break;
      case '<': out += "&amp;lt;"; break;
      case '>': out += "&amp;gt;"; break;
      case '\n': case '\r': out += ' '; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

/// A tolerance with as few digits as keep it within 1 % below its value (never above: Moodle must
/// not accept more than the grader).
std::string toleranceText(double t) {
  for (int digits = 2; digits <= 17; ++digits) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, t);
    const double v = std::strtod(buf, nullptr);
    if (v <= t && v >= 0.99 * t) return clozeNumber(v);
  }
  return clozeNumber(t);
}

}  // namespace

std::string clozeSubquestion(const ClozeValue& v, Language lang) {
  const std::string tolerance = toleranceText(v.tolerance);
  std::string s = "{" + std::to_string(v.weight) + ":NUMERICAL:=" + clozeNumber(v.value) + ":" + tolerance + "#" +
                  clozeFeedbackText(inLanguage(lang, "Right.", "Richtig."));
  for (const ClozeDistractor& d : v.mistakes)
    s += "~%0%" + clozeNumber(d.value) + ":" + tolerance + "#" + clozeFeedbackText(d.feedback);
  s += "~%0%*#" + clozeFeedbackText(inLanguage(lang, "Wrong: compare with the worked solution.",
                                               "Falsch: vergleichen Sie mit der Musterlösung."));
  return s + "}";
}

std::string sheetHtml(std::string_view markdown) {
  std::string out, list;  // list: the open list's tag ("ul", "ol") or empty
  bool inMath = false;
  std::string math;
  auto closeList = [&] {
    if (!list.empty()) out += "</" + list + ">\n";
    list.clear();
  };
  size_t at = 0;
  while (at <= markdown.size()) {
    const size_t end = std::min(markdown.find('\n', at), markdown.size());
    const std::string_view line = markdown.substr(at, end - at);
    at = end + 1;
    if (line == "$$") {
      if (inMath) out += "<p>\\[" + htmlEscape(math) + "\\]</p>\n", math.clear();
      else closeList();
      inMath = !inMath;
      continue;
    }
    if (inMath) {
      math += std::string(line) + "\n";
      continue;
    }
    size_t textAt = 0;
    if (line.empty()) {
      closeList();
    } else if (line.substr(0, 3) == "## ") {
      closeList(), out += "<h4>" + inlineHtml(line.substr(3)) + "</h4>\n";
    } else if (line.substr(0, 2) == "# ") {
      closeList(), out += "<h3>" + inlineHtml(line.substr(2)) + "</h3>\n";
    } else if (line.substr(0, 2) == "- " || isNumberedItem(line, textAt)) {
      const std::string tag = line.substr(0, 2) == "- " ? "ul" : "ol";
      if (list != tag) closeList(), out += "<" + tag + ">\n", list = tag;
      out += "<li>" + inlineHtml(line.substr(tag == "ul" ? 2 : textAt)) + "</li>\n";
    } else if (line.substr(0, 2) == "![" && line.find("](") != std::string_view::npos && line.back() == ')') {
      closeList();
      const size_t mid = line.find("](");
      std::string file(line.substr(mid + 2, line.size() - mid - 3));
      if (file.size() > 4 && file.substr(file.size() - 4) == ".svg") file = file.substr(0, file.size() - 4) + ".png";
      out += "<p><img src=\"@@PLUGINFILE@@/" + htmlEscape(file) + "\" alt=\"" + htmlEscape(line.substr(2, mid - 2)) +
             "\" style=\"max-width: 100%\"><br>" + inlineHtml(line.substr(2, mid - 2)) + "</p>\n";
    } else {
      closeList(), out += "<p>" + inlineHtml(line) + "</p>\n";
    }
  }
  closeList();
  return out;
}

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t n = uint32_t(static_cast<unsigned char>(bytes[i])) << 16;
    if (i + 1 < bytes.size()) n |= uint32_t(static_cast<unsigned char>(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) n |= uint32_t(static_cast<unsigned char>(bytes[i + 2]));
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[n & 63] : '=';
  }
  return out;
}

namespace {

std::string questionXml(const MoodleQuestion& q) {
  if (q.values.empty()) throw Error("Moodle bank: question \"" + q.name + "\" has no values to ask for");
  std::string text = sheetHtml(q.sheetMarkdown);
  text += std::string("<h4>") + std::string(inLanguage(q.lang, "Answers", "Antworten")) + "</h4>\n<p>" +
          std::string(inLanguage(q.lang, "Exact values or decimals; the tolerance is that of the grader.",
                                 "Exakte Werte oder Dezimalzahlen; die Toleranz ist die des Bewerters.")) +
          "</p>\n";
  if (std::any_of(q.values.begin(), q.values.end(), [](const ClozeValue& v) { return isPolygonItem(v.item); }))
    text += "<p>" + htmlEscape(vertexOrderRule(q.lang)) + "</p>\n";
  text += "<table>\n";
  for (size_t i = 0; i < q.values.size(); ++i) {
    const ClozeValue& v = q.values[i];
    if (i == 0 || v.item != q.values[i - 1].item)
      if (const std::string note = vertexOrderNote(v.item, q.lang); !note.empty())
        text += "<tr><td colspan=\"2\"><em>" + htmlEscape(note) + "</em></td></tr>\n";
    text += "<tr><td>" + htmlEscape(v.label) + "</td><td>" + clozeSubquestion(v, q.lang) + "</td></tr>\n";
  }
  text += "</table>\n";
  std::string files;
  for (const MoodleFigure& f : q.figures) {
    if (!validFigureName(f.name))
      throw Error("Moodle bank: figure name \"" + f.name + "\": letters, digits, '.', '-' and '_' expected");
    files += "      <file name=\"" + f.name + "\" path=\"/\" encoding=\"base64\">" + base64(f.png) + "</file>\n";
  }
  return "  <question type=\"cloze\">\n"
         "    <name><text>" + xmlEscape(q.name) + "</text></name>\n"
         "    <questiontext format=\"html\">\n"
         "      <text>" + cdata(text) + "</text>\n" + files +
         "    </questiontext>\n"
         "    <generalfeedback format=\"html\"><text></text></generalfeedback>\n"
         "    <penalty>0.3333333</penalty>\n"
         "    <hidden>0</hidden>\n"
         "  </question>\n";
}

}  // namespace

std::string moodleBankXml(std::string_view category, const std::vector<MoodleQuestion>& questions) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<quiz>\n"
                    "  <question type=\"category\">\n"
                    "    <category><text>$course$/top/" + xmlEscape(category) + "</text></category>\n"
                    "  </question>\n";
  for (const MoodleQuestion& q : questions) out += questionXml(q);
  return out + "</quiz>\n";
}

}  // namespace vplab
