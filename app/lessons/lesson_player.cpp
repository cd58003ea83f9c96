#include "app/lessons/lesson_player.h"

#include <algorithm>

namespace vplab {

LessonPlayer::LessonPlayer(Lesson lesson, size_t step) : lesson_(std::move(lesson)) {
  step_ = std::min(step, lesson_.steps.empty() ? 0 : lesson_.steps.size() - 1);
}

void LessonPlayer::go(size_t step, const LessonState& shown, double now, double seconds) {
  step_ = std::min(step, lesson_.steps.size() - 1);
  from_ = shown;
  start_ = now;
  // From or to a state that has no blend (an invalid camera left in a free step): a cut.
  seconds_ = blendable(from_, lesson_.steps[step_].state) ? std::max(0.0, seconds) : 0.0;
  settled_ = false;
  marksShown_ = false;
}

LessonState LessonPlayer::stateAt(double now) const {
  const LessonState& to = lesson_.steps[step_].state;
  if (!moving(now)) return to;
  return stateBetween(from_, to, easeInOut((now - start_) / seconds_));
}

}  // namespace vplab
