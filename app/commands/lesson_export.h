// Lessons leave the room (docs/lecturers.md "Lessons"): `vplab render --lesson FILE --out DIR` writes every
// step as a picture with its caption (PNG or SVG) and a Markdown index, so that slides and the course page
// come from the same file; `--animate --out x.gif` writes the moves between the steps as an animation,
// and `render --view morph --animate` the stage morph.
//
// A step's picture is the view as the viewer shows the step: the step's styles, observers,
// overlays, strategy and marks (app/lessons/lesson_marks.h), the labels in the lesson's language, and
// the caption under it (app/views/caption_strip.h). The PNG and the SVG are one picture drawn by two
// backends.
#pragma once

#include "app/lessons/lesson.h"
#include "app/render/view_renderer.h"
#include "app/views/image.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vplab {

/// What each step's picture shows.
struct LessonPictureOptions {
  ViewKind view = ViewKind::all;
  int width = 0, height = 0;  // each view's pixels (all: each panel's); 0: the step's scene's device
  float scale = 1.f;          // text, lines and markers (a projector's 1.5 or 2)
  Theme theme = Theme::dark;
};

/// Called after each picture or frame: how many are done of how many (a progress bar). Returning
/// false gives up (the files already complete stay; an animation leaves no file).
using LessonProgress = std::function<bool(size_t done, size_t total)>;

/// The heading over a step's caption: "View orientation · step 3 / 9 · lecture notes 15.2.2".
std::string lessonHeading(const Lesson& lesson, size_t step);

/// Step `step`'s picture: `state` (the step's own, or a moment of the move into it) with the step's
/// heading and caption under it, drawn by `renderer`. Throws vplab::Error (a picture beyond the
/// image limits, a state the pipeline cannot run).
Image lessonImage(ViewRenderer& renderer, const Lesson& lesson, size_t step, const LessonState& state,
                  const LessonPictureOptions& options);
/// The same picture as an SVG document (no GL).
std::string lessonSvg(const Lesson& lesson, size_t step, const LessonPictureOptions& options);

/// Writes DIR/step-01.png … (or .svg with `svg`; `renderer` may then be null) and DIR/index.md: the
/// lesson's title, then each step's number, source, picture and caption. Creates DIR. Returns the
/// files written. Throws vplab::Error naming the file that could not be written.
std::vector<std::filesystem::path> writeLessonStills(ViewRenderer* renderer, const Lesson& lesson,
                                                     const LessonPictureOptions& options, bool svg,
                                                     const std::filesystem::path& dir, const LessonProgress& progress);

/// How an animation plays.
struct AnimationOptions {
  int fps = 15;               // of the moves
  double moveSeconds = 0.8;   // each move between two steps, as the viewer's
  double holdSeconds = 3;     // each step's still
};

/// The frames an animation of the lesson has: each step's still, and between two steps of the same
/// scene the moves' frames (a move into another scene is a cut, as in the viewer).
size_t lessonAnimationFrames(const Lesson& lesson, const AnimationOptions& options);

/// Writes the lesson as an animated GIF: the first frame is step 1's still, the last the last
/// step's. Throws vplab::Error; a failed or given-up animation leaves no file.
void writeLessonAnimation(ViewRenderer& renderer, const Lesson& lesson, const LessonPictureOptions& options,
                          const AnimationOptions& animation, const std::filesystem::path& file,
                          const LessonProgress& progress);

/// Writes the stage morph of `scene` (pipeline/stage_morph.h) as an animated GIF: t from 0 (MC) to 4
/// (DC), a second a stage at `fps`, each stage held `holdSeconds`, with `display`'s morph observer and style.
void writeMorphAnimation(ViewRenderer& renderer, const Scene& scene, const DisplaySettings& display, int width,
                         int height, const AnimationOptions& animation, const std::filesystem::path& file,
                         const LessonProgress& progress);

}  // namespace vplab
