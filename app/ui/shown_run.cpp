// The CPU pipeline's run of the shown scene (shown_run.h).
#include "app/ui/shown_run.h"

#include "base/error.h"

#include <chrono>

namespace vplab {

namespace {

/// How long the frame that changed the scene may wait for the pipeline's worker: a small scene's run
/// (well under a millisecond) arrives in it. A scene whose last run took longer is not waited for at
/// all: the 1M-triangle sphere's run (0.1–0.2 s) arrives a few frames later.
constexpr double kFrameWaitForRun = 0.02;

/// A run in steps looks at the clock after this many units of work (a vertex, face or edge each) at
/// first, then adapts (stepJob).
constexpr uint64_t kFirstUnitsPerCheck = 20000;

}  // namespace

void ShownRun::useWorker(std::function<void()> wake) { worker_ = std::make_unique<PipelineWorker>(std::move(wake)); }

void ShownRun::update() {
  const PipelineOptions& o = state_.pipeline;
  const bool same = ranOnce_ && state_.doc.shownRevision() == ranShownRevision_ && o.strategy == ranOptions_.strategy &&
                    o.boundingBoxTest == ranOptions_.boundingBoxTest && o.clipEdges == ranOptions_.clipEdges;
  if (!same) {
    ranOnce_ = true;
    ranShownRevision_ = state_.doc.shownRevision();
    ranOptions_ = o;
    auto scene = std::make_shared<const Scene>(state_.doc.shown());  // shares the meshes: a cheap copy
    job_.reset();  // a run in steps of an older state is dropped (its buffer stays fit for reuse)
    if (stepSeconds_ > 0) {
      try {
        job_ = std::make_unique<Job>(std::move(scene), o, nextRun());
        unitsPerCheck_ = kFirstUnitsPerCheck;
      } catch (const Error& e) {
        state_.runError = e.what();  // the previous run stays
      }
    } else if (worker_) {
      ticket_ = worker_->request(std::move(scene), o);
      pending_ = true;
      askedAt_ = frameNumber_;
    } else {
      // Into the run published before the current one when nothing holds it any more: its buffers
      // are reused (a large scene's arrays are not allocated anew). The render thread may still draw
      // from it: then a new one.
      std::shared_ptr<PipelineRun>& into = nextRun();
      try {
        runPipeline(*scene, o, *into);
        publish(std::move(scene), into);
      } catch (const Error& e) {
        state_.runError = e.what();  // the previous run stays
      }
    }
  }
  // Once a frame: update() runs again in the frame after a change (the session's callback), and
  // the frame's share of time is to be spent once.
  if (job_ && steppedFrame_ != frameNumber_) stepJob();
  if (!pending_) return;
  // Only the frame that asked for the run waits for it, when it is expected in time (a small scene's
  // arrives in it); later frames only look whether it is finished.
  const double expected = 2 * lastSeconds_ + 0.001;
  const double wait = askedAt_ == frameNumber_ && expected <= kFrameWaitForRun ? expected : 0;
  std::optional<PipelineWorker::Finished> done = worker_->take(ticket_, wait);
  if (!done) return;
  lastSeconds_ = done->seconds;
  if (done->run) publish(std::move(done->scene), std::move(done->run));
  else state_.runError = done->error;  // the previous run stays
  if (done->ticket == ticket_) pending_ = false;
}

std::shared_ptr<PipelineRun>& ShownRun::nextRun() {
  std::shared_ptr<PipelineRun>& into = runs_[0] == state_.ran ? runs_[1] : runs_[0];
  if (!into || into.use_count() > 1) into = std::make_shared<PipelineRun>();
  return into;
}

// Steps until the frame's share of time is spent, looking at the clock every unitsPerCheck_ units
// (adapted so that a look comes about every millisecond: a clock read per vertex would cost more
// than the vertex).
void ShownRun::stepJob() {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  const double spent = std::chrono::duration<double>(start - frameStart_).count();
  // A frame left to other work (leaveFrame) leaves the run to the next, which steps whatever it has.
  if (leaveFrame_ && skippedFrame_ + 1 != frameNumber_) skippedFrame_ = frameNumber_;
  if (skippedFrame_ == frameNumber_) return;  // (update() runs again in a frame that changed the scene)
  steppedFrame_ = frameNumber_;
  // What is left of the frame's share, but at least kLeastStepSeconds (or the share, when smaller).
  const double budget = std::max(std::min(kLeastStepSeconds, stepSeconds_), stepSeconds_ - spent);
  for (;;) {
    const Clock::time_point before = Clock::now();
    const bool done = job_->job.step(unitsPerCheck_);
    const double took = std::chrono::duration<double>(Clock::now() - before).count();
    if (took < 0.0005) unitsPerCheck_ = std::min<uint64_t>(unitsPerCheck_ * 2, 1u << 24);
    else if (took > 0.002) unitsPerCheck_ = std::max<uint64_t>(unitsPerCheck_ / 2, 1000);
    if (done) {
      publish(std::move(job_->scene), std::move(job_->into));
      job_.reset();
      return;
    }
    if (std::chrono::duration<double>(Clock::now() - start).count() >= budget) return;
  }
}

std::optional<double> ShownRun::progress() const {
  if (!job_) return std::nullopt;
  return job_->job.progress();
}

void ShownRun::publish(std::shared_ptr<const Scene> scene, std::shared_ptr<const PipelineRun> run) {
  state_.ranScene = std::move(scene);
  state_.ran = std::move(run);
  ++revision_;
  state_.runError.clear();
}

std::optional<double> ShownRun::wakeIn(double busyStep) const {
  if (job_) return 0.0;  // the next step is due in the next frame
  if (!pending_) return std::nullopt;
  return worker_->hasFinished() ? 0.0 : busyStep;
}

}  // namespace vplab
