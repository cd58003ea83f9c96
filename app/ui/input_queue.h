// Input events queued between frames and handed to ImGui a frame at a time. Dear ImGui 1.86 reads
// input as state (is the button down now?), so a press and its release arriving within one frame
// (a fast tap on a touchpad, a quick key stroke while a frame is slow) would cancel out and the
// click be lost. The queue gives ImGui at most one transition of any button or key per frame and
// keeps the rest for the next frames, as ImGui 1.87's own input queue does ("input trickling").
// The GLFW callbacks (run_viewer.cpp) and the tests push events; no GLFW header is needed.
#pragma once

#include <cstddef>
#include <deque>

struct ImGuiIO;

namespace vplab {

class InputQueue {
 public:
  static constexpr int kMouseButtons = 5;

  void mouseMove(double x, double y);
  void mouseButton(int button, bool down);
  void wheel(double dx, double dy);
  /// A key (GLFW key code = ImGui 1.86 KeysDown index, see keys.h); Ctrl, Shift, Alt and Super
  /// count as held while their keys are down.
  void key(int code, bool down);
  void character(unsigned codepoint);
  /// The window lost the focus: every button and key held is released (their releases go elsewhere).
  void focusLost();

  bool empty() const { return events_.empty(); }
  size_t pending() const { return events_.size(); }

  /// Writes the input state (mouse position, buttons, keys) into `io`, then applies this frame's
  /// share of the queued events: everything up to the second button or key transition, and no
  /// mouse motion after a button transition (the click happens where the button went down).
  void feed(ImGuiIO& io);

 private:
  struct Event {
    enum class Kind { move, button, wheel, key, character } kind;
    double x = 0, y = 0;  // move: position; wheel: offsets
    int code = 0;         // button or key
    bool down = false;
    unsigned codepoint = 0;
  };
  std::deque<Event> events_;
  // The state as of the last applied event (ImGui's GLFW backend overwrites io's every frame).
  float mouseX_ = -1e30f, mouseY_ = -1e30f;
  bool buttons_[kMouseButtons] = {};
  bool ctrl_ = false, shift_ = false, alt_ = false, super_ = false;
  std::deque<int> keysHeld_;
};

}  // namespace vplab
