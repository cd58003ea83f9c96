#include "app/ui/input_queue.h"

#include <imgui.h>

#include <algorithm>

namespace vplab {

void InputQueue::mouseMove(double x, double y) { events_.push_back({Event::Kind::move, x, y}); }

void InputQueue::mouseButton(int button, bool down) {
  if (button < 0 || button >= kMouseButtons) return;
  Event e{Event::Kind::button};
  e.code = button;
  e.down = down;
  events_.push_back(e);
}

void InputQueue::wheel(double dx, double dy) { events_.push_back({Event::Kind::wheel, dx, dy}); }

void InputQueue::key(int code, bool down) {
  if (code < 0 || code >= int(IM_ARRAYSIZE(ImGuiIO::KeysDown))) return;  // GLFW_KEY_UNKNOWN is -1
  Event e{Event::Kind::key};
  e.code = code;
  e.down = down;
  events_.push_back(e);
}

void InputQueue::character(unsigned codepoint) {
  Event e{Event::Kind::character};
  e.codepoint = codepoint;
  events_.push_back(e);
}

void InputQueue::focusLost() {
  for (int b = 0; b < kMouseButtons; ++b)
    if (buttons_[b]) mouseButton(b, false);
  for (int k : keysHeld_) key(k, false);
}

void InputQueue::feed(ImGuiIO& io) {
  io.MousePos = ImVec2(mouseX_, mouseY_);
  for (int b = 0; b < kMouseButtons; ++b) io.MouseDown[b] = buttons_[b];
  io.KeyCtrl = ctrl_;
  io.KeyShift = shift_;
  io.KeyAlt = alt_;
  io.KeySuper = super_;

  auto held = [this](int code) {
    return std::find(keysHeld_.begin(), keysHeld_.end(), code) != keysHeld_.end();
  };
  bool transition = false;  // a button or key changed in this frame
  while (!events_.empty()) {
    const Event& e = events_.front();
    switch (e.kind) {
      case Event::Kind::move:
        if (transition) return;
        mouseX_ = float(e.x);
        mouseY_ = float(e.y);
        io.MousePos = ImVec2(mouseX_, mouseY_);
        break;
      case Event::Kind::button:
        if (transition) return;
        transition = true;
        buttons_[e.code] = io.MouseDown[e.code] = e.down;
        break;
      case Event::Kind::wheel:
        io.MouseWheelH += float(e.x);
        io.MouseWheel += float(e.y);
        break;
      case Event::Kind::key:
        if (transition) return;
        transition = true;
        io.KeysDown[e.code] = e.down;
        keysHeld_.erase(std::remove(keysHeld_.begin(), keysHeld_.end(), e.code), keysHeld_.end());
        if (e.down) keysHeld_.push_back(e.code);
        // The modifiers as the keys held say (GLFW key codes), as ImGui 1.86's GLFW backend does:
        // X11's modifier flags of an event are those from before it.
        io.KeyCtrl = ctrl_ = held(341) || held(345);
        io.KeyShift = shift_ = held(340) || held(344);
        io.KeyAlt = alt_ = held(342) || held(346);
        io.KeySuper = super_ = held(343) || held(347);
        break;
      case Event::Kind::character:
        if (e.codepoint > 0 && e.codepoint < 0x110000) io.AddInputCharacter(e.codepoint);
        break;
    }
    events_.pop_front();
  }
}

}  // namespace vplab
