// The CPU pipeline on a worker thread (app/workers/pipeline_worker.h, docs/lecturers.md "The viewer"): a run is
// the synchronous runPipeline's, the latest request wins, runs nobody holds are run into again, a failing
// run is an error (the viewer drawing on meanwhile: tests/app/ui/pipeline_worker_test.cpp).
#include "app/workers/pipeline_worker.h"
#include "io/dump.h"

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

}  // namespace
}  // namespace vplab
