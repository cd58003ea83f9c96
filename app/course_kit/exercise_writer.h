// `vplab exercise` (issue 14): an exercise sheet and its worked solution as Markdown (with LaTeX
// math, as course platforms and notebooks render it) and standalone LaTeX, with their figures.
//
// The solution follows the lecture notes' order and notation (15.2.1–15.2.5, 15.3; Hill 7.4):
// modeling, view orientation (N, U, V, VPD), view mapping, clipping in homogeneous coordinates
// (boundary coordinates, outcode, Sutherland–Hodgman plane by plane), the division by w and the
// device mapping. Every number is the pipeline's own (course/exercise.h), printed as an exact
// fraction where it is a small rational (course/rational.h), else rounded to 4 decimals.
#pragma once
#include "app/views/render_request.h"
#include "course/exercise.h"
#include "base/language.h"

#include <filesystem>
#include <string>

namespace vplab {

struct ExerciseDocuments {
  std::string sheetMd, solutionMd, sheetTex, solutionTex;
};

/// The four documents; the figures they use are world.svg/world.png (the sheet) and npc.svg/npc.png
/// (the solution) in the same folder.
ExerciseDocuments exerciseDocuments(const Exercise& exercise, const ExerciseSolution& solution, Language lang);

/// The figures' text, line and marker scale: labels readable at the figure's printed width.
inline constexpr float kExerciseFigureScale = 1.5f;

/// How a figure of the exercise is drawn: `view` (world: the sheet's; npc: the solution's) at
/// 800 × 600 in the hidden-line style, the light theme, the sheet's language, the vertices named.
RenderRequest exerciseFigureRequest(const Exercise& exercise, ViewKind view, Language lang);

/// Writes sheet.md, solution.md, sheet.tex, solution.tex, scene.json (the exercise's scene, for
/// `vplab dump` and `vplab grade`), exercise.json (which exercise it is, for `vplab --exercise DIR`) and the figures (SVG on the CPU, PNG rendered headless) into
/// `dir` (created). The same exercise gives the same bytes. Throws vplab::Error.
void writeExercise(const Exercise& exercise, Language lang, const std::filesystem::path& dir);

}  // namespace vplab
