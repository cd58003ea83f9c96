// Index: 1 controls  2 inspector  3 the compact layout's switcher
#include "app/ui/panel_windows.h"

#include "app/ui/layout.h"
#include "app/ui/panels.h"
#include "app/ui/widgets.h"

#define IMGUI_DEFINE_MATH_OPERATORS
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <tuple>

namespace vplab {

// ---------------------------------------------------------------- 1 controls

void PanelWindows::controls(float scale, bool relayout) {
  const ui::Layout l = ui::currentLayout(s_, scale);
  if (l.compact && s_.compactPanel != ViewerState::controlsPanel) return;
  ui::placeNext(l, l.controls, relayout);
  ImGui::Begin(ui::tr(s_, "Controls###Controls"), nullptr, ui::layoutFlags(l, ImGuiWindowFlags_NoCollapse));
  const Scene& scene = s_.doc.scene();
  // In a lesson the caption box says what to look at (the scene's own caption would leave the panel
  // no room at a projector's scale), in an exercise the Tasks panel.
  if (!s_.lesson && !s_.practice && (!scene.title.empty() || !scene.caption.empty())) {
    ImGui::PushStyleColor(ImGuiCol_Text, ui::accentColor());
    const std::string& title = titleIn(scene, s_.display.language);
    ImGui::TextWrapped("%s", title.empty() ? ui::tr(s_, "Scene") : title.c_str());
    ImGui::PopStyleColor();
    if (const std::string& caption = captionIn(scene, s_.display.language); !caption.empty())
      ImGui::TextWrapped("%s", caption.c_str());
    ImGui::Spacing();
  }
  // The tabs stay in place while their panel scrolls; the status line stays below.
  if (s_.showStepThrough) s_.controlsTab = ViewerState::lectureTab;
  ui::Widgets widgets(s_);
  ui::tabRow(widgets, "controls", {"Camera", "Scene", "Clipping", "Display", "Lecture"}, s_.controlsTab);
  const float wrap = ImGui::GetContentRegionAvail().x;
  float footer = 0;
  for (const std::string* text : {&s_.status, &s_.runError})
    if (!text->empty())
      footer += ImGui::CalcTextSize(text->c_str(), nullptr, false, wrap).y + ImGui::GetStyle().ItemSpacing.y * 2 + 1;
  if (ImGui::BeginChild("panel", ImVec2(0, -footer))) {
    switch (s_.controlsTab) {
      case ViewerState::cameraTab: ui::cameraPanel(widgets, s_, s_, s_); break;
      case ViewerState::sceneTab: ui::scenePanel(widgets, s_, s_, s_, session_.files().fileDialog()); break;
      case ViewerState::clippingTab: ui::clippingPanel(widgets, s_, s_); break;
      case ViewerState::displayTab: ui::displayPanel(widgets, s_, s_, s_); break;
      default: ui::lecturePanel(widgets, s_, s_, s_, s_, s_, s_); break;
    }
  }
  ImGui::EndChild();
  if (!s_.status.empty()) {
    ImGui::Separator();
    if (s_.statusIsError) ui::errorText(s_.status);
    else ImGui::TextWrapped("%s", s_.status.c_str());
  }
  if (!s_.runError.empty()) ui::errorText(s_.runError);
  ImGui::End();
}

// ---------------------------------------------------------------- 2 inspector

void PanelWindows::inspect(float scale, bool relayout) {
  const ui::Layout l = ui::currentLayout(s_, scale);
  if (l.compact && s_.compactPanel != ViewerState::inspectPanel) return;
  ui::placeNext(l, l.inspect, relayout);
  ImGui::Begin(ui::tr(s_, "Inspect###Inspect"), nullptr, ui::layoutFlags(l, ImGuiWindowFlags_NoCollapse));
  // A new probe (a vertex clicked in a view) brings the probe forward; the tabs stay in place while
  // the panel scrolls.
  if (s_.probe && s_.probe != s_.probeShown) s_.inspectTab = ViewerState::probeTab;
  s_.probeShown = s_.probe;
  // An exercise adds its Tasks, brought forward when it opens.
  if (s_.showTasks && s_.practice) s_.inspectTab = ViewerState::tasksTab;
  s_.showTasks = false;
  if (!s_.practice && s_.inspectTab == ViewerState::tasksTab) s_.inspectTab = ViewerState::probeTab;
  ui::Widgets widgets(s_);
  if (s_.practice) ui::tabRow(widgets, "inspect", {"Vertex probe", "Matrices", "Depth", "Tasks"}, s_.inspectTab);
  else ui::tabRow(widgets, "inspect", {"Vertex probe", "Matrices", "Depth"}, s_.inspectTab);
  if (ImGui::BeginChild("panel")) {
    switch (s_.inspectTab) {
      case ViewerState::probeTab: ui::probePanel(widgets, s_, s_); break;
      case ViewerState::matricesTab: ui::matricesPanel(widgets, s_, s_, s_); break;
      case ViewerState::tasksTab: ui::tasksPanel(widgets, s_, session_.exercises(), !l.compact); break;
      default: ui::depthPanel(widgets, s_, s_); break;
    }
  }
  ImGui::EndChild();
  ImGui::End();
}

// ---------------------------------------------------------------- 3 the compact layout's switcher

/// The compact layout's switcher (a phone): the three views, one at a time, and the two panels, each
/// opened and closed again by its button. A probe brings the inspector forward, as on the desktop.
void PanelWindows::compactSwitcher(float scale) {
  const ui::Layout l = ui::currentLayout(s_, scale);
  s_.compactShown = l.compact;
  if (!l.compact) return;
  if (s_.probe && s_.probe != s_.probeShown && s_.compactPanel == ViewerState::noPanel) s_.compactPanel = ViewerState::inspectPanel;
  ImGui::SetNextWindowPos(l.switcher.pos);
  ImGui::SetNextWindowSize(l.switcher.size);
  // Every button on the screen's width: the padding beside the names shrinks to fit a narrow phone
  // (a finger's padding made "Tasks" run off a 390 px screen), down to a few pixels.
  const char* names[] = {ui::tr(s_, "World"), ui::tr(s_, "Camera"), "NPC", ui::tr(s_, "Controls"), ui::tr(s_, "Inspect"),
                         ui::tr(s_, "Tasks")};
  const int buttons = s_.practice ? 6 : 5;
  const ImGuiStyle& style = ImGui::GetStyle();
  float textWidth = 0;
  for (int i = 0; i < buttons; ++i) textWidth += ImGui::CalcTextSize(names[i]).x;
  const float room = l.switcher.size.x - style.WindowPadding.x * 2 - style.ItemSpacing.x * float(buttons + 1) - 1;
  ImVec2 padding = ui::switcherPadding(s_.touch);
  padding.x = std::clamp((room - textWidth) / float(2 * buttons), 2.f, padding.x);
  // Names that do not fit even so (a 320 px phone at a raised UI scale) are set smaller, the
  // buttons keeping their height.
  const float square = std::min(ImGui::GetFrameHeight(), room / float(buttons) - style.ItemSpacing.x);
  auto needed = [&](float fontScale) {
    float sum = 0;
    for (int i = 0; i < buttons; ++i) sum += std::max(ImGui::CalcTextSize(names[i]).x * fontScale + padding.x * 2, square);
    return sum;
  };
  float fontScale = 1;
  while (fontScale > 0.6f && needed(fontScale) > room) fontScale -= 0.05f;
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(padding.x, padding.y + ImGui::GetFontSize() * (1 - fontScale) / 2));
  ImGui::Begin("##switcher", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
  ImGui::SetWindowFontScale(fontScale);
  auto choice = [&](const char* name, const char* id, bool selected) {
    ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(selected ? ImGuiCol_TabActive : ImGuiCol_Tab));
    // At least as wide as tall where the screen has room: "NPC" is a finger's target too.
    const float width = std::max(ImGui::CalcTextSize(name).x + ImGui::GetStyle().FramePadding.x * 2, square);
    const bool pressed = ImGui::Button(name, ImVec2(width, 0));
    ImGui::PopStyleColor();
    ui::recordRect(id);
    ImGui::SameLine();
    return pressed;
  };
  for (const auto& [kind, name, id] : {std::tuple{ViewKind::world, text::Text("World"), "switch.world"},
                                       std::tuple{ViewKind::camera, text::Text("Camera"), "switch.camera"},
                                       std::tuple{ViewKind::npc, text::Text("NPC"), "switch.npc"}})
    if (choice(ui::tr(s_, name), id, s_.compactView == kind)) s_.compactView = kind;
  ImGui::SeparatorEx(ImGuiSeparatorFlags_Vertical);
  ImGui::SameLine();
  for (const auto& [panel, name, id] : {std::tuple{int(ViewerState::controlsPanel), text::Text("Controls"), "switch.controls"},
                                        std::tuple{int(ViewerState::inspectPanel), text::Text("Inspect"), "switch.inspect"}})
    if (choice(ui::tr(s_, name), id, s_.compactPanel == panel && !(s_.practice && s_.inspectTab == ViewerState::tasksTab)))
      s_.compactPanel = s_.compactPanel == panel ? ViewerState::noPanel : panel;
  // An exercise's Tasks: the inspector with its Tasks tab.
  if (s_.practice) {
    const bool tasksShown = s_.compactPanel == ViewerState::inspectPanel && s_.inspectTab == ViewerState::tasksTab;
    if (choice(ui::tr(s_, "Tasks"), "switch.tasks", tasksShown)) {
      s_.compactPanel = tasksShown ? ViewerState::noPanel : ViewerState::inspectPanel;
      s_.inspectTab = ViewerState::tasksTab;
    }
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

}  // namespace vplab
