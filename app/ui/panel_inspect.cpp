// The matrices panel (each stage's 4 × 4 matrix and the composite, live) and the vertex probe
// (one vertex through every stage: MC, WC, VRC, homogeneous NPC, NPC, DC, its boundary coordinates
// and outcode; lecture notes 15.2, Hill 7.4).
#include "app/views/number_text.h"
#include "app/inspect/matrix_text.h"
#include "app/ui/panels.h"
#include "app/ui/widgets.h"

#include "pipeline/clipping.h"

#include <algorithm>
#include <string>
#include <string_view>

namespace vplab::ui {

namespace {

/// A cube plane's name (planeName, English) in the viewer's language; a user plane's as the pipeline
/// names it.
std::string planeLabel(const Widgets& w, int plane) {
  static constexpr text::Text kNames[] = {"left", "right", "bottom", "top", "back", "front"};
  const std::string_view en = planeName(plane);
  for (const text::Text& name : kNames)
    if (name.english() == en) return tr(w, name);
  return std::string(en);
}

void matrixTable(Widgets& w, LecturePart& lec, const char* name, const char* id, const Mat4& m, const char* explanation) {
  ImGui::PushID(id);
  ImGui::TextWrapped("%s", name);
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", explanation);
  ImGui::PopStyleColor();
  const Mat4 shown = lec.seedForm ? glm::transpose(m) : m;
  const double scale = largestEntry(m);
  std::string cells[4][4];
  float widest = 0;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      cells[r][c] = num(shown[c][r], scale);
      widest = std::max(widest, ImGui::CalcTextSize(cells[r][c].c_str()).x);
    }
  // Four columns of the widest entry; in a narrow inspector (a large UI scale) the table's text is
  // made smaller rather than cut off.
  const float needed = 4 * (widest + ImGui::GetStyle().CellPadding.x * 2 + 2);
  const float fontScale = std::clamp(ImGui::GetContentRegionAvail().x / needed, 0.5f, 1.f);
  ImGui::SetWindowFontScale(fontScale);
  // A lesson's step may point at the matrix, a row, a column or an entry of it (in the column-vector
  // form; the row-vector form shows it transposed).
  auto marked = [&](int r, int c) {
    if (lec.seedForm) std::swap(r, c);
    for (const LessonHighlight& h : lec.lessonMarks)
      if (h.kind == LessonHighlight::Kind::matrix && h.matrix == id && (h.row < 0 || h.row == r) && (h.column < 0 || h.column == c))
        return true;
    return false;
  };
  bool anyMarked = false;
  for (int k = 0; k < 16; ++k) anyMarked = anyMarked || marked(k / 4, k % 4);
  if (anyMarked && lec.lessonScroll) {
    ImGui::SetScrollHereY(0.2f);  // the step's matrix comes into sight, once
    lec.lessonScroll = false;
  }
  const ImU32 markColor = ImGui::ColorConvertFloat4ToU32(ImVec4(accentColor().x, accentColor().y, accentColor().z, 0.35f));
  if (ImGui::BeginTable("m", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchSame)) {
    for (int r = 0; r < 4; ++r) {
      ImGui::TableNextRow();
      for (int c = 0; c < 4; ++c) {
        ImGui::TableNextColumn();
        if (marked(r, c)) ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, markColor);
        ImGui::TextUnformatted(cells[r][c].c_str());
      }
    }
    ImGui::EndTable();
  }
  ImGui::SetWindowFontScale(1.f);
  // The buttons wrap onto the next line when the inspector is narrow (a large UI scale).
  const std::string base = std::string("copy.") + id;
  const std::string ids[] = {base + ".text", base + ".markdown", base + ".latex"};
  const char* labels[] = {tr(w, "copy text"), tr(w, "copy Markdown"), tr(w, "copy LaTeX")};
  const MatrixFormat formats[] = {MatrixFormat::plain, MatrixFormat::markdown, MatrixFormat::latex};
  const ImGuiStyle& style = ImGui::GetStyle();
  float x = 0;
  for (int i = 0; i < 3; ++i) {
    const float width = ImGui::CalcTextSize(labels[i]).x + style.FramePadding.x * 2;
    if (i > 0 && x + style.ItemSpacing.x + width <= ImGui::GetContentRegionAvail().x) {
      ImGui::SameLine();
      x += style.ItemSpacing.x;
    } else {
      x = 0;
    }
    copyButton(w, labels[i], ids[i].c_str(), matrixText(m, name, formats[i], lec.seedForm, w.language()));
    x += width;
  }
  for (const std::string& i : ids) copiedNotice(w, i.c_str());
  ImGui::PopID();
  ImGui::Spacing();
}

}  // namespace

void matricesPanel(Widgets& w, const RunPart& r, const EditPart& e, LecturePart& lec) {
  checkbox(tr(w, "the lecture notes' row-vector form (p' = p · M, transposed)"), &lec.seedForm);
  tooltip(w, "The project computes with column vectors (p' = M · p, as GLM). The lecture notes write points "
             "as row vectors; their matrices are the transposes.");
  const PipelineRun& run = r.run();
  Mat4 wcFromMc(1.0);
  std::string objectName = tr(w, "(no object)");
  if (!run.objects.empty()) {
    int k = 0;
    for (size_t i = 0; i < run.sceneIndex.size(); ++i)
      if (int(run.sceneIndex[i]) == e.selectedObject) k = int(i);
    wcFromMc = run.objects[size_t(k)].wcFromMc;
    objectName = nameIn(run.objects[size_t(k)], w.language());
  }
  matrixTable(w, lec, ("wcFromMc — " + objectName).c_str(), "wcFromMc", wcFromMc, tr(w, "stage 1, modeling"));
  matrixTable(w, lec, "vrcFromWc", "vrcFromWc", run.vrcFromWc, tr(w, "stage 2, view orientation"));
  matrixTable(w, lec, "npcFromVrc", "npcFromVrc", run.npcFromVrc,
              tr(w, "stage 3, view mapping (then clip, then ÷ w)"));
  matrixTable(w, lec, "dcFromNpc", "dcFromNpc", run.dcFromNpc, tr(w, "stage 5, device mapping"));
  matrixTable(w, lec, "dcFromMc", "dcFromMc", run.dcFromNpc * run.npcFromVrc * run.vrcFromWc * wcFromMc,
              tr(w, "the composite, right to left"));
}

void probePanel(Widgets& w, const RunPart& r, EditPart& e) {
  scrollAnchor(w, "probe");
  if (!e.probe) {
    ImGui::TextWrapped("%s", tr(w, "Click a vertex in any view to follow it through the pipeline."));
    return;
  }
  const PipelineRun& run = r.run();
  const ObjectRun* o = nullptr;
  for (size_t i = 0; i < run.sceneIndex.size(); ++i)
    if (run.sceneIndex[i] == e.probe->object) o = &run.objects[i];
  if (!o || e.probe->vertex >= o->vertexCount()) {
    ImGui::TextWrapped("%s", tr(w, "The probed vertex is not in the scene any more."));
    return;
  }
  const uint32_t v = e.probe->vertex;
  const Vec4 h = o->npcH[v];
  ImGui::TextUnformatted(tr(w, "{1}, vertex {2}", {nameIn(*o, w.language()), std::to_string(v)}).c_str());
  ImGui::SameLine();
  if (ImGui::SmallButton(tr(w, "clear"))) e.probe.reset();
  // Each space's name, then its coordinates beside it, wrapped at the window's edge between
  // coordinates, never inside a number (ImGui breaks a line after a '.': "6." over "109").
  auto row = [](const char* space, const std::string& value) {
    ImGui::TextDisabled("%s", space);
    size_t start = 0;
    while (start < value.size()) {
      const size_t comma = value.find(", ", start);
      const size_t end = comma == std::string::npos ? value.size() : comma + 1;
      const std::string part = value.substr(start, end - start);
      sameLineIfFits(part.c_str(), false);
      ImGui::TextUnformatted(part.c_str());
      start = comma == std::string::npos ? value.size() : comma + 2;
    }
  };
  row("MC", vecText(o->mesh->positions[v]));
  row("WC", vecText(o->wc(v)));
  row("VRC", vecText(o->vrc(v)));
  row(tr(w, "NPC (homogeneous)"), vecText(h));
  if (h.w > 0) {
    const Vec3 npc = Vec3(h) / h.w;
    row("NPC (÷ w)", vecText(npc));
    row("DC", vecText(Vec3(run.dcFromNpc * Vec4(npc, 1.0))));
  } else {
    row("NPC (÷ w)", tr(w, "w ≤ 0: behind the eye, no image point"));
    row("DC", "—");
  }
  // Blinn's boundary coordinates of the homogeneous point, whatever the strategy (Hill 7.4); the
  // outcode they give first, in binary and as the lecture says it (34), then each coordinate.
  const Boundary bc = boundaryCoordinates(h);
  const Outcode code = outcodeOf(bc);
  section(tr(w, "boundary coordinates (inside when ≥ 0)"));
  std::string bits, names;
  for (int i = kPlaneCount - 1; i >= 0; --i) bits += (code >> i & 1) ? '1' : '0';
  bits += " = " + std::to_string(code & ((1u << kPlaneCount) - 1));
  for (int i = 0; i < kPlaneCount; ++i)
    if (code >> i & 1) names += (names.empty() ? "" : ", ") + planeLabel(w, i);
  const std::string outcode =
      code ? tr(w, "outcode {1}  outside: {2}", {bits, names}) : tr(w, "outcode {1}  inside", {bits});
  ImGui::TextWrapped("%s", outcode.c_str());
  const double bcScale = magnitudeOf({bc[0], bc[1], bc[2], bc[3], bc[4], bc[5], h.w});
  // One line per plane (wrapping in a narrow inspector): the form, its value, the plane.
  static constexpr const char* kForms[] = {"BC0 = x", "BC1 = w − x", "BC2 = y", "BC3 = w − y", "BC4 = z", "BC5 = w − z"};
  for (int i = 0; i < kPlaneCount; ++i) {
    ImGui::TextUnformatted(kForms[i]);
    const std::string value = num(bc[i], bcScale, 5);
    sameLineIfFits(value.c_str(), false);
    ImGui::TextColored(bc[i] < 0 ? outsideColor() : insideColor(), "%s", value.c_str());
    const std::string plane = planeLabel(w, i) + " (" + std::string(planeInequality(i)) + ")";
    sameLineIfFits(plane.c_str(), false);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", plane.c_str());
    ImGui::PopStyleColor();
  }
}

}  // namespace vplab::ui
