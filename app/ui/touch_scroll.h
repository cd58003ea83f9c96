// A swipe scrolls a panel, as on every phone (issue 41): where the last pointer was a finger, a drag
// that begins on no widget (a label, a table's text, a panel's empty space) scrolls the window under
// it, the nearest one that can scroll; let go while moving, it coasts and slows down (inertia). A
// drag that begins on a field, a button or a view is theirs: a field is still edited by dragging it.
// ImGui 1.86 scrolls only by the wheel and the scrollbar, which a finger hardly hits.
#pragma once

#include <imgui.h>

#include <deque>
#include <optional>

namespace vplab::ui {

class TouchScroll {
 public:
  /// After every window of the frame was submitted (so that a press an item took is known), with
  /// the frame's time in seconds: starts, follows and ends a swipe, and coasts after it. `touch`:
  /// the last pointer was a finger (ViewerModel::touch); with a mouse nothing happens.
  void endOfFrame(bool touch, double now);
  /// The finger lifts moving at `velocity` (pixels a second, measured by the input's own clock: a
  /// page drawn in software sees a flick over only a frame or two, and frame times would say it
  /// was slow). Without it the speed is estimated from the frames that saw the finger move.
  void fingerLifting(ImVec2 velocity);
  /// Still coasting: the window wants frames until it stops.
  bool moving() const { return window_ != 0 && !held_ && (velocity_.x != 0 || velocity_.y != 0); }

 private:
  struct Sample {
    double time;
    ImVec2 position;
  };
  void scrollBy(ImVec2 delta);
  ImGuiID window_ = 0;       // the window being scrolled (0: none)
  bool held_ = false;        // the finger is still down
  int framesSinceMove_ = 0;  // frames since the finger last moved
  ImVec2 velocity_{0, 0};    // px/s while coasting
  double last_ = 0;          // the last frame's time
  std::deque<Sample> recent_;  // the finger's last positions, for its speed as it lifts
  std::optional<ImVec2> lifted_;  // the lifting finger's speed, told by the input (fingerLifting)
};

}  // namespace vplab::ui
