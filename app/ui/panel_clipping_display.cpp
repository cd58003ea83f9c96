// The clipping panel (strategy, bounding-box test, statistics and operation counts; lecture notes 15.3) and
// the display panel (styles and overlays per view).
#include "app/ui/panels.h"
#include "app/ui/widgets.h"

#include <algorithm>
#include <array>
#include <type_traits>
#include <utility>

namespace vplab::ui {

namespace {

// The panel's names of the counters (pipeline/cost_model.h's tables), looked up in the catalogue
// while compiling as every text is: a counter named there but missing from app/text/ does not compile.
template <auto& kFields, size_t... I>
constexpr auto catalogueLabels(std::index_sequence<I...>) {
  return std::array<text::Text, sizeof...(I)>{text::Text(kFields[I].label)...};
}
template <auto& kFields>
constexpr size_t labelledCount() {
  size_t n = 0;
  for (const auto& field : kFields) n += field.label != nullptr;
  return n;
}
template <auto& kFields>
constexpr auto labelledFields() {  // the rows with a label, in order
  std::array<std::remove_cvref_t<decltype(kFields[0])>, labelledCount<kFields>()> rows{};
  size_t n = 0;
  for (const auto& field : kFields)
    if (field.label) rows[n++] = field;
  return rows;
}
constexpr auto kPanelStats = labelledFields<kStatsFields>();
constexpr auto kStatsLabels = catalogueLabels<kPanelStats>(std::make_index_sequence<kPanelStats.size()>());
constexpr auto kOperationLabels = catalogueLabels<kOperationFields>(std::make_index_sequence<std::size(kOperationFields)>());

void statRow(const ViewerState& s, text::Text name, uint64_t value) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextWrapped("%s", tr(s, name));
  ImGui::TableNextColumn();
  ImGui::Text("%llu", static_cast<unsigned long long>(value));
}

bool styleCombo(const ViewerState& s, text::Text text, Style& style) {
  int current = int(style);
  const char* label = tr(s, text);
  const char* names[] = {tr(s, "flat"), tr(s, "shaded"), tr(s, "wire"), tr(s, "hidden-line (dashed)"),
                         tr(s, "hidden-line (removed)")};
  // The combo leaves room for its label, which cannot wrap.
  ImGui::SetNextItemWidth(std::max(ImGui::GetFontSize() * 5, ImGui::GetContentRegionAvail().x -
                                                                  ImGui::CalcTextSize(label).x -
                                                                  ImGui::GetStyle().ItemInnerSpacing.x));
  const bool changed = ImGui::Combo(label, &current, names, IM_ARRAYSIZE(names));
  style = Style(current);
  return changed;
}

}  // namespace

void clippingPanel(ViewerState& s) {
  int strategy = int(s.pipeline.strategy);
  radio(tr(s, "homogeneous NPC (Blinn)"), &strategy, int(ClipStrategy::npc));
  tooltip(s, "Clip against the unit cube in homogeneous coordinates, 0 ≤ x, y, z ≤ w, then divide "
             "(Hill 7.4).");
  radio(tr(s, "the six frustum planes in WC"), &strategy, int(ClipStrategy::wc));
  tooltip(s, "Clip in WC against the plane equations of the view volume (lecture notes 15.3.1).");
  radio(tr(s, "divide first, then clip — WRONG on purpose"), &strategy, int(ClipStrategy::divideFirst));
  tooltip(s, "Divides by w before clipping: for points behind the eye (w < 0) x/w and y/w flip sign, so "
             "edges reaching behind the eye wrap around through infinity.");
  s.pipeline.strategy = ClipStrategy(strategy);
  if (!isCorrect(s.pipeline.strategy))
    errorText(tr(s, "Wrong on purpose: after the division a point behind the eye has x/w and y/w of flipped "
                    "sign, so an edge reaching behind the eye wraps around through infinity."));
  checkbox(tr(s, "bounding-box test per object (15.3.4)"), &s.pipeline.boundingBoxTest);
  tooltip(s, "One test of an object's bounding box decides all its polygons when the box is wholly inside "
             "or wholly outside the view volume.");

  const PipelineStats& st = s.run().stats;
  scrollAnchor(s, "clipping.counts");
  if (ImGui::BeginTable("stats", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
    ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("count", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("00000000").x);
    // The cost first (what the strategies are compared by, lecture notes 15.3.3), then the vertices
    // and polygons it was spent on: at a projector's scale the panel shows a dozen rows.
    for (size_t i = 0; i < std::size(kOperationFields); ++i)
      statRow(s, kOperationLabels[i], st.operations.*kOperationFields[i].member);
    for (size_t i = 0; i < kPanelStats.size(); ++i) statRow(s, kStatsLabels[i], st.*kPanelStats[i].member);
    ImGui::EndTable();
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", tr(s, "Operation counts follow the lecture notes' cost model (15.3.3)."));
  ImGui::PopStyleColor();
}

void displayPanel(ViewerState& s) {
  styleCombo(s, "camera view", s.display.camera.style);
  styleCombo(s, "world view", s.display.world.style);
  styleCombo(s, "NPC view", s.display.npc.style);
  OverlaySettings& o = s.display.overlays;
  section(tr(s, "world view"));
  checkbox(tr(s, "view volume"), &o.frustum);
  ImGui::SameLine();
  checkbox(tr(s, "window"), &o.viewPlane);
  ImGui::SameLine();
  checkbox(tr(s, "camera axes"), &o.cameraAxes);
  section(tr(s, "world and NPC views"));
  checkbox(tr(s, "fade what is outside"), &o.fadeOutside);
  ImGui::SameLine();
  checkbox(tr(s, "highlight new edges"), &o.newEdges);
  checkbox(tr(s, "unit cube"), &o.cube);
  ImGui::SameLine();
  checkbox(tr(s, "labels"), &o.labels);
  section(tr(s, "camera view"));
  checkbox(tr(s, "CPU clipped polygons"), &o.cpuPolygons);
  tooltip(s, "The CPU clipper's polygons in DC, outlined over the GPU's image.");
  ImGui::SameLine();
  checkbox(tr(s, "difference to the CPU"), &o.difference);
  tooltip(s, "Where the GPU's image differs from the CPU's polygons filled (magenta).");
  checkbox(tr(s, "antialiasing (4× multisampling)"), &s.antialias);
  tooltip(s, "Smooth edges in the world, NPC and morph views. On a software renderer (Mesa llvmpipe) it "
             "costs more than all the drawing, so it starts off there.");
  if (ImGui::Button(tr(s, "reset the observers"))) {
    s.display.world.orbit = defaultWorldOrbit(s.doc.shown(), s.worldAspect);
    s.display.npc.orbit = defaultNpcOrbit();
  }
}

}  // namespace vplab::ui
