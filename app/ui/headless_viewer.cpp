#include "app/ui/headless_viewer.h"

#include "app/ui/keys.h"
#include "base/error.h"

#include <imgui.h>

namespace vplab {

HeadlessViewer::HeadlessViewer(GlContext& context, Scene scene, int width, int height, float uiScale)
    : viewer_(context, std::move(scene), uiScale), target_(context.gl()), width_(width), height_(height) {
  target_.resize(width, height, 1);
  viewer_.makeCurrent();
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(-1, -1);
  // ImGui's own keys at the codes the window's GLFW backend maps them to (app/ui/keys.h): Tab moves
  // between fields, Enter ends an edit, as in the window.
  io.KeyMap[ImGuiKey_Tab] = keys::kTab;
  io.KeyMap[ImGuiKey_Enter] = keys::kEnter;
  io.KeyMap[ImGuiKey_KeyPadEnter] = keys::kKeypadEnter;
  io.KeyMap[ImGuiKey_Escape] = keys::kEscape;
  io.KeyMap[ImGuiKey_Backspace] = keys::kBackspace;
  io.KeyMap[ImGuiKey_LeftArrow] = keys::kLeft;
  io.KeyMap[ImGuiKey_RightArrow] = keys::kRight;
  io.KeyMap[ImGuiKey_Home] = keys::kHome;
  io.KeyMap[ImGuiKey_End] = keys::kEnd;
  io.KeyMap[ImGuiKey_A] = 'A';
}

void HeadlessViewer::frame() {
  viewer_.makeCurrent();
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(float(width_), float(height_));
  io.DisplayFramebufferScale = ImVec2(1, 1);
  io.DeltaTime = 1.f / 60.f;
  if (inputQueued_) input_.feed(io);
  viewer_.frame(target_.framebuffer(), width_, height_);
  io.MouseWheel = 0;
}

void HeadlessViewer::frames(int n) {
  for (int i = 0; i < n; ++i) frame();
}

void HeadlessViewer::mouseMove(double x, double y) {
  viewer_.makeCurrent();
  ImGui::GetIO().MousePos = ImVec2(float(x), float(y));
}

void HeadlessViewer::mouseButton(int button, bool down) {
  viewer_.makeCurrent();
  ImGui::GetIO().MouseDown[button] = down;
}

void HeadlessViewer::wheel(float steps) {
  viewer_.makeCurrent();
  ImGui::GetIO().MouseWheel = steps;
}

void HeadlessViewer::key(int code, bool ctrl, bool shift) {
  viewer_.makeCurrent();
  ImGuiIO& io = ImGui::GetIO();
  io.KeyCtrl = ctrl;
  io.KeyShift = shift;
  io.KeysDown[code] = true;
  frame();
  io.KeysDown[code] = false;
  frame();
  io.KeyCtrl = io.KeyShift = false;
}

void HeadlessViewer::type(const std::string& text) {
  viewer_.makeCurrent();
  ImGui::GetIO().AddInputCharactersUTF8(text.c_str());
  frame();
}

void HeadlessViewer::drag(double fromX, double fromY, double toX, double toY, int button, int steps) {
  mouseMove(fromX, fromY);
  frame();
  mouseButton(button, true);
  frame();
  for (int i = 1; i <= steps; ++i) {
    mouseMove(fromX + (toX - fromX) * i / steps, fromY + (toY - fromY) * i / steps);
    frame();
  }
  mouseButton(button, false);
  frame();
}

void HeadlessViewer::click(double x, double y, int button) {
  mouseMove(x, y);
  frame();
  mouseButton(button, true);
  frame();
  mouseButton(button, false);
  frame();
}

std::pair<double, double> HeadlessViewer::centreOf(const std::string& id) const {
  const auto& rects = viewer_.rects().rects;
  auto it = rects.find(id);
  if (it == rects.end()) throw Error("no widget \"" + id + "\" was drawn");
  return {it->second.x + it->second.z / 2, it->second.y + it->second.w / 2};
}

}  // namespace vplab
