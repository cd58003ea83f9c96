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
