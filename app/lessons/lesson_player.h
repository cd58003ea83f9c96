// Presenting a lesson (docs/lecturers.md "Lessons"): which step is shown, and the move into it. The viewer
// (app/ui/lesson_presenter.h) asks for the state to show each frame and applies it; this holds no
// UI and no clock of its own (times are the caller's, in seconds).
#pragma once

#include "app/lessons/lesson.h"
#include "app/lessons/lesson_transition.h"

#include <optional>

namespace vplab {

class LessonPlayer {
 public:
  /// Starts at `step` (clamped to the lesson's), shown at once.
  explicit LessonPlayer(Lesson lesson, size_t step = 0);

  const Lesson& lesson() const { return lesson_; }
  /// The step shown, or being moved into.
  size_t step() const { return step_; }
  size_t stepCount() const { return lesson_.steps.size(); }
  const LessonStep& current() const { return lesson_.steps[step_]; }

  /// Moves into `step` (clamped) from `shown`, what the lab shows now (a step's state, or what the
  /// class made of it in a free step), over `seconds` from `now`; 0 seconds: at once. Going to the
  /// step already shown restores its state too.
  void go(size_t step, const LessonState& shown, double now, double seconds);

  /// The state to show at `now`: between `shown` and the step's, eased in and out; the step's own
  /// once the move is over.
  LessonState stateAt(double now) const;
  /// Ends a move at once: the step's own state from now on (an error arose on the way).
  void cut() { seconds_ = 0; }
  /// Whether the move is still under way at `now` (the viewer draws frames until it is over).
  bool moving(double now) const { return now < start_ + seconds_; }
  /// Whether the step's state has been applied once the move ended (the viewer records it once).
  bool settled() const { return settled_; }
  void markSettled() { settled_ = true; }
  /// Whether the step's marks (tab, highlights) have been shown since the move into it began: only
  /// then is the step settled (a lesson opened from the menu late in a frame is not settled before
  /// its first step was ever shown).
  bool marksShown() const { return marksShown_; }
  void markMarksShown() { marksShown_ = true; }

 private:
  Lesson lesson_;
  size_t step_ = 0;
  LessonState from_;
  double start_ = 0, seconds_ = 0;
  bool settled_ = false;
  bool marksShown_ = false;
};

}  // namespace vplab
