// The viewer with the CPU pipeline on a worker thread (app/workers/pipeline_worker.h, docs/lecturers.md
// "The viewer"): it goes on drawing frames while a large scene's run is under way, then shows what the
// synchronous viewer shows (the worker alone: tests/app/workers/pipeline_worker_test.cpp). And the
// page's way without threads: the run in steps across frames.
#include "app/ui/headless_viewer.h"
#include "app/ui/shown_run.h"
#include "app/workers/pipeline_worker.h"
#include "io/dump.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace vplab {
namespace {

// The viewer with the worker (as the window runs it): the frame that changes the camera of a large
// scene does not wait for its run; the views keep the last run until the new one arrives, and then
// the picture is the one the synchronous viewer draws after the same edit.
TEST(PipelineWorker, TheViewerDrawsOnWhileALargeSceneRunsThenShowsTheNewRun) {
  GlContext& context = *test::egl().context;
#ifdef VPLAB_SANITIZED  // some 130 000 triangles: ASan's run still takes many frames (the 512 sphere took 243 s)
  const Scene scene = test::sphereScene(256);
#else
  const Scene scene = test::sphereScene(512);
#endif
  HeadlessViewer sync(context, scene, 1280, 720), async(context, scene, 1280, 720);
  async.viewer().run().useWorker({});
  sync.frames(3);
  async.frames(3);
  const PipelineRun* before = &async.state().run();
  for (HeadlessViewer* v : {&sync, &async}) v->state().doc.scene().camera.prp.x += 0.5;
  const auto t0 = std::chrono::steady_clock::now();
  async.frame();
  const double changing = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("the frame that changed the camera: %.1f ms with the worker\n", changing * 1e3);
  EXPECT_TRUE(async.viewer().run().pending()) << "the large scene's run arrived within the frame";
  EXPECT_EQ(&async.state().run(), before) << "the frame shows the last run meanwhile";
  EXPECT_FALSE(async.viewer().viewsNotReady().empty()) << "no screenshot of the last run's views";
  for (int i = 0; i < 600 && async.viewer().run().pending(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    async.frame();
  }
  ASSERT_FALSE(async.viewer().run().pending());
  EXPECT_TRUE(async.viewer().viewsNotReady().empty());
  sync.frames(3);
  async.frames(2);
  EXPECT_EQ(dumpJson(async.state().run()), dumpJson(sync.state().run()));
  const Image a = async.image(), b = sync.image();
  const size_t differ = test::differingPixels(a, b);
  if (differ) {
    writePng(a, (test::outputDir() / "pipeline_worker_async.png").string());
    writePng(b, (test::outputDir() / "pipeline_worker_sync.png").string());
  }
  EXPECT_EQ(differ, 0u) << "the worker's run draws what the synchronous one draws";
}

// The page's way, without threads (ShownRun::runInSteps): a large scene's run goes on across frames,
// a few ms of each; the views show the last run meanwhile (its progress in their busy mark); a
// change in the middle drops the run under way for one of the newest state; and the run finally
// shown is the synchronous viewer's, bit for bit, and so is the picture. 1 ns a frame: each frame
// does one step, whatever the machine's speed: 20 000 units in a run's first frame, at most twice as
// many in each next one, and the sphere has about 130 000, so a run takes at least three frames.
TEST(PipelineSteps, TheViewerRunsALargeSceneAcrossFramesThenShowsWhatTheSynchronousOneShows) {
  GlContext& context = *test::egl().context;
  const Scene scene = test::sphereScene(256);
  HeadlessViewer sync(context, scene, 1280, 720), stepped(context, scene, 1280, 720);
  stepped.viewer().run().runInSteps(1e-9);
  sync.frames(3);
  for (int i = 0; i < 100 && stepped.viewer().run().pending(); ++i) stepped.frame();
  ASSERT_FALSE(stepped.viewer().run().pending());
  EXPECT_EQ(dumpJson(stepped.state().run()), dumpJson(sync.state().run()));

  const PipelineRun* before = &stepped.state().run();
  for (HeadlessViewer* v : {&sync, &stepped}) v->state().doc.scene().camera.prp.x += 0.5;
  stepped.frame();
  ASSERT_TRUE(stepped.viewer().run().pending());
  const double first = stepped.viewer().run().progress().value_or(-1);
  EXPECT_GT(first, 0.0);
  EXPECT_LT(first, 1.0);
  EXPECT_EQ(&stepped.state().run(), before) << "a half-done run is never shown";
  EXPECT_FALSE(stepped.viewer().viewsNotReady().empty());
  stepped.frame();
  EXPECT_GT(stepped.viewer().run().progress().value_or(-1), first);
  // Changed again half way: the newest camera wins.
  for (HeadlessViewer* v : {&sync, &stepped}) v->state().doc.scene().camera.prp.x += 0.75;
  int frames = 0;
  for (; frames < 100 && stepped.viewer().run().pending(); ++frames) {
    EXPECT_EQ(&stepped.state().run(), before);
    stepped.frame();
  }
  EXPECT_GT(frames, 2) << "the run went across frames";
  ASSERT_FALSE(stepped.viewer().run().pending());
  EXPECT_FALSE(stepped.viewer().run().progress());
  sync.frames(3);
  stepped.frames(3);
  EXPECT_EQ(stepped.state().run().camera.prp, sync.state().run().camera.prp);
  EXPECT_EQ(dumpJson(stepped.state().run()), dumpJson(sync.state().run()));
  const Image a = stepped.image(), b = sync.image();
  const size_t differ = test::differingPixels(a, b);
  if (differ) {
    writePng(a, (test::outputDir() / "pipeline_steps.png").string());
    writePng(b, (test::outputDir() / "pipeline_steps_sync.png").string());
  }
  EXPECT_EQ(differ, 0u) << "the run in steps draws what the synchronous one draws";
}

// The page's frames share their time (issue 42): the run's step takes what is left of the frame's
// share from its start, and a frame left to a view's list (leaveFrame) takes no step, but never two
// frames in a row, so the run always goes on. (ShownRun alone, no GL: progress says whether it stepped.)
TEST(PipelineSteps, AStepTakesWhatIsLeftOfTheFrameAndALeftFrameNoneButNeverTwoInARow) {
  ViewerState state(test::sphereScene(256));
  ShownRun run(state);
  run.runInSteps(1e-9);  // one step of the smallest size a frame: progress tells frames apart
  run.beginFrame();
  run.update();
  ASSERT_TRUE(run.pending());
  const double first = run.progress().value_or(-1);
  EXPECT_GT(first, 0.0);

  run.beginFrame();
  run.leaveFrame();
  run.update();
  run.update();  // again in the same frame (the session's callback): still no step
  EXPECT_EQ(run.progress().value_or(-1), first) << "a frame left to a view's list stepped the run";
  run.beginFrame();
  run.leaveFrame();
  run.update();
  const double second = run.progress().value_or(-1);
  EXPECT_GT(second, first) << "two frames in a row left the run: it could starve";
  run.beginFrame();
  run.update();
  EXPECT_GT(run.progress().value_or(-1), second);

  // A frame that spent its share before the run's turn still steps, the least step: ~4 ms of work
  // besides making the job, where the whole share would be 100 ms (the tolerance: the job's arrays,
  // slower under ASan, and a step's overrun by its last check, about a millisecond's units).
  ShownRun shared(state);
  shared.runInSteps(0.1);
  shared.beginFrame();
  std::this_thread::sleep_for(std::chrono::milliseconds(110));
  const auto before = std::chrono::steady_clock::now();
  shared.update();
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
  EXPECT_GT(shared.progress().value_or(1), 0.0);
  EXPECT_LT(took, 0.05) << "the step took the whole share after the frame had spent it";
}

}  // namespace
}  // namespace vplab
