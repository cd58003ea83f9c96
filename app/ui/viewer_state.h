// Everything the interactive viewer knows between frames, in one owned struct (no globals): the
// GL-free parts of ViewerModel (app/session/viewer_model.h: document, views, run, edit, lecture,
// layout, status) and what the widgets remember from one frame to the next.
#pragma once

#include "app/session/viewer_model.h"

#include <imgui.h>

#include <array>
#include <string>

namespace vplab {

/// What the widgets remember from one frame to the next (ImGui's ids).
struct WidgetMemory {
  struct Typing {
    ImGuiID id = 0;             // the drag field whose text is being typed (0: none)
    ImGuiID field = 0;          // which of its components
    std::array<double, 4> values{};  // its values so far, applied when it loses focus
  } typing;
  // A drag field pressed and let go without dragging opens its text (issue 41: a tapped field takes
  // the keys, so that a digit typed next goes into it and not to the lesson).
  struct Pressed {
    ImGuiID id = 0;             // the drag field held down, not dragged (0: none)
    int component = 0;          // which of its components
    bool open = false;          // let go: its text opens in the next frame
  } pressed;
  struct Copied {
    std::string id;             // the copy button that copied last
    double at = 0;              // when (ImGui time, s)
  } copied;
};

struct ViewerState : ViewerModel {
  explicit ViewerState(Scene scene) : ViewerModel(std::move(scene)) {}
  WidgetMemory widgets;
};

}  // namespace vplab
