// The lecture panel: the stage morph, the clipping step-through (Hill 7.4's boundary coordinates,
// one Sutherland–Hodgman pass at a time), vanishing points (lecture notes 14.2) and lecture mode; and the
// depth plot (lecture notes 15.2.4) in the inspector.
#define IMGUI_DEFINE_MATH_OPERATORS
#include "app/ui/imdrawlist_backend.h"
#include "app/ui/panels.h"
#include "app/inspect/vanishing_text.h"
#include "app/ui/widgets.h"

#include "app/views/depth_plot.h"
#include "pipeline/clip_steps.h"
#include "pipeline/clipping.h"
#include "pipeline/vanishing_points.h"
#include "pipeline/view_mapping.h"

#include <imgui_internal.h>

#include <cstdio>

namespace vplab::ui {

namespace {

const ObjectRun* runOf(const RunPart& r, int sceneIndex) {
  for (size_t i = 0; i < r.run().sceneIndex.size(); ++i)
    if (int(r.run().sceneIndex[i]) == sceneIndex) return &r.run().objects[i];
  return nullptr;
}

/// "its fate: clipped" in the viewer's language (the English names the pipeline's Fate as toString does).
text::Text fateText(Fate f) {
  switch (f) {
    case Fate::accepted: return "its fate: accepted";
    case Fate::rejected: return "its fate: rejected";
    case Fate::clipped: return "its fate: clipped";
    case Fate::clippedAway: return "its fate: clipped_away";
  }
  return "its fate: clipped";
}

/// "left plane", …, "user plane 2": a clipping plane (pipeline's planeName) in the viewer's language.
std::string planeText(const Widgets& w, int plane) {
  static constexpr text::Text kCube[] = {"left plane", "right plane", "bottom plane", "top plane", "back plane", "front plane"};
  if (plane >= 0 && plane < kPlaneCount) return tr(w, kCube[plane]);
  return tr(w, "user plane {1}", {std::to_string(plane - kPlaneCount + 1)});
}

void morphSection(Widgets& w, ViewsPart& v, LecturePart& lec) {
  checkbox(tr(w, "show the stage morph"), &lec.showMorph);
  tooltip(w, "One view moves the visible scene from MC through WC, VRC and homogeneous NPC to NPC and DC; "
             "the division by w is its own step (2.5 → 3).");
  if (!lec.showMorph) return;
  float t = float(v.display.morphing.t);
  fitLabel("t");
  if (ImGui::SliderFloat("t", &t, 0.f, 4.f, "%.2f")) v.display.morphing.t = t;
  recordRect("morph.t");
  if (ImGui::Button(lec.morphPlaying ? tr(w, "pause") : tr(w, "play"))) {
    if (!lec.morphPlaying && v.display.morphing.t >= 4) v.display.morphing.t = 0;
    lec.morphPlaying = !lec.morphPlaying;
  }
  ImGui::SameLine();
  for (auto [label, value] : {std::pair{"MC", 0.0}, {"WC", 1.0}, {"VRC", 2.0}, {"NPC h", 2.5}, {"NPC", 3.0}, {"DC", 4.0}}) {
    if (ImGui::SmallButton(label)) {
      v.display.morphing.t = value;
      lec.morphPlaying = false;
    }
    ImGui::SameLine();
  }
  ImGui::NewLine();
  float speed = float(lec.morphSpeed);
  const char* speedLabel = tr(w, "speed (stages/s)");
  fitLabel(speedLabel);
  if (ImGui::SliderFloat(speedLabel, &speed, 0.1f, 2.f, "%.2f")) lec.morphSpeed = speed;
}

/// The outcodes of the polygon's vertices as it enters stage 4, with their AND (all outside one
/// plane: rejected whole) and OR (all inside: accepted whole; else the planes it is clipped against),
/// in binary as the bits lie and in decimal as the lecture says them (Blinn; lecture notes 15.3.2).
void outcodeTable(const Widgets& w, const std::vector<ClipVertex>& polygon) {
  auto bitsOf = [](Outcode code) {
    std::string bits;
    for (int i = kPlaneCount - 1; i >= 0; --i) bits += (code >> i & 1) ? '1' : '0';
    return bits + " = " + std::to_string(code & ((1u << kPlaneCount) - 1));
  };
  Outcode all = ~Outcode(0), any = 0;
  if (ImGui::BeginTable("outcodes", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupColumn(tr(w, "vertex"));
    ImGui::TableSetupColumn(tr(w, "outcode"));
    ImGui::TableHeadersRow();
    for (size_t i = 0; i < polygon.size(); ++i) {
      const Outcode code = outcodeOf(polygon[i].p) & ((1u << kPlaneCount) - 1);
      all &= code;
      any |= code;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("%zu", i);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(bitsOf(code).c_str());
    }
    ImGui::EndTable();
  }
  all &= (1u << kPlaneCount) - 1;
  std::string planes;
  for (int i = 0; i < kPlaneCount; ++i)
    if (any >> i & 1) planes += (planes.empty() ? "" : ", ") + planeText(w, i);
  ImGui::TextWrapped("%s", tr(w, "AND of the outcodes = {1}: {2}",
                              {bitsOf(all), all ? tr(w, "rejected whole: every vertex lies outside one plane")
                                                : tr(w, "not rejected whole")})
                               .c_str());
  ImGui::TextWrapped("%s", tr(w, "OR of the outcodes = {1}: {2}",
                              {bitsOf(any), any ? tr(w, "clipped against {1}", {planes}) : tr(w, "accepted whole")})
                               .c_str());
}

void stepThroughSection(Widgets& w, const DocumentPart& d, const RunPart& r, LecturePart& lec) {
  StepThrough& st = lec.stepThrough;
  if (lec.showStepThrough) {  // Shift+click in the camera view chose a polygon: show it
    ImGui::SetScrollHereY(0.f);
    lec.showStepThrough = false;
  }
  checkbox(tr(w, "step through the clipping of a polygon"), &st.active);
  recordRect("step.active");
  tooltip(w, "Sutherland–Hodgman one plane at a time in homogeneous NPC: each vertex's boundary coordinate for "
             "the plane, and the vertices each pass creates (Hill 7.4). Shift+click a polygon in the camera view "
             "to choose it.");
  if (!st.active) return;
  const Scene& scene = d.doc.shown();
  if (scene.objects.empty()) return;
  st.object = std::clamp(st.object, 0, int(scene.objects.size()) - 1);
  const char* objectLabel = tr(w, "object");
  fitLabel(objectLabel);
  const Language lang = w.language();
  if (ImGui::BeginCombo(objectLabel, nameIn(scene.objects[size_t(st.object)], lang).c_str())) {
    const FingerRows rows(w.touch);
    for (int i = 0; i < int(scene.objects.size()); ++i)
      if (ImGui::Selectable((nameIn(scene.objects[size_t(i)], lang) + "##" + std::to_string(i)).c_str(), i == st.object))
        st.object = i;
    ImGui::EndCombo();
  }
  const ObjectRun* o = runOf(r, st.object);
  if (!o || o->faceCount() == 0) {
    ImGui::TextDisabled("%s", tr(w, "(the object is hidden)"));
    return;
  }
  st.face = std::clamp(st.face, 0, int(o->faceCount()) - 1);
  const char* polygonLabel = tr(w, "polygon");
  fitLabel(polygonLabel);
  // Typed values (Ctrl+click) are held to the range too: the face and the pass index arrays below.
  ImGui::SliderInt(polygonLabel, &st.face, 0, int(o->faceCount()) - 1, "%d", ImGuiSliderFlags_AlwaysClamp);
  st.face = std::clamp(st.face, 0, int(o->faceCount()) - 1);
  ImGui::TextDisabled("%s", tr(w, fateText(o->fate[size_t(st.face)])));
  const std::vector<ClipStep> steps = clipSteps(r.run(), *o, size_t(st.face));
  const int last = int(steps.size());
  st.step = std::clamp(st.step, 0, last);
  // A lesson's step shows the pass: its buttons at the panel's top, its result below them.
  scrollAnchor(w, "lecture.stepThrough");
  ImGui::BeginDisabled(st.step == 0);  // nothing before the first plane
  if (ImGui::Button(tr(w, "< back"))) --st.step;
  ImGui::EndDisabled();
  recordRect("step.back");
  ImGui::SameLine();
  ImGui::BeginDisabled(st.step == last);  // nothing after the last
  if (ImGui::Button(tr(w, "next >"))) ++st.step;
  ImGui::EndDisabled();
  recordRect("step.next");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(std::max(ImGui::GetFontSize() * 4, ImGui::GetContentRegionAvail().x));
  ImGui::SliderInt("##step", &st.step, 0, last, tr(w, "pass %d"), ImGuiSliderFlags_AlwaysClamp);
  st.step = std::clamp(st.step, 0, last);
  recordRect("step.slider");

  if (st.step == 0) {
    ImGui::TextWrapped(tr(w, "The polygon as it enters stage 4: %zu vertices in homogeneous NPC."), steps[0].input.size());
    outcodeTable(w, steps[0].input);
    return;
  }
  const ClipStep& step = steps[size_t(st.step - 1)];
  ImGui::TextWrapped(tr(w, "pass %d of %d: %s, keep %s"), st.step, last, planeText(w, step.plane).c_str(),
                     std::string(planeInequality(step.plane)).c_str());
  if (step.skipped) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", tr(w, "no vertex outside this plane: the pass changes nothing"));
    ImGui::PopStyleColor();
  }
  double scale = 0;
  for (double b : step.boundary) scale = std::max(scale, std::abs(b));
  if (ImGui::BeginTable("bc", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupColumn(tr(w, "vertex"));
    ImGui::TableSetupColumn(tr(w, "boundary coordinate"));
    ImGui::TableSetupColumn(tr(w, "side"));
    ImGui::TableHeadersRow();
    for (size_t i = 0; i < step.input.size(); ++i) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("%zu", i);
      ImGui::TableNextColumn();
      const double b = step.boundary[i];
      ImGui::TextColored(b < 0 ? outsideColor() : insideColor(), "%s", num(b, scale, 5).c_str());
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", b < 0 ? tr(w, "outside") : tr(w, "inside"));
    }
    ImGui::EndTable();
  }
  const long created = std::count(step.created.begin(), step.created.end(), true);
  ImGui::TextWrapped(tr(w, "%zu vertices in, %zu out, %ld new (yellow in the views)"), step.input.size(), step.output.size(),
                     created);
  // The new vertices where the polygon's edges cross the plane, snapped onto it as they are drawn.
  for (size_t k = 0; k < step.output.size(); ++k) {
    if (!step.created[k]) continue;
    Vec4 p = step.output[k].p;
    snapToPlanes(p, step.output[k].onPlanes);
    ImGui::BulletText(tr(w, "new vertex %zu:"), k);
    ImGui::Indent();
    ImGui::TextWrapped("%s", tr(w, "{1} (homogeneous NPC)", {vecText(p)}).c_str());
    ImGui::Unindent();
    recordRect(("step.new." + std::to_string(k)).c_str());
  }
}

void vanishingSection(Widgets& w, ViewsPart& v, const RunPart& r, const EditPart& e) {
  checkbox(tr(w, "vanishing points of the selected object"), &v.display.overlays.vanishingPoints);
  tooltip(w, "In a perspective projection, edges parallel to an axis that is not parallel to the view plane meet "
             "in one image point (lecture notes 14.2): one, two or three of them.");
  if (!v.display.overlays.vanishingPoints) return;
  const ObjectRun* o = runOf(r, e.selectedObject);
  if (!o) return;
  const VanishingText t = vanishingText(r.run(), *o, w.language());
  ImGui::TextWrapped("%s", t.headline.c_str());
  for (const std::string& axis : t.axes) {
    ImGui::Bullet();
    ImGui::TextWrapped("%s", axis.c_str());
  }
}

void lectureModeSection(Widgets& w, LecturePart& lec, LayoutPart& l) {
  float scale = l.uiScale;
  const char* scaleLabel = tr(w, "UI scale");
  fitLabel(scaleLabel);
  if (ImGui::SliderFloat(scaleLabel, &scale, 0.8f, 2.5f, "%.2f")) l.uiScale = scale;
  tooltip(w, "Larger fonts, labels and handles for a projector.");
  const char* names[] = {tr(w, "world"), tr(w, "camera"), "NPC", tr(w, "stage morph")};
  const ViewKind kinds[] = {ViewKind::world, ViewKind::camera, ViewKind::npc, ViewKind::morph};
  int current = 0;
  for (int i = 0; i < 4; ++i)
    if (kinds[i] == lec.lectureView) current = i;
  const char* viewLabel = tr(w, "full-screen view");
  fitLabel(viewLabel);
  if (ImGui::Combo(viewLabel, &current, names, 4)) lec.lectureView = kinds[current];
  // F11 is the browser's own (its full screen, of the page and its address bar): the page's lecture
  // mode takes the browser's full screen itself (app/web/page.cpp), and Esc returns.
  if (ImGui::Button(tr(w, l.inBrowser ? text::Text("lecture mode (full screen)") : text::Text("lecture mode (F11)"))))
    lec.lectureMode = true;
  recordRect("lecture.mode");
  if (l.inBrowser) tooltip(w, "One view fills the screen, without panels; Esc returns.");
  else tooltip(w, "One view fills the window, without panels; F11 or Esc returns.");
}

}  // namespace

void lecturePanel(Widgets& w, ViewsPart& v, const DocumentPart& d, const RunPart& r, const EditPart& e, LecturePart& lec,
                  LayoutPart& l) {
  scrollAnchor(w, "lecture.morph");
  section(tr(w, "stage morph"));
  morphSection(w, v, lec);
  section(tr(w, "clipping step-through"));
  stepThroughSection(w, d, r, lec);
  scrollAnchor(w, "lecture.vanishing");
  section(tr(w, "vanishing points"));
  vanishingSection(w, v, r, e);
  section(tr(w, "lecture mode"));
  lectureModeSection(w, lec, l);
}

// The depth plot: NPC z and GL's window depth against VRC z between B and F, the objects' depth
// ranges, equal VRC steps and where they land in NPC (crowding near the back plane, lecture notes 15.2.4),
// and what 16- and 24-bit depth buffers can resolve.
void depthPanel(Widgets& w, const RunPart& r, const LayoutPart& l) {
  const Camera& c = r.run().camera;
  const VrcAxes& f = r.run().vrc;
  const float line = ImGui::GetTextLineHeight();
  // The legend above the plot, off the curves.
  ImGui::BeginGroup();
  const char* glDepth = tr(w, "- - GL window depth = 1 − z");
  ImGui::TextColored(ImVec4(0.55f, 0.86f, 1.f, 1.f), "— NPC z");
  if (ImGui::CalcTextSize(("— NPC z    " + std::string(glDepth)).c_str()).x <= ImGui::GetContentRegionAvail().x)
    ImGui::SameLine(0, line);
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.78f, 0.35f, 1.f));
  ImGui::TextWrapped("%s", glDepth);
  ImGui::PopStyleColor();
  ImGui::EndGroup();
  recordRect("depth.legend");
  // The chart (app/views/depth_plot.h), drawn from its display list with ImGui's font; invisible
  // items over its plot and each bar's row give the hover boxes and tooltips.
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = std::max(line * 10, ImGui::GetContentRegionAvail().x);
  // At least ten lines of text high, so the curves read at any UI scale.
  const float height = std::clamp(ImGui::GetContentRegionAvail().y - line * 9, line * 10, line * 22);
  const ImGuiTextMetrics text(l.uiScale);
  const DepthPlot plot = depthPlot(r.run(), int(width), int(height), text, {false, false, w.language()});
  drawDisplayList(*ImGui::GetWindowDrawList(), plot.list, origin);
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(ImGui::GetStyle().ItemSpacing.x, 0));
  ImGui::Dummy(ImVec2(width, plot.plot.max.y + 2));
  recordRect("depth.plot");
  for (const DepthPlot::Bar& bar : plot.bars) {
    ImGui::SetCursorScreenPos(origin + ImVec2(0, bar.row.min.y));
    ImGui::Dummy(ImVec2(width, bar.row.max.y - bar.row.min.y));
    recordRect(("depth.bar." + bar.name).c_str());
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(tr(w, "%s: VRC z from %s to %s"), bar.name.c_str(), num(bar.lo).c_str(), num(bar.hi).c_str());
  }
  ImGui::SetCursorScreenPos(origin + ImVec2(0, float(plot.list.height)));
  ImGui::PopStyleVar();
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped(tr(w, "VRC z: B at the left, F at the right; the eye is at z = VPD = %s, beyond F"), num(f.vpd).c_str());
  ImGui::PopStyleColor();
  // The smallest VRC step a depth buffer resolves, as sentences (they wrap; a table would not fit
  // a narrow inspector at a large UI scale).
  ImGui::TextWrapped("%s", tr(w, "Smallest VRC step a depth buffer resolves:"));
  for (int bits : {16, 24}) {
    ImGui::Bullet();
    ImGui::TextWrapped(tr(w, "%d bit: %s at F, %s half way, %s at B"), bits,
                       num(depthResolution(c, f, c.front, bits), 0, 3).c_str(),
                       num(depthResolution(c, f, (c.front + c.back) / 2, bits), 0, 3).c_str(),
                       num(depthResolution(c, f, c.back, bits), 0, 3).c_str());
  }
}

}  // namespace vplab::ui
