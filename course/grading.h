// `vplab grade numbers` (issue 14): a student's numbers, in the dump format (io/dump.h) or any
// subset of it, against the reference pipeline's dump of the same scene, value by value; the first
// stage where the student departs; and which mistake model (mistake_models.h) the numbers match.
//
// Tolerance: a number is right when |student − reference| ≤ tolerance · max(1, |reference|)
// (default 1e-3: students print 4 to 6 digits; a DC coordinate of 400 may be 0.4 px off). Integers
// (outcodes, the device, statistics), names, fates and the projection compare exactly. A clipped
// polygon (clipped_dc) is a cycle: it may start at any of its vertices and run in either direction
// (clippers differ in both); it is compared at the shift and direction that match it best. A value
// outside the tolerance but within half a unit of the student's last printed digit is "rounded":
// still wrong, but blamed on the rounding, not on a stage. A per-vertex list (mc, wc, vrc, npc_h,
// outcodes) may give its first vertices only (P1 alone). `null` marks a value not given (the answer
// template's empty fields).
#pragma once
#include "base/language.h"
#include "course/mistake_models.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

/// The stages of docs/conventions.md, for "where the student departs": 0 the scene's MC, 1 modeling,
/// 2 view orientation, 3 view mapping, 4 clipping, 5 device mapping (in the lecture's terms in German).
std::string_view stageName(int stage, Language lang = Language::en);

struct GradedValue {
  std::string path;       // JSON pointer into the student's file, "/matrices/vrc_from_wc/1/3"
  std::string group;      // the vector or matrix it belongs to, "/matrices/vrc_from_wc"
  int stage = 0;
  bool right = true;
  bool rounded = false;  // wrong, but within half a unit of the student's last digit (rounding)
  bool consequent = false;  // wrong, but what the student's own earlier values give (ItemGrade::followsThrough)
  int decimals = -1;     // the digits the student printed after the point (-1: not a plain decimal)
  std::string student, reference;  // as JSON text
  std::string problem, problemDe;  // a value in a form that cannot be graded: why (wrong, 0 points for its item)
  bool count = false;  // a list of another length: student and reference are the two lengths
  bool malformed() const { return !problem.empty(); }
};

struct ModelMatch {
  Mistake mistake;
  size_t explained = 0;  // wrong values the model predicts (within the tolerance)
  size_t contradicted = 0;  // values (right or wrong) where the student and the model differ
};

/// What an assignment asks for (course/assignment.h), graded: its values right, wrong or missing.
struct ItemGrade {
  std::string path, title;
  double points = 0, earned = 0;
  bool required = true;
  size_t values = 0, wrong = 0;  // of the item's values the student gave
  bool followsThrough = false;   // wrong, but what the student's own earlier values give: its points earned
  std::optional<Mistake> withdrawnFor;  // it followed through, but after a mistake that removed its subject
                                        // (AssignmentItem::noFollowThroughAfter): no points
  bool missing() const { return values == 0; }
  bool right() const { return values > 0 && wrong == 0; }
};

struct NumbersGrade {
  double tolerance = 1e-3;
  std::vector<GradedValue> values;
  size_t wrong = 0;                      // every value not right, the rounded ones included
  size_t rounded = 0;                    // of those, the ones off by the student's rounding only
  int roundedDecimals = -1;              // the most decimals among the rounded values (what the student printed)
  size_t consequent = 0;                 // of those, the ones that follow from the student's earlier values
  std::optional<int> firstStage;         // the smallest stage with a wrong value not explained by rounding or
                                         // by the student's earlier values
  std::vector<ModelMatch> models;        // every model that differs from the reference on the values given
  std::optional<Mistake> mistake;        // the model matching every value, when exactly one does
  std::vector<Mistake> fitting;          // every model matching every value (several: they cannot be told apart)
  std::vector<ItemGrade> items;          // with an assignment: its items in its order
  std::optional<double> passMark;        // the assignment's: passed with at least these points
  bool rowVectorForm = false;            // every matrix given in the lecture notes' row-vector form: read transposed
  std::vector<std::string> warnings, warningsDe;  // keys the answer format does not have: not graded
  double points = 0, maxPoints = 0;
  bool passed() const {
    if (passMark) return points >= *passMark - 1e-9;
    if (wrong != 0) return false;
    for (const ItemGrade& i : items)
      if (i.required && !i.right()) return false;
    return true;
  }
};

struct Assignment;

/// A number as an answer may write it: a JSON number, or a fraction or decimal as a string ("-3/5").
std::optional<double> answerNumber(const nlohmann::ordered_json& j);

/// Parses a student's answer file's text. Throws vplab::Error "SOURCE: line L, column C: …".
nlohmann::ordered_json parseAnswer(std::string_view text, std::string_view source);

/// Grades the answer against the scene's reference run. A value in a form that cannot be graded (a
/// wrong type, a vector of the wrong length, a matrix that is not 4 × 4, more objects than the scene
/// has) is that value's error: wrong, named (GradedValue::problem), its item earns nothing, the rest
/// is graded (issue 38). Decimal commas ("0,6"), fractions ("-3/5") and an outcode's bits ("100010")
/// are read as what they say; unknown keys are warned about. An answer that is not a JSON object, or
/// that gives no value at all without an assignment (it would pass having checked nothing), throws
/// vplab::Error "SOURCE: /json/path: …". With an assignment, each of its items is graded (a required
/// item not given fails, named) and earns its points when all its values are right.
NumbersGrade gradeNumbers(const nlohmann::ordered_json& answer, std::string_view source, const Scene& scene,
                          double tolerance = 1e-3, const Assignment* assignment = nullptr);

/// What every answer to one scene is graded against: the reference answer and each mistake model's
/// (course/sheet_values.h), computed once for a whole class (vplab grade batch).
struct GradingReference {
  Scene scene;
  nlohmann::ordered_json reference;
  std::vector<std::pair<Mistake, nlohmann::ordered_json>> models;  // the models whose camera is valid
};
GradingReference gradingReference(const Scene& scene);
NumbersGrade gradeNumbers(const nlohmann::ordered_json& answer, std::string_view source, const GradingReference& reference,
                          double tolerance = 1e-3, const Assignment* assignment = nullptr);

}  // namespace vplab
