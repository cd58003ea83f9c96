// What an exercise sheet asks for, as an assignment (course/assignment.h), and the answer template a
// student fills in (issue 21): every item of the sheet's tasks, in their order, with its points, at
// its place in the answer format (the `vplab dump` format with the sheet's values,
// course/sheet_values.h), its numbers null.
#pragma once

#include "course/assignment.h"
#include "course/exercise.h"
#include "base/language.h"

#include <nlohmann/json.hpp>

namespace vplab {

/// Whether a sheet of `topic` has the tasks of `part`: each topic its own; the pipeline topic
/// orientation and mapping (P1 through every stage, its clipping test and DC), not the polygon's
/// clipping, which is a sheet of its own (a weekly sheet's size).
bool exerciseShows(ExerciseTopic topic, ExerciseTopic part);

/// One numbered task of a sheet: its text (LaTeX math in $…$) and the items it asks for.
struct ExerciseTask {
  std::string text;
  std::vector<AssignmentItem> items;
};
/// A task's points: the sum of its items'.
double points(const ExerciseTask& task);

/// The sheet's tasks, in order: for orientation wcFromMc and P1 in WC; N, U, V, VPD, vrcFromWc and
/// P1 in VRC; for mapping npcFromVrc and P1 in homogeneous NPC; P1's boundary coordinates and outcode
/// and where P1 is inside its NPC and DC; for clipping the six Sutherland–Hodgman passes; dcFromNpc
/// and the clipped polygon in DC. Matrices and the clipped polygon are worth 2 points, everything
/// else 1.
std::vector<ExerciseTask> exerciseTasks(const Exercise& exercise, const ExerciseSolution& solution, Language lang);

/// The sheet's items as an assignment (course/assignment.h): every task's, in order. The scene is
/// "scene.json" (written beside it).
Assignment exerciseAssignment(const Exercise& exercise, const ExerciseSolution& solution, Language lang);

/// The template of an answer to `assignment`: each item's place in `referenceAnswer` with its
/// structure kept and its values null; a polygon (a clipper's pass, the clipped polygon) is null as a
/// whole, its vertex count being part of the answer. A pass is its polygon: the sheet names the
/// planes in order.
nlohmann::ordered_json answerTemplate(const Assignment& assignment, const nlohmann::ordered_json& referenceAnswer);

/// The answer key: the template with every item's values from `referenceAnswer` (solution.json).
nlohmann::ordered_json answerKey(const Assignment& assignment, const nlohmann::ordered_json& referenceAnswer);

}  // namespace vplab
