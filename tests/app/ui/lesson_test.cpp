// Presenting a lesson in the viewer (app/ui/lesson_presenter.h): the keys, the move into a step
// (valid cameras on the way, the step's state exactly at its end), free exploration and undo that
// do not break the lesson, and the caption box.
#include "app/ui/lesson_presenter.h"

#include "app/document/assets.h"
#include "app/ui/headless_viewer.h"
#include "app/ui/keys.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>

namespace vplab {
namespace {

std::filesystem::path lessonFile(const char* name) { return std::filesystem::path(VPLAB_ASSETS) / "lessons" / name; }

/// A viewer presenting the view-orientation lesson at its first step, settled.
struct Presenting {
  HeadlessViewer v{*test::egl().context, defaultScene(), 1280, 720};
  Presenting() {
    v.frames(2);
    v.viewer().session().openLesson(lessonFile("02-view-orientation.en.json"));
    v.frames(3);
  }
  ViewerState& s() { return v.state(); }
  const LessonState& step(size_t i) { return s().lesson->lesson().steps[i].state; }
  /// Frames until the move into the step is over (0.8 s at 1/60 s a frame, and one to settle).
  void settle() { v.frames(int(s().lessonSeconds * 60) + 3); }
};

TEST(LessonPresenter, OpensAtTheFirstStepWithItsStateAndCaption) {
  Presenting p;
  ASSERT_TRUE(p.s().lesson);
  EXPECT_EQ(p.s().lesson->step(), 0u);
  EXPECT_EQ(p.s().doc.scene().camera, p.step(0).scene.camera);
  EXPECT_EQ(p.s().display.world.orbit, p.step(0).display.world.orbit);
  EXPECT_FALSE(p.s().doc.dirty()) << "a lesson's step is what its file says: nothing is unsaved";
  EXPECT_TRUE(p.v.rects().rects.count("lesson.caption"));
  EXPECT_TRUE(p.v.rects().rects.count("lesson.next"));
}

TEST(LessonPresenter, TheNextStepIsReachedThroughValidCamerasAndThenExactly) {
  Presenting p;
  // Step 5 to 6 of this lesson moves PRP round the cube: a move, not a jump.
  p.s().lesson->go(5, LessonState{}, 0, 0);  // at once
  p.v.frames(3);
  const Camera from = p.step(5).scene.camera, to = p.step(6).scene.camera;
  ASSERT_NE(from, to);
  EXPECT_EQ(p.s().doc.scene().camera, from);
  p.v.key(keys::kRight);
  bool between = false;
  for (int i = 0; i < 40; ++i) {
    p.v.frame();
    const Camera& c = p.s().doc.scene().camera;
    EXPECT_FALSE(cameraError(c)) << "frame " << i;
    between = between || (c != from && c != to);
  }
  EXPECT_TRUE(between) << "the camera moved through cameras between the steps'";
  p.settle();
  EXPECT_EQ(p.s().lesson->step(), 6u);
  EXPECT_EQ(p.s().doc.scene().camera, to);
  EXPECT_FALSE(p.s().doc.dirty());
  EXPECT_TRUE(p.s().doc.canUndo()) << "entering a step is one undo step";
}

TEST(LessonPresenter, FreeExplorationAndUndoDoNotBreakTheLesson) {
  Presenting p;
  p.v.key(keys::kSpace);
  p.settle();
  ASSERT_EQ(p.s().lesson->step(), 1u);
  // The class drags PRP and changes a style; undo takes back the step entered.
  p.s().doc.scene().camera.prp += Vec3(1, 2, 0);
  p.s().display.world.style = Style::wire;
  p.v.frames(2);
  EXPECT_TRUE(p.s().doc.dirty());
  p.v.key(keys::kPageDown);
  p.settle();
  EXPECT_EQ(p.s().lesson->step(), 2u);
  EXPECT_EQ(p.s().doc.scene().camera, p.step(2).scene.camera);
  EXPECT_EQ(p.s().display.world.style, p.step(2).display.world.style);
  p.v.key(keys::kZ, /*ctrl=*/true);
  p.v.frames(2);
  EXPECT_NE(p.s().doc.scene().camera, p.step(2).scene.camera) << "undo went back to the exploration";
  p.v.key(keys::kLeft);
  p.settle();
  EXPECT_EQ(p.s().lesson->step(), 1u);
  EXPECT_EQ(p.s().doc.scene().camera, p.step(1).scene.camera) << "going back restores the step as written";
}

TEST(LessonPresenter, HomeEndAndANumberJumpEscClosesTheStylesKeysWaitForIt) {
  Presenting p;
  const size_t last = p.s().lesson->stepCount() - 1;
  p.v.key(keys::kEnd);
  p.settle();
  EXPECT_EQ(p.s().lesson->step(), last);
  p.v.key(keys::kRight);  // past the last: stays
  p.settle();
  EXPECT_EQ(p.s().lesson->step(), last);
  p.v.key(keys::kHome);
  p.settle();
  EXPECT_EQ(p.s().lesson->step(), 0u);
  // "4" then Enter: step 4 (index 3); the digit does not choose a style.
  const Style style = p.s().display.camera.style;
  p.v.type("4");
  p.v.key(keys::kDigit1 + 3);
  EXPECT_EQ(p.s().display.camera.style, style);
  EXPECT_EQ(p.s().lessonTyped, "4");
  p.v.key(keys::kEnter);
  p.settle();
  EXPECT_EQ(p.s().lesson->step(), 3u);
  p.v.key(keys::kEscape);
  p.v.frames(2);
  EXPECT_FALSE(p.s().lesson);
  p.v.key(keys::kDigit1 + 2);
  EXPECT_EQ(p.s().display.camera.style, Style::wire) << "without a lesson the digits choose styles again";
}

TEST(LessonPresenter, TheStepsMarksShowOnceItIsReached) {
  Presenting p;
  // Step 3 of the view-orientation lesson probes a vertex and shows the matrices.
  p.s().lesson->go(3, LessonState{}, 0, 0);
  p.v.frames(3);
  const LessonState& step = p.step(3);
  EXPECT_EQ(p.s().probe, step.probe);
  EXPECT_EQ(p.s().lessonMarks, step.highlights);
  for (const LessonHighlight& h : step.highlights)
    if (h.kind == LessonHighlight::Kind::handle) {
      bool hot = false;
      for (const Highlights::HandleMark& m : p.s().highlights.handles) hot = hot || (m.name == handleName(h.handle) && m.hot);
      EXPECT_TRUE(hot) << handleName(h.handle);
    }
}

// File ▸ Lessons while another lesson is open: the new lesson's first step shows its own tab and
// highlights (issue 37 item 6: the menu's lesson was settled in the frame it opened, before its step
// was ever shown, and the tab and highlights were skipped).
TEST(LessonPresenter, ALessonOpenedFromTheMenuOverAnotherShowsItsFirstStepsMarks) {
  Presenting p;
  p.v.key(keys::kEnd);
  p.settle();
  auto click = [&](const char* id) {
    const auto [x, y] = p.v.centreOf(id);
    p.v.click(x, y);
    p.v.frames(2);
  };
  click("menu.file");
  const auto [lx, ly] = p.v.centreOf("menu.lessons");
  p.v.mouseMove(lx, ly);
  p.v.frames(3);
  click("menu.lesson.05-clipping.en");
  p.v.frames(3);
  ASSERT_TRUE(p.s().lesson);
  EXPECT_EQ(p.s().lesson->lesson().file.filename(), "05-clipping.en.json");
  EXPECT_EQ(p.s().lesson->step(), 0u);
  EXPECT_EQ(p.s().controlsTab, int(ViewerState::clippingTab)) << "step 1's tab";
  ASSERT_EQ(p.s().lessonMarks.size(), 1u) << "step 1's highlight";
  EXPECT_EQ(p.s().lessonMarks[0].kind, LessonHighlight::Kind::plane);
}

TEST(LessonPresenter, ABrokenLessonChangesNothingAndSaysWhy) {
  HeadlessViewer v{*test::egl().context, defaultScene(), 1280, 720};
  v.frames(2);
  const Scene before = v.state().doc.scene();
  v.viewer().session().openLesson(std::filesystem::path(VPLAB_TEST_DATA) / "no-such-lesson.json");
  v.frames(2);
  EXPECT_FALSE(v.state().lesson);
  EXPECT_EQ(v.state().doc.scene(), before);
  EXPECT_TRUE(v.state().statusIsError);
  EXPECT_NE(v.state().status.find("no-such-lesson.json"), std::string::npos) << v.state().status;
}

}  // namespace
}  // namespace vplab
