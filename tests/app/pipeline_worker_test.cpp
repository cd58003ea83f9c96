// The CPU pipeline on a worker thread (app/ui/pipeline_worker.h, README "The viewer"): a run is the
// synchronous runPipeline's, the latest request wins, runs nobody holds are run into again, and the
// viewer goes on drawing frames while a large scene's run is under way, then shows what the
// synchronous viewer shows.
#include "app/ui/headless_viewer.h"
#include "app/ui/pipeline_worker.h"
#include "pipeline/dump.h"
#include "tests/app/gl_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace vplab {
namespace {

PipelineWorker::Finished waitFor(PipelineWorker& worker, uint64_t ticket) {
  for (int i = 0; i < 600; ++i)  // 60 s
    if (auto done = worker.take(ticket, 0.1); done && done->ticket == ticket) return *done;
  ADD_FAILURE() << "run " << ticket << " did not finish in 60 s";
  return {};
}

TEST(PipelineWorker, ARunIsTheSynchronousPipelinesRun) {
  PipelineWorker worker({});
  auto scene = std::make_shared<const Scene>(defaultScene());
  const PipelineOptions options{ClipStrategy::wc, true, true};
  const PipelineWorker::Finished done = waitFor(worker, worker.request(scene, options));
  ASSERT_TRUE(done.run) << done.error;
  EXPECT_EQ(done.scene, scene) << "the run comes with the scene it ran on";
  EXPECT_EQ(dumpJson(*done.run), dumpJson(runPipeline(*scene, options)));
}

TEST(PipelineWorker, TheLatestRequestWinsAndRunsNobodyHoldsAreReused) {
  PipelineWorker worker({});
  Scene scene = defaultScene();
  // Ten requests in a row: those not yet started are replaced, the last one is answered.
  uint64_t last = 0;
  for (int i = 0; i < 10; ++i) {
    scene.camera.vrp.x = 0.1 * i;
    last = worker.request(std::make_shared<const Scene>(scene), {});
  }
  PipelineWorker::Finished done = waitFor(worker, last);
  ASSERT_TRUE(done.run);
  EXPECT_EQ(done.run->camera.vrp.x, scene.camera.vrp.x);
  // Shown runs let go (the window shows a newer one): the worker keeps running into its three.
  done = {};
  for (int i = 0; i < 6; ++i) {
    scene.camera.vrp.y = 0.1 * i;
    done = waitFor(worker, worker.request(std::make_shared<const Scene>(scene), {}));
    ASSERT_TRUE(done.run);
  }
  EXPECT_LE(worker.allocated(), 3u) << "a run nobody holds is run into again";
  // While the window holds a run, the worker never writes into it.
  const std::shared_ptr<const PipelineRun> held = done.run;
  const std::string before = dumpJson(*held);
  for (int i = 0; i < 4; ++i) {
    scene.camera.vrp.z = 0.1 * i;
    waitFor(worker, worker.request(std::make_shared<const Scene>(scene), {}));
  }
  EXPECT_EQ(dumpJson(*held), before);
}

TEST(PipelineWorker, AFailingRunIsAnErrorNotACrash) {
  PipelineWorker worker({});
  Scene scene = defaultScene();
  scene.camera.front = scene.camera.back - 1;  // F < B: not a camera
  const PipelineWorker::Finished done = waitFor(worker, worker.request(std::make_shared<const Scene>(scene), {}));
  EXPECT_FALSE(done.run);
  EXPECT_FALSE(done.error.empty());
}

// The viewer with the worker (as the window runs it): the frame that changes the camera of a large
// scene does not wait for its run; the views keep the last run until the new one arrives, and then
// the picture is the one the synchronous viewer draws after the same edit.
TEST(PipelineWorker, TheViewerDrawsOnWhileALargeSceneRunsThenShowsTheNewRun) {
  GlContext& context = *test::egl().context;
  const Scene scene = test::sphereScene(512);
  HeadlessViewer sync(context, scene, 1280, 720), async(context, scene, 1280, 720);
  async.viewer().usePipelineWorker({});
  sync.frames(3);
  async.frames(3);
  const PipelineRun* before = &async.state().run();
  for (HeadlessViewer* v : {&sync, &async}) v->state().doc.scene().camera.prp.x += 0.5;
  const auto t0 = std::chrono::steady_clock::now();
  async.frame();
  const double changing = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("the frame that changed the camera: %.1f ms with the worker\n", changing * 1e3);
  EXPECT_TRUE(async.viewer().runPending()) << "the large scene's run arrived within the frame";
  EXPECT_EQ(&async.state().run(), before) << "the frame shows the last run meanwhile";
  EXPECT_FALSE(async.viewer().viewsNotReady().empty()) << "no screenshot of the last run's views";
  for (int i = 0; i < 600 && async.viewer().runPending(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    async.frame();
  }
  ASSERT_FALSE(async.viewer().runPending());
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

}  // namespace
}  // namespace vplab
