// What the mouse does in a view (view_mouse.h).
#include "app/ui/view_mouse.h"

#include "app/inspect/picking.h"
#include "app/ui/touch.h"
#include "app/ui/widgets.h"

#include <imgui.h>

#include <cctype>
#include <cmath>
#include <string>

namespace vplab {

double ViewMouse::pickRadius() const {
  if (!s_.touch) return kPickRadiusPx;
  // In the image's pixels, the framebuffer's.
  return double(ui::fingerPixels(ui::kTouchRadiusPx, s_.uiScale, s_.cssPixel) * ImGui::GetIO().DisplayFramebufferScale.x);
}

// A click: the left button released where it went down.
bool ui::viewClicked() {
  if (!ImGui::IsMouseReleased(ImGuiMouseButton_Left)) return false;
  const ImVec2 d = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.f);
  return d.x * d.x + d.y * d.y < 4.f;
}

// Left-drag orbits, right- or middle-drag pans, the wheel zooms; a click without motion probes.
void ViewMouse::orbit(bool hovered, ViewKind view, Orbit& orbit, const ViewCamera& observer, int w, int h, Vec2 mouse) {
  ImGuiIO& io = ImGui::GetIO();
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && s_.drag.kind == Drag::Kind::none)
    s_.drag = {Drag::Kind::orbit, view, Handle::none};
  if (hovered && (ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsMouseClicked(ImGuiMouseButton_Middle)))
    s_.drag = {Drag::Kind::pan, view, Handle::none};
  // The frame of the press moves nothing: a touch lands far from where the last one lifted, and
  // MouseDelta holds that jump, not a drag.
  const bool pressedNow = ImGui::IsMouseClicked(ImGuiMouseButton_Left) || ImGui::IsMouseClicked(ImGuiMouseButton_Right) ||
                          ImGui::IsMouseClicked(ImGuiMouseButton_Middle);
  if (s_.drag.view == view && !pressedNow) {
    if (s_.drag.kind == Drag::Kind::orbit) orbitBy(orbit, io.MouseDelta.x * 0.4, io.MouseDelta.y * 0.4);
    if (s_.drag.kind == Drag::Kind::pan) panBy(orbit, io.MouseDelta.x / std::min(w, h), io.MouseDelta.y / std::min(w, h));
  }
  if (hovered && io.MouseWheel != 0) zoomBy(orbit, std::pow(0.88, io.MouseWheel));
  if (hovered && ui::viewClicked() && view != ViewKind::morph) s_.probe = pickVertex(s_.run(), view, observer, w, h, mouse, pickRadius());
}

void ViewMouse::morph(bool hovered) {
  // The morph's observer frames the scene by itself: only its angles are dragged.
  ImGuiIO& io = ImGui::GetIO();
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) s_.drag = {Drag::Kind::orbit, ViewKind::morph, Handle::none};
  if (s_.drag.view == ViewKind::morph && s_.drag.kind == Drag::Kind::orbit && !ImGui::IsMouseClicked(ImGuiMouseButton_Left))
    orbitBy(s_.display.morphing.orbit, io.MouseDelta.x * 0.4, io.MouseDelta.y * 0.4);
}

// Where the world view's handles are, in screen units (ui::RectLog "handle.vrp", "handle.prp",
// "handle.xmin", …, "handle.front-f"): the UI tests and the browser tests grab them there.
void ViewMouse::recordHandles(ImVec2 origin, const ViewCamera& observer, int w, int h, ImVec2 fbScale) {
  const float r = float(pickRadius()) / fbScale.x;
  for (Handle handle : kHandles) {
    const Projected p = projectToPixels(observer, handlePosition(s_.run(), handle), w, h);
    if (!p.visible) continue;
    std::string id = std::string("handle.") + handleName(handle);
    for (char& c : id) c = c == ' ' ? '-' : char(std::tolower(static_cast<unsigned char>(c)));
    const float x = origin.x + float(p.pixel.x) / fbScale.x, y = origin.y + float(p.pixel.y) / fbScale.y;
    if (ui::RectLog* log = ui::rectLog()) log->rects[id] = ImVec4(x - r, y - r, 2 * r, 2 * r);
  }
}

void ViewMouse::world(bool hovered, const ViewCamera& observer, int w, int h, Vec2 mouse) {
  s_.hovered = hovered && s_.drag.kind == Drag::Kind::none
                   ? pickHandle(s_.run(), observer, w, h, mouse, pickRadius() + 3)
                   : Handle::none;
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && s_.hovered != Handle::none)
    s_.drag = {Drag::Kind::handle, ViewKind::world, s_.hovered};
  if (s_.drag.kind == Drag::Kind::handle) {
    const ImVec2 d = ImGui::GetIO().MouseDelta;
    if ((d.x != 0 || d.y != 0) && !ImGui::IsMouseClicked(ImGuiMouseButton_Left))  // as orbit()
      dragHandle(s_.doc.scene().camera, s_.run(), s_.drag.handle, observer, h, Vec2(d.x, d.y),
                 s_.keepAspect ? std::optional(s_.doc.scene().device.aspect()) : std::nullopt);
    return;
  }
  orbit(hovered, ViewKind::world, s_.display.world.orbit, observer, w, h, mouse);
}

}  // namespace vplab
