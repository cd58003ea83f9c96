// Index: 1 a step's picture  2 the stills and the index  3 animations
#include "app/commands/lesson_export.h"

#include "app/document/atomic_file.h"
#include "app/lessons/lesson_marks.h"
#include "app/lessons/lesson_transition.h"
#include "app/export/gif.h"
#include "app/export/svg.h"
#include "app/fonts/font_atlas.h"
#include "app/text/catalogue.h"
#include "app/views/caption_strip.h"
#include "app/views/caption_text.h"
#include "app/views/render_request.h"
#include "io/dump.h"
#include "io/limits.h"
#include "base/error.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace vplab {

// ---------------------------------------------------------------- 1 a step's picture

namespace {

/// "lecture notes 15.2.2" in the lesson's language, or another text's short name as written.
std::string sourceText(const Lesson& lesson, const std::string& section) {
  if (section.empty()) return "";
  const bool lectureNotes = std::isdigit(static_cast<unsigned char>(section[0]));
  return lectureNotes ? text::fill(lesson.language, "lecture notes {1}", {section}) : section;
}

/// Builds the picture of `state` with step `step`'s caption under it and hands it to `draw` (the
/// picture points into the run, which lives only during the call).
void withPicture(const Lesson& lesson, size_t step, const LessonState& state, const LessonPictureOptions& o,
                 const TextMetrics& text, const std::function<void(const draw::Picture&)>& draw) {
  RenderRequest request;
  request.view = o.view;
  request.width = o.width;
  request.height = o.height;
  request.pipeline = {state.strategy, state.boundingBoxTest, true};
  const PixelSize size = pixelSizeOf(request, state.scene);
  const PipelineRun run = runPipeline(state.scene, pipelineOptionsOf(request));
  if (auto e = nonFiniteError(run)) throw Error(lesson.file.string() + ", step " + std::to_string(step + 1) + ": " + *e);
  DisplaySettings display = state.display;
  display.theme = o.theme;
  display.language = lesson.language;  // the views' labels speak the lesson's language
  const Highlights marks = lessonMarks(run, state);
  draw::Picture picture = buildPicture(o.view, ViewInput{state.scene, run, display, marks, size.width, size.height, text});
  // Every picture of a lesson is as tall as its longest caption needs: slides of one size, and the
  // frames of an animation.
  int lines = 1;
  for (const LessonStep& s : lesson.steps) lines = std::max(lines, captionLineCount(s.caption, picture.width, text));
  appendCaption(picture, lessonHeading(lesson, step), lesson.steps[step].caption, text, o.theme, lines);
  if (picture.width > kMaxImageSide || picture.height > kMaxImageSide ||
      int64_t(picture.width) * picture.height > kMaxImagePixels)
    throw Error("a step's picture of " + std::to_string(picture.width) + " × " + std::to_string(picture.height) +
                " pixels exceeds the image limits (" + std::to_string(kMaxImageSide) + " a side, " +
                std::to_string(kMaxImagePixels) + " pixels): choose a smaller --size");
  draw(picture);
}

}  // namespace

std::string lessonHeading(const Lesson& lesson, size_t step) {
  std::string heading = lesson.title + "  ·  " +
                        text::fill(lesson.language, "step {1} / {2}",
                                   {std::to_string(step + 1), std::to_string(lesson.steps.size())});
  const std::string source = sourceText(lesson, lesson.steps[step].section);
  return source.empty() ? heading : heading + "  ·  " + source;
}

Image lessonImage(ViewRenderer& renderer, const Lesson& lesson, size_t step, const LessonState& state,
                  const LessonPictureOptions& options) {
  if (renderer.scale() != options.scale) renderer.setScale(options.scale);
  Image image;
  withPicture(lesson, step, state, options, renderer.textMetrics(), [&](const draw::Picture& p) { image = renderer.render(p); });
  return image;
}

std::string lessonSvg(const Lesson& lesson, size_t step, const LessonPictureOptions& options) {
  const FontAtlas fonts(options.scale);
  std::string svg;
  withPicture(lesson, step, lesson.steps[step].state, options, fonts, [&](const draw::Picture& p) {
    svg = svgOfPicture(p, fonts, lesson.title + " — " + std::to_string(step + 1));
  });
  return svg;
}

// ---------------------------------------------------------------- 2 the stills and the index

std::vector<std::filesystem::path> writeLessonStills(ViewRenderer* renderer, const Lesson& lesson,
                                                     const LessonPictureOptions& options, bool svg,
                                                     const std::filesystem::path& dir, const LessonProgress& progress) {
  if (!svg && !renderer) throw std::invalid_argument("writeLessonStills: a PNG needs a renderer");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error(dir.string() + ": cannot make the directory: " + ec.message());
  const size_t n = lesson.steps.size();
  std::vector<std::filesystem::path> written;
  std::string index = "# " + lesson.title + "\n\n";
  index += text::fill(lesson.language, "A lesson of vplab in {1} steps; present it with `vplab --lesson {2}`.",
                      {std::to_string(n), lesson.file.filename().string()}) +
           "\n";
  for (size_t i = 0; i < n; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "step-%02zu.%s", i + 1, svg ? "svg" : "png");
    const std::filesystem::path file = dir / name;
    if (svg) writeFileAtomically(file, lessonSvg(lesson, i, options));
    else writePng(lessonImage(*renderer, lesson, i, lesson.steps[i].state, options), file);
    written.push_back(file);
    const LessonStep& step = lesson.steps[i];
    const std::string source = sourceText(lesson, step.section);
    index += "\n## " + std::to_string(i + 1) + (source.empty() ? "" : ". " + source) + "\n\n";
    index += "![" + text::fill(lesson.language, "Step {1}", {std::to_string(i + 1)}) + "](" + name + ")\n\n";
    index += captionMarkdown(step.caption) + "\n";
    if (step.free) {
      const text::Text explore = "*Explore freely: the next step restores its own state.*";
      index += std::string("\n") + explore.in(lesson.language) + "\n";
    }
    if (progress && !progress(i + 1, n + 1)) return written;
  }
  const std::filesystem::path indexFile = dir / "index.md";
  writeFileAtomically(indexFile, index);
  written.push_back(indexFile);
  if (progress) progress(n + 1, n + 1);
  return written;
}

// ---------------------------------------------------------------- 3 animations

namespace {

/// Frames of one move: the moments strictly between two stills.
int moveFrames(const AnimationOptions& a) { return std::max(0, int(std::lround(a.moveSeconds * a.fps)) - 1); }
int centiseconds(double seconds) { return std::max(2, int(std::lround(seconds * 100))); }

}  // namespace

size_t lessonAnimationFrames(const Lesson& lesson, const AnimationOptions& options) {
  size_t frames = lesson.steps.size();
  for (size_t i = 0; i + 1 < lesson.steps.size(); ++i)
    if (sameSceneObjects(lesson.steps[i].state.scene, lesson.steps[i + 1].state.scene)) frames += size_t(moveFrames(options));
  return frames;
}

void writeLessonAnimation(ViewRenderer& renderer, const Lesson& lesson, const LessonPictureOptions& options,
                          const AnimationOptions& animation, const std::filesystem::path& file,
                          const LessonProgress& progress) {
  if (animation.fps < 1 || animation.fps > 60) throw Error("an animation plays at 1 to 60 frames a second, not " + std::to_string(animation.fps));
  const size_t total = lessonAnimationFrames(lesson, animation);
  std::optional<GifWriter> gif;
  size_t done = 0;
  auto add = [&](const Image& frame, double seconds) {
    if (!gif) gif.emplace(file, frame.width, frame.height);
    gif->add(frame, centiseconds(seconds));
    return !progress || progress(++done, total);
  };
  const int k = moveFrames(animation);
  for (size_t i = 0; i < lesson.steps.size(); ++i) {
    if (i > 0 && sameSceneObjects(lesson.steps[i - 1].state.scene, lesson.steps[i].state.scene))
      for (int j = 1; j <= k; ++j) {
        const double t = easeInOut(double(j) / (k + 1));
        const LessonState between = stateBetween(lesson.steps[i - 1].state, lesson.steps[i].state, t);
        if (!add(lessonImage(renderer, lesson, i, between, options), 1.0 / animation.fps)) return;
      }
    if (!add(lessonImage(renderer, lesson, i, lesson.steps[i].state, options), animation.holdSeconds)) return;
  }
  gif->finish();
}

void writeMorphAnimation(ViewRenderer& renderer, const Scene& scene, const DisplaySettings& display, int width,
                         int height, const AnimationOptions& animation, const std::filesystem::path& file,
                         const LessonProgress& progress) {
  if (animation.fps < 1 || animation.fps > 60) throw Error("an animation plays at 1 to 60 frames a second, not " + std::to_string(animation.fps));
  const PipelineRun run = runPipeline(scene, {});
  if (auto e = nonFiniteError(run)) throw Error(*e);
  const int perStage = animation.fps;  // a second a stage
  const size_t total = size_t(4 * perStage + 1);
  GifWriter gif(file, width, height);
  DisplaySettings d = display;
  for (int k = 0; k <= 4 * perStage; ++k) {
    d.morphing.t = double(k) / perStage;
    const bool stage = k % perStage == 0;  // MC, WC, VRC, NPC, DC: held
    gif.add(renderer.render(ViewKind::morph, scene, run, d, {}, width, height), stage ? centiseconds(animation.holdSeconds)
                                                                                          : centiseconds(1.0 / animation.fps));
    if (progress && !progress(size_t(k + 1), total)) return;
  }
  gif.finish();
}

}  // namespace vplab
