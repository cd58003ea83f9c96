// A swipe scrolls a panel (touch_scroll.h).
#include "app/ui/touch_scroll.h"

#include <imgui_internal.h>

#include <algorithm>
#include <cmath>

namespace vplab::ui {

namespace {

// A coast slows as a phone's list does: its speed falls to 1/e in 0.33 s (iOS's "normal"
// deceleration, 0.998 a millisecond), and stops under 20 px/s.
constexpr double kCoastTimeConstant = 0.33;
constexpr float kStopSpeed = 20;
// The finger's speed as it lifts: over its last 80 ms (a few frames; a pause before lifting is no flick).
constexpr double kSpeedWindow = 0.08;

/// The window under the pointer that can scroll, or one of its parents that can (a table in a tab).
ImGuiWindow* scrollableUnder(ImGuiWindow* w) {
  for (; w; w = w->ParentWindow)
    if (w->ScrollMax.x > 0 || w->ScrollMax.y > 0) return w;
  return nullptr;
}

}  // namespace

void TouchScroll::scrollBy(ImVec2 delta) {
  ImGuiWindow* w = ImGui::FindWindowByID(window_);
  if (!w) {
    window_ = 0;
    return;
  }
  ImGui::SetScrollX(w, std::clamp(w->Scroll.x + delta.x, 0.f, w->ScrollMax.x));
  ImGui::SetScrollY(w, std::clamp(w->Scroll.y + delta.y, 0.f, w->ScrollMax.y));
}

void TouchScroll::fingerLifting(ImVec2 velocity) { lifted_ = velocity; }

void TouchScroll::endOfFrame(bool touch, double now) {
  const double dt = std::max(0.0, now - last_);
  last_ = now;
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  const ImGuiIO& io = ImGui::GetIO();
  if (!touch) {
    window_ = 0;
    return;
  }
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    // A press no item took (ActiveId is set by the item pressed, this frame), over a window that scrolls.
    ImGuiWindow* w = g.ActiveId == 0 ? scrollableUnder(g.HoveredWindow) : nullptr;
    window_ = w ? w->ID : 0;
    held_ = window_ != 0;
    framesSinceMove_ = 0;
    lifted_.reset();
    velocity_ = ImVec2(0, 0);
    recent_.clear();
    if (held_) recent_.push_back({now, io.MousePos});
    return;
  }
  if (window_ == 0) return;
  if (held_) {
    const bool moved = io.MouseDelta.x != 0 || io.MouseDelta.y != 0;
    if (moved) {
      scrollBy(ImVec2(-io.MouseDelta.x, -io.MouseDelta.y));  // the content follows the finger
      recent_.push_back({now, io.MousePos});
      while (recent_.size() > 2 && now - recent_.front().time > kSpeedWindow) recent_.pop_front();
    }
    framesSinceMove_ = moved ? 0 : framesSinceMove_ + 1;
    if (io.MouseDown[0]) return;
    // Let go: it coasts at the finger's speed if the finger was still moving: within the last
    // 80 ms, or in the last two frames before it lifted however slow the frames are (a page drawn
    // in software takes 200 ms a frame, and a frame that settles the layout may come between the
    // finger's last move and its lifting).
    held_ = false;
    const Sample& first = recent_.front();
    const Sample& last = recent_.back();
    const double span = last.time - first.time;
    const bool moving = framesSinceMove_ <= 2 || now - last.time < kSpeedWindow;
    velocity_ = moving && span > 0 ? ImVec2(float((first.position.x - last.position.x) / span),
                                            float((first.position.y - last.position.y) / span))
                                   : ImVec2(0, 0);
    if (lifted_) velocity_ = ImVec2(-lifted_->x, -lifted_->y);  // the finger's own speed, from its events' times
    lifted_.reset();
    if (velocity_.x == 0 && velocity_.y == 0) window_ = 0;
    return;
  }
  scrollBy(ImVec2(float(velocity_.x * dt), float(velocity_.y * dt)));
  const float slow = float(std::exp(-dt / kCoastTimeConstant));
  velocity_ = ImVec2(velocity_.x * slow, velocity_.y * slow);
  if (std::hypot(velocity_.x, velocity_.y) < kStopSpeed) {
    velocity_ = ImVec2(0, 0);
    window_ = 0;
  }
}

}  // namespace vplab::ui
