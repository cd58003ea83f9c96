// The three views in resizable ImGui windows, and direct manipulation: orbit, pan and zoom the
// observers; drag the scene camera's handles in the world view; click a vertex to probe it.
#include "app/render/cpu_raster.h"
#include "app/image_compare.h"
#include "app/ui/layout.h"
#include "app/ui/picking.h"
#include "app/ui/viewer.h"
#include "app/ui/widgets.h"

#define IMGUI_DEFINE_MATH_OPERATORS
#include <imgui.h>
#include <imgui_internal.h>

namespace vplab {

namespace {

constexpr double kPickRadiusPx = 9;

ImTextureID textureId(GLuint texture) { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture)); }

// An interactive image: an invisible button over the whole region takes the mouse (so dragging in
// a view never moves its window), the view's texture is drawn into it, flipped (GL's rows go up).
bool viewImage(const char* id, GLuint texture, ImVec2 size) {
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  ImGui::GetWindowDrawList()->AddImage(textureId(texture), at, at + size, ImVec2(0, 1), ImVec2(1, 0));
  return ImGui::IsItemHovered();
}

Vec2 mouseIn(ImVec2 itemMin, ImVec2 scale) {
  const ImVec2 m = ImGui::GetIO().MousePos;
  return {(m.x - itemMin.x) * scale.x, (m.y - itemMin.y) * scale.y};
}

}  // namespace

void Viewer::viewWindows() {
  ImGuiIO& io = ImGui::GetIO();
  const ImVec2 fbScale = io.DisplayFramebufferScale;
  const ui::Layout layout = ui::computeLayout(io.DisplaySize, ImGui::GetFrameHeight(), uiScale_);

  // Highlights for this frame's views.
  Highlights& hl = s_.frame.highlights;
  hl = {};
  if (s_.probe) {
    hl.probeWc = probePositionOf(ViewKind::world);
    hl.probeNpc = probePositionOf(ViewKind::npc);
    hl.probeDc = probePositionOf(ViewKind::camera);
  }
  for (Handle handle : kHandles)
    hl.handles.push_back({handlePosition(s_.run, handle), handleName(handle),
                          handle == s_.hovered || (s_.drag.kind == Drag::Kind::handle && s_.drag.handle == handle)});

  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left) && !ImGui::IsMouseDown(ImGuiMouseButton_Right) &&
      !ImGui::IsMouseDown(ImGuiMouseButton_Middle))
    s_.drag = {};

  // ---- world
  ui::placeNext(layout.world, relayout_);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2, 2));
  if (ImGui::Begin("World view (WC)", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoScrollbar)) {
    const ImVec2 size = ImGui::GetContentRegionAvail();
    if (size.x >= 8 && size.y >= 8) {
      const int w = int(size.x * fbScale.x), hgt = int(size.y * fbScale.y);
      world_.resize(w, hgt, 4);
      s_.worldAspect = double(w) / hgt;
      const ViewCamera observer = viewCameraOf(observerCamera(s_.frame.world.orbit, double(w) / hgt));
      renderer_.drawWorld(s_.doc.shown(), s_.run, s_.frame, world_);
      world_.resolve();
      const bool hovered = viewImage("world", world_.colorTexture(), size);
      ui::recordRect(s_, "view.world");
      const ImVec2 at = ImGui::GetItemRectMin();
      const Vec2 mouse = mouseIn(at, fbScale);
      worldInteraction(hovered, observer, w, hgt, mouse);
    }
  }
  ImGui::End();

  // ---- camera
  ui::placeNext(layout.camera, relayout_);
  if (ImGui::Begin("Camera view (DC)", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoScrollbar)) {
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const Device& device = s_.doc.shown().device;
    // Rendered at the device's W × H (pixel-aligned with DC), shown scaled to fit, aspect kept.
    const float fit = std::min(avail.x / device.width, avail.y / device.height);
    if (fit > 0) {
      camera_.resize(device.width, device.height, 1);
      renderer_.drawCamera(s_.doc.shown(), s_.run, s_.frame, camera_);
      GLuint texture = camera_.colorTexture();
      if (s_.frame.overlays.difference) texture = differenceTexture();
      const ImVec2 size(device.width * fit, device.height * fit);
      ImGui::SetCursorPos(ImGui::GetCursorPos() + (avail - size) * 0.5f);
      const bool hovered = viewImage("camera", texture, size);
      ui::recordRect(s_, "view.camera");
      const Vec2 mouse = mouseIn(ImGui::GetItemRectMin(), ImVec2(1, 1));
      if (hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Left) && ImGui::GetMouseDragDelta(0, 0).x == 0 &&
          ImGui::GetMouseDragDelta(0, 0).y == 0) {
        // Picking in the displayed image's pixels; DC positions are scaled to it.
        ViewCamera none;
        s_.probe = pickVertex(s_.run, ViewKind::camera, none, int(size.x), int(size.y), mouse, kPickRadiusPx);
      }
    }
  }
  ImGui::End();

  // ---- NPC
  ui::placeNext(layout.npc, relayout_);
  if (ImGui::Begin("NPC view", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoScrollbar)) {
    const ImVec2 size = ImGui::GetContentRegionAvail();
    if (size.x >= 8 && size.y >= 8) {
      const int w = int(size.x * fbScale.x), hgt = int(size.y * fbScale.y);
      npc_.resize(w, hgt, 4);
      const ViewCamera observer = viewCameraOf(observerCamera(s_.frame.npc.orbit, double(w) / hgt));
      renderer_.drawNpc(s_.doc.shown(), s_.run, s_.frame, npc_);
      npc_.resolve();
      const bool hovered = viewImage("npc", npc_.colorTexture(), size);
      ui::recordRect(s_, "view.npc");
      const Vec2 mouse = mouseIn(ImGui::GetItemRectMin(), fbScale);
      orbitInteraction(hovered, ViewKind::npc, s_.frame.npc.orbit, observer, w, hgt, mouse);
    }
  }
  ImGui::End();
  ImGui::PopStyleVar();
  ctx_.gl().BindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::optional<Vec3> Viewer::probePositionOf(ViewKind view) const {
  return s_.probe ? probePosition(s_.run, *s_.probe, view) : std::nullopt;
}

// Left-drag orbits, right- or middle-drag pans, the wheel zooms; a click without motion probes.
void Viewer::orbitInteraction(bool hovered, ViewKind view, Orbit& orbit, const ViewCamera& observer, int w, int h,
                              Vec2 mouse) {
  ImGuiIO& io = ImGui::GetIO();
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && s_.drag.kind == Drag::Kind::none)
    s_.drag = {Drag::Kind::orbit, view, Handle::none};
  if (hovered && (ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsMouseClicked(ImGuiMouseButton_Middle)))
    s_.drag = {Drag::Kind::pan, view, Handle::none};
  if (s_.drag.view == view) {
    if (s_.drag.kind == Drag::Kind::orbit) orbitBy(orbit, io.MouseDelta.x * 0.4, io.MouseDelta.y * 0.4);
    if (s_.drag.kind == Drag::Kind::pan) panBy(orbit, io.MouseDelta.x / h, io.MouseDelta.y / h);
  }
  if (hovered && io.MouseWheel != 0) zoomBy(orbit, std::pow(0.88, io.MouseWheel));
  if (hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    const ImVec2 d = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.f);
    if (d.x * d.x + d.y * d.y < 4.f) {
      // GetMouseDragDelta is reset on release in 1.86 only after this frame: a click has no motion.
      s_.probe = pickVertex(s_.run, view, observer, w, h, mouse, kPickRadiusPx);
    }
  }
}

void Viewer::worldInteraction(bool hovered, const ViewCamera& observer, int w, int h, Vec2 mouse) {
  s_.hovered = hovered && s_.drag.kind == Drag::Kind::none
                   ? pickHandle(s_.run, observer, w, h, mouse, kPickRadiusPx + 3)
                   : Handle::none;
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && s_.hovered != Handle::none) {
    s_.drag = {Drag::Kind::handle, ViewKind::world, s_.hovered};
  }
  if (s_.drag.kind == Drag::Kind::handle) {
    const ImVec2 d = ImGui::GetIO().MouseDelta;
    if (d.x != 0 || d.y != 0)
      dragHandle(s_.doc.scene().camera, s_.run, s_.drag.handle, observer, h, Vec2(d.x, d.y));
    return;
  }
  orbitInteraction(hovered, ViewKind::world, s_.frame.world.orbit, observer, w, h, mouse);
}

GLuint Viewer::differenceTexture() {
  // The GPU's image against the CPU's clipped polygons filled: differing pixels in magenta.
  const Image gpu = camera_.read();
  const Image cpu = rasterizeClippedPolygons(s_.run, s_.doc.shown().background, gpu.width, gpu.height);
  Image diff = differenceImage(gpu, cpu, 0);
  // Upload bottom row first, as the views' textures are.
  std::vector<Rgba> rows(diff.pixels.size());
  for (int y = 0; y < diff.height; ++y)
    std::copy_n(diff.pixels.begin() + ptrdiff_t(y) * diff.width, diff.width,
                rows.begin() + ptrdiff_t(diff.height - 1 - y) * diff.width);
  const GladGLContext& gl = ctx_.gl();
  if (!differenceTexture_) differenceTexture_ = gl::makeTexture(gl);
  gl.BindTexture(GL_TEXTURE_2D, differenceTexture_.id());
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, diff.width, diff.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return differenceTexture_.id();
}

}  // namespace vplab
