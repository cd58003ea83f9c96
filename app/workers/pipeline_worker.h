// The CPU pipeline on a worker thread (docs/lecturers.md "The viewer": the window never waits for the
// pipeline). A run of the 1M-triangle sphere takes 0.15–0.2 s; in the window's thread every drag of
// a camera field would pause the lecture for that long. The window asks for a run of the shown
// scene and goes on drawing the last run's views; the run arrives a few frames later. The latest
// request replaces one not yet started (the latest camera wins: no queue of stale work).
//
// Runs are published whole as shared_ptr<const PipelineRun>, never copied: the views' render
// thread draws from the same run. The worker runs into a run nobody holds any more, reusing its
// buffers (a large scene's arrays are not allocated anew for every camera).
#pragma once

#include "app/workers/latest_wins.h"
#include "pipeline/pipeline.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace vplab {

class PipelineWorker {
 public:
  /// Starts the thread. `wake` is called on it when a run is finished (glfwPostEmptyEvent).
  explicit PipelineWorker(std::function<void()> wake);
  /// Lets the run under way finish (a run cannot be interrupted), then ends the thread.
  ~PipelineWorker();
  PipelineWorker(const PipelineWorker&) = delete;
  PipelineWorker& operator=(const PipelineWorker&) = delete;

  /// Asks for a run of `scene` (which must be runnable: Document::shown) with `options`; replaces a
  /// request not yet started. Returns its ticket (tickets grow).
  uint64_t request(std::shared_ptr<const Scene> scene, PipelineOptions options);
  /// A finished run and the scene it ran on, or the error that stopped it (run null).
  struct Finished {
    uint64_t ticket = 0;
    std::shared_ptr<const Scene> scene;
    std::shared_ptr<const PipelineRun> run;
    std::string error;
    double seconds = 0;  // how long the run took
  };
  /// The newest run finished since the last call, waiting up to `seconds` for the request `ticket`.
  std::optional<Finished> take(uint64_t ticket, double seconds);
  /// Whether a run is finished and not yet taken (the window then draws a frame at once).
  bool hasFinished() const;
  /// How many runs were made into a new PipelineRun rather than into one given back (tests).
  unsigned allocated() const;

 private:
  struct Request {
    std::shared_ptr<const Scene> scene;
    PipelineOptions options;
  };
  void loop();

  LatestWins<Request, Finished> queue_;
  // Under the queue's lock: how many runs were made anew, and the runs the thread made, run into
  // again once nobody else holds them.
  unsigned allocated_ = 0;
  std::array<std::shared_ptr<PipelineRun>, 3> runs_;
};

}  // namespace vplab
