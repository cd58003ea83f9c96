// The views in resizable ImGui windows, and direct manipulation: orbit, pan and zoom the observers;
// drag the scene camera's handles in the world view; click a vertex to probe it; Shift+click a
// polygon in the camera view to step through its clipping. Also the stage morph window and lecture
// mode's full-window view. The images come from ViewImages (app/render/view_images.h), drawn from the
// published run (app/ui/shown_run.h); what the mouse does in them is app/ui/view_mouse.h.
#pragma once

#include "app/context/context.h"
#include "app/render/view_images.h"
#include "app/ui/layout.h"
#include "app/ui/shown_run.h"
#include "app/ui/view_mouse.h"
#include "app/ui/viewer_state.h"

#include <imgui.h>

#include <optional>

namespace vplab {

class ViewPanes {
 public:
  ViewPanes(GlContext& context, ViewerState& state, ViewImages& images, const ShownRun& run)
      : ctx_(context), s_(state), images_(images), run_(run), mouse_(state) {}

  /// A new frame at UI scale `uiScale`; `relayout`: the windows go back to the computed layout.
  void beginFrame(float uiScale, bool relayout) {
    uiScale_ = uiScale;
    relayout_ = relayout;
  }
  /// The world, camera and NPC views in their windows.
  void viewWindows();
  /// The stage morph's window, when shown.
  void morphWindow();
  /// Lecture mode: one view fills the window, no panels; the scene's title and caption at the top.
  void lectureWindow();

 private:
  /// Draws a view for an image of `size` screen units; returns the texture. Reuses the last image
  /// while nothing it shows changed.
  GLuint drawView(ViewKind kind, ImVec2 size);
  /// A spinner and "updating…" in the top right corner of the last item (a view's image) while
  /// `kind` (or the run it shows) is being drawn anew.
  void busyMark(ViewKind kind);
  /// While the edited camera (or scene) is invalid, across the bottom of the last item (a view's
  /// image): that the view shows the last valid one, and why (issue 37: seen where people look).
  void lastValidNote();
  /// While a link's parts were left out (ViewerModel::linkProblems), across the top of the last item
  /// of the first view drawn: each part and why (issue 41: seen on any screen, a phone's too).
  void linkNote();
  std::optional<Vec3> probePositionOf(ViewKind view) const;
  void stepHighlight();
  void cameraWindowContents();
  void worldWindow(const ui::Layout& layout, ImGuiWindowFlags flags, ImVec2 fbScale);
  void npcWindow(const ui::Layout& layout, ImGuiWindowFlags flags, ImVec2 fbScale);
  /// The pixel size of the image of `kind` asked for last (for picking in it).
  int cachedWidth(ViewKind kind) const { return images_.width(kind); }
  int cachedHeight(ViewKind kind) const { return images_.height(kind); }

  GlContext& ctx_;
  ViewerState& s_;
  ViewImages& images_;
  const ShownRun& run_;
  ViewMouse mouse_;
  float uiScale_ = 1.f;
  bool relayout_ = true;
  bool linkNoteDrawn_ = false;  // this frame's link note is in a view already
  int worldFramesDrawn_ = 0;     // the world view's frames so far (its first shape frames the scene)
};

}  // namespace vplab
