#include "app/ui/widgets.h"

#include "app/views/number_text.h"

#include <imgui_internal.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <functional>

namespace vplab::ui {

RectLog* rectLog() { return static_cast<RectLog*>(ImGui::GetIO().UserData); }

void recordRect(const char* id) {
  RectLog* log = rectLog();
  if (!log) return;  // a context without a viewer (a test of one widget)
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  log->rects[id] = ImVec4(a.x, a.y, b.x - a.x, b.y - a.y);
  // The draw list's clip rect is the window's visible area, within its parents' (child windows,
  // tables' cells): what of the item can be seen.
  const ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 c0 = draw->GetClipRectMin(), c1 = draw->GetClipRectMax();
  const ImVec2 v0(std::max(a.x, c0.x), std::max(a.y, c0.y)), v1(std::min(b.x, c1.x), std::min(b.y, c1.y));
  log->visible[id] = ImVec4(v0.x, v0.y, std::max(0.f, v1.x - v0.x), std::max(0.f, v1.y - v0.y));
}

void scrollAnchor(Widgets& w, const char* id) {
  if (w.scrollTo != id) return;
  // Over a few frames: a tab just brought forward has not measured its content yet, and ImGui
  // clamps the scroll to the last frame's content.
  ImGui::SetScrollHereY(0.f);
  if (--w.scrollFrames <= 0) w.scrollTo.clear();
}

FingerRows::FingerRows(bool touch) : pushed_(touch) {
  // The style padded every frame to a target's height (setUpStyle): a row as tall as a frame.
  if (pushed_)
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing,
                        ImVec2(ImGui::GetStyle().ItemSpacing.x, ImGui::GetFrameHeight() - ImGui::GetFontSize()));
}

FingerRows::~FingerRows() {
  if (pushed_) ImGui::PopStyleVar();
}

namespace {

/// The ImGui id of component `i` of the drag field `label` with N components (as DragScalarN and
/// DragScalar make them, in the current ID stack).
template <int N>
ImGuiID componentId(const char* label, int i) {
  if (N == 1) return ImGui::GetID(label);
  ImGui::PushID(label);
  ImGui::PushID(i);
  const ImGuiID id = ImGui::GetID("");
  ImGui::PopID();
  ImGui::PopID();
  return id;
}

/// Follows a press on the drag field `group` (`label`, N components): held and not dragged beyond
/// ImGui's drag threshold, then let go, its text opens in the next frame (editInPlace).
template <int N>
void pressedWithoutDrag(WidgetMemory::Pressed& pressed, ImGuiID group, const char* label, bool typing) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool dragged = io.MouseDragMaxDistanceSqr[0] > io.MouseDragThreshold * io.MouseDragThreshold;
  if (ImGui::IsItemActive() && !typing) {
    if (dragged || io.KeyCtrl || !ImGui::IsMouseDown(0)) {  // dragged, Ctrl+click, or reached by keys
      if (pressed.id == group) pressed = {};
      return;
    }
    const ImGuiID active = ImGui::GetActiveID();
    for (int i = 0; i < N; ++i)
      if (componentId<N>(label, i) == active) pressed = {group, i, false};
    return;
  }
  if (pressed.id != group || pressed.open) return;
  if (ImGui::IsItemDeactivated() && !dragged && !typing) pressed.open = true;
  else if (!ImGui::IsItemActive()) pressed = {};
}

// ImGui's drag fields become text fields on Ctrl+click or double-click, and then write the value
// parsed from the text at every keystroke: typing "10" would apply F = 1 first (another camera, maybe
// an invalid one, and an undo step). The field works on a copy instead; while its text is being
// typed, the copy is kept in w.memory.typing and applied once, when the field loses focus (Enter, Tab or a
// click elsewhere); Esc drops it. Dragging writes through at once, as before.
//
// A click or a tap that does not drag opens the text too (issue 41): a field that was tapped takes
// the keys, as in a spreadsheet, so that "8" and Enter typed next go into it and not to a lesson's
// step keys. Dragging still changes the value.
template <int N>
bool editInPlace(Widgets& w, const char* label, double* value, const std::function<bool(double*)>& widget) {
  std::array<double, N> copy;
  std::copy_n(value, N, copy.begin());
  const ImGuiID group = ImGui::GetID("##typing");  // this field's identity (within the panel's ID stack)
  if (w.memory.typing.id == group) std::copy_n(w.memory.typing.values.begin(), N, copy.begin());
  WidgetMemory::Pressed& pressed = w.memory.pressed;
  if (pressed.open && pressed.id == group) {
    ImGui::SetKeyboardFocusHere(pressed.component);  // ImGui opens a drag field's text when it is focused
    pressed = {};
  }
  ImGui::BeginGroup();
  const bool changed = widget(copy.data());
  ImGui::EndGroup();
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  const bool typing = ImGui::IsItemActive() && g.TempInputId != 0 && g.TempInputId == g.ActiveId;
  pressedWithoutDrag<N>(pressed, group, label, typing);
  // A double-click's first click opened the text already; its second selects the whole number, as
  // a double-click on a drag field always did (ImGui's text would select one "word" of "3.000").
  if (typing && ImGui::IsMouseDoubleClicked(0) && ImGui::IsItemHovered())
    if (ImGuiInputTextState* state = ImGui::GetInputTextState(g.ActiveId)) state->SelectAll();
  if (typing) {
    // Ctrl+click from one component's text straight into another's: the first is finished.
    const bool otherField = w.memory.typing.id == group && w.memory.typing.field != g.ActiveId;
    if (changed || w.memory.typing.id != group || otherField) {
      w.memory.typing.id = group;
      w.memory.typing.field = g.ActiveId;
      std::copy_n(copy.begin(), N, w.memory.typing.values.begin());
    }
    if (!otherField) return false;
    const bool differs = !std::equal(copy.begin(), copy.end(), value);
    std::copy_n(copy.begin(), N, value);
    return differs;
  }
  if (w.memory.typing.id == group) {  // the text field closed: commit, unless Esc cancelled it
    w.memory.typing.id = 0;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) return false;
    const bool differs = !std::equal(copy.begin(), copy.end(), value);
    std::copy_n(copy.begin(), N, value);
    return differs;
  }
  if (changed) std::copy_n(copy.begin(), N, value);
  return changed;
}

}  // namespace

void fitLabel(const char* label) {
  const float labelWidth = ImGui::CalcTextSize(label, nullptr, true).x;
  const float spacing = labelWidth > 0 ? ImGui::GetStyle().ItemInnerSpacing.x : 0.f;
  ImGui::SetNextItemWidth(std::max(ImGui::GetFontSize() * 4, ImGui::GetContentRegionAvail().x - labelWidth - spacing));
}

bool dragVec3(Widgets& w, const char* label, const char* id, Vec3& v, float speed) {
  fitLabel(label);
  ImGui::PushID(id);
  const bool changed = editInPlace<3>(w, label, &v.x, [&](double* p) {
    return ImGui::DragScalarN(label, ImGuiDataType_Double, p, 3, speed, nullptr, nullptr, "%.3f");
  });
  ImGui::PopID();
  recordRect(id);
  return changed;
}

bool dragDouble(Widgets& w, const char* label, const char* id, double& v, float speed, double min, double max,
                const char* format) {
  const bool bounded = min < max;
  fitLabel(label);
  ImGui::PushID(id);
  const bool changed = editInPlace<1>(w, label, &v, [&](double* p) {
    return ImGui::DragScalar(label, ImGuiDataType_Double, p, speed, bounded ? &min : nullptr, bounded ? &max : nullptr,
                             format);
  });
  ImGui::PopID();
  recordRect(id);
  return changed;
}

void tabRow(Widgets& w, const char* id, std::initializer_list<text::Text> names, int& current) {
  const ImGuiStyle& style = ImGui::GetStyle();
  ImGui::PushID(id);
  ImGui::PushStyleVar(ImGuiStyleVar_FrameRounding, style.TabRounding);
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(style.ItemInnerSpacing.x, style.ItemInnerSpacing.x));
  float x = 0;
  int i = 0;
  for (const text::Text tab : names) {
    const char* name = tr(w, tab);
    const float width = ImGui::CalcTextSize(name).x + style.FramePadding.x * 2;
    if (i > 0 && x + style.ItemInnerSpacing.x + width <= ImGui::GetContentRegionAvail().x) {
      ImGui::SameLine();
      x += style.ItemInnerSpacing.x;
    } else {
      x = 0;
    }
    const bool selected = i == current;
    ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(selected ? ImGuiCol_TabActive : ImGuiCol_Tab));
    ImGui::PushStyleColor(ImGuiCol_ButtonHovered, ImGui::GetStyleColorVec4(ImGuiCol_TabHovered));
    ImGui::PushStyleColor(ImGuiCol_ButtonActive, ImGui::GetStyleColorVec4(ImGuiCol_TabActive));
    ImGui::PushID(i);  // the same button in either language
    if (ImGui::Button(name)) current = i;
    ImGui::PopID();
    ImGui::PopStyleColor(3);
    recordRect((std::string("tab.") + id + "." + std::string(tab.english())).c_str());
    x += width;
    ++i;
  }
  ImGui::PopStyleVar(2);
  ImGui::PopID();
  ImGui::Separator();
}

namespace {

// The label of a checkbox or radio button after it, wrapped at the window's edge (ImGui's own
// label is one line, cut off in a narrow panel at a large UI scale); hovering it is hovering the box.
void wrappedLabel(const char* label) {
  const char* end = ImGui::FindRenderedTextEnd(label);
  if (end == label) return;
  ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::PushTextWrapPos(0.f);
  ImGui::TextUnformatted(label, end);
  ImGui::PopTextWrapPos();
}

}  // namespace

bool checkbox(const char* label, bool* v) {
  ImGui::PushID(label);
  bool changed = ImGui::Checkbox("##box", v);
  const bool boxHovered = ImGui::IsItemHovered();
  ImGui::PopID();
  wrappedLabel(label);
  if (ImGui::IsItemClicked()) {
    *v = !*v;
    changed = true;
  }
  if (boxHovered) ImGui::SetItemAllowOverlap();
  return changed;
}

bool radio(const char* label, int* v, int value) {
  ImGui::PushID(label);
  bool changed = ImGui::RadioButton("##radio", v, value);
  ImGui::PopID();
  wrappedLabel(label);
  if (ImGui::IsItemClicked() && *v != value) {
    *v = value;
    changed = true;
  }
  return changed;
}

void sameLineIfFits(const char* next, bool button) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float previousEnd = ImGui::GetItemRectMax().x;
  const float width = ImGui::CalcTextSize(next, nullptr, true).x + (button ? style.FramePadding.x * 2 : 0.f);
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (previousEnd + style.ItemSpacing.x + width <= right) ImGui::SameLine();
}


void tooltip(const Widgets& w, text::Text t) {
  if (!ImGui::IsItemHovered()) return;
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28);
  ImGui::TextUnformatted(t.in(w.language()));
  // In English the lecture notes' German follows: the terms the students read in the notes.
  if (w.language() == Language::en) ImGui::TextDisabled("%s", t.in(Language::de));
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

void help(const Widgets& w, text::Text t) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  tooltip(w, t);
}

ImU32 errorColour() { return ImGui::ColorConvertFloat4ToU32(ImVec4(1.f, 0.38f, 0.35f, 1.f)); }

void errorText(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, errorColour());
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

void section(const char* title) {
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", title);
  ImGui::PopStyleColor();
}

std::string vecText(const Vec3& v) { return formatVector(v, 4); }

std::string vecText(const Vec4& v) { return formatVector(v, 4); }

std::string num(double v, double scale, int digits) { return formatNumber(v, {digits, scale}); }

namespace {
constexpr double kCopiedShownSeconds = 2.0;
}

bool copyButton(Widgets& w, const char* label, const char* id, const std::string& text) {
  const bool pressed = ImGui::SmallButton(label);
  recordRect(id);
  if (pressed) {
    ImGui::SetClipboardText(text.c_str());
    w.memory.copied = {id, ImGui::GetTime()};
    // The window draws only on input: keep frames coming until the notice has gone again.
    w.animateUntil = std::max(w.animateUntil, w.memory.copied.at + kCopiedShownSeconds + 0.05);
  }
  return pressed;
}

void copiedNotice(Widgets& w, const char* id) {
  if (w.memory.copied.id != id) return;
  if (ImGui::GetTime() - w.memory.copied.at > kCopiedShownSeconds) {
    w.memory.copied = {};
    return;
  }
  ImGui::SameLine();
  ImGui::TextColored(insideColor(), "%s", tr(w, "copied"));
}

namespace {
bool lightGround() {
  const ImVec4 bg = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
  return bg.x + bg.y + bg.z > 1.5f;
}
}  // namespace

ImVec4 accentColor() { return lightGround() ? ImVec4(0.62f, 0.36f, 0.f, 1.f) : ImVec4(1.f, 0.86f, 0.45f, 1.f); }
ImVec4 insideColor() { return lightGround() ? ImVec4(0.1f, 0.5f, 0.1f, 1.f) : ImVec4(0.55f, 0.9f, 0.5f, 1.f); }
ImVec4 outsideColor() { return lightGround() ? ImVec4(0.75f, 0.1f, 0.08f, 1.f) : ImVec4(1.f, 0.4f, 0.35f, 1.f); }

}  // namespace vplab::ui
