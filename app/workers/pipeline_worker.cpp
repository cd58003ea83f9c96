// The CPU pipeline on a worker thread (pipeline_worker.h).
#include "app/workers/pipeline_worker.h"

#include "app/workers/background_priority.h"

#include <chrono>
#include <utility>

namespace vplab {

PipelineWorker::PipelineWorker(std::function<void()> wake) : queue_(1, std::move(wake)) {
  queue_.start([this] { loop(); });
}

PipelineWorker::~PipelineWorker() { queue_.stop(); }

uint64_t PipelineWorker::request(std::shared_ptr<const Scene> scene, PipelineOptions options) {
  return queue_.request(0, Request{std::move(scene), options});
}

std::optional<PipelineWorker::Finished> PipelineWorker::take(uint64_t ticket, double seconds) {
  return queue_.take(0, ticket, seconds);
}

bool PipelineWorker::hasFinished() const { return queue_.hasFinished(0); }

unsigned PipelineWorker::allocated() const {
  return queue_.locked([&] { return allocated_; });
}

void PipelineWorker::loop() {
  runBelowTheWindow();
  std::shared_ptr<PipelineRun>* into = nullptr;
  // A run that only this thread still holds (the window shows a newer one, the render thread has
  // finished with it): its buffers are reused. Only holders can copy a shared_ptr, so a count of 1
  // cannot grow while we look.
  const auto findReusable = [&](const auto&) {
    into = nullptr;
    for (std::shared_ptr<PipelineRun>& run : runs_)
      if (!run || run.use_count() == 1) {
        into = &run;
        break;
      }
  };
  while (auto job = queue_.next(findReusable)) {
    Finished done{job->ticket, job->request.scene, nullptr, {}};
    std::shared_ptr<PipelineRun> fresh;
    if (!into || !*into) fresh = std::make_shared<PipelineRun>();
    PipelineRun& run = fresh ? *fresh : **into;
    const auto start = std::chrono::steady_clock::now();
    try {
      runPipeline(*job->request.scene, job->request.options, run);
      done.run = fresh ? fresh : *into;
    } catch (const std::exception& e) {
      done.error = e.what();
    }
    done.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    queue_.finish(*job, std::move(done), [&] {
      if (!fresh) return;
      ++allocated_;
      if (into) *into = std::move(fresh);  // kept for reuse; else (all three held) dropped with the run
    });
  }
}

}  // namespace vplab
