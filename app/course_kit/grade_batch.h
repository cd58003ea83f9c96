// `vplab grade batch` (issue 21): a class's answers graded in parallel against one assignment. Every
// file of the answers folder is one student (its name without the extension is the student's id);
// each gets its reports (text, JSON, JUnit) in OUT/reports/, and the class a gradebook (grades.csv:
// the points per item) and results.json (per student the fields autograder platforms read:
// score, max_score, execution_time, output, tests). A broken or hostile file is that student's error
// row, never the end of the batch.
#pragma once

#include "course/grade_report.h"
#include "course/assignment.h"
#include "base/language.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vplab {

struct BatchOptions {
  std::filesystem::path assignment, answers, out;
  int jobs = 1;
  Language lang = Language::en;
  Reveal reveal = Reveal::values;  // what each report shows of the reference
};

struct BatchRow {
  std::string id, file;
  bool passed = false;
  std::string error;               // could not be graded: why
  double points = 0;
  std::vector<double> itemPoints;  // per item of the assignment
  double seconds = 0;
};

struct BatchResult {
  Assignment assignment;
  std::vector<BatchRow> rows;  // in the order of the files' names
  double seconds = 0;
};

/// The most answer files one batch grades (checked before any is read).
inline constexpr size_t kMaxBatchAnswers = 20000;

/// Grades every answer; `progress(done, total)` is called after each (from the workers, serialised).
/// Throws vplab::Error for what stops the whole batch: an unreadable assignment or scene, an
/// answers folder that is not one, an output folder that cannot be written.
BatchResult gradeBatch(const BatchOptions& options, const std::function<void(size_t, size_t)>& progress = {});

/// The gradebook: one row per student, its points per item (CSV, RFC 4180 quoting).
std::string gradesCsv(const BatchResult& result);

}  // namespace vplab
