// `vplab grade batch --exercises DIR --answers A --out O` (issue 38, parts 3 and 4): a class's
// answers, each graded against that student's own variant (DIR/staff/ID of `vplab exercise --roster`).
//
// Submissions in A, matched to the roster (DIR/roster.csv):
//   A/ID.json                                      (ID a roster id)
//   A/Full Name_N_assignsubmission_file_/*.json    Moodle's "Download all submissions", unpacked:
//                                                  N the participant number (the roster's id when the
//                                                  roster was Moodle's worksheet); answer.json, or the
//                                                  folder's only .json file
//   A.zip                                          the same download as it comes (a zip of those folders;
//                                                  stored or deflated entries, each at most 64 MiB by its
//                                                  header, CRC-checked; nothing is extracted to disk)
// Links, hidden files and anything else are listed as not matched (never followed); a roster
// student without a submission gets 0 points and "no submission". An answer whose values are those
// of another student's variant (more of them right there than in its own) is graded against its own
// variant, and the report says whose variant it was.
//
// Written into O: reports/ID.{txt,json,xml}, grades.csv (one row per roster student),
// unmatched.txt, moodle-grading-worksheet.csv (course/roster.h moodleWorksheet: Grade and Feedback
// comments filled in) and moodle-feedback-files.zip ("Full Name_N_assignsubmission_file_/report.md"
// per student, the layout of "Download all submissions", which "Upload multiple feedback files in a
// zip" reads back).
#pragma once

#include "course/grade_report.h"
#include "course/roster.h"
#include "base/language.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vplab {

struct ClassOptions {
  std::filesystem::path exercises, answers, out;
  Language lang = Language::en;
  Reveal reveal = Reveal::values;  // what each report shows of the reference
};

struct ClassRow {
  RosterStudent student;
  std::string file;           // the submission, relative to the answers folder; empty: none
  bool passed = false;
  double points = 0, maxPoints = 0;
  std::string status;         // "graded", "no submission", "could not be graded"
  std::string error;          // why it could not be graded
  std::string otherVariant;   // the id whose variant the answer's values match, if not the student's own
  std::string feedback;       // one line for the worksheet
};

struct ClassResult {
  Roster roster;
  std::vector<ClassRow> rows;          // in the roster's order
  std::vector<std::string> unmatched;  // entries of the answers folder not matched to a student, with why
};

/// Grades the class. Throws vplab::Error for what stops the whole batch (no roster in the exercises
/// folder, an answers folder that is not one, an output folder that cannot be written).
ClassResult gradeClass(const ClassOptions& options);

}  // namespace vplab
