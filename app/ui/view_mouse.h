// What the mouse does in a view (docs/lecturers.md "The viewer"): left-drag orbits the observer,
// right- or middle-drag pans, the wheel zooms, a click without motion probes a vertex; in the world
// view the camera's handles (VRP, PRP, the window's edges, the planes) are grabbed and dragged. It
// edits the drag, the probe and the hovered handle, the observers and, through a handle, the document's
// camera. The views' windows (app/ui/view_panes.h) call it with each view's image under the mouse.
#pragma once

#include "app/ui/viewer_state.h"
#include "app/views/view_camera.h"

#include <imgui.h>

namespace vplab {

namespace ui {
/// A click in a view: the left button released where it went down (a drag is no click).
bool viewClicked();
}  // namespace ui

class ViewMouse {
 public:
  explicit ViewMouse(ViewerState& state) : s_(state) {}

  /// Orbit, pan, zoom and probe in `view` (an image of w × h pixels seen through `observer`, the
  /// mouse at `mouse` pixels); `hovered`: the mouse is over its image.
  void orbit(bool hovered, ViewKind view, Orbit& orbit, const ViewCamera& observer, int w, int h, Vec2 mouse);
  /// The world view: a handle under the mouse is hovered, grabbed and dragged; elsewhere as orbit().
  void world(bool hovered, const ViewCamera& observer, int w, int h, Vec2 mouse);
  /// The stage morph: its observer frames the scene by itself, only its angles are dragged.
  void morph(bool hovered);
  /// Where the world view's handles are, in screen units, for the tests (ui::RectLog "handle.vrp", …).
  void recordHandles(ImVec2 origin, const ViewCamera& observer, int w, int h, ImVec2 fbScale);

  /// How near (image pixels) the pointer must be to a handle or a vertex: a mouse's kPickRadiusPx, a
  /// finger's radius on touch (app/ui/touch.h) in the image's pixels.
  double pickRadius() const;

 private:
  ViewerState& s_;
};

/// How near (image pixels) the mouse must be to a vertex to probe it, to a handle to grab it.
inline constexpr double kPickRadiusPx = 9;

}  // namespace vplab
