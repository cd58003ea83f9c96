// The CPU pipeline's run of the shown scene (README "The viewer"). It runs again only when the shown
// scene (Document::shownRevision) or the options changed: frames drawn for hover and ImGui's settling
// cost none. Headless (the UI tests, `vplab render --view ui`) it runs in the frame that needs it; in
// the window on a worker thread (app/core/pipeline_worker.h), so the window never waits for the
// pipeline. A finished run is published whole into the viewer's state with the scene it ran on
// (ViewerState::ran, ranScene), never copied.
#pragma once

#include "app/core/pipeline_worker.h"
#include "app/ui/viewer_state.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

namespace vplab {

class ShownRun {
 public:
  /// Runs `state`'s shown scene with its options into state.ran.
  explicit ShownRun(ViewerState& state) : state_(state) {}

  /// Runs the pipeline on a worker thread from now on; `wake` wakes the window's event wait (called
  /// on the worker).
  void useWorker(std::function<void()> wake);
  /// A new frame: the frame that asks for a run may wait a little for it.
  void beginFrame() { ++frameNumber_; }
  /// Runs, or asks the worker for, a run when the shown scene or the options changed; publishes a
  /// finished one. A failed run leaves the last one and says why in state.runError.
  void update();

  /// Counts the runs published: what a view's image was drawn from.
  unsigned revision() const { return revision_; }
  /// Whether a run is under way on the worker (the views show the last one meanwhile).
  bool pending() const { return pending_; }
  /// Seconds until the window should draw again for the run: 0 when the worker has finished one,
  /// `busyStep` while it works, else nothing.
  std::optional<double> wakeIn(double busyStep) const;

 private:
  void publish(std::shared_ptr<const Scene> scene, std::shared_ptr<const PipelineRun> run);

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
  bool pending_ = false;
  double lastSeconds_ = 0;         // how long the worker's last run took
};

}  // namespace vplab
