// Where the viewer's windows go on a display: controls on the left, the world and camera views
// above, the NPC view and the inspector below. Fits a 1280 × 720 projector and laptop screens; the
// user may move and resize them, and the layout is computed again when the display changes size.
#pragma once

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace vplab::ui {

struct Rect {
  ImVec2 pos, size;
};

struct Layout {
  Rect controls, world, camera, npc, inspect;
};

inline Layout computeLayout(ImVec2 display, float menuHeight, float scale) {
  Layout l;
  const float top = menuHeight;
  const float h = display.y - top;
  const float left = std::clamp(display.x * 0.26f, 300.f * scale, 430.f * scale);
  const float rw = display.x - left;
  const float upper = std::floor(h * 0.56f);
  const float wWorld = std::floor(rw * 0.55f);
  l.controls = {{0, top}, {left, h}};
  l.world = {{left, top}, {wWorld, upper}};
  l.camera = {{left + wWorld, top}, {rw - wWorld, upper}};
  l.npc = {{left, top + upper}, {wWorld, h - upper}};
  l.inspect = {{left + wWorld, top + upper}, {rw - wWorld, h - upper}};
  return l;
}

/// Positions the next window: always on a relayout frame, else only the first time.
inline void placeNext(const Rect& r, bool relayout) {
  const ImGuiCond cond = relayout ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
  ImGui::SetNextWindowPos(r.pos, cond);
  ImGui::SetNextWindowSize(r.size, cond);
}

}  // namespace vplab::ui
