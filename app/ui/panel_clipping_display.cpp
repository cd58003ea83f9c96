// The clipping panel (strategy, bounding-box test, statistics and operation counts; lecture notes 15.3) and
// the display panel (styles and overlays per view).
#include "app/ui/panels.h"
#include "app/ui/widgets.h"

#include <algorithm>

namespace vplab::ui {

namespace {

void statRow(const char* name, uint64_t value) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextWrapped("%s", name);
  ImGui::TableNextColumn();
  ImGui::Text("%llu", static_cast<unsigned long long>(value));
}

bool styleCombo(const char* label, Style& style) {
  int current = int(style);
  const char* names[] = {"flat", "shaded", "wire", "hidden-line (dashed)", "hidden-line (removed)"};
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
  radio("homogeneous NPC (Blinn)", &strategy, int(ClipStrategy::npc));
  tooltip("Clip against the unit cube in homogeneous coordinates, 0 ≤ x, y, z ≤ w, then divide (Hill 7.4).",
          "Clipping im NPC in homogenen Koordinaten, dann Division durch w.");
  radio("the six frustum planes in WC", &strategy, int(ClipStrategy::wc));
  tooltip("Clip in WC against the plane equations of the view volume (lecture notes 15.3.1).", "Clipping im WC (15.3.1).");
  radio("divide first, then clip — WRONG on purpose", &strategy, int(ClipStrategy::divideFirst));
  tooltip("Divides by w before clipping: for points behind the eye (w < 0) x/w and y/w flip sign, so edges "
          "reaching behind the eye wrap around through infinity.",
          "Erst dividieren, dann clippen: hinter dem Auge kehren x/w und y/w ihr Vorzeichen um.");
  s.pipeline.strategy = ClipStrategy(strategy);
  if (!isCorrect(s.pipeline.strategy))
    errorText("Wrong on purpose: after the division a point behind the eye has x/w and y/w of flipped sign, so "
              "an edge reaching behind the eye wraps around through infinity.");
  checkbox("bounding-box test per object (15.3.4)", &s.pipeline.boundingBoxTest);
  tooltip("One test of an object's bounding box decides all its polygons when the box is wholly inside "
          "or wholly outside the view volume.",
          "Umgebungsclipping: ein Test des umgebenden Quaders entscheidet für alle Polygone.");

  const PipelineStats& st = s.run().stats;
  if (ImGui::BeginTable("stats", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
    ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("count", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("00000000").x);
    statRow("vertices transformed", st.verticesTransformed);
    statRow("vertices classified", st.verticesClassified);
    statRow("polygons", st.polygons);
    statRow("  trivially accepted", st.polygonsTriviallyAccepted);
    statRow("  trivially rejected", st.polygonsTriviallyRejected);
    statRow("  clipped", st.polygonsClipped);
    statRow("  clipped away", st.polygonsClippedAway);
    statRow("  decided by bounding box", st.polygonsDecidedByBox);
    statRow("vertices created", st.verticesCreated);
    statRow("vertices divided and mapped", st.verticesOutput);
    statRow("objects box-tested", st.objectsBoxTested);
    statRow("objects accepted by box", st.objectsAcceptedByBox);
    statRow("objects rejected by box", st.objectsRejectedByBox);
    statRow("multiplications", st.operations.multiplications);
    statRow("additions", st.operations.additions);
    statRow("divisions", st.operations.divisions);
    statRow("comparisons", st.operations.comparisons);
    ImGui::EndTable();
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("Operation counts follow the lecture notes' cost model (15.3.3).");
  ImGui::PopStyleColor();
}

void displayPanel(ViewerState& s) {
  styleCombo("camera view", s.display.camera.style);
  styleCombo("world view", s.display.world.style);
  styleCombo("NPC view", s.display.npc.style);
  OverlaySettings& o = s.display.overlays;
  section("world view");
  checkbox("view volume", &o.frustum);
  ImGui::SameLine();
  checkbox("window", &o.viewPlane);
  ImGui::SameLine();
  checkbox("camera axes", &o.cameraAxes);
  section("world and NPC views");
  checkbox("fade what is outside", &o.fadeOutside);
  ImGui::SameLine();
  checkbox("highlight new edges", &o.newEdges);
  checkbox("unit cube", &o.cube);
  ImGui::SameLine();
  checkbox("labels", &o.labels);
  section("camera view");
  checkbox("CPU clipped polygons", &o.cpuPolygons);
  tooltip("The CPU clipper's polygons in DC, outlined over the GPU's image.", "Die Polygone des CPU-Clippers im DC.");
  ImGui::SameLine();
  checkbox("difference to the CPU", &o.difference);
  tooltip("Where the GPU's image differs from the CPU's polygons filled (magenta).",
          "Wo das Bild der GPU von den gefüllten CPU-Polygonen abweicht.");
  checkbox("antialiasing (4× multisampling)", &s.antialias);
  tooltip("Smooth edges in the world, NPC and morph views. On a software renderer (Mesa llvmpipe) it costs "
          "more than all the drawing, so it starts off there.",
          "Kantenglättung; auf einem Software-Renderer teuer, daher dort zunächst aus.");
  if (ImGui::Button("reset the observers")) {
    s.display.world.orbit = defaultWorldOrbit(s.doc.shown(), s.worldAspect);
    s.display.npc.orbit = defaultNpcOrbit();
  }
}

}  // namespace vplab::ui
