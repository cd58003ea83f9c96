// `vplab exercise --roster ROSTER.csv` and `--moodle BANK.xml` (issue 38, parts 3 and 4): a class's
// variants and their Moodle question bank.
//
//   DIR/roster.csv           the roster as given (vplab grade batch --exercises DIR reads it back)
//   DIR/students/ID/         what student ID may see: sheet.md, sheet.tex, sheet.pdf (where pdflatex
//                            is installed), answer.json (the template), scene.json, world.svg, world.png
//   DIR/staff/ID/            everything `vplab exercise --student-id ID` writes: the solution,
//                            solution.json (the key), assignment.json, the NPC figure
//
// Student ID's variant is generateExercise(seed, topic, projection; ID): a function of the
// exercise's number and the id alone (course/exercise.h), the same on every machine.
#pragma once

#include "course/exercise.h"
#include "course/moodle_bank.h"
#include "course/roster.h"
#include "base/language.h"

#include <filesystem>
#include <vector>

namespace vplab {

/// The files of an exercise folder a student may see (the rest stays with the staff).
const std::vector<std::string>& studentFiles();

/// The cloze question of an exercise written by writeExercise into `dir` (its figure world.png is
/// read from there). Throws vplab::Error.
MoodleQuestion moodleQuestion(const Exercise& exercise, Language lang, const std::filesystem::path& dir);

/// Writes every roster student's variant into `out` (layout above); returns the questions for a
/// bank when `withQuestions`. Throws vplab::Error naming the student and the file.
std::vector<MoodleQuestion> writeClassExercises(const ExerciseSpec& spec, const Roster& roster, std::string_view rosterText,
                                                Language lang, const std::filesystem::path& out, bool withQuestions);

/// The bank's category: "vplab/Exercise N (topic, projection)".
std::string moodleCategory(const ExerciseSpec& spec);

}  // namespace vplab
