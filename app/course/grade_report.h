// The reports of `vplab grade` (issue 14): a human report for stdout, JSON (--json) and JUnit XML
// (--junit FILE, what course autograders read), built from one GradeReport.
#pragma once
#include "app/course/grade_image.h"
#include "course/grading.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace vplab {

/// One checked item: a vector or matrix of the dump (numbers), or the image and its models.
struct GradeCase {
  std::string name;
  bool passed = true;
  std::string message;               // one line
  std::vector<std::string> details;  // the wrong values, the worst pixels, …
};

struct GradeReport {
  std::string kind;     // "numbers" or "image"
  std::string student;  // the student's file
  std::string scene;    // the scene file, or "(built-in default scene)"
  bool passed = true;
  std::vector<std::string> header;     // what was compared and with which tolerance
  std::vector<GradeCase> cases;
  std::vector<std::string> diagnosis;  // the first departing stage, the mistake found
  nlohmann::ordered_json json;         // the machine report
};

GradeReport numbersReport(const NumbersGrade& grade, const std::string& student, const std::string& scene);
GradeReport imageReport(const ImageGrade& grade, const std::string& student, const std::string& scene,
                        const std::string& differenceFile);

std::string reportText(const GradeReport& report);
std::string reportJunit(const GradeReport& report);

}  // namespace vplab
