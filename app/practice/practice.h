// An exercise being practised (issue 40): the sheet of `vplab exercise` beside the views, its tasks
// with the student's fields, Check through the very grader of `vplab grade numbers` (course/), and the
// answer file handed in. Without ImGui or GL: the Tasks panel (app/ui/panel_tasks.cpp) draws it, the
// viewer and the page keep it, tests/app/practice/ drive it as a student would.
//
// What the student sees of the reference follows the exercise's `reveal` (course/grade_report.h):
// values (the reference values beside the wrong ones, the lab's own P1 drawn beside theirs), stages
// (which values are wrong, the first departing stage and the mistake named; the default) or none
// (which values are wrong and the points).
#pragma once

#include "app/practice/answer_fields.h"
#include "course/exercise.h"
#include "course/exercise_answer.h"
#include "course/exercise_file.h"
#include "course/grade_report.h"
#include "course/grading.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vplab {

struct Practice {
  ExerciseRef ref;
  Reveal reveal = Reveal::stages;
  Language language = Language::en;  // of the tasks' texts and the items' titles (the UI's)
  Exercise exercise;                  // its scene is the document the views show
  ExerciseSolution solution;
  Assignment assignment;              // what Check grades, as `vplab exercise` writes it
  std::vector<ExerciseTask> tasks;    // the sheet's tasks; task i holds the next tasks[i].items.size() fields
  GradingReference grading;           // the reference and the mistake models' answers, computed once
  nlohmann::ordered_json answerTemplate;
  std::vector<ItemFields> fields;     // one per assignment item, in the sheet's order
  std::filesystem::path folder;       // the exercise's folder it was opened from; empty: from a link
  bool answerOpened = false;          // its fields hold an answer.json the student opened (not the kept one)
  uint64_t edits = 0;                 // counts the changes of the fields (what was checked, kept, handed in)

  /// The index of the first field of task `task`.
  size_t firstField(size_t task) const;
};

/// The exercise `ref` names, its tasks in `lang`, its fields empty. Throws vplab::Error when no
/// exercise can be made of it (generateExercise's error).
Practice openPractice(const ExerciseRef& ref, Reveal reveal, Language lang);

/// The exercise of a folder written by `vplab exercise` (its exercise.json), with the values of the
/// folder's answer.json in its fields (the template's nulls leave them empty). Throws vplab::Error
/// naming the file: a folder without exercise.json, an unreadable or hostile file.
Practice openPracticeFolder(const std::filesystem::path& dir, Reveal reveal, Language lang);

/// File ▸ Open exercise…: an exercise's exercise.json (openPracticeFolder of its folder), or an
/// answer.json that names its exercise (the template `vplab exercise` writes, a handed-in answer), its
/// values in the fields. Throws vplab::Error naming the file for any other file.
Practice openPracticeFile(const std::filesystem::path& file, Reveal reveal, Language lang);

/// The tasks' texts and the items' titles in `lang`; the fields keep what was typed.
void setPracticeLanguage(Practice& p, Language lang);

/// The sheet's given data, one line each, in plain text with exact fractions ("VRP = (-1, -1/2, 1/2)").
std::vector<std::string> givenLines(const Practice& p, Language lang);

/// A task's text for the panel: the sheet's LaTeX math in plain text ("$\mathit{wcFromMc}$" → "wcFromMc").
std::string plainMath(std::string_view latex);

/// The answer file of the fields (answer.json: what Hand in writes, `vplab grade numbers` reads).
nlohmann::ordered_json practiceAnswer(const Practice& p);

// ---------------------------------------------------------------- Check

/// What Check found for one field.
enum class FieldVerdict { unchecked, right, wrong, rounded, follows, unreadable };

struct PracticeCheck {
  uint64_t edits = 0;   // the fields' state it graded (Practice::edits)
  NumbersGrade grade;   // the grader's, whole (the marks in the views need no reference values)
  GradeReport report;   // `vplab grade numbers --reveal R --lang L` of the same answer: what the panel shows
  double seconds = 0;   // how long grading took
};

/// Grades the fields' answer against the exercise with its assignment, as `vplab grade numbers
/// --assignment assignment.json --reveal R` does, in `lang`.
PracticeCheck checkPractice(const Practice& p, Language lang);

/// The verdict of field (`row`, `column`) of `fields`: the worst of the graded values at or above its place.
FieldVerdict fieldVerdict(const PracticeCheck& check, const ItemFields& fields, int row, int column);

}  // namespace vplab
