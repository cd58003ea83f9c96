// The viewer's runtime and document lifecycle (issue 11 items 2, 11, 13; issue 10 "no lost work"):
// new documents start clean, scenes load on a worker thread while frames go on, queued input loses
// no click, saving is atomic and never overwrites a bundled scene, autosave and crash recovery.
// The real window's idle CPU and SIGTERM recovery are tested under Xvfb
// (tests/app/window/idle_and_recovery.sh).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <future>

#include "app/document/atomic_file.h"
#include "app/document/autosave.h"
#include "app/ui/headless_viewer.h"
#include "app/ui/input_queue.h"
#include "app/ui/keys.h"
#include "base/error.h"
#include "io/scene_io.h"
#include "tests/support/gl_test_support.h"
#include "tests/support/crash.h"
#include "tests/support/files.h"

namespace vplab {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;
using test::readFile;
using test::TempDir;

constexpr int kWidth = 1280, kHeight = 720;

std::unique_ptr<HeadlessViewer> makeViewer(Scene scene = defaultScene()) {
  auto v = std::make_unique<HeadlessViewer>(*test::egl().context, std::move(scene), kWidth, kHeight);
  v->frames(3);
  return v;
}

fs::path preset(const char* name) { return fs::path(VPLAB_ASSETS) / "scenes" / name; }

/// Frames until the loader is idle (at most `limit`); returns how many ended with the load still
/// running (a loader that blocked the frame would finish within the first).
int framesWhileLoading(HeadlessViewer& v, int limit = 3000) {
  int n = 0;
  for (int i = 0; i < limit && v.viewer().session().loader().busy(); ++i) {
    v.frame();
    if (v.viewer().session().loader().busy()) ++n;
  }
  v.frames(2);
  return n;
}

void clickId(HeadlessViewer& v, const std::string& id) {
  const auto [x, y] = v.centreOf(id);
  v.click(x, y);
}

// ---------------------------------------------------------------- new documents (issue 11 item 2)

TEST(Document, NewFromTheMenuIsCleanWithNoUndoIntoThePreviousScene) {
  auto v = makeViewer();
  v->key(keys::kP);  // an unsaved edit: New asks before discarding it
  ASSERT_TRUE(v->state().doc.dirty());
  clickId(*v, "menu.file");
  v->frames(2);
  clickId(*v, "menu.new");
  v->frames(2);
  clickId(*v, "discard.confirm");
  v->frames(2);
  EXPECT_EQ(v->state().doc.scene().camera.projection, Projection::perspective);
  EXPECT_FALSE(v->state().doc.dirty());
  EXPECT_FALSE(v->state().doc.canUndo());
  EXPECT_THAT(v->viewer().title(), ::testing::Not(HasSubstr("*")));
}

TEST(Document, OpeningAPresetAfterEditsStartsACleanDocumentWithDefaultViewSettings) {
  auto v = makeViewer();
  v->key(keys::kP);           // an edit: the next projection
  v->key(keys::kDigit1 + 3);  // hidden-line in every view: a choice for this scene only
  ASSERT_TRUE(v->state().doc.dirty());
  ASSERT_TRUE(v->state().doc.canUndo());
  v->viewer().session().openScene(preset("parallel.json"));
  framesWhileLoading(*v);
  EXPECT_EQ(v->state().doc.path(), preset("parallel.json"));
  EXPECT_FALSE(v->state().doc.dirty());
  EXPECT_FALSE(v->state().doc.canUndo());
  EXPECT_THAT(v->viewer().title(), ::testing::Not(HasSubstr("*")));
  EXPECT_EQ(v->state().display.world.style, DisplaySettings{}.world.style);
  v->key(keys::kZ, /*ctrl=*/true);  // undo has nothing to go back to
  EXPECT_EQ(v->state().doc.scene().camera.projection, Projection::parallel);
  EXPECT_EQ(v->state().doc.path(), preset("parallel.json"));
}

// ---------------------------------------------------------------- idle (item 10)

// The window's event wait sleeps for wakeIn() (tests/app/window/idle_and_recovery.sh measures the
// CPU): long when nothing happens, zero while something moves.
TEST(Idle, TheViewerAsksForFramesOnlyWhileSomethingMoves) {
  auto v = makeViewer();
  v->frames(3);
  EXPECT_GE(v->viewer().wakeIn(), 60.0) << "idle: no frame needed";
  v->viewer().requestFrames(2);
  EXPECT_EQ(v->viewer().wakeIn(), 0.0);
  v->frames(2);
  EXPECT_GE(v->viewer().wakeIn(), 60.0) << "settled after the frames asked for";
  v->state().morphPlaying = true;
  EXPECT_EQ(v->viewer().wakeIn(), 0.0) << "the stage morph plays";
  v->state().morphPlaying = false;
  v->viewer().makeCurrent();
  v->state().animateUntil = ImGui::GetTime() + 0.5;
  EXPECT_EQ(v->viewer().wakeIn(), 0.0) << "a timed notice is showing";
  v->frames(40);
  EXPECT_GE(v->viewer().wakeIn(), 60.0) << "the notice's time is over";
}

// A frame drawn for hover or ImGui's settling reuses the views' images (a view of a million
// triangles takes seconds on llvmpipe); anything the views show draws them again.
TEST(Idle, FramesWithoutChangesReuseTheViewsImages) {
  auto v = makeViewer();
  const unsigned settled = v->viewer().images().drawn();
  const auto [cx, cy] = v->centreOf("view.camera");
  v->mouseMove(cx, cy);  // hovering over a view
  v->frames(3);
  v->mouseMove(100, 300);  // and over the panels
  v->frames(3);
  EXPECT_EQ(v->viewer().images().drawn(), settled);
  const Image before = v->image();
  v->key(keys::kDigit1 + 2);  // wireframe in every view
  EXPECT_GE(v->viewer().images().drawn(), settled + 3) << "camera, world and NPC views drawn again";
  EXPECT_GT(test::differingPixels(before, v->image()), 1000u);
  const unsigned styled = v->viewer().images().drawn();
  v->key(keys::kP);  // the camera changes
  EXPECT_GE(v->viewer().images().drawn(), styled + 3);
}

// ---------------------------------------------------------------- loading on a worker thread (item 11)

/// A reader that waits until the test opens its gate: the load lasts exactly as long as the test
/// wants, whatever the machine's speed.
struct GatedReader {
  std::shared_ptr<std::promise<void>> gate = std::make_shared<std::promise<void>>();
  std::shared_future<void> opened = gate->get_future().share();
  SceneLoader::Reader reader() const {
    return [opened = opened](const fs::path& f) {
      opened.wait();
      return loadScene(f);
    };
  }
  void open() const { gate->set_value(); }
};

TEST(Loading, FramesGoOnWhileASceneLoadsAndItArrivesClean) {
  auto v = makeViewer();
  GatedReader gated;
  v->viewer().session().loader().setReader(gated.reader());
  v->viewer().session().openScene(preset("parallel.json"));
  v->frames(20);  // each returns while the worker is still reading
  EXPECT_TRUE(v->viewer().session().loader().busy());
  EXPECT_TRUE(v->state().doc.path().empty()) << "the open scene stays until the new one is there";
  EXPECT_THAT(v->rects().rects, ::testing::Contains(::testing::Key("load.cancel"))) << "no progress window";
  gated.open();
  framesWhileLoading(*v);
  EXPECT_EQ(v->state().doc.path(), preset("parallel.json"));
  EXPECT_FALSE(v->state().doc.dirty());
  EXPECT_FALSE(v->state().doc.canUndo());
}

TEST(Loading, TheBundledLargeMeshLoadsWithoutBlockingFrames) {
  auto v = makeViewer();
  v->viewer().session().openScene(preset("large-mesh.json"));
  // Tessellating n = 1024 (half a million polygons) takes ~0.2 s, a frame of the settled default
  // scene a few milliseconds (its views are reused; 14 frames measured): a loader that blocked the
  // frame would end within the first one.
  EXPECT_GE(framesWhileLoading(*v), 3);
  EXPECT_EQ(v->state().doc.path(), preset("large-mesh.json"));
  EXPECT_GT(v->state().doc.shown().objects.at(0).mesh->faceCount(), 500000u);
}

TEST(Loading, CancelKeepsTheOpenScene) {
  auto v = makeViewer();
  v->key(keys::kP);  // unsaved work that Cancel must keep
  const Scene before = v->state().doc.scene();
  GatedReader gated;
  v->viewer().session().loader().setReader(gated.reader());
  v->viewer().session().openScene(preset("parallel.json"));
  v->frames(2);  // the loading window lays itself out
  ASSERT_TRUE(v->viewer().session().loader().busy());
  // A quick click (pointer there, press and release at once) on Cancel.
  const auto [x, y] = v->centreOf("load.cancel");
  v->input().mouseMove(x, y);
  v->input().mouseButton(0, true);
  v->input().mouseButton(0, false);
  v->frames(2);
  EXPECT_FALSE(v->viewer().session().loader().busy());
  gated.open();  // the abandoned read ends; its scene must not arrive
  v->frames(5);
  EXPECT_TRUE(v->state().doc.scene() == before);
  EXPECT_TRUE(v->state().doc.dirty());
  EXPECT_THAT(v->state().status, HasSubstr("cancelled"));
}

TEST(Loading, AnObjMeshFromTheScenePanelIsAddedAsOneUndoStep) {
  auto v = makeViewer();
  const size_t before = v->state().doc.scene().objects.size();
  SceneObject o;
  o.shape = Shape::mesh;
  o.name = "house";
  o.file = (fs::path(VPLAB_ASSETS) / "meshes" / "house.obj").string();
  v->state().objectToLoad = o;  // what "+ OBJ mesh…" does
  v->frame();
  EXPECT_TRUE(v->viewer().session().loader().busy() || v->state().doc.scene().objects.size() == before + 1);
  framesWhileLoading(*v);
  ASSERT_EQ(v->state().doc.scene().objects.size(), before + 1);
  EXPECT_GT(v->state().doc.scene().objects.back().mesh->faceCount(), 0u);
  EXPECT_EQ(v->state().selectedObject, int(before));
  EXPECT_TRUE(v->state().doc.dirty());
  v->key(keys::kZ, /*ctrl=*/true);
  EXPECT_EQ(v->state().doc.scene().objects.size(), before);
}

TEST(Loading, AnUnreadableFileIsAnErrorAndTheSceneStays) {
  TempDir dir;
  const fs::path bad = dir.path / "bad.json";
  std::ofstream(bad) << "{ \"camera\": 3 }";
  auto v = makeViewer();
  v->viewer().session().openScene(bad);
  framesWhileLoading(*v);
  EXPECT_TRUE(v->state().statusIsError);
  EXPECT_THAT(v->state().status, HasSubstr("bad.json"));
  EXPECT_TRUE(v->state().doc.path().empty());
}

// ---------------------------------------------------------------- input queue (item 13)

TEST(InputQueue, APressAndReleaseInOneFrameAreSeenInTwo) {
  ImGuiContext* ctx = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // as the viewer: nothing written into the working directory
  InputQueue q;
  q.mouseMove(10, 20);
  q.mouseButton(0, true);
  q.mouseButton(0, false);
  q.key(keys::kP, true);
  q.key(keys::kP, false);
  q.feed(io);
  EXPECT_EQ(io.MousePos.x, 10.f);
  EXPECT_TRUE(io.MouseDown[0]);
  EXPECT_FALSE(io.KeysDown[keys::kP]);
  q.feed(io);
  EXPECT_FALSE(io.MouseDown[0]);
  q.feed(io);
  EXPECT_TRUE(io.KeysDown[keys::kP]);
  q.feed(io);
  EXPECT_FALSE(io.KeysDown[keys::kP]);
  EXPECT_TRUE(q.empty());
  ImGui::DestroyContext(ctx);
}

TEST(InputQueue, AFastClickOnTheFileMenuOpensIt) {
  auto v = makeViewer();
  const auto [x, y] = v->centreOf("menu.file");
  v->input().mouseMove(x, y);
  v->frame();
  v->input().mouseButton(0, true);  // press and release before the same frame
  v->input().mouseButton(0, false);
  v->frames(3);
  v->viewer().makeCurrent();
  EXPECT_NE(ImGui::FindWindowByName("##Menu_00"), nullptr);
  EXPECT_TRUE(ImGui::FindWindowByName("##Menu_00") && ImGui::FindWindowByName("##Menu_00")->Active);
}

TEST(InputQueue, AFastKeyStrokeIsNotLost) {
  auto v = makeViewer();
  ASSERT_EQ(v->state().doc.scene().camera.projection, Projection::perspective);
  v->input().key(keys::kP, true);
  v->input().key(keys::kP, false);
  v->frames(3);
  EXPECT_EQ(v->state().doc.scene().camera.projection, Projection::parallel);
}

// ---------------------------------------------------------------- saving (issue 10 item 6)

TEST(Save, ABundledSceneIsNeverOverwrittenSaveAsksForACopy) {
  const fs::path file = preset("perspective.json");
  const std::string original = readFile(file);
  auto v = makeViewer(loadScene(file));
  v->key(keys::kP);
  ASSERT_TRUE(v->state().doc.dirty());
  v->key(keys::kS, /*ctrl=*/true);
  EXPECT_TRUE(v->viewer().session().files().fileDialog().isOpen());
  EXPECT_TRUE(v->state().doc.dirty());
  EXPECT_EQ(readFile(file), original);
  EXPECT_TRUE(v->viewer().session().files().isBundled(file));
  EXPECT_TRUE(v->viewer().session().files().isBundled({}));  // the built-in default scene
  EXPECT_FALSE(v->viewer().session().files().isBundled(fs::temp_directory_path() / "mine.json"));
}

// ---------------------------------------------------------------- autosave and recovery

TEST(Autosave, WritesAfterTheDelayAndRemovesTheFileWhenSaved) {
  TempDir dir;
  auto v = makeViewer();
  v->viewer().session().recovery().enableAutosave(dir.path / "state", 0.1);  // 6 frames of 1/60 s
  const fs::path file = v->viewer().session().recovery().autosave()->file();
  v->frames(10);
  EXPECT_FALSE(fs::exists(file)) << "nothing changed, nothing to save";
  v->key(keys::kP);
  EXPECT_FALSE(fs::exists(file)) << "written before the delay";
  EXPECT_GT(v->viewer().wakeIn(), 0.0);
  EXPECT_LE(v->viewer().wakeIn(), 0.1) << "the event wait must wake for the autosave";
  v->frames(10);
  ASSERT_TRUE(fs::exists(file));
  EXPECT_THAT(readFile(file), HasSubstr("\"projection\": \"parallel\""));
  // Saving makes the document clean: its recovery file goes.
  v->state().doc.save(dir.path / "mine.json");
  v->frames(2);
  EXPECT_FALSE(fs::exists(file));
}

TEST(Autosave, ARecoveryFileOfAnEndedProcessIsOfferedAndRecovered) {
  TempDir dir;
  const fs::path state = dir.path / "state";
  // A session in a child process autosaves an edited scene and ends without cleaning up (a crash).
  ASSERT_FALSE(test::crashWithUnsavedFront(state, preset("perspective.json"), 0.75).empty());

  const std::optional<Recovery> r = Autosave::find(state);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->scenePath, preset("perspective.json"));

  auto v = makeViewer();
  v->viewer().session().recovery().enableAutosave(state, 3);
  v->viewer().session().recovery().offerRecoveries({*r});
  v->frames(3);
  clickId(*v, "recovery.recover");
  v->frames(2);
  EXPECT_EQ(v->state().doc.scene().camera.front, 0.75);
  EXPECT_EQ(v->state().doc.path(), preset("perspective.json"));
  EXPECT_TRUE(v->state().doc.dirty()) << "recovered changes are still unsaved";
  EXPECT_FALSE(v->state().doc.canUndo());
  EXPECT_FALSE(fs::exists(r->file)) << "the old session's file is taken over";
  EXPECT_TRUE(fs::exists(v->viewer().session().recovery().autosave()->file())) << "this session keeps the changes at once";
}

namespace {

/// A child process that autosaves `preset` with its front plane at `front` and ends without
/// cleaning up (a crash); returns its recovery file.
fs::path crashWithUnsavedFront(const fs::path& state, const char* presetName, double front) {
  return test::crashWithUnsavedFront(state, preset(presetName), front);
}

}  // namespace

TEST(Autosave, EverySessionLeftWithUnsavedChangesIsOfferedAndTheOthersStayKept) {
  TempDir dir;
  const fs::path state = dir.path / "state";
  const fs::path older = crashWithUnsavedFront(state, "perspective.json", 0.75);
  ASSERT_TRUE(fs::exists(older));
  // Modification times have a file system's resolution: the newer one is made visibly newer.
  const fs::path newer = crashWithUnsavedFront(state, "parallel.json", 0.5);
  ASSERT_TRUE(fs::exists(newer));
  fs::last_write_time(older, fs::last_write_time(newer) - std::chrono::seconds(10));

  const std::vector<Recovery> all = Autosave::findAll(state);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].file, newer) << "the newest is offered first";
  EXPECT_EQ(all[1].file, older);

  auto v = makeViewer();
  v->viewer().session().recovery().enableAutosave(state, 3);
  v->viewer().session().recovery().offerRecoveries(all);
  v->frames(3);
  EXPECT_EQ(v->viewer().session().recovery().recoveries().size(), 2u);
  clickId(*v, "recovery.recover.1");  // the older one
  v->frames(2);
  EXPECT_TRUE(v->viewer().session().recovery().recoveries().empty());
  EXPECT_EQ(v->state().doc.scene().camera.front, 0.75);
  EXPECT_EQ(v->state().doc.path(), preset("perspective.json"));
  EXPECT_FALSE(fs::exists(older)) << "the recovered one is taken over";
  EXPECT_TRUE(fs::exists(newer)) << "the other one is kept for the next start";
  EXPECT_THAT(v->state().status, HasSubstr("1 other kept scene is offered at the next start"));
  const std::vector<Recovery> left = Autosave::findAll(state);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].file, newer);

  // Discarding one of several leaves the dialog open with the rest.
  const fs::path third = crashWithUnsavedFront(state, "perspective.json", 0.25);
  auto w = makeViewer();
  w->viewer().session().recovery().offerRecoveries(Autosave::findAll(state));
  w->frames(3);
  ASSERT_EQ(w->viewer().session().recovery().recoveries().size(), 2u);
  clickId(*w, "recovery.discard");
  w->frames(2);
  EXPECT_EQ(w->viewer().session().recovery().recoveries().size(), 1u);
  EXPECT_EQ(Autosave::findAll(state).size(), 1u);
  clickId(*w, "recovery.discard");
  w->frames(2);
  EXPECT_TRUE(w->viewer().session().recovery().recoveries().empty());
  EXPECT_TRUE(Autosave::findAll(state).empty());
  EXPECT_FALSE(w->state().doc.dirty()) << "discarding recovers nothing";
}

TEST(Autosave, AfterManyCrashesTheDialogListsTheNewestAndTheRestComeUpAsTheyGo) {
  TempDir dir;
  const fs::path state = dir.path / "state";
  for (int i = 0; i < 8; ++i) ASSERT_FALSE(crashWithUnsavedFront(state, "perspective.json", 0.1 * (i + 1)).empty());
  auto v = makeViewer();
  v->viewer().session().recovery().offerRecoveries(Autosave::findAll(state));
  v->frames(3);
  EXPECT_EQ(v->viewer().session().recovery().recoveries().size(), 8u);
  EXPECT_TRUE(v->rects().rects.count("recovery.recover.5")) << "the six newest are listed";
  EXPECT_FALSE(v->rects().rects.count("recovery.recover.6")) << "a list of every crash would not fit a screen";
  clickId(*v, "recovery.discard");
  v->frames(2);
  EXPECT_EQ(v->viewer().session().recovery().recoveries().size(), 7u);
  EXPECT_TRUE(v->rects().rects.count("recovery.recover.5"));
  EXPECT_FALSE(v->rects().rects.count("recovery.recover.6"));
  EXPECT_EQ(Autosave::findAll(state).size(), 7u);
}

// ---------------------------------------------------------------- a lost graphics context (issue 24 item 1)

TEST(Graphics, EveryGlObjectMadeAgainGivesThePictureBackAndKeepsTheDocument) {
  auto v = makeViewer();
  v->key(keys::kP);  // an edit: the projection changes, one undo step
  v->frames(4);
  ASSERT_TRUE(v->state().doc.canUndo());
  const Camera edited = v->state().doc.scene().camera;
  const Image before = v->image();
  const unsigned drawn = v->viewer().images().drawn();

  // What the page does when WebGL gives its context back: every GL object is made again.
  v->viewer().recreateGlObjects();
  v->frames(4);  // the frame's GL error check passes: nothing of the old objects is left to fail
  EXPECT_GT(v->viewer().images().drawn(), drawn) << "the views were not drawn again into new targets";
  const Image after = v->image();
  ASSERT_EQ(after.width, before.width);
  ASSERT_EQ(after.height, before.height);
  // The same draws on the same renderer give the same bytes: anything else is an object not made
  // again (an empty font atlas, a view target left black).
  size_t differing = 0;
  for (size_t i = 0; i < before.pixels.size(); ++i) differing += before.pixels[i] != after.pixels[i];
  EXPECT_EQ(differing, 0u) << "bytes differ after the GL objects were made again";
  EXPECT_EQ(v->state().doc.scene().camera, edited);
  ASSERT_TRUE(v->state().doc.canUndo()) << "the undo history was lost";
  v->key(keys::kZ, /*ctrl=*/true);
  v->frames(2);
  EXPECT_NE(v->state().doc.scene().camera.projection, edited.projection) << "undo after the restore does not undo the edit";
}

TEST(Autosave, AFailureIsShownNotSwallowed) {
  TempDir dir;
  const fs::path notADirectory = dir.path / "file";
  std::ofstream(notADirectory) << "x";
  auto v = makeViewer();
  v->viewer().session().recovery().enableAutosave(notADirectory / "vplab", 0);
  v->key(keys::kP);
  v->frames(2);
  EXPECT_TRUE(v->state().statusIsError);
  EXPECT_THAT(v->state().status, HasSubstr("autosave failed"));
  EXPECT_THAT(v->state().status, HasSubstr(notADirectory.string()));
}

}  // namespace
}  // namespace vplab

// ---------------------------------------------------------------- the browser's files (issue 13)

namespace vplab {
namespace {

/// A FileChooser as the page's: saving downloads (a new file each time, under the suggested name in
/// `dir`), opening gives back `toOpen`. Records what it was asked.
struct DownloadingChooser final : FileChooser {
  fs::path dir, toOpen;
  std::vector<std::pair<Mode, fs::path>> asked;
  void open(std::string, Mode mode, std::vector<std::string>, fs::path start,
            std::function<void(const fs::path&)> onChosen) override {
    asked.emplace_back(mode, start);
    onChosen(mode == Mode::save ? dir / start.filename() : toOpen);
  }
  bool isOpen() const override { return false; }
  bool downloads() const override { return true; }
};

TEST(Browser, SaveIsANewDownloadEveryTimeAndTheBrowsersShortcutsAreLeftToIt) {
  TempDir tmp;
  auto v = makeViewer();
  auto chooser = std::make_unique<DownloadingChooser>();
  DownloadingChooser& c = *chooser;
  c.dir = tmp.path;
  c.toOpen = preset("parallel.json");
  v->viewer().session().files().useFileChooser(std::move(chooser), /*browser=*/true);
  v->frames(2);
  v->key(keys::kS, /*ctrl=*/true);  // the browser's own "save page": the viewer does nothing
  v->key(keys::kO, /*ctrl=*/true);
  EXPECT_TRUE(c.asked.empty());

  v->key(keys::kP);  // an edit
  clickId(*v, "menu.file");
  v->frames(2);
  clickId(*v, "menu.save");
  v->frames(2);
  ASSERT_EQ(c.asked.size(), 1u);
  EXPECT_EQ(c.asked[0].second, "lecture-scene.json") << "the built-in scene downloads under a name of its own";
  EXPECT_EQ(loadScene(tmp.path / "lecture-scene.json").camera, v->state().doc.scene().camera);
  EXPECT_FALSE(v->state().doc.dirty());

  clickId(*v, "menu.file");  // again: a second download, though the document now has a path
  v->frames(2);
  clickId(*v, "menu.save");
  v->frames(2);
  EXPECT_EQ(c.asked.size(), 2u);

  clickId(*v, "menu.file");  // Open asks the page's picker for a scene or an OBJ
  v->frames(2);
  clickId(*v, "menu.open");
  framesWhileLoading(*v);
  ASSERT_EQ(c.asked.size(), 3u);
  EXPECT_EQ(c.asked[2].first, FileChooser::Mode::open);
  EXPECT_EQ(v->state().doc.path(), preset("parallel.json"));
}

}  // namespace
}  // namespace vplab

namespace vplab {
namespace {

// ---------------------------------------------------------------- the language (issue 22 item 4)

// View > Language switches the menus, the panels, the windows' titles and the views' labels at once,
// and hands the choice to what remembers it (the preferences file, the page's localStorage); a
// choice that cannot be remembered still applies and says why it is not kept.
TEST(Language, ViewLanguageSwitchesTheViewerAndIsRemembered) {
  auto v = makeViewer();
  std::vector<Language> remembered;
  v->viewer().session().start({.rememberLanguage = [&](Language lang) { remembered.push_back(lang); }});
  v->frames(2);
  EXPECT_EQ(v->viewer().title(), "vplab — default lecture scene");
  const Image english = v->image();
  // A tab is as wide as its name: "Display", then "Darstellung".
  const float displayTab = v->rects().rects.at("tab.controls.Display").z;

  clickId(*v, "menu.view");
  v->frames(2);
  clickId(*v, "menu.language");
  v->frames(2);
  clickId(*v, "menu.language.de");
  v->frames(3);
  EXPECT_EQ(v->state().display.language, Language::de);
  EXPECT_EQ(remembered, std::vector<Language>{Language::de});
  EXPECT_GT(v->rects().rects.at("tab.controls.Display").z, displayTab * 1.3f);
  EXPECT_EQ(v->viewer().title(), "vplab — Standardszene der Vorlesung");
  EXPECT_FALSE(v->state().doc.dirty()) << "a preference is no change of the scene";
  EXPECT_FALSE(v->state().doc.canUndo());
  // The tabs keep their ids (and the tests their names) in either language.
  const auto [tx, ty] = v->centreOf("tab.controls.Display");
  v->click(tx, ty);
  v->frames(2);
  EXPECT_EQ(v->state().controlsTab, ViewerState::displayTab);
  EXPECT_GT(test::differingPixels(english, v->image()), 2000u) << "the German window looks like the English one";

  v->viewer().session().start({.language = v->state().display.language,
                               .rememberLanguage = [](Language) { throw Error("/ro/preferences.json: read-only file system"); }});
  clickId(*v, "menu.view");
  v->frames(2);
  clickId(*v, "menu.language");
  v->frames(2);
  clickId(*v, "menu.language.en");
  v->frames(2);
  EXPECT_EQ(v->state().display.language, Language::en);
  EXPECT_TRUE(v->state().statusIsError);
  EXPECT_THAT(v->state().status, HasSubstr("/ro/preferences.json"));
  v->frames(2);
  EXPECT_EQ(v->rects().rects.at("tab.controls.Display").z, displayTab);
}

// A new document keeps the language (a preference, not a setting of the scene).
TEST(Language, ANewDocumentKeepsTheLanguage) {
  auto v = makeViewer();
  v->state().display.language = Language::de;
  clickId(*v, "menu.file");
  v->frames(2);
  clickId(*v, "menu.new");
  v->frames(2);
  EXPECT_EQ(v->state().display.language, Language::de);
}

}  // namespace
}  // namespace vplab
