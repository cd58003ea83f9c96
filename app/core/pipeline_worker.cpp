// The CPU pipeline on a worker thread (pipeline_worker.h).
#include "app/core/pipeline_worker.h"

#include "app/core/background_priority.h"
#include "pipeline/error.h"

#include <chrono>
#include <utility>

namespace vplab {

PipelineWorker::PipelineWorker(std::function<void()> wake) : wake_(std::move(wake)) {
  thread_ = std::thread([this] { loop(); });
}

PipelineWorker::~PipelineWorker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

uint64_t PipelineWorker::request(std::shared_ptr<const Scene> scene, PipelineOptions options) {
  std::lock_guard lock(mutex_);
  pending_ = Request{nextTicket_++, std::move(scene), options};
  changed_.notify_all();
  return pending_->ticket;
}

std::optional<PipelineWorker::Finished> PipelineWorker::take(uint64_t ticket, double seconds) {
  std::unique_lock lock(mutex_);
  if (seconds > 0)
    changed_.wait_for(lock, std::chrono::duration<double>(seconds),
                      [&] { return stop_ || (finished_ && finished_->ticket >= ticket); });
  return std::exchange(finished_, std::nullopt);
}

bool PipelineWorker::hasFinished() const {
  std::lock_guard lock(mutex_);
  return finished_.has_value();
}

unsigned PipelineWorker::allocated() const {
  std::lock_guard lock(mutex_);
  return allocated_;
}

void PipelineWorker::loop() {
  runBelowTheWindow();
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return stop_ || pending_.has_value(); });
    if (stop_) return;
    Request r = std::move(*pending_);
    pending_.reset();
    // A run that only this thread still holds (the window shows a newer one, the render thread has
    // finished with it): its buffers are reused. Only holders can copy a shared_ptr, so a count of 1
    // cannot grow while we look.
    std::shared_ptr<PipelineRun>* into = nullptr;
    for (std::shared_ptr<PipelineRun>& run : runs_)
      if (!run || run.use_count() == 1) {
        into = &run;
        break;
      }
    lock.unlock();
    Finished done{r.ticket, r.scene, nullptr, {}};
    std::shared_ptr<PipelineRun> fresh;
    if (!into || !*into) fresh = std::make_shared<PipelineRun>();
    PipelineRun& run = fresh ? *fresh : **into;
    const auto start = std::chrono::steady_clock::now();
    try {
      runPipeline(*r.scene, r.options, run);
      done.run = fresh ? fresh : *into;
    } catch (const std::exception& e) {
      done.error = e.what();
    }
    done.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    lock.lock();
    if (fresh) {
      ++allocated_;
      if (into) *into = std::move(fresh);  // kept for reuse; else (all three held) dropped with the run
    }
    finished_ = std::move(done);
    changed_.notify_all();
    if (wake_) wake_();
  }
}

}  // namespace vplab
