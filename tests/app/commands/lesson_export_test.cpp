// A lesson's pictures and animation (app/commands/lesson_export.h): every step's still with its
// caption, the index, the SVG beside the PNG, and the GIF whose first and last frames are the stills.
#include "app/commands/lesson_export.h"

#include "app/document/assets.h"
#include "app/export/gif.h"
#include "app/export/image_compare.h"
#include "tests/support/files.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>

namespace vplab {
namespace {

Lesson bundled(const char* name) {
  LessonContext context;
  context.scenesDirectory = std::filesystem::path(VPLAB_ASSETS) / "scenes";
  return loadLesson(std::filesystem::path(VPLAB_ASSETS) / "lessons" / name, context);
}

/// Small pictures: the tests draw many.
LessonPictureOptions small(ViewKind view = ViewKind::all) {
  LessonPictureOptions o;
  o.view = view;
  o.width = 240;
  o.height = 180;
  return o;
}

TEST(LessonExport, EveryStepIsAStillWithItsCaptionAndTheIndexNamesThemAll) {
  const Lesson lesson = bundled("02-view-orientation.en.json");
  ViewRenderer renderer(*test::egl().context);
  test::TempDir dir;
  size_t calls = 0;
  const auto files = writeLessonStills(&renderer, lesson, small(), false, dir.path / "out",
                                       [&](size_t done, size_t total) {
                                         ++calls;
                                         EXPECT_EQ(total, lesson.steps.size() + 1);
                                         EXPECT_LE(done, total);
                                         return true;
                                       });
  ASSERT_EQ(files.size(), lesson.steps.size() + 1);
  EXPECT_EQ(calls, lesson.steps.size() + 1);
  const std::string index = test::readFile(dir.path / "out" / "index.md");
  EXPECT_EQ(index.rfind("# " + lesson.title, 0), 0u) << index.substr(0, 80);
  for (size_t i = 0; i < lesson.steps.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "step-%02zu.png", i + 1);
    EXPECT_NE(index.find(std::string("](") + name + ")"), std::string::npos) << name;
    const Image still = readPng(dir.path / "out" / name);
    // The three 240 × 180 panels side by side, the title strip over them, the caption under them.
    EXPECT_EQ(still.width, 3 * 240 + 2 * 6);
    EXPECT_GT(still.height, 180 + 60);
  }
  // A still is the step's state drawn: two steps with other cameras draw other pictures, the same
  // step twice the same bytes.
  const Image a = lessonImage(renderer, lesson, 5, lesson.steps[5].state, small());
  const Image b = lessonImage(renderer, lesson, 6, lesson.steps[6].state, small());
  EXPECT_EQ(a.pixels, lessonImage(renderer, lesson, 5, lesson.steps[5].state, small()).pixels);
  EXPECT_NE(a.pixels, b.pixels);
}

TEST(LessonExport, TheCaptionIsDrawnUnderThePicture) {
  // The still is the picture of the views with a strip under it; the strip carries text (pixels of
  // the text colour on the strip's ground), and a longer caption makes a taller strip.
  Lesson lesson = bundled("01-synthetic-camera.en.json");
  ViewRenderer renderer(*test::egl().context);
  const LessonPictureOptions o = small(ViewKind::camera);
  lesson.steps.resize(2);
  lesson.steps[0].caption = lesson.steps[1].caption = "Short.";
  const Image shortCaption = lessonImage(renderer, lesson, 0, lesson.steps[0].state, o);
  lesson.steps[1].caption = std::string(60, 'x') + " " + std::string(60, 'y') + " " + std::string(60, 'z');
  const Image longCaption = lessonImage(renderer, lesson, 1, lesson.steps[1].state, o);
  EXPECT_GT(longCaption.height, shortCaption.height) << "three words wider than the picture take three lines";
  EXPECT_EQ(lessonImage(renderer, lesson, 0, lesson.steps[0].state, o).height, longCaption.height)
      << "every picture of a lesson is as tall as its longest caption needs";
  // Under the view (rows 180 on) some pixels are bright text on the dark strip.
  int bright = 0;
  for (int y = 180; y < shortCaption.height; ++y)
    for (int x = 0; x < shortCaption.width; ++x) bright += shortCaption.at(x, y).r > 180;
  EXPECT_GT(bright, 20);
}

TEST(LessonExport, TheSvgStillsAreTheSamePictures) {
  const Lesson lesson = bundled("07-clip-planes.de.json");
  test::TempDir dir;
  const auto files = writeLessonStills(nullptr, lesson, small(), true, dir.path, {});
  ASSERT_EQ(files.size(), lesson.steps.size() + 1);
  const std::string svg = test::readFile(files[0]);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  // The caption's words are text of the document (the German lesson's own).
  const std::string firstWord = lesson.steps[0].caption.substr(0, lesson.steps[0].caption.find(' '));
  EXPECT_NE(svg.find(firstWord), std::string::npos) << firstWord;
}

TEST(LessonExport, TheAnimationStartsAndEndsWithTheStillsAndHasAFrameForEachMoment) {
  const Lesson lesson = bundled("02-view-orientation.en.json");
  ViewRenderer renderer(*test::egl().context);
  test::TempDir dir;
  AnimationOptions a;
  a.fps = 5;  // 3 frames between two steps of 0.8 s
  a.holdSeconds = 1.5;
  const LessonPictureOptions o = small(ViewKind::camera);
  size_t last = 0;
  writeLessonAnimation(renderer, lesson, o, a, dir.path / "lesson.gif", [&](size_t done, size_t) {
    last = done;
    return true;
  });
  const GifFrames gif = readGif(dir.path / "lesson.gif");
  // Readable by others, as any file vplab writes (giflib's own open would make it the owner's only).
  const auto perms = std::filesystem::status(dir.path / "lesson.gif").permissions();
  EXPECT_NE(perms & std::filesystem::perms::others_read, std::filesystem::perms::none);
  const size_t expected = lessonAnimationFrames(lesson, a);
  EXPECT_EQ(expected, lesson.steps.size() + (lesson.steps.size() - 1) * 3) << "one scene: every move has its frames";
  ASSERT_EQ(gif.frames.size(), expected);
  EXPECT_EQ(last, expected);
  EXPECT_EQ(gif.centiseconds.front(), 150);
  EXPECT_EQ(gif.centiseconds[1], 20);
  // First and last frames are the stills, up to the GIF's 256 colours a frame: giflib's median cut
  // works on colours of 5 bits a channel, so no channel may be off by more than 7 (8 allowed), and
  // most are off by a few levels.
  for (const auto& [frame, step] : {std::pair{gif.frames.front(), size_t(0)}, std::pair{gif.frames.back(), lesson.steps.size() - 1}}) {
    const Image still = lessonImage(renderer, lesson, step, lesson.steps[step].state, o);
    const ImageComparison d = compareImages(frame, still, 8);
    EXPECT_TRUE(d.passed()) << "step " << step << "\n" << describe(d);
    EXPECT_LT(d.meanChannelDelta, 4.0) << describe(d);
  }
  // No file is left when the animation is given up.
  EXPECT_NO_THROW(writeLessonAnimation(renderer, lesson, o, a, dir.path / "given-up.gif", [](size_t done, size_t) { return done < 3; }));
  EXPECT_FALSE(std::filesystem::exists(dir.path / "given-up.gif"));
  EXPECT_FALSE(std::filesystem::exists(dir.path / "given-up.gif.part"));
}

TEST(LessonExport, TheStageMorphAsAnAnimation) {
  ViewRenderer renderer(*test::egl().context);
  test::TempDir dir;
  AnimationOptions a;
  a.fps = 3;
  DisplaySettings d;
  writeMorphAnimation(renderer, defaultScene(), d, 160, 120, a, dir.path / "morph.gif", {});
  const GifFrames gif = readGif(dir.path / "morph.gif");
  ASSERT_EQ(gif.frames.size(), 13u);  // t = 0, 1/3, … 4
  EXPECT_EQ(gif.centiseconds[0], 300);
  EXPECT_EQ(gif.centiseconds[1], 33);
  EXPECT_NE(gif.frames.front().pixels, gif.frames.back().pixels) << "MC and DC are other pictures";
}

}  // namespace
}  // namespace vplab
