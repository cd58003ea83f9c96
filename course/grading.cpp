#include "course/grading.h"

#include "course/assignment.h"
#include "course/follow_through.h"
#include "course/rational.h"
#include "course/sheet_values.h"
#include "io/json_read.h"
#include "io/limits.h"

#include "base/error.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>

namespace vplab {

using Json = nlohmann::ordered_json;

std::string_view stageName(int stage, Language lang) {
  const bool de = lang == Language::de;
  switch (stage) {
    case 0: return de ? "die Szene (MC)" : "the scene (MC)";
    case 1: return de ? "Stufe 1, Modellierung (MC → WC)" : "stage 1, modeling (MC → WC)";
    case 2: return de ? "Stufe 2, Sichtorientierung (WC → VRC)" : "stage 2, view orientation (WC → VRC)";
    case 3: return de ? "Stufe 3, Sichtabbildung (VRC → homogene NPC)" : "stage 3, view mapping (VRC → homogeneous NPC)";
    case 4: return de ? "Stufe 4, Clipping" : "stage 4, clipping";
    default: return de ? "Stufe 5, Gerätetransformation (NPC → DC)" : "stage 5, device mapping (NPC → DC)";
  }
}

Json parseAnswer(std::string_view text, std::string_view source) {
  // The dump nests 8 deep (/objects/0/polygons/0/npc_h/0/0); an answer is read with a scene's limit.
  return parseCheckedJson(text, source, kDefaultLimits.jsonDepth);
}

namespace {

// Which stage a key of the dump belongs to.
int stageOfKey(const std::string& section, const std::string& key) {
  if (section == "camera") return key == "dmin" || key == "dmax" || key == "projection" ? 3 : 2;
  if (section == "device") return 5;
  if (section == "stats") return 4;
  if (key == "vrc_from_wc" || key == "vrc") return 2;
  if (key == "npc_from_vrc" || key == "npc_h") return 3;
  if (key == "dc_from_npc" || key == "clipped_dc") return 5;
  if (key == "wc_from_mc" || key == "wc") return 1;
  if (key == "outcodes" || key == "fate" || key == "boundary" || key == "clip_steps") return 4;
  if (key == "npc" || key == "dc") return 5;
  return 0;  // name, mc
}

std::string typeName(const Json& j) {
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_boolean()) return "true or false";
  if (j.is_array()) return "an array";
  if (j.is_object()) return "an object";
  return "null";
}

std::string typeNameDe(const Json& j) {
  if (j.is_number()) return "eine Zahl";
  if (j.is_string()) return "ein Text";
  if (j.is_boolean()) return "true oder false";
  if (j.is_array()) return "eine Liste";
  if (j.is_object()) return "ein Objekt";
  return "null";
}

std::optional<double> numberOf(const Json& j);

}  // namespace

std::optional<double> answerNumber(const Json& j) { return numberOf(j); }

namespace {

// A number the student wrote: a JSON number, or a fraction or decimal as a string ("-3/5", "0.6"),
// as the sheet's exact solutions print them. nullopt for anything else.
std::optional<double> numberOf(const Json& j) {
  if (j.is_number()) return j.get<double>();
  if (!j.is_string()) return std::nullopt;
  const std::string t = j.get<std::string>();
  if (t.empty() || t.size() > 40) return std::nullopt;
  if (const size_t slash = t.find('/'); slash != std::string::npos) {
    auto whole = [](const std::string& x, bool sign) {
      const size_t from = sign && !x.empty() && x[0] == '-' ? 1 : 0;
      return x.size() > from && x.size() - from <= 15 && x.find_first_not_of("0123456789", from) == std::string::npos;
    };
    const std::string num = t.substr(0, slash), den = t.substr(slash + 1);
    if (!whole(num, true) || !whole(den, false) || std::stoll(den) == 0) return std::nullopt;
    return double(std::stoll(num)) / double(std::stoll(den));
  }
  // A decimal comma, as German students write it ("0,6"): one comma and no point.
  std::string decimal = t;
  if (std::count(t.begin(), t.end(), ',') == 1 && t.find('.') == std::string::npos) decimal[t.find(',')] = '.';
  if (decimal.find_first_not_of("+-0123456789.eE") != std::string::npos) return std::nullopt;
  size_t used = 0;
  try {
    const double v = std::stod(decimal, &used);
    if (used == decimal.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// How many digits the student printed after the decimal point: from the shortest text that reads
// back as the number (JSON keeps no trailing zeros), -1 for exponent forms and fractions.
int decimalsOf(const Json& j) {
  if (j.is_string() && numberOf(j)) {  // "0,667", "0.667": as printed; fractions are exact
    const std::string t = j.get<std::string>();
    if (t.find_first_of("/eE") != std::string::npos) return -1;
    const size_t mark = t.find_first_of(".,");
    return mark == std::string::npos ? 0 : int(t.size() - mark - 1);
  }
  if (!j.is_number_float()) return j.is_number() ? 0 : -1;
  const std::string t = j.dump();
  if (t.find_first_of("eE") != std::string::npos) return -1;
  const size_t dot = t.find('.');
  if (dot == std::string::npos) return 0;
  const std::string frac = t.substr(dot + 1);
  return frac == "0" ? 0 : int(frac.size());
}

// |student − value| within half a unit of the student's last digit: what rounding would give. A
// whole number counts as rounded only where whole units are a plausible precision (|value| ≥ 10: DC
// pixels), not 0 for 0.5.
bool withinRounding(const Json& student, double value) {
  const int d = decimalsOf(student);
  const std::optional<double> s = numberOf(student);
  if (d < 0 || !s || (d == 0 && std::abs(value) < 10)) return false;
  const double halfUnit = 0.5 * std::pow(10.0, -d);
  return std::abs(*s - value) <= halfUnit * (1 + 1e-9) + 1e-12 * std::abs(value);
}

// A clipped polygon is a cycle: the student's vertex i is the other's vertex map(i), for the shift
// and direction that put the student's vertices nearest the other's (clippers start anywhere and go
// either way round).
struct Cycle {
  size_t shift = 0;
  bool reversed = false;
  size_t map(size_t i, size_t n) const { return reversed ? (shift + n - i % n) % n : (i + shift) % n; }
  size_t unmap(size_t r, size_t n) const { return reversed ? (shift + n - r % n) % n : (r + n - shift % n) % n; }
};

double vertexDistance(const Json& a, const Json& b) {
  double d = 0;
  if (!a.is_array() || !b.is_array()) return INFINITY;
  for (size_t c = 0; c < std::min(a.size(), b.size()); ++c) {
    const std::optional<double> x = numberOf(a[c]), y = numberOf(b[c]);
    d += x && y ? std::abs(*x - *y) : 1e9;
  }
  return d;
}

Cycle alignment(const Json& student, const Json& other) {
  Cycle best;
  if (student.empty() || other.empty() || !student[0].is_array()) return best;
  const size_t n = other.size();
  // With as many vertices as the other, all of them count; otherwise the first decides the shift.
  const size_t compared = student.size() == n ? n : 1;
  double bestDistance = INFINITY;
  for (const bool reversed : {false, true})
    for (size_t shift = 0; shift < n; ++shift) {
      const Cycle c{shift, reversed};
      double d = 0;
      for (size_t i = 0; i < compared; ++i) d += vertexDistance(student[i], other[c.map(i, n)]);
      if (d < bestDistance - 1e-12) bestDistance = d, best = c;
    }
  return best;
}

// The lists of a polygon's vertices (P1, P2, …) that a student may give in part, from P1 on.
bool isPerVertexList(const std::string& key) {
  return key == "mc" || key == "wc" || key == "vrc" || key == "npc_h" || key == "outcodes" || key == "boundary" ||
         key == "npc" || key == "dc";
}

struct Walker {
  Walker(std::string source_, double tolerance_) : source(std::move(source_)), tolerance(tolerance_) {}

  std::string source;
  double tolerance = 0;
  std::vector<GradedValue> values;
  std::vector<const Json*> referenceOf;  // per value: the reference leaf (for the models)
  std::vector<const Json*> studentOf;    // per value: the student's leaf
  std::vector<std::vector<std::string>> pathKeys;  // per value: the path into the dump

  std::vector<std::string> warnings, warningsDe;  // unknown keys: said, not fatal
  std::deque<Json> readAs;  // a student's value read as what it says ("100110" as an outcode)

  // A value the student gave in a form that cannot be graded: that value's error (wrong, named),
  // not the whole file's (issue 38: one bad value costs one item).
  void malformed(const Json& s, const std::string& path, const std::string& group, int stage,
                 std::vector<std::string> keys, std::string what, std::string whatDe) {
    GradedValue v;
    v.path = path;
    v.group = group;
    v.stage = stage;
    v.right = false;
    std::string shown = s.dump();
    if (shown.size() > 60) shown = shown.substr(0, 57) + "…";
    v.student = shown;
    v.problem = std::move(what);
    v.problemDe = std::move(whatDe);
    values.push_back(std::move(v));
    referenceOf.push_back(nullptr);
    studentOf.push_back(&s);
    pathKeys.push_back(std::move(keys));
  }

  bool same(const Json& s, const Json& r) const {
    if (r.is_number_integer() || r.is_number_unsigned()) return s.is_number_integer() && s == r;
    if (r.is_number()) {
      const std::optional<double> a = numberOf(s);
      const double b = r.get<double>();
      return a && std::isfinite(*a) && std::abs(*a - b) <= tolerance * std::max(1.0, std::abs(b));
    }
    return s == r;
  }
  // The same, or off by no more than the student's rounding (for the mistake models: a student who
  // rounds and makes a mistake still makes that mistake).
  bool agrees(const Json& s, const Json& r) const {
    return same(s, r) || (r.is_number() && !r.is_number_integer() && !r.is_number_unsigned() &&
                          withinRounding(s, r.get<double>()));
  }

  // An integer the student wrote as text: an outcode's six bits as the solution prints them
  // ("100010" is 34), or decimal digits.
  static std::optional<long long> integerOf(const Json& s, const std::vector<std::string>& keys) {
    if (!s.is_string()) return std::nullopt;
    const std::string t = s.get<std::string>();
    const bool outcode = std::find(keys.begin(), keys.end(), "outcodes") != keys.end();
    if (outcode && t.size() == 6 && t.find_first_not_of("01") == std::string::npos) return std::stoll(t, nullptr, 2);
    if (!t.empty() && t.size() <= 15 && t.find_first_not_of("0123456789") == std::string::npos) return std::stoll(t);
    return std::nullopt;
  }

  void leaf(const Json& given, const Json& r, const std::string& path, const std::string& group, int stage,
            std::vector<std::string> keys) {
    if (given.is_null()) return;  // not given (the template's empty field)
    const Json* read = &given;
    const bool integer = r.is_number_integer() || r.is_number_unsigned();
    if (integer && !given.is_number_integer()) {
      if (const std::optional<long long> i = integerOf(given, keys)) read = &readAs.emplace_back(*i);
    }
    const Json& s = *read;
    if (r.is_number()) {
      if (!s.is_number() && !(s.is_string() && numberOf(s) && !integer))
        return malformed(given, path, group, stage, std::move(keys),
                         typeName(s) + " where a number is expected" + (s.is_string() ? " (a fraction is written \"-3/5\")" : ""),
                         typeNameDe(s) + ", wo eine Zahl erwartet wird" + (s.is_string() ? " (ein Bruch wird \"-3/5\" geschrieben)" : ""));
      if (integer && !s.is_number_integer())
        return malformed(given, path, group, stage, std::move(keys), "not a whole number where one is expected",
                         "keine ganze Zahl, wo eine erwartet wird");
    } else if (r.is_string() && !s.is_string()) {
      return malformed(given, path, group, stage, std::move(keys), typeName(s) + " where a text is expected",
                       typeNameDe(s) + ", wo ein Text erwartet wird");
    } else if (r.is_boolean() && !s.is_boolean()) {
      return malformed(given, path, group, stage, std::move(keys), typeName(s) + " where true or false is expected",
                       typeNameDe(s) + ", wo true oder false erwartet wird");
    }
    GradedValue v;
    v.path = path;
    v.group = group;
    v.stage = stage;
    v.right = same(s, r);
    v.decimals = decimalsOf(s);
    v.rounded = !v.right && r.is_number_float() && withinRounding(s, r.get<double>());
    v.student = s.dump();
    v.reference = r.dump();
    values.push_back(std::move(v));
    referenceOf.push_back(&r);
    studentOf.push_back(&s);
    pathKeys.push_back(std::move(keys));
  }

  static bool isMatrix(const Json& j) {
    for (const Json& row : j)
      if (!row.is_array() || row.size() != 4) return false;
    return true;
  }

  static bool isNumberArray(const Json& j) {
    return j.is_array() && !j.empty() && std::all_of(j.begin(), j.end(), [](const Json& e) { return e.is_number(); });
  }

  void walk(const Json& s, const Json& r, const std::string& path, const std::string& group, int stage,
            std::vector<std::string> keys, const std::string& section) {
    if (r.is_object()) {
      if (!s.is_object()) {
        if (path.empty()) throw Error(source + ": /: " + typeName(s) + " where an answer (a JSON object) is expected");
        return malformed(s, path, group, stage, keys, typeName(s) + " where an object is expected",
                         typeNameDe(s) + ", wo ein Objekt erwartet wird");
      }
      for (const auto& [key, value] : s.items()) {
        // The exercise an answer names (course/exercise_file.h) labels it, as a file's name does: no value.
        if (path.empty() && key == "exercise") continue;
        if (!r.contains(key)) {
          std::string known;
          for (const auto& [k, v] : r.items()) known += (known.empty() ? "" : ", ") + k;
          warnings.push_back(path + "/" + key + ": unknown key, not graded (known here: " + known + ")");
          warningsDe.push_back(path + "/" + key + ": unbekannter Schlüssel, nicht bewertet (bekannt sind hier: " + known + ")");
          continue;
        }
        auto sub = keys;
        sub.push_back(key);
        const std::string sec = section.empty() ? key : section;
        // A key of no stage of its own (a pass's "polygon") is in its parent's stage.
        const int own = section.empty() ? stageOfKey(key, "") : stageOfKey(sec, key);
        walk(value, r[key], path + "/" + key, path + "/" + key, own == 0 ? stage : own, sub, sec);
      }
      return;
    }
    if (s.is_null()) return;  // not given
    if (r.is_array()) {
      if (!s.is_array())
        return malformed(s, path, group, stage, keys, typeName(s) + " where a list is expected",
                         typeNameDe(s) + ", wo eine Liste erwartet wird");
      const bool numbers = isNumberArray(r);
      // P1 alone (or P1 … Pk) of a per-vertex list: graded as far as given.
      const bool prefix = isPerVertexList(keys.back()) && s.size() <= r.size();
      if (prefix && numbers) {
        for (size_t i = 0; i < s.size(); ++i) {
          auto sub = keys;
          sub.push_back(std::to_string(i));
          walk(s[i], r[i], path + "/" + std::to_string(i), group, stage, sub, section);
        }
        return;
      }
      const std::string n = std::to_string(s.size()), m = std::to_string(r.size());
      if (keys.back().find("_from_") != std::string::npos && (s.size() != r.size() || !isMatrix(s)))
        return malformed(s, path, group, stage, keys, "not a 4 × 4 matrix (4 rows of 4 numbers)",
                         "keine 4 × 4-Matrix (4 Zeilen mit je 4 Zahlen)");
      if (numbers && s.size() != r.size())
        return malformed(s, path, group, stage, keys, n + " numbers where " + m + " are expected",
                         n + (s.size() == 1 ? " Zahl" : " Zahlen") + ", wo " + m + " erwartet werden");
      const bool objects = !r.empty() && r[0].is_object();
      if (objects && s.size() > r.size())
        return malformed(s, path, group, stage, keys, n + " entries, but the scene has only " + m,
                         n + " Einträge, die Szene hat aber nur " + m);
      if (!numbers && !objects && s.size() != r.size() && !prefix) {
        // A list of points or outcodes of another length: wrong, not malformed.
        GradedValue v;
        v.path = v.group = path;
        v.stage = stage;
        v.right = false;
        v.student = std::to_string(s.size());
        v.reference = std::to_string(r.size());
        v.count = true;
        values.push_back(std::move(v));
        referenceOf.push_back(nullptr);
        studentOf.push_back(&s);
        pathKeys.push_back(keys);
        return;
      }
      // The clipped polygon is a cycle: align it (any start, either direction).
      const Cycle cycle = keys.back() == "clipped_dc" || keys.back() == "polygon" ? alignment(s, r) : Cycle{};
      for (size_t i = 0; i < s.size(); ++i) {
        const size_t ri = cycle.map(i, r.size());
        auto sub = keys;
        sub.push_back(std::to_string(ri));
        const std::string p = path + "/" + std::to_string(i);
        walk(s[i], r[ri], p, objects ? p : group, stage, sub, section);
      }
      return;
    }
    leaf(s, r, path, group, stage, keys);
  }
};

const Json* at(const Json& dump, const std::vector<std::string>& keys) {
  const Json* j = &dump;
  for (const std::string& k : keys) {
    if (j->is_object()) {
      if (!j->contains(k)) return nullptr;
      j = &(*j)[k];
    } else if (j->is_array()) {
      const size_t i = std::stoul(k);
      if (i >= j->size()) return nullptr;
      j = &(*j)[i];
    } else {
      return nullptr;
    }
  }
  return j;
}

// The keys of a value in a model's dump: the same as in the reference, except that a clipped
// polygon's vertices are aligned with the model's polygon instead of the reference's.
// The two alignments of a student's polygon: with the reference's and with a model's.
using Alignments = std::map<std::string, std::pair<Cycle, Cycle>>;

std::vector<std::string> predictedKeys(const Json& answer, const Json& reference, const Json& model,
                                       std::vector<std::string> keys, Alignments& cache) {
  const auto it = std::find_if(keys.begin(), keys.end(),
                               [](const std::string& k) { return k == "clipped_dc" || k == "polygon"; });
  if (it == keys.end() || it + 1 == keys.end()) return keys;
  const std::vector<std::string> polygonKeys(keys.begin(), it + 1);
  const Json *ref = at(reference, polygonKeys), *mod = at(model, polygonKeys);
  // The answer's polygon: the same keys (objects and polygons are not shifted).
  const Json* stu = at(answer, polygonKeys);
  if (!ref || !mod || !stu || ref->empty() || mod->empty() || mod->size() != ref->size()) return keys;
  std::string id;
  for (const std::string& k : polygonKeys) id += "/" + k;
  auto found = cache.find(id);
  if (found == cache.end()) found = cache.emplace(id, std::pair{alignment(*stu, *ref), alignment(*stu, *mod)}).first;
  const auto& [withReference, withModel] = found->second;
  const size_t n = ref->size();
  const size_t ri = std::stoul(*(it + 1));
  *(it + 1) = std::to_string(withModel.map(withReference.unmap(ri, n), n));
  return keys;
}

}  // namespace

namespace {

// ---------------------------------------------------------------- row-vector form (issue 38)

// The answer's 4 × 4 matrices: the view's three and each object's wcFromMc, where given whole.
std::vector<Json::json_pointer> matricesOf(const Json& answer) {
  std::vector<Json::json_pointer> out;
  const auto whole = [&](const Json::json_pointer& p) {
    if (!answer.contains(p)) return;
    const Json& m = answer[p];
    if (!m.is_array() || m.size() != 4) return;
    for (const Json& row : m) {
      if (!row.is_array() || row.size() != 4) return;
      for (const Json& x : row)
        if (!numberOf(x)) return;
    }
    out.push_back(p);
  };
  if (answer.contains("matrices") && answer["matrices"].is_object())
    for (const auto& [key, value] : answer["matrices"].items()) whole(Json::json_pointer("/matrices/" + key));
  if (answer.contains("objects") && answer["objects"].is_array())
    for (size_t i = 0; i < answer["objects"].size(); ++i)
      whole(Json::json_pointer("/objects/" + std::to_string(i) + "/wc_from_mc"));
  return out;
}

Json transposed(const Json& m) {
  Json t = m;
  for (size_t r = 0; r < 4; ++r)
    for (size_t c = 0; c < 4; ++c) t[r][c] = m[c][r];
  return t;
}

// How the student's matrix at `p` is written: in the column form, the row form (transposed), both
// (a symmetric matrix) or neither (wrong either way).
struct Form {
  bool column = false, row = false;
};
Form formOf(const Json& answer, const Json& reference, const Json::json_pointer& p, const Walker& w) {
  Form f;
  if (!reference.contains(p)) return f;
  const Json& s = answer[p];
  const Json& r = reference[p];
  const auto agree = [&](const Json& expected) {
    for (size_t i = 0; i < 4; ++i)
      for (size_t j = 0; j < 4; ++j)
        if (!w.agrees(s[i][j], expected[i][j])) return false;
    return true;
  };
  f.column = agree(r);
  f.row = agree(transposed(r));
  return f;
}

// The matrices written in row form only (their transposes agree, they do not).
std::vector<Json::json_pointer> rowFormMatrices(const Json& answer, const Json& reference, const Walker& w,
                                                size_t* columnOnly = nullptr) {
  std::vector<Json::json_pointer> rows;
  size_t columns = 0;
  for (const Json::json_pointer& p : matricesOf(answer)) {
    const Form f = formOf(answer, reference, p, w);
    if (f.row && !f.column) rows.push_back(p);
    columns += f.column && !f.row;
  }
  if (columnOnly) *columnOnly = columns;
  return rows;
}

// The transposed model for this answer: the reference with the matrices the student wrote in row
// form transposed, the others as they are (one transposed matrix is the mistake, not all).
std::optional<Json> transposedModelFor(const Json& answer, const Json& reference, const Walker& w) {
  const std::vector<Json::json_pointer> rows = rowFormMatrices(answer, reference, w);
  if (rows.empty()) return std::nullopt;
  Json model = reference;
  for (const Json::json_pointer& p : rows) model[p] = transposed(reference[p]);
  return model;
}

// Whether the student's value agrees with `expected` (within the tolerance or the student's
// rounding); a polygon at its best cyclic alignment.
bool agreesWith(const Json& s, const Json& e, const Walker& w) {
  if (e.is_number()) return w.agrees(s, e);
  if (!e.is_array() || !s.is_array() || s.size() != e.size()) return false;
  const bool polygon = !e.empty() && e[0].is_array() && e[0].size() >= 3 && e[0][0].is_number();
  const Cycle c = polygon ? alignment(s, e) : Cycle{};
  for (size_t i = 0; i < s.size(); ++i)
    if (!agreesWith(s[i], e[c.map(i, e.size())], w)) return false;
  return true;
}

// Grades the assignment's items: each collects the values below its path. A wrong item whose
// values are what the student's own earlier values give earns its points (course/follow_through.h).
void gradeItems(NumbersGrade& g, const Assignment& assignment, const Json& answer, const GradingReference& r,
                const Walker& w) {
  for (const AssignmentItem& item : assignment.items) {
    ItemGrade i{item.path, item.title, item.points, 0, item.required, 0, 0, false, std::nullopt};
    for (const GradedValue& v : g.values)
      if (isWithin(v.path, item.path)) ++i.values, i.wrong += !v.right;
    if (i.right()) {
      i.earned = i.points;
    } else if (!i.missing()) {
      const Json::json_pointer at(item.path);
      if (const std::optional<Json> expected = followingValue(item.path, answer, r.reference, r.scene);
          expected && answer.contains(at) && agreesWith(answer[at], *expected, w)) {
        i.followsThrough = true;
        i.earned = i.points;
      }
    }
    g.points += i.earned;
    g.maxPoints += i.points;
    g.items.push_back(std::move(i));
  }
}

}  // namespace

GradingReference gradingReference(const Scene& scene) {
  GradingReference r{scene, referenceAnswer(scene), {}};
  for (const MistakeModel& model : mistakeModels()) {
    try {
      Json dump = mistakeDump(scene, model.id);
      addSheetValues(dump, model.id == Mistake::transposed, model.id == Mistake::divideFirst);
      r.models.emplace_back(model.id, std::move(dump));
    } catch (const Error&) {
      // the variant's camera is invalid: that model cannot be told for this scene
    }
  }
  return r;
}

NumbersGrade gradeNumbers(const Json& answer, std::string_view source, const Scene& scene, double tolerance,
                          const Assignment* assignment) {
  return gradeNumbers(answer, source, gradingReference(scene), tolerance, assignment);
}

namespace {

// Which values are consequences of the student's earlier ones (their items follow through), and
// where the student first departs on their own: recomputed whenever an item's credit changes.
void markConsequences(NumbersGrade& g) {
  g.firstStage.reset();
  g.consequent = 0;
  g.points = 0;
  for (GradedValue& v : g.values) {
    v.consequent = false;
    for (const ItemGrade& i : g.items)
      if (i.followsThrough && !v.right && isWithin(v.path, i.path)) v.consequent = true;
    g.consequent += v.consequent && !v.rounded;
    if (!v.right && !v.rounded && !v.consequent) g.firstStage = std::min(g.firstStage.value_or(99), v.stage);
  }
  for (const ItemGrade& i : g.items) g.points += i.earned;
}

// The mistake models that predict the student's numbers (up to the student's rounding), the values
// that follow from the student's earlier ones left aside.
void matchModels(NumbersGrade& g, const Json& answer, const GradingReference& references, const Walker& w) {
  const Json& reference = references.reference;
  g.models.clear();
  g.fitting.clear();
  g.mistake.reset();
  std::optional<Json> transposedModel = transposedModelFor(answer, reference, w);
  for (const auto& [mistake, fullDump] : references.models) {
    const Json* dumpOf = &fullDump;
    if (mistake == Mistake::transposed) {
      if (!transposedModel) continue;
      dumpOf = &*transposedModel;
    }
    const Json& dump = *dumpOf;
    ModelMatch match{mistake};
    bool differs = false;
    Alignments alignments;  // per polygon, computed once per model
    for (size_t i = 0; i < g.values.size(); ++i) {
      if (g.values[i].consequent || g.values[i].malformed()) continue;  // neither for nor against a model
      const Json* predicted = at(dump, predictedKeys(answer, reference, dump, w.pathKeys[i], alignments));
      const Json* ref = w.referenceOf[i];
      if (!ref) {
        // A list of another length than the reference's: does the model's list have the student's length?
        const Json* given = at(answer, w.pathKeys[i]);
        const bool agrees = predicted && given && predicted->is_array() && given->is_array() &&
                            predicted->size() == given->size();
        if (!agrees) ++match.contradicted;
        else ++match.explained;
        differs = true;
        continue;
      }
      if (!predicted) {
        ++match.contradicted;
        continue;
      }
      const bool agrees = w.agrees(*w.studentOf[i], *predicted);
      differs = differs || !w.same(*predicted, *ref);
      if (!agrees) ++match.contradicted;
      else if (!g.values[i].right && !g.values[i].rounded) ++match.explained;
    }
    if (!differs) continue;  // the model changes nothing the student gave: it cannot be told apart
    g.models.push_back(match);
    if (match.contradicted == 0 && match.explained > 0) g.fitting.push_back(mistake);
  }
  if (g.fitting.size() == 1) g.mistake = g.fitting[0];
  std::stable_sort(g.models.begin(), g.models.end(),
                   [](const ModelMatch& a, const ModelMatch& b) { return a.explained > b.explained; });
}

// Folgefehler ends where the mistake removed the item's subject: an item that lists a fitting
// mistake in its no_follow_through_after loses the credit it had from following through.
bool withdrawFollowThrough(NumbersGrade& g, const Assignment& assignment) {
  bool changed = false;
  for (size_t k = 0; k < g.items.size() && k < assignment.items.size(); ++k) {
    ItemGrade& i = g.items[k];
    if (!i.followsThrough) continue;
    for (const std::string& key : assignment.items[k].noFollowThroughAfter)
      for (Mistake m : g.fitting)
        if (mistakeModel(m).key == key) {
          i.followsThrough = false;
          i.withdrawnFor = m;
          i.earned = 0;
          changed = true;
        }
  }
  return changed;
}

}  // namespace

NumbersGrade gradeNumbers(const Json& givenAnswer, std::string_view source, const GradingReference& references,
                          double tolerance, const Assignment* assignment) {
  if (!(tolerance >= 0 && tolerance < 1)) throw Error("the tolerance must lie in [0, 1), not " + std::to_string(tolerance));
  const Json& reference = references.reference;
  Walker w(std::string(source), tolerance);
  NumbersGrade g;
  g.tolerance = tolerance;
  // Every matrix in the lecture notes' row-vector form: a notation, read transposed (issue 38).
  Json rowsRead;
  const Json* answerOf = &givenAnswer;
  size_t columnOnly = 0;
  if ((!assignment || assignment->rowVectorFormAccepted) &&
      !rowFormMatrices(givenAnswer, reference, w, &columnOnly).empty() && columnOnly == 0) {
    rowsRead = givenAnswer;
    for (const Json::json_pointer& p : matricesOf(givenAnswer)) rowsRead[p] = transposed(givenAnswer[p]);
    answerOf = &rowsRead;
    g.rowVectorForm = true;
  }
  const Json& answer = *answerOf;
  w.walk(answer, reference, "", "", 0, {}, "");
  if (w.values.empty() && !assignment)
    throw Error(std::string(source) + ": the answer gives no value to check (every field is empty or missing); "
                "an answer that checks nothing cannot pass: fill in the template (answer.json) or grade with "
                "--assignment, which names what is required");
  g.values = std::move(w.values);
  g.warnings = std::move(w.warnings);
  g.warningsDe = std::move(w.warningsDe);
  for (const GradedValue& v : g.values) {
    if (v.right) continue;
    ++g.wrong;
    if (v.rounded) {
      ++g.rounded;
      // The most digits printed: JSON drops trailing zeros (0.50 reads back as 0.5).
      g.roundedDecimals = std::max(g.roundedDecimals, v.decimals);
    } else {
      g.firstStage = std::min(g.firstStage.value_or(99), v.stage);
    }
  }
  if (assignment) {
    g.passMark = assignment->passMark;
    gradeItems(g, *assignment, answer, references, w);
    // Values that follow from the student's earlier ones are consequences, not mistakes of their own:
    // neither a stage's departure nor something for (or against) a mistake model.
    markConsequences(g);
  }
  if (g.wrong == g.rounded + g.consequent) return g;  // nothing for the mistake models to explain
  matchModels(g, answer, references, w);
  if (assignment && withdrawFollowThrough(g, *assignment)) {
    markConsequences(g);
    matchModels(g, answer, references, w);  // the withdrawn values are the mistake's own now
  }
  return g;
}

}  // namespace vplab
