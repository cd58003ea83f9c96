// The CPU pipeline's run of the shown scene (docs/lecturers.md "The viewer"). It runs again only when the
// shown scene (Document::shownRevision) or the options changed: frames drawn for hover and ImGui's settling
// cost none. Headless (the UI tests, `vplab render --view ui`) it runs in the frame that needs it; in
// the window on a worker thread (app/workers/pipeline_worker.h), so the window never waits for the
// pipeline; in the page, which has no threads, in steps across frames (PipelineJob), a few ms of
// each frame. A finished run is published whole into the viewer's state with the scene it ran on
// (ViewerState::ran, ranScene), never copied.
#pragma once

#include "app/workers/pipeline_worker.h"
#include "app/ui/viewer_state.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

namespace vplab {

class ShownRun {
 public:
  /// Runs `state`'s shown scene with its options into state.ran.
  explicit ShownRun(ViewerState& state) : state_(state) {}

  /// Runs the pipeline on a worker thread from now on: the frame that changed the scene waits a few ms
  /// for its run (a small scene's arrives in it), later frames show the last run until the new one is
  /// finished. `wake` wakes the window's event wait (called on the worker). Without it (headless, the
  /// UI tests) the pipeline runs in the frame that needs it.
  void useWorker(std::function<void()> wake);
  /// Runs the pipeline in steps from now on, spending what is left of `secondsPerFrame` from the
  /// frame's start on it, at least kLeastStepSeconds (a small scene's run still completes in the frame
  /// that asks for it; a frame that opened a scene leaves the run little; issue 42).
  void runInSteps(double secondsPerFrame) { stepSeconds_ = secondsPerFrame; }
  static constexpr double kLeastStepSeconds = 0.004;
  /// A new frame: the frame that asks for a run may wait a little for it.
  void beginFrame() {
    ++frameNumber_;
    frameStart_ = std::chrono::steady_clock::now();
    leaveFrame_ = false;
  }
  /// In steps: this frame has other long work (a view's list put off to it): the run takes no step in
  /// it, unless it took none in the frame before either.
  void leaveFrame() { leaveFrame_ = true; }
  /// Runs, or asks the worker for, a run when the shown scene or the options changed; publishes a
  /// finished one. A failed run leaves the last one and says why in state.runError.
  void update();

  /// Counts the runs published: what a view's image was drawn from.
  unsigned revision() const { return revision_; }
  /// Whether a run is under way on the worker or in steps (the views show the last one meanwhile).
  bool pending() const { return pending_ || job_ != nullptr; }
  /// How far the run under way in steps is, from 0 to 1 (nothing when none is).
  std::optional<double> progress() const;
  /// Seconds until the window should draw again for the run: 0 when the worker has finished one,
  /// `busyStep` while it works, else nothing.
  std::optional<double> wakeIn(double busyStep) const;

 private:
  void publish(std::shared_ptr<const Scene> scene, std::shared_ptr<const PipelineRun> run);
  /// The run buffer to run into next: not the one shown, and held by nobody else.
  std::shared_ptr<PipelineRun>& nextRun();
  void stepJob();

  ViewerState& state_;
  // In the frame: the runs, state_.ran one of them; the other is run into next, reusing its
  // buffers, when nothing else (the render thread) still holds it.
  std::array<std::shared_ptr<PipelineRun>, 2> runs_;
  std::unique_ptr<PipelineWorker> worker_;
  unsigned revision_ = 0;
  unsigned ranShownRevision_ = 0;  // the shown scene's revision of the last run asked for
  PipelineOptions ranOptions_;     // ... and its options
  bool ranOnce_ = false;
  uint64_t ticket_ = 0;            // the worker's run asked for last
  uint64_t askedAt_ = 0;           // the frame that asked for it
  uint64_t frameNumber_ = 0;
  std::chrono::steady_clock::time_point frameStart_;
  bool pending_ = false;
  double lastSeconds_ = 0;         // how long the worker's last run took
  // In steps: the run under way, the scene it runs and the buffer it runs into (nextRun's).
  double stepSeconds_ = 0;         // 0: not in steps
  struct Job {
    std::shared_ptr<const Scene> scene;
    std::shared_ptr<PipelineRun> into;
    PipelineJob job;
    Job(std::shared_ptr<const Scene> s, const PipelineOptions& o, std::shared_ptr<PipelineRun> r)
        : scene(std::move(s)), into(std::move(r)), job(*scene, o, *into) {}
  };
  std::unique_ptr<Job> job_;
  uint64_t unitsPerCheck_ = 0;  // units of work between two looks at the clock
  uint64_t steppedFrame_ = 0;   // the frame that spent its share on the run in steps
  uint64_t skippedFrame_ = 0;   // the last frame left to other work (leaveFrame) with no step
  bool leaveFrame_ = false;
};

}  // namespace vplab
