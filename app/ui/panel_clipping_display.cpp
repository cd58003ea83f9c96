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

void statRow(const Widgets& w, text::Text name, uint64_t value) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextWrapped("%s", tr(w, name));
  ImGui::TableNextColumn();
  ImGui::Text("%llu", static_cast<unsigned long long>(value));
}

bool styleCombo(const Widgets& w, text::Text text, Style& style) {
  int current = int(style);
  const char* label = tr(w, text);
  const char* names[] = {tr(w, "flat"), tr(w, "shaded"), tr(w, "wire"), tr(w, "hidden-line (dashed)"),
                         tr(w, "hidden-line (removed)")};
  // The combo leaves room for its label, which cannot wrap.
  ImGui::SetNextItemWidth(std::max(ImGui::GetFontSize() * 5, ImGui::GetContentRegionAvail().x -
                                                                  ImGui::CalcTextSize(label).x -
                                                                  ImGui::GetStyle().ItemInnerSpacing.x));
  const bool changed = ImGui::Combo(label, &current, names, IM_ARRAYSIZE(names));
  style = Style(current);
  return changed;
}

}  // namespace

void clippingPanel(Widgets& w, ViewsPart& v, const RunPart& r) {
  int strategy = int(v.pipeline.strategy);
  radio(tr(w, "homogeneous NPC (Blinn)"), &strategy, int(ClipStrategy::npc));
  tooltip(w, "Clip against the unit cube in homogeneous coordinates, 0 ≤ x, y, z ≤ w, then divide "
             "(Hill 7.4).");
  radio(tr(w, "the six frustum planes in WC"), &strategy, int(ClipStrategy::wc));
  tooltip(w, "Clip in WC against the plane equations of the view volume (lecture notes 15.3.1).");
  radio(tr(w, "divide first, then clip — WRONG on purpose"), &strategy, int(ClipStrategy::divideFirst));
  tooltip(w, "Divides by w before clipping: for points behind the eye (w < 0) x/w and y/w flip sign, so "
             "edges reaching behind the eye wrap around through infinity.");
  v.pipeline.strategy = ClipStrategy(strategy);
  if (!isCorrect(v.pipeline.strategy))
    errorText(tr(w, "Wrong on purpose: after the division a point behind the eye has x/w and y/w of flipped "
                    "sign, so an edge reaching behind the eye wraps around through infinity."));
  checkbox(tr(w, "bounding-box test per object (15.3.4)"), &v.pipeline.boundingBoxTest);
  tooltip(w, "One test of an object's bounding box decides all its polygons when the box is wholly inside "
             "or wholly outside the view volume.");

  const PipelineStats& st = r.run().stats;
  scrollAnchor(w, "clipping.counts");
  if (ImGui::BeginTable("stats", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
    ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("count", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("00000000").x);
    // The cost first (what the strategies are compared by, lecture notes 15.3.3), then the vertices
    // and polygons it was spent on: at a projector's scale the panel shows a dozen rows.
    for (size_t i = 0; i < std::size(kOperationFields); ++i)
      statRow(w, kOperationLabels[i], st.operations.*kOperationFields[i].member);
    for (size_t i = 0; i < kPanelStats.size(); ++i) statRow(w, kStatsLabels[i], st.*kPanelStats[i].member);
    ImGui::EndTable();
    recordRect("clipping.counts");  // the browser tests swipe it into sight on a phone
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", tr(w, "Operation counts follow the lecture notes' cost model (15.3.3)."));
  ImGui::PopStyleColor();
}

void displayPanel(Widgets& w, ViewsPart& v, const DocumentPart& d, LayoutPart& l) {
  styleCombo(w, "camera view", v.display.camera.style);
  styleCombo(w, "world view", v.display.world.style);
  styleCombo(w, "NPC view", v.display.npc.style);
  OverlaySettings& o = v.display.overlays;
  section(tr(w, "world view"));
  checkbox(tr(w, "view volume"), &o.frustum);
  ImGui::SameLine();
  checkbox(tr(w, "window"), &o.viewPlane);
  ImGui::SameLine();
  checkbox(tr(w, "camera axes"), &o.cameraAxes);
  section(tr(w, "world and NPC views"));
  checkbox(tr(w, "fade what is outside"), &o.fadeOutside);
  ImGui::SameLine();
  checkbox(tr(w, "highlight new edges"), &o.newEdges);
  checkbox(tr(w, "unit cube"), &o.cube);
  ImGui::SameLine();
  checkbox(tr(w, "labels"), &o.labels);
  section(tr(w, "camera view"));
  checkbox(tr(w, "CPU clipped polygons"), &o.cpuPolygons);
  tooltip(w, "The CPU clipper's polygons in DC, outlined over the GPU's image.");
  ImGui::SameLine();
  checkbox(tr(w, "difference to the CPU"), &o.difference);
  tooltip(w, "Where the GPU's image differs from the CPU's polygons filled (magenta).");
  checkbox(tr(w, "antialiasing (4× multisampling)"), &l.antialias);
  tooltip(w, "Smooth edges in the world, NPC and morph views. On a software renderer (Mesa llvmpipe) it "
             "costs more than all the drawing, so it starts off there.");
  if (ImGui::Button(tr(w, "reset the observers"))) {
    v.display.world.orbit = defaultWorldOrbit(d.doc.shown(), l.worldAspect);
    v.display.npc.orbit = defaultNpcOrbit();
  }
}

}  // namespace vplab::ui
