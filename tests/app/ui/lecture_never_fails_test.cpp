// The lecture never fails (issue 37 item 1): no input ends the window. The lecturer's reproduction
// (lesson 02's free step, PRP typed onto VUP's line, ←) moves the lesson; an error that arises in a
// frame is caught, the last good state shown and the reason said; a modal dialog takes the keys;
// recovery restores exactly what was on screen, the lesson and its step and the typed camera
// included. The real window under a random user: tests/app/window/monkey_test.cpp.
#include "app/document/autosave.h"
#include "app/ui/headless_viewer.h"
#include "app/ui/keys.h"
#include "tests/support/files.h"
#include "tests/support/gl_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace vplab {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path lessonFile(const char* name) { return fs::path(VPLAB_ASSETS) / "lessons" / name; }

/// A viewer presenting lesson 02 in German at `step` (from 0), settled.
struct Presenting {
  HeadlessViewer v{*test::egl().context, defaultScene(), 1280, 720, 1.6f};
  explicit Presenting(size_t step) {
    v.state().display.language = Language::de;
    v.frames(2);
    v.viewer().session().openLesson(lessonFile("02-view-orientation.de.json"), step);
    v.frames(3);
  }
  ViewerState& s() { return v.state(); }
  const LessonState& step(size_t i) { return s().lesson->lesson().steps[i].state; }
  void settle() { v.frames(int(s().lessonSeconds * 60) + 3); }
};

/// Offers the recovery file `file` in `v` (another session's) and clicks Recover, as a user would;
/// false when the file is no recovery file.
bool recoverIn(HeadlessViewer& v, const fs::path& file) {
  const std::optional<Recovery> r = Autosave::read(file);
  if (!r) return false;
  v.frames(2);
  v.viewer().session().recovery().offerRecoveries({*r});
  v.frames(3);
  const auto [x, y] = v.centreOf("recovery.recover");
  v.click(x, y);
  v.frames(3);
  return true;
}

void expectFinite(const Camera& c) {
  for (const Vec3& v : {c.vrp, c.prp, c.vup})
    EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
}

// The reproduction: step 9 (a free step) asks for PRP = (0, 8, 0), which puts N on VUP's
// line; ← then moved from that invalid camera into step 8 and the window ended. Now the move is a
// cut into step 8, with nothing caught.
TEST(LectureNeverFails, AnInvalidCameraInAFreeStepThenBackIsACutIntoTheStep) {
  Presenting p(8);
  ASSERT_EQ(p.s().lesson->step(), 8u);
  ASSERT_TRUE(p.s().lesson->current().free) << "lesson 02's step 9 is the free step the issue names";
  p.s().doc.scene().camera.prp = {0, 8, 0};
  p.s().doc.scene().camera.vrp = {0, 0, 0};
  p.v.frames(2);
  ASSERT_THAT(p.s().doc.error(), HasSubstr("VUP")) << "PRP (0, 8, 0) makes N parallel to VUP";
  p.v.key(keys::kLeft);
  p.settle();
  EXPECT_EQ(p.v.viewer().caught().count, 0u) << p.v.viewer().caught().last;
  EXPECT_EQ(p.s().lesson->step(), 7u);
  EXPECT_EQ(p.s().doc.scene().camera, p.step(7).scene.camera);
  EXPECT_TRUE(p.s().doc.error().empty()) << p.s().doc.error();
  expectFinite(p.s().run().camera);
  // And forward again, into the free step, then on past it: every move still works.
  p.v.key(keys::kRight);
  p.settle();
  p.v.key(keys::kRight);
  p.settle();
  EXPECT_EQ(p.v.viewer().caught().count, 0u) << p.v.viewer().caught().last;
  EXPECT_EQ(p.s().lesson->step(), std::min<size_t>(9, p.s().lesson->stepCount() - 1));
}

// Issue 41: a field clicked (or tapped) once takes the keys. Lesson 02's step 9 asks for PRP = (0, 8, 0):
// one click on PRP's y, "8" and Enter type it, and the lesson stays on step 9 (before, the digits
// and Enter went to the lesson's step keys: it jumped to step 8 and replaced the camera). A drag on
// the same field still changes the value, and opens no text.
TEST(LectureNeverFails, AFieldClickedOnceTakesTheKeysAndTheLessonStays) {
  Presenting p(8);
  p.settle();
  p.s().controlsTab = ViewerState::cameraTab;
  p.v.frames(2);
  const Vec3 before = p.s().doc.scene().camera.prp;
  // The PRP row: x, y, z side by side, then the label; y is a little left of the row's middle.
  const ImVec4 r = p.v.viewer().rects().rects.at("camera.prp");
  const double x = r.x + r.z * 0.42, y = r.y + r.w / 2;
  p.v.click(x, y);
  p.v.frames(3);  // the text opens in the next frame; ImGui says it wants the keys from the frame after
  ASSERT_TRUE(ImGui::GetIO().WantTextInput) << "one click opened the field's text";
  p.v.type("8");
  p.v.key(keys::kEnter);
  p.settle();
  EXPECT_EQ(p.s().lesson->step(), 8u) << "the digit and Enter went into the field, not to the lesson";
  EXPECT_EQ(p.s().doc.scene().camera.prp, (Vec3{before.x, 8, before.z}));
  EXPECT_FALSE(ImGui::GetIO().WantTextInput);
  // A drag along the field changes the value as before and leaves no text open.
  p.v.drag(x, y, x + 40, y);
  p.v.frame();
  EXPECT_NE(p.s().doc.scene().camera.prp.y, 8.0) << "dragging still changes the value";
  EXPECT_FALSE(ImGui::GetIO().WantTextInput) << "a drag opens no text";
  EXPECT_EQ(p.s().lesson->step(), 8u);
  // A double-click, as users are used to, still types the whole number anew (not one "word" of it).
  const double z = r.x + r.z * 0.70;
  p.v.click(z, y);
  p.v.click(z, y);
  p.v.frames(3);
  p.v.type("7");
  p.v.key(keys::kEnter);
  p.settle();
  EXPECT_EQ(p.s().doc.scene().camera.prp.z, 7.0);
  EXPECT_EQ(p.s().lesson->step(), 8u);
}

// An error in the middle of a frame (here: a step number that is no number, put where only digits
// can come from the keys) is caught: the frame is closed, the status line says why in the UI's
// language, and the next frames draw as before.
TEST(LectureNeverFails, AnErrorInAFrameIsCaughtSaidAndTheNextFramesDraw) {
  Presenting p(2);
  const size_t step = p.s().lesson->step();
  p.s().lessonTyped = "x";  // std::stoul throws on Enter
  p.v.key(keys::kEnter);
  EXPECT_EQ(p.v.viewer().caught().count, 1u);
  EXPECT_TRUE(p.s().statusIsError);
  EXPECT_THAT(p.s().status, HasSubstr("ein Fehler wurde abgefangen")) << p.s().status;
  p.s().lessonTyped.clear();
  p.v.frames(3);
  EXPECT_EQ(p.v.viewer().caught().count, 1u) << "the frames after it draw without error";
  EXPECT_EQ(p.s().lesson->step(), step);
  p.v.key(keys::kRight);
  p.settle();
  EXPECT_EQ(p.s().lesson->step(), step + 1) << "the lesson still moves";
  const Image image = p.v.image();
  EXPECT_GT(test::distinctColours(image), 200u) << "the window still shows the viewer";
}

// A GL error raised in a frame (the driver refusing a call) is caught the same way.
TEST(LectureNeverFails, AGlErrorInAFrameIsCaughtAndSaid) {
  HeadlessViewer v{*test::egl().context, defaultScene(), 1280, 720};
  v.frames(2);
  test::egl().context->gl().Enable(0xFFFF);  // GL_INVALID_ENUM, found when the frame checks
  v.frame();
  EXPECT_EQ(v.viewer().caught().count, 1u);
  EXPECT_THAT(v.viewer().caught().last, HasSubstr("GL_INVALID_ENUM"));
  EXPECT_THAT(v.state().status, HasSubstr("GL_INVALID_ENUM"));
  v.frames(2);
  EXPECT_EQ(v.viewer().caught().count, 1u);
}

// The recovery dialog is modal: keys pressed behind it (a clicker's → and Page Down) move nothing.
TEST(LectureNeverFails, AModalDialogTakesTheKeys) {
  test::TempDir dir;
  Presenting p(3);
  // Any recovery file will do: the dialog is what matters.
  Document doc(defaultScene());
  doc.scene().camera.front = 0.75;
  doc.endFrame(false);
  Autosave a(dir.path, 0);
  ASSERT_TRUE(a.writeNow(doc));
  const std::optional<Recovery> r = Autosave::read(a.file());
  ASSERT_TRUE(r);
  p.v.viewer().session().recovery().offerRecoveries({*r});
  p.v.frames(2);
  ASSERT_TRUE(p.v.viewer().dialogOpen());
  for (int key : {keys::kRight, keys::kPageDown, keys::kSpace, keys::kEnd, keys::kP}) p.v.key(key);
  p.settle();
  EXPECT_EQ(p.s().lesson->step(), 3u) << "a key behind the dialog moved the lesson";
  EXPECT_EQ(p.s().doc.scene().camera.projection, p.step(3).scene.camera.projection) << "P behind the dialog changed the projection";
}

// What was on screen comes back: the lesson at its step, the views' styles and the camera as typed
// (invalid: the views show the last valid one, the fields the typed one).
TEST(LectureNeverFails, RecoveryRestoresTheLessonItsStepAndTheTypedCamera) {
  test::TempDir dir;
  fs::path kept;
  Camera typed, shown;
  {
    Presenting p(8);
    p.v.viewer().session().recovery().enableAutosave(dir.path / "state", 3);
    p.s().display.npc.style = Style::wire;
    p.s().doc.scene().camera.prp = {0, 8, 0};
    p.v.frames(2);
    ASSERT_FALSE(p.s().doc.error().empty());
    typed = p.s().doc.scene().camera;
    shown = p.s().doc.shown().camera;
    kept = p.v.viewer().session().recovery().writeRecoveryNow();
    ASSERT_FALSE(kept.empty()) << "an invalid camera typed is an unsaved change";
    const nlohmann::json j = nlohmann::json::parse(test::readFile(kept));
    EXPECT_EQ(j["lesson"]["step"], 8);
    EXPECT_EQ(j["edited_camera"]["prp"], nlohmann::json::array({0, 8, 0}));
  }
  // Another session finds it (read by its name: this process is still running).
  const fs::path copy = dir.path / "recovery-copy.json";
  fs::copy_file(kept, copy);
  HeadlessViewer v{*test::egl().context, defaultScene(), 1280, 720};
  ASSERT_TRUE(recoverIn(v, copy));
  ASSERT_TRUE(v.state().lesson) << v.state().status;
  EXPECT_EQ(v.state().lesson->step(), 8u);
  EXPECT_EQ(v.state().lesson->lesson().file.filename(), "02-view-orientation.de.json");
  EXPECT_EQ(v.state().doc.scene().camera, typed) << "the fields show the camera as typed";
  EXPECT_EQ(v.state().doc.shown().camera, shown) << "the views the last valid one";
  EXPECT_EQ(v.state().display.npc.style, Style::wire);
  EXPECT_TRUE(v.state().doc.dirty());
  v.frames(30);
  EXPECT_EQ(v.state().doc.scene().camera, typed) << "the lesson's step is not applied over the recovered state";
  EXPECT_EQ(v.viewer().caught().count, 0u) << v.viewer().caught().last;
}

// An object's transform typed invalid (a scale of 0: the views keep the last valid one) comes back
// as typed, in the fields, with the views on the valid one.
TEST(LectureNeverFails, RecoveryRestoresAnObjectsTransformAsTyped) {
  test::TempDir dir;
  fs::path kept;
  ModelTransform typed;
  {
    HeadlessViewer v{*test::egl().context, defaultScene(), 1280, 720};
    v.viewer().session().recovery().enableAutosave(dir.path / "state", 3);
    v.frames(2);
    v.state().doc.scene().objects[1].transform.scale = {0, 1.5, 1.5};
    v.state().doc.scene().objects[1].transform.rotations.push_back({{0, 0, 0}, 30, std::nullopt});
    v.frames(2);
    ASSERT_FALSE(v.state().doc.error().empty()) << "a scale of 0 is an invalid transform";
    typed = v.state().doc.scene().objects[1].transform;
    kept = v.viewer().session().recovery().writeRecoveryNow();
    ASSERT_FALSE(kept.empty());
  }
  const fs::path copy = dir.path / "recovery-copy.json";
  fs::copy_file(kept, copy);
  HeadlessViewer v{*test::egl().context, defaultScene(), 1280, 720};
  ASSERT_TRUE(recoverIn(v, copy));
  EXPECT_EQ(v.state().doc.scene().objects[1].transform, typed) << "the fields show the transform as typed";
  EXPECT_EQ(v.state().doc.shown().objects[1].transform, defaultScene().objects[1].transform) << "the views the valid one";
  EXPECT_EQ(v.viewer().caught().count, 0u) << v.viewer().caught().last;
}

// A recovery file someone else wrote (or a disk that garbled it): its scene is valid, everything
// beside it hostile — a lesson outside the bundled ones and one that does not exist, a step of 10^18,
// the typed camera with strings, NaN and a missing key, views that are no link. Recovering shows the
// scene, says nothing it cannot do in a way that stops the viewer, and catches no error.
TEST(LectureNeverFails, AHostileRecoveryFileRecoversItsSceneAndNothingElseBreaks) {
  test::TempDir dir;
  const std::vector<nlohmann::json> extras = {
      {{"lesson", {{"file", "/etc/passwd"}, {"step", 3}}}},
      {{"lesson", {{"file", "no-such-lesson.json"}, {"step", 1000000000000000000ull}}}},
      {{"lesson", {{"file", 7}, {"step", "two"}}}},
      {{"edited_camera", {{"vrp", {"a", "b", "c"}}, {"prp", {0, 8}}}}},
      {{"edited_camera", {{"vrp", {0, 0, 0}}, {"prp", {1e308, -1e308, 0}}, {"vup", {0, 0, 0}}}}},
      {{"edited_camera", "PRP = (0, 8, 0)"}},
      {{"views", {{"npc", "wire"}}}},
      {{"views", "npc=toon&world=&orbit=nan,nan"}},
      {{"edited_transforms", {{{"object", 99}, {"transform", {{"translate", {0, 0, 0}}, {"rotate", nlohmann::json::array()}, {"scale", {0, 1, 1}}}}},
                              {{"object", -1}},
                              "x",
                              {{"object", 0}, {"transform", {{"translate", {"a"}}}}}}}},
  };
  Scene scene = defaultScene();
  scene.camera.prp = {3, 2.4, 9};
  for (size_t i = 0; i < extras.size(); ++i) {
    SCOPED_TRACE(extras[i].dump());
    nlohmann::json j = nlohmann::json::parse(test::readFile([&] {
      const fs::path valid = dir.path / ("valid-" + std::to_string(i) + ".json");
      {
        HeadlessViewer writer{*test::egl().context, scene, 640, 480};
        writer.viewer().session().recovery().enableAutosave(dir.path / ("state-" + std::to_string(i)), 3);
        writer.state().doc.scene().camera.vrp = {0.25, 0, 0};
        writer.frames(2);
        fs::copy_file(writer.viewer().session().recovery().writeRecoveryNow(), valid);
      }
      return valid;
    }()));
    for (auto it = extras[i].begin(); it != extras[i].end(); ++it) j[it.key()] = it.value();
    const fs::path file = dir.write("hostile-" + std::to_string(i) + ".json", j.dump());
    HeadlessViewer v{*test::egl().context, defaultScene(), 1280, 720};
    ASSERT_TRUE(recoverIn(v, file));
    v.frames(2);
    EXPECT_EQ(v.state().doc.shown().camera.vrp, Vec3(0.25, 0, 0)) << "the recovered scene is not shown";
    EXPECT_EQ(v.viewer().caught().count, 0u) << v.viewer().caught().last;
    expectFinite(v.state().run().camera);
    if (v.state().lesson) {
      EXPECT_LT(v.state().lesson->step(), v.state().lesson->stepCount());
    }
  }
}

}  // namespace
}  // namespace vplab
