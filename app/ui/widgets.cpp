#include "app/ui/widgets.h"

#include <cstdio>

namespace vplab::ui {

void recordRect(ViewerState& s, const char* id) {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  s.rects[id] = ImVec4(a.x, a.y, b.x - a.x, b.y - a.y);
}

bool dragVec3(ViewerState& s, const char* label, const char* id, Vec3& v, float speed) {
  const bool changed = ImGui::DragScalarN(label, ImGuiDataType_Double, &v.x, 3, speed, nullptr, nullptr, "%.3f");
  recordRect(s, id);
  return changed;
}

bool dragDouble(ViewerState& s, const char* label, const char* id, double& v, float speed, double min, double max,
                const char* format) {
  const bool bounded = min < max;
  const bool changed = ImGui::DragScalar(label, ImGuiDataType_Double, &v, speed, bounded ? &min : nullptr,
                                         bounded ? &max : nullptr, format);
  recordRect(s, id);
  return changed;
}

void tooltip(const char* english, const char* german) {
  if (!ImGui::IsItemHovered()) return;
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28);
  ImGui::TextUnformatted(english);
  ImGui::TextDisabled("%s", german);
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

void help(const char* english, const char* german) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  tooltip(english, german);
}

void errorText(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.38f, 0.35f, 1.f));
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

void section(const char* title) {
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextDisabled("%s", title);
}

std::string vecText(const Vec3& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", v.x, v.y, v.z);
  return buf;
}

std::string vecText(const Vec4& v) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g, %.4g)", v.x, v.y, v.z, v.w);
  return buf;
}

}  // namespace vplab::ui
