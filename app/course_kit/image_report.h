// The report of `vplab grade image` (issue 14), in the form of every grade's report
// (course/grade_report.h): the thresholds, the wrong pixels, the shift and the image mistake model found.
#pragma once
#include "app/course_kit/grade_image.h"
#include "course/grade_report.h"

#include <string>

namespace vplab {

GradeReport imageReport(const ImageGrade& grade, const std::string& student, const std::string& scene,
                        const std::string& differenceFile, Language lang = Language::en);

}  // namespace vplab
