// `vplab grade numbers` (issue 14): a student's numbers, in the dump format (io/dump.h) or any
// subset of it, against the reference pipeline's dump of the same scene, value by value; the first
// stage where the student departs; and which mistake model (mistake_models.h) the numbers match.
//
// Tolerance: a number is right when |student − reference| ≤ tolerance · max(1, |reference|)
// (default 1e-3: students print 4 to 6 digits; a DC coordinate of 400 may be 0.4 px off). Integers
// (outcodes, the device, statistics), names, fates and the projection compare exactly. A clipped
// polygon (clipped_dc) may start at any of its vertices (clippers differ in where they start): it is
// compared at the cyclic shift that matches its first vertex best.
#pragma once
#include "course/mistake_models.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

/// The stages of docs/conventions.md, for "where the student departs": 0 the scene's MC, 1 modeling,
/// 2 view orientation, 3 view mapping, 4 clipping, 5 device mapping.
std::string_view stageName(int stage);

struct GradedValue {
  std::string path;       // JSON pointer into the student's file, "/matrices/vrc_from_wc/1/3"
  std::string group;      // the vector or matrix it belongs to, "/matrices/vrc_from_wc"
  int stage = 0;
  bool right = true;
  std::string student, reference;  // as JSON text
};

struct ModelMatch {
  Mistake mistake;
  size_t explained = 0;  // wrong values the model predicts (within the tolerance)
  size_t contradicted = 0;  // values (right or wrong) where the student and the model differ
};

struct NumbersGrade {
  double tolerance = 1e-3;
  std::vector<GradedValue> values;
  size_t wrong = 0;
  std::optional<int> firstStage;         // the smallest stage with a wrong value
  std::vector<ModelMatch> models;        // every model that differs from the reference on the values given
  std::optional<Mistake> mistake;        // the model matching every value, when exactly one does
  bool passed() const { return wrong == 0; }
};

/// Parses a student's answer file's text. Throws vplab::Error "SOURCE: line L, column C: …".
nlohmann::ordered_json parseAnswer(std::string_view text, std::string_view source);

/// Grades the answer against the scene's reference run. Malformed answers (unknown keys, wrong
/// types, more objects or polygons than the scene has, vectors of the wrong length) throw
/// vplab::Error "SOURCE: /json/path: what is wrong, what was expected".
NumbersGrade gradeNumbers(const nlohmann::ordered_json& answer, std::string_view source, const Scene& scene,
                          double tolerance = 1e-3);

}  // namespace vplab
