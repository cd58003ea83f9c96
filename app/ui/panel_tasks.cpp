// The Tasks panel (issue 40): an exercise's sheet beside the views, in the UI's language: the given
// data, each task with its points and a field wherever the answer has a value (4 × 4 grids, vectors,
// a polygon's vertices, an outcode's bits), Check and what it found, Hand in. Every field is reached
// with Tab in the sheet's order and filled from the keyboard (the first takes the keys when the
// exercise opens); Ctrl+Enter checks.
// Index: 1 the fields  2 the verdicts  3 the panel
#include "app/practice/practice.h"
#include "app/session/exercises.h"
#include "app/ui/panels.h"
#include "app/ui/widgets.h"
#include "course/grade_report.h"

#include <imgui_stdlib.h>

#include <algorithm>
#include <string>
#include <string_view>

namespace vplab::ui {

namespace {

// ---------------------------------------------------------------- 1 the fields

/// The frame of a field: red while what is typed cannot be read, else Check's verdict (while the
/// fields are as checked).
ImVec4 verdictColour(FieldVerdict v) {
  switch (v) {
    case FieldVerdict::right: return insideColor();
    case FieldVerdict::follows: return ImVec4(0.95f, 0.75f, 0.2f, 1.f);
    case FieldVerdict::rounded: return ImVec4(0.95f, 0.75f, 0.2f, 1.f);
    case FieldVerdict::wrong:
    case FieldVerdict::unreadable: return ImGui::ColorConvertU32ToFloat4(errorColour());
    default: return ImVec4(0, 0, 0, 0);
  }
}

/// One field: its text as typed, in the font scaled by `fontScale`. Returns whether it changed.
bool field(Widgets& w, PracticePart& p, ItemFields& f, int row, int column, float width, float fontScale = 1.f) {
  std::string& text = f.text(row, column);
  const std::string path = f.path(row, column);
  FieldVerdict verdict = FieldVerdict::unchecked;
  if (!readableField(f.kind, normalizedField(text))) verdict = FieldVerdict::unreadable;
  else if (p.check && p.check->edits == p.practice->edits && !text.empty()) verdict = fieldVerdict(*p.check, f, row, column);
  const ImVec4 frame = verdictColour(verdict);
  const bool framed = frame.w > 0;
  if (framed) {
    ImGui::PushStyleVar(ImGuiStyleVar_FrameBorderSize, 2.f);
    ImGui::PushStyleColor(ImGuiCol_Border, frame);
  }
  ImGui::SetNextItemWidth(width);
  if (fontScale != 1.f) ImGui::SetWindowFontScale(fontScale);
  const bool changed = ImGui::InputText(("##" + path).c_str(), &text, ImGuiInputTextFlags_AutoSelectAll);
  if (fontScale != 1.f) ImGui::SetWindowFontScale(1.f);
  recordRect(("task" + path).c_str());
  if (framed) {
    ImGui::PopStyleColor();
    ImGui::PopStyleVar();
  }
  if (verdict == FieldVerdict::unreadable && ImGui::IsItemHovered())
    ImGui::SetTooltip("%s", f.kind == FieldKind::outcode ? tr(w, "six bits (010010) or a whole number from 0 to 63")
                                                         : tr(w, "a number: 0.6, 0,6 or a fraction such as -3/5"));
  if (text.size() > kMaxFieldText) text.resize(kMaxFieldText);
  return changed;
}

/// The fields of one item, shaped as its value: a row of a vector, a grid, a polygon's vertex rows.
bool itemFields(Widgets& w, PracticePart& p, ItemFields& f) {
  bool changed = false;
  const float unit = ImGui::GetFontSize();
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float avail = ImGui::GetContentRegionAvail().x;
  // A cell wide enough for "-301/80" where there is room, never less than four digits.
  auto cellWidth = [&](int columns, float label) {
    return std::clamp((avail - label - spacing * float(columns)) / float(columns), unit * 3.2f, unit * 5.5f);
  };
  // A number wider than its field is drawn in a smaller font rather than cut off at the field's edge
  // (the cut-off rule; a 6-decimal "-0,333333" in a 4-column grid at a projector's scale), as the
  // matrices panel shrinks a wide table.
  const int columns = f.kind == FieldKind::number || f.kind == FieldKind::outcode ? 1 : f.columns;
  const float cell = cellWidth(columns, f.kind == FieldKind::polygon ? ImGui::CalcTextSize("P16").x + spacing : 0);
  float widest = 0;
  for (const std::string& t : f.texts) widest = std::max(widest, ImGui::CalcTextSize(t.c_str()).x);
  widest += ImGui::GetStyle().FramePadding.x * 2 + 2;
  const float fontScale = widest > cell ? std::max(0.55f, cell / widest) : 1.f;
  ImGui::PushID(f.item.path.c_str());
  switch (f.kind) {
    case FieldKind::number:
    case FieldKind::outcode:
      changed |= field(w, p, f, 0, 0, cellWidth(1, 0) * (f.kind == FieldKind::outcode ? 1.2f : 1.f), fontScale);
      if (f.kind == FieldKind::outcode) {  // the bits' planes, wrapped below the field (a phone's width)
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s", tr(w, "bits: front back top bottom right left"));
        ImGui::PopStyleColor();
      }
      break;
    case FieldKind::vector:
    case FieldKind::matrix:
      for (int r = 0; r < f.rows; ++r)
        for (int c = 0; c < f.columns; ++c) {
          if (c > 0) ImGui::SameLine();
          changed |= field(w, p, f, r, c, cellWidth(f.columns, 0), fontScale);
        }
      break;
    case FieldKind::polygon: {
      // The vertex count is part of the answer: typed (Tab reaches it) or stepped with − and +.
      int rows = f.rows;
      ImGui::AlignTextToFramePadding();
      ImGui::TextUnformatted(tr(w, "vertices"));
      ImGui::SameLine();
      ImGui::SetNextItemWidth(unit * 6);
      if (ImGui::InputInt("##vertices", &rows, 1, 1)) {
        f.setRows(rows);
        changed = true;
      }
      recordRect(("task" + f.item.path + "/count").c_str());
      const float label = ImGui::CalcTextSize("P16").x + spacing;
      for (int r = 0; r < f.rows; ++r) {
        ImGui::AlignTextToFramePadding();
        ImGui::Text("P%d", r + 1);
        ImGui::SameLine(label);
        for (int c = 0; c < f.columns; ++c) {
          if (c > 0) ImGui::SameLine();
          changed |= field(w, p, f, r, c, cellWidth(f.columns, label), fontScale);
        }
      }
      break;
    }
  }
  ImGui::PopID();
  return changed;
}

// ---------------------------------------------------------------- 2 the verdicts

/// "2 of 2 points" and what Check said of the item, in its colour.
void itemVerdict(const GradeCase& c) {
  const ImVec4 colour = c.passed ? insideColor() : ImGui::ColorConvertU32ToFloat4(errorColour());
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  ImGui::TextWrapped("%s", c.message.c_str());
  ImGui::PopStyleColor();
  // The report's "… and 2 more": the panel draws no ellipsis glyph (the cut-off rule reads one as text
  // shortened).
  for (const std::string& d : c.details) {
    const std::string_view shown = std::string_view(d).starts_with("\u2026 ") ? std::string_view(d).substr(4) : std::string_view(d);
    ImGui::TextWrapped("  %.*s", int(shown.size()), shown.data());
  }
}

void checkSummary(Widgets& w, const PracticePart& p) {
  const GradeReport& r = p.check->report;
  section(tr(w, "Check"));
  const std::string points = tr(w, "{1} of {2} points", {num(r.points), num(r.maxPoints)});
  ImGui::PushStyleColor(ImGuiCol_Text, r.passed ? insideColor() : ImGui::ColorConvertU32ToFloat4(errorColour()));
  ImGui::TextWrapped("%s · %s", points.c_str(), r.passed ? tr(w, "passed") : tr(w, "not passed yet"));
  ImGui::PopStyleColor();
  recordRect("task.points");
  for (const std::string& line : r.diagnosis) ImGui::TextWrapped("%s", line.c_str());
  if (p.check->edits != p.practice->edits) ImGui::TextDisabled("%s", tr(w, "changed since: Check again"));
}

// ---------------------------------------------------------------- 3 the panel

/// "1 point", "2 points", "1,5 Punkte" (a German decimal comma).
std::string pointsText(Widgets& w, double x) {
  if (x == 1) return tr(w, "1 point");
  std::string n = num(x);
  if (w.language() == Language::de) std::replace(n.begin(), n.end(), '.', ',');
  return tr(w, "{1} points", {n});
}

const char* topicName(Widgets& w, ExerciseTopic t) {
  static constexpr text::Text kNames[] = {"orientation", "mapping", "clipping", "pipeline"};
  return tr(w, kNames[size_t(t)]);
}

const char* projectionName(Widgets& w, Projection p) {
  static constexpr text::Text kNames[] = {"perspective", "parallel", "oblique"};
  return tr(w, kNames[size_t(p)]);
}

void given(Widgets& w, const Practice& practice) {
  if (!ImGui::CollapsingHeader(tr(w, "Given###given"), ImGuiTreeNodeFlags_DefaultOpen)) return;
  for (const std::string& line : givenLines(practice, w.language())) {
    ImGui::Bullet();
    ImGui::TextWrapped("%s", line.c_str());
  }
}

void legend(Widgets& w) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.35f, 0.85f, 1.f));
  ImGui::TextWrapped("%s", tr(w, "In the views, your numbers are drawn in this colour: points as dots, polygons and "
                                 "the view volume dashed."));
  ImGui::PopStyleColor();
}

}  // namespace

void tasksPanel(Widgets& w, PracticePart& p, Exercises& exercises, bool mayFocus) {
  if (!p.practice) {
    ImGui::TextWrapped("%s", tr(w, "No exercise is open: File > Open exercise…, or a link #exercise=…"));
    return;
  }
  Practice& practice = *p.practice;
  if (practice.language != w.language()) setPracticeLanguage(practice, w.language());
  ImGui::PushStyleColor(ImGuiCol_Text, accentColor());
  const std::string title = tr(w, "Exercise {1} ({2}, {3})", {std::to_string(practice.ref.spec.seed), topicName(w, practice.ref.spec.topic),
                                                             projectionName(w, practice.ref.spec.projection)});
  ImGui::TextWrapped("%s", title.c_str());
  ImGui::PopStyleColor();
  if (!practice.ref.studentId.empty()) ImGui::TextWrapped("%s", tr(w, "your own variant, for {1}", {practice.ref.studentId}).c_str());
  given(w, practice);
  legend(w);
  const bool checked = p.check && p.check->edits == practice.edits;
  size_t index = 0;
  for (size_t t = 0; t < practice.tasks.size(); ++t) {
    const ExerciseTask& task = practice.tasks[t];
    section((std::to_string(t + 1) + ". " + pointsText(w, points(task))).c_str());
    ImGui::TextWrapped("%s", plainMath(task.text).c_str());
    for (size_t i = 0; i < task.items.size() && index < practice.fields.size(); ++i, ++index) {
      ItemFields& f = practice.fields[index];
      ImGui::Spacing();
      ImGui::TextWrapped("%s (%s)", f.item.title.c_str(), pointsText(w, f.item.points).c_str());
      // Opened, the exercise is typed into at once: the keyboard alone reaches every field.
      if (index == 0 && p.focusFirstField) {
        if (mayFocus) {
          ImGui::SetWindowFocus();  // Tab moves within the focused window: the Tasks', not the one clicked last
          ImGui::SetKeyboardFocusHere();
        }
        p.focusFirstField = false;
      }
      if (itemFields(w, p, f)) ++practice.edits;
      if (checked && index < p.check->report.cases.size()) itemVerdict(p.check->report.cases[index]);
    }
  }
  ImGui::Spacing();
  ImGui::Separator();
  const bool ctrlEnter = ImGui::GetIO().KeyCtrl && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)) &&
                         ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows);
  if (ImGui::Button(tr(w, "Check (Ctrl+Enter)")) || ctrlEnter) exercises.check();
  recordRect("task.check");
  sameLineIfFits(tr(w, "Hand in"));
  if (ImGui::Button(tr(w, "Hand in"))) exercises.handIn();
  recordRect("task.handIn");
  sameLineIfFits(tr(w, "Close the exercise"));
  if (ImGui::Button(tr(w, "Close the exercise"))) {
    exercises.close();
    return;
  }
  if (p.check) checkSummary(w, p);
}

}  // namespace vplab::ui
