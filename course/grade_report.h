// The reports of `vplab grade` (issues 14, 21): a human report for stdout, JSON (--json) and JUnit
// XML (--junit FILE, what course autograders read), built from one GradeReport, in English or in
// the lecture's German (--lang de). A malformed or unreadable answer gets a report too (errorReport):
// the student always learns what was wrong with the file.
#pragma once
#include "base/enum_table.h"
#include "course/grading.h"
#include "base/language.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

/// One checked item: an assignment's item, a vector or matrix of the dump, or the image.
struct GradeCase {
  std::string name;
  bool passed = true;
  std::string message;               // one line
  std::vector<std::string> details;  // the wrong values, the worst pixels, … (the first ones of `total`)
  size_t total = 0;                  // how many wrong things the details are the first of
  double points = 0, maxPoints = 0;  // with an assignment
};

struct GradeReport {
  std::string kind;     // "numbers" or "image"
  std::string student;  // the student's file
  std::string id;       // the student's id (the file's name without its extension): JUnit's classname
  std::string scene;    // the scene file, or "(built-in default scene)"
  Language lang = Language::en;
  bool passed = true;
  std::string error;    // a malformed or unreadable answer: why (then no cases)
  double seconds = 0;   // how long grading took (JUnit's time)
  std::vector<std::string> header;     // what was compared and with which tolerance
  std::vector<GradeCase> cases;
  std::vector<std::string> diagnosis;  // the first departing stage, the mistake found, rounding
  bool graded = false;                 // with an assignment: points below count
  double points = 0, maxPoints = 0;
  std::optional<double> passMark;      // the assignment's, when it has one: it decides passed
  nlohmann::ordered_json json;         // the machine report
};

/// What a report shows of the reference (issue 38; a course with resubmission hides the values):
/// values: the reference values beside the student's wrong ones; stages: which values are wrong, the
/// first departing stage and the mistake named, no reference value; none: only which values are
/// wrong and the points.
enum class Reveal { values, stages, none };
inline constexpr EnumTable<Reveal, 3> kRevealNames = {
    {{Reveal::values, "values"}, {Reveal::stages, "stages"}, {Reveal::none, "none"}}};
constexpr const auto& namesOf(Reveal) { return kRevealNames; }

GradeReport numbersReport(const NumbersGrade& grade, const std::string& student, const std::string& scene,
                          Language lang = Language::en, Reveal reveal = Reveal::values);
/// The report of an answer that could not be graded (malformed, unreadable): `error` names the problem.
GradeReport errorReport(const std::string& kind, const std::string& student, const std::string& scene,
                        const std::string& error, Language lang = Language::en);

/// The report's number and name texts, for the image report (app/course_kit/image_report.h):
/// `v` with `places` decimals; `s` in the language's quotation marks.
std::string fixed(double v, int places);
std::string quoted(std::string_view s, Language lang);

/// The student's id from the answer file's name: "alice.json" → "alice".
std::string studentIdOf(const std::string& file);

std::string reportText(const GradeReport& report);
std::string reportJunit(const GradeReport& report);

}  // namespace vplab
