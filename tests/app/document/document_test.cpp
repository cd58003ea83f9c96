// The document (app/document/document.h) without a window: one undo step per finished edit, none while
// a drag is under way, the last valid scene shown while the edited camera is invalid, and the
// revisions that tell the pipeline and the autosave what changed (issue 20: by revision, not copies).
#include "app/document/document.h"

#include "io/scene_io.h"
#include "tests/support/files.h"

#include <gtest/gtest.h>

namespace vplab {
namespace {

TEST(Document, AFinishedEditIsOneUndoStepAndADragInProgressIsNone) {
  Document doc(defaultScene());
  EXPECT_FALSE(doc.canUndo());
  EXPECT_FALSE(doc.dirty());
  doc.scene().camera.front = 2.0;
  doc.endFrame(/*editInProgress=*/true);
  doc.scene().camera.front = 2.5;
  doc.endFrame(true);
  EXPECT_FALSE(doc.canUndo()) << "a drag under way records nothing";
  doc.endFrame(false);
  ASSERT_TRUE(doc.canUndo());
  EXPECT_TRUE(doc.dirty());
  doc.undo();
  EXPECT_EQ(doc.scene().camera.front, defaultScene().camera.front) << "the whole drag is one step";
  EXPECT_FALSE(doc.canUndo());
  doc.redo();
  EXPECT_EQ(doc.scene().camera.front, 2.5);
  EXPECT_FALSE(doc.canRedo());
}

TEST(Document, AnInvalidCameraIsNamedAndTheLastValidSceneIsShown) {
  Document doc(defaultScene());
  doc.scene().camera.prp = doc.scene().camera.vrp + Vec3(0, 0, doc.scene().camera.front);  // PRP on the front plane
  doc.scene().camera.vup = Vec3(0, 0, 0);
  doc.endFrame(false);
  EXPECT_NE(doc.error().find("camera"), std::string::npos) << doc.error();
  EXPECT_EQ(doc.shown().camera, defaultScene().camera);
  doc.undo();
  EXPECT_TRUE(doc.error().empty()) << doc.error();
}

TEST(Document, RevisionsCountRecordedChangesAndTheShownSceneCountsDrags) {
  Document doc(defaultScene());
  const unsigned revision = doc.revision(), shown = doc.shownRevision();
  doc.endFrame(false);
  EXPECT_EQ(doc.revision(), revision) << "a frame without a change is no revision";
  EXPECT_EQ(doc.shownRevision(), shown);
  doc.scene().camera.vrp.x = 0.25;
  doc.endFrame(true);
  EXPECT_EQ(doc.revision(), revision) << "not recorded while the drag goes on";
  EXPECT_EQ(doc.shownRevision(), shown + 1) << "but the views show it at once";
  doc.endFrame(false);
  EXPECT_EQ(doc.revision(), revision + 1);
  EXPECT_EQ(doc.shownRevision(), shown + 1) << "the same scene is shown: the pipeline need not run again";
  const unsigned generation = doc.generation();
  doc.replace(defaultScene());
  EXPECT_EQ(doc.generation(), generation + 1);
  EXPECT_FALSE(doc.canUndo()) << "a new document starts with an empty history";
  EXPECT_FALSE(doc.dirty());
}

TEST(Document, SavingWritesTheSceneAndMakesItClean) {
  test::TempDir dir;
  Document doc(defaultScene());
  doc.scene().camera.back = -2.0;
  doc.endFrame(false);
  ASSERT_TRUE(doc.dirty());
  doc.save(dir.path / "scene.json");
  EXPECT_FALSE(doc.dirty());
  EXPECT_EQ(loadScene(dir.path / "scene.json").camera.back, -2.0);
}

}  // namespace
}  // namespace vplab
