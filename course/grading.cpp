#include "course/grading.h"

#include "io/json_read.h"
#include "io/limits.h"

#include "pipeline/error.h"

#include <algorithm>
#include <cmath>

namespace vplab {

using Json = nlohmann::ordered_json;

std::string_view stageName(int stage) {
  switch (stage) {
    case 0: return "the scene (MC)";
    case 1: return "stage 1, modeling (MC → WC)";
    case 2: return "stage 2, view orientation (WC → VRC)";
    case 3: return "stage 3, view mapping (VRC → homogeneous NPC)";
    case 4: return "stage 4, clipping";
    default: return "stage 5, device mapping (NPC → DC)";
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
  if (key == "outcodes" || key == "fate") return 4;
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

// The cyclic shift k that puts the reference's vertex k under the student's first vertex, for
// clipped polygons that start elsewhere: the shift that puts all the student's vertices nearest the
// reference's when both have as many (the first vertex alone cannot tell twins apart: a polygon
// that passes through a corner of the cube twice has two vertices a few ulps apart, and a rounded
// answer's first vertex may be nearer the wrong one), else the one nearest the first vertex.
size_t alignment(const Json& student, const Json& reference) {
  if (student.empty() || reference.empty() || !student[0].is_array()) return 0;
  const size_t n = reference.size(), compared = student.size() == n ? n : 1;
  size_t shift = 0;
  double best = INFINITY;
  for (size_t k = 0; k < n; ++k) {
    double d = 0;
    for (size_t i = 0; i < compared; ++i) {
      const Json &s = student[i], &r = reference[(i + k) % n];
      if (!s.is_array() || !r.is_array()) continue;
      for (size_t c = 0; c < std::min(s.size(), r.size()); ++c)
        if (s[c].is_number() && r[c].is_number()) d += std::abs(s[c].get<double>() - r[c].get<double>());
    }
    if (d < best) best = d, shift = k;
  }
  return shift;
}

struct Walker {
  std::string source;
  double tolerance;
  std::vector<GradedValue> values;
  std::vector<const Json*> referenceOf;  // per value: the reference leaf (for the models)
  std::vector<const Json*> studentOf;    // per value: the student's leaf
  std::vector<std::vector<std::string>> pathKeys;  // per value: the path into the dump

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw Error(source + ": " + (path.empty() ? "/" : path) + ": " + what);
  }

  bool same(const Json& s, const Json& r) const {
    if (r.is_number_integer() || r.is_number_unsigned()) return s.is_number_integer() && s == r;
    if (r.is_number()) {
      const double a = s.get<double>(), b = r.get<double>();
      return std::isfinite(a) && std::abs(a - b) <= tolerance * std::max(1.0, std::abs(b));
    }
    return s == r;
  }

  void leaf(const Json& s, const Json& r, const std::string& path, const std::string& group, int stage,
            std::vector<std::string> keys) {
    if (r.is_number()) {
      if (!s.is_number()) fail(path, typeName(s) + " where a number is expected (reference " + r.dump() + ")");
      if ((r.is_number_integer() || r.is_number_unsigned()) && !s.is_number_integer())
        fail(path, s.dump() + " where an integer is expected");
    } else if (r.is_string() && !s.is_string()) {
      fail(path, typeName(s) + " where a string is expected (for example " + r.dump() + ")");
    } else if (r.is_boolean() && !s.is_boolean()) {
      fail(path, typeName(s) + " where true or false is expected");
    }
    values.push_back({path, group, stage, same(s, r), s.dump(), r.dump()});
    referenceOf.push_back(&r);
    studentOf.push_back(&s);
    pathKeys.push_back(std::move(keys));
  }

  static bool isNumberArray(const Json& j) {
    return j.is_array() && !j.empty() && std::all_of(j.begin(), j.end(), [](const Json& e) { return e.is_number(); });
  }

  void walk(const Json& s, const Json& r, const std::string& path, const std::string& group, int stage,
            std::vector<std::string> keys, const std::string& section) {
    if (r.is_object()) {
      if (!s.is_object()) fail(path, typeName(s) + " where an object is expected");
      for (const auto& [key, value] : s.items()) {
        if (!r.contains(key)) {
          std::string known;
          for (const auto& [k, v] : r.items()) known += (known.empty() ? "" : ", ") + k;
          fail(path + "/" + key, "unknown key (the dump has here: " + known + ")");
        }
        auto sub = keys;
        sub.push_back(key);
        const std::string sec = section.empty() ? key : section;
        walk(value, r[key], path + "/" + key, path + "/" + key, section.empty() ? stageOfKey(key, "") : stageOfKey(sec, key),
             sub, sec);
      }
      return;
    }
    if (r.is_array()) {
      if (!s.is_array()) fail(path, typeName(s) + " where an array is expected");
      const bool numbers = isNumberArray(r);
      if (numbers && s.size() != r.size())
        fail(path, std::to_string(s.size()) + " numbers where " + std::to_string(r.size()) + " are expected");
      if (keys.back().find("_from_") != std::string::npos && s.size() != r.size())
        fail(path, std::to_string(s.size()) + " rows where a 4 × 4 matrix (4 rows of 4 numbers) is expected");
      const bool objects = !r.empty() && r[0].is_object();
      if (objects && s.size() > r.size())
        fail(path, std::to_string(s.size()) + " entries, but the scene has only " + std::to_string(r.size()));
      if (!numbers && !objects && s.size() != r.size()) {
        // A list of points or outcodes of another length: wrong, not malformed.
        values.push_back({path, path, stage, false, std::to_string(s.size()) + " entries",
                          std::to_string(r.size()) + " entries"});
        referenceOf.push_back(nullptr);
        studentOf.push_back(&s);
        pathKeys.push_back(keys);
        return;
      }
      // The clipped polygon may start anywhere: align the student's first vertex.
      const size_t shift = keys.back() == "clipped_dc" ? alignment(s, r) : 0;
      for (size_t i = 0; i < s.size(); ++i) {
        const size_t ri = (i + shift) % r.size();
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
std::vector<std::string> predictedKeys(const Json& answer, const Json& reference, const Json& model,
                                       std::vector<std::string> keys) {
  const auto it = std::find(keys.begin(), keys.end(), "clipped_dc");
  if (it == keys.end() || it + 1 == keys.end()) return keys;
  const std::vector<std::string> polygonKeys(keys.begin(), it + 1);
  const Json *ref = at(reference, polygonKeys), *mod = at(model, polygonKeys);
  // The answer's polygon: the same keys (objects and polygons are not shifted).
  const Json* stu = at(answer, polygonKeys);
  if (!ref || !mod || !stu || ref->empty() || mod->empty() || mod->size() != ref->size()) return keys;
  const size_t n = ref->size();
  const size_t ri = std::stoul(*(it + 1));
  const size_t studentIndex = (ri + n - alignment(*stu, *ref)) % n;
  *(it + 1) = std::to_string((studentIndex + alignment(*stu, *mod)) % n);
  return keys;
}

}  // namespace

NumbersGrade gradeNumbers(const Json& answer, std::string_view source, const Scene& scene, double tolerance) {
  if (!(tolerance >= 0 && tolerance < 1)) throw Error("the tolerance must lie in [0, 1), not " + std::to_string(tolerance));
  const Json reference = referenceDump(scene);
  Walker w{std::string(source), tolerance, {}, {}, {}, {}};
  w.walk(answer, reference, "", "", 0, {}, "");
  NumbersGrade g;
  g.tolerance = tolerance;
  g.values = std::move(w.values);
  for (const GradedValue& v : g.values)
    if (!v.right) {
      ++g.wrong;
      g.firstStage = std::min(g.firstStage.value_or(99), v.stage);
    }
  if (g.wrong == 0) return g;
  // The mistake models: which of them predict the student's numbers?
  std::vector<Mistake> full;
  for (const MistakeModel& model : mistakeModels()) {
    Json dump;
    try {
      dump = mistakeDump(scene, model.id);
    } catch (const Error&) {
      continue;
    }
    ModelMatch match{model.id};
    bool differs = false;
    for (size_t i = 0; i < g.values.size(); ++i) {
      const Json* predicted = at(dump, predictedKeys(answer, reference, dump, w.pathKeys[i]));
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
      const bool agrees = w.same(*w.studentOf[i], *predicted);
      differs = differs || !w.same(*predicted, *ref);
      if (!agrees) ++match.contradicted;
      else if (!g.values[i].right) ++match.explained;
    }
    if (!differs) continue;  // the model changes nothing the student gave: it cannot be told apart
    g.models.push_back(match);
    if (match.contradicted == 0) full.push_back(model.id);
  }
  if (full.size() == 1) g.mistake = full[0];
  std::stable_sort(g.models.begin(), g.models.end(),
                   [](const ModelMatch& a, const ModelMatch& b) { return a.explained > b.explained; });
  return g;
}

}  // namespace vplab
