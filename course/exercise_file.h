// What names one exercise (issue 40): its topic, seed, projection and the student whose variant it is,
// as `vplab exercise` takes them on its command line, a page link gives them
// (`#exercise=clipping&seed=7&id=100`) and an exercise's folder keeps them (exercise.json, written
// beside the sheet so that the viewer opens the very exercise the sheet shows):
//
//   {"vplab_exercise": 1, "topic": "clipping", "seed": 7, "projection": "perspective",
//    "student_id": "100", "language": "de"}
//
// student_id is empty for the class's sheet; language is the sheet's (the viewer shows the tasks in its
// own). The seed is a decimal string in a link and on the command line, a number below 10^18 here.
#pragma once

#include "base/language.h"
#include "course/exercise.h"
#include "course/roster.h"  // validStudentId: an id is printed on the sheet and names files

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace vplab {

/// The largest seed: 18 decimal digits (it round-trips through every JSON reader as an integer).
inline constexpr uint64_t kMaxExerciseSeed = 999999999999999999ull;

/// A seed as written: 1 to 18 decimal digits. Nullopt otherwise.
std::optional<uint64_t> exerciseSeedFrom(std::string_view text);

struct ExerciseRef {
  ExerciseSpec spec;
  std::string studentId;
  Language language = Language::en;  // the sheet's
  bool operator==(const ExerciseRef&) const = default;
};

/// exercise.json of an exercise, as an object and as the file's text.
nlohmann::ordered_json exerciseFileObject(const ExerciseRef& ref);
std::string exerciseFileJson(const ExerciseRef& ref);
/// Reads exercise.json as strictly as a scene. Throws vplab::Error "SOURCE: /json/path: …".
ExerciseRef parseExerciseFile(std::string_view text, std::string_view source);
/// The same of an object already parsed; `at` is its JSON path in the source ("" or "/exercise").
ExerciseRef parseExerciseObject(const nlohmann::ordered_json& j, std::string_view source, std::string_view at = "");

/// An answer that names its exercise: {"exercise": {exercise.json's members}, …the answer's values}.
/// The template `vplab exercise` writes and the file Hand in writes carry it, so that an answer.json
/// opens on its own (File ▸ Open exercise… in the page); the graders pass over it.
nlohmann::ordered_json answerNamingExercise(const nlohmann::ordered_json& answer, const ExerciseRef& ref);
/// The exercise an answer names (its "exercise" member, read as strictly as exercise.json), or
/// nullopt when it names none. Throws vplab::Error "SOURCE: /exercise/…: …" for a member that is wrong.
std::optional<ExerciseRef> exerciseOfAnswer(const nlohmann::ordered_json& answer, std::string_view source);

/// A name for one exercise's files and kept answers: "clipping-7-perspective" or
/// "clipping-7-perspective-100" (letters, digits, '.', '-' and '@' only).
std::string exerciseKey(const ExerciseRef& ref);

}  // namespace vplab
