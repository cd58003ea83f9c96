// The matrices panel (each stage's 4 × 4 matrix and the composite, live) and the vertex probe
// (one vertex through every stage: MC, WC, VRC, homogeneous NPC, NPC, DC, its boundary coordinates
// and outcode; seed 15.2, seed 002).
#include "app/ui/matrix_text.h"
#include "app/ui/panels.h"
#include "app/ui/widgets.h"

#include "pipeline/clipping.h"

namespace vplab::ui {

namespace {

void matrixTable(ViewerState& s, const char* name, const char* id, const Mat4& m, const char* explanation) {
  ImGui::PushID(id);
  ImGui::TextUnformatted(name);
  ImGui::SameLine();
  ImGui::TextDisabled("%s", explanation);
  const Mat4 shown = s.seedForm ? glm::transpose(m) : m;
  if (ImGui::BeginTable("m", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchSame)) {
    for (int r = 0; r < 4; ++r) {
      ImGui::TableNextRow();
      for (int c = 0; c < 4; ++c) {
        ImGui::TableNextColumn();
        const double v = shown[c][r];
        ImGui::Text("%.4g", v == 0 ? 0.0 : v);
      }
    }
    ImGui::EndTable();
  }
  if (ImGui::SmallButton("copy text")) ImGui::SetClipboardText(matrixText(m, name, MatrixFormat::plain, s.seedForm).c_str());
  ImGui::SameLine();
  if (ImGui::SmallButton("copy Markdown"))
    ImGui::SetClipboardText(matrixText(m, name, MatrixFormat::markdown, s.seedForm).c_str());
  ImGui::SameLine();
  if (ImGui::SmallButton("copy LaTeX")) ImGui::SetClipboardText(matrixText(m, name, MatrixFormat::latex, s.seedForm).c_str());
  ImGui::PopID();
  ImGui::Spacing();
}

}  // namespace

void matricesPanel(ViewerState& s) {
  ImGui::Checkbox("the seed's row-vector form (p' = p · M, transposed)", &s.seedForm);
  tooltip("The project computes with column vectors (p' = M · p, as GLM). The lecture notes write points as "
          "row vectors; their matrices are the transposes.",
          "Die Vorlesung schreibt Punkte als Zeilenvektoren; ihre Matrizen sind die transponierten.");
  const PipelineRun& run = s.run;
  Mat4 wcFromMc(1.0);
  std::string objectName = "(no object)";
  if (!run.objects.empty()) {
    int k = 0;
    for (size_t i = 0; i < run.sceneIndex.size(); ++i)
      if (int(run.sceneIndex[i]) == s.selectedObject) k = int(i);
    wcFromMc = run.objects[size_t(k)].wcFromMc;
    objectName = run.objects[size_t(k)].name;
  }
  matrixTable(s, ("wcFromMc — " + objectName).c_str(), "wcFromMc", wcFromMc, "stage 1, modeling");
  matrixTable(s, "vrcFromWc", "vrcFromWc", run.vrcFromWc, "stage 2, view orientation");
  matrixTable(s, "npcFromVrc", "npcFromVrc", run.npcFromVrc, "stage 3, view mapping (then clip, then ÷ w)");
  matrixTable(s, "dcFromNpc", "dcFromNpc", run.dcFromNpc, "stage 5, device mapping");
  matrixTable(s, "dcFromMc", "dcFromMc", run.dcFromNpc * run.npcFromVrc * run.vrcFromWc * wcFromMc,
              "the composite, right to left");
}

void probePanel(ViewerState& s) {
  if (!s.probe) {
    ImGui::TextWrapped("Click a vertex in any view to follow it through the pipeline.");
    return;
  }
  const PipelineRun& run = s.run;
  const ObjectRun* o = nullptr;
  for (size_t i = 0; i < run.sceneIndex.size(); ++i)
    if (run.sceneIndex[i] == s.probe->object) o = &run.objects[i];
  if (!o || s.probe->vertex >= o->vertexCount()) {
    ImGui::TextWrapped("The probed vertex is not in the scene any more.");
    return;
  }
  const uint32_t v = s.probe->vertex;
  const Vec4 h = o->npcH[v];
  ImGui::Text("%s, vertex %u", o->name.c_str(), v);
  if (ImGui::SmallButton("clear")) s.probe.reset();
  if (ImGui::BeginTable("stages", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
    auto row = [](const char* space, const std::string& value) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(space);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(value.c_str());
    };
    row("MC", vecText(o->mesh->positions[v]));
    row("WC", vecText(o->wc(v)));
    row("VRC", vecText(o->vrc(v)));
    row("NPC (homogeneous)", vecText(h));
    if (h.w > 0) {
      const Vec3 npc = Vec3(h) / h.w;
      row("NPC (÷ w)", vecText(npc));
      row("DC", vecText(Vec3(run.dcFromNpc * Vec4(npc, 1.0))));
    } else {
      row("NPC (÷ w)", "w ≤ 0: behind the eye, no image point");
      row("DC", "—");
    }
    ImGui::EndTable();
  }
  // Blinn's boundary coordinates of the homogeneous point, whatever the strategy (seed 002).
  const Boundary bc = boundaryCoordinates(h);
  const Outcode code = outcodeOf(bc);
  section("boundary coordinates (inside when ≥ 0)");
  if (ImGui::BeginTable("bc", 3, ImGuiTableFlags_RowBg)) {
    static constexpr const char* kForms[] = {"BC0 = x", "BC1 = w − x", "BC2 = y", "BC3 = w − y", "BC4 = z", "BC5 = w − z"};
    for (int i = 0; i < kPlaneCount; ++i) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(kForms[i]);
      ImGui::TableNextColumn();
      ImGui::TextColored(bc[i] < 0 ? ImVec4(1, 0.4f, 0.35f, 1) : ImVec4(0.55f, 0.9f, 0.5f, 1), "%.5g", bc[i]);
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s (%s)", std::string(planeName(i)).c_str(), std::string(planeInequality(i)).c_str());
    }
    ImGui::EndTable();
  }
  std::string bits, names;
  for (int i = kPlaneCount - 1; i >= 0; --i) bits += (code >> i & 1) ? '1' : '0';
  for (int i = 0; i < kPlaneCount; ++i)
    if (code >> i & 1) names += (names.empty() ? "" : ", ") + std::string(planeName(i));
  ImGui::Text("outcode %s  %s", bits.c_str(), code ? ("outside: " + names).c_str() : "inside");
}

}  // namespace vplab::ui
