// Exercise sheets for the grading tests (issue 38): a sheet of `vplab exercise`, its assignment,
// the grader's reference and the answer key, and how a grade reads in a failure message.
#pragma once

#include "course/exercise.h"
#include "course/exercise_answer.h"
#include "course/grading.h"
#include "course/mistake_models.h"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

namespace vplab::test {

struct Sheet {
  Exercise exercise;
  Assignment assignment;
  GradingReference reference;
  nlohmann::ordered_json key;  // the answer key: the template with every value
};

inline Sheet sheetOf(uint64_t seed, ExerciseTopic topic) {
  Exercise e = generateExercise({seed, topic, Projection::perspective});
  const ExerciseSolution s = solveExercise(e);
  Assignment a = exerciseAssignment(e, s, Language::en);
  GradingReference r = gradingReference(e.scene);
  nlohmann::ordered_json key = answerKey(a, r.reference);
  return {std::move(e), std::move(a), std::move(r), std::move(key)};
}

inline const std::string kPolygon = "/objects/0/polygons/0";

inline const ItemGrade& itemAt(const NumbersGrade& g, const std::string& path) {
  for (const ItemGrade& i : g.items)
    if (i.path == path) return i;
  throw std::runtime_error("no item " + path);
}

inline bool hasItem(const NumbersGrade& g, const std::string& path) {
  for (const ItemGrade& i : g.items)
    if (i.path == path) return true;
  return false;
}

inline std::string describe(const NumbersGrade& g) {
  std::string out = "points " + std::to_string(g.points) + " of " + std::to_string(g.maxPoints) + "; mistake ";
  out += g.mistake ? std::string(mistakeModel(*g.mistake).key) : "none";
  for (const ItemGrade& i : g.items)
    out += "\n  " + i.title + ": " + std::to_string(i.earned) + "/" + std::to_string(i.points) +
           (i.right() ? " right" : i.followsThrough ? " follows through" : i.withdrawnFor ? " withdrawn" : " wrong");
  return out;
}

}  // namespace vplab::test
