// The lecture panel: the stage morph, the clipping step-through (seed 002's boundary coordinates,
// one Sutherland–Hodgman pass at a time), vanishing points (seed 14.2) and lecture mode; and the
// depth plot (seed 15.2.4) in the inspector.
#define IMGUI_DEFINE_MATH_OPERATORS
#include "app/ui/panels.h"
#include "app/ui/widgets.h"

#include "pipeline/clip_steps.h"
#include "pipeline/vanishing_points.h"
#include "pipeline/view_mapping.h"

#include <imgui_internal.h>

#include <cstdio>

namespace vplab::ui {

namespace {

const ObjectRun* runOf(const ViewerState& s, int sceneIndex) {
  for (size_t i = 0; i < s.run.sceneIndex.size(); ++i)
    if (int(s.run.sceneIndex[i]) == sceneIndex) return &s.run.objects[i];
  return nullptr;
}

void morphSection(ViewerState& s) {
  ImGui::Checkbox("show the stage morph", &s.showMorph);
  tooltip("One view moves the visible scene from MC through WC, VRC and homogeneous NPC to NPC and DC; "
          "the division by w is its own step (2.5 → 3).",
          "Die Szene wandert durch die Stufen der Viewing Pipeline; die Division durch w ist ein eigener Schritt.");
  if (!s.showMorph) return;
  float t = float(s.frame.morphing.t);
  if (ImGui::SliderFloat("t", &t, 0.f, 4.f, "%.2f")) s.frame.morphing.t = t;
  recordRect(s, "morph.t");
  if (ImGui::Button(s.morphPlaying ? "pause" : "play")) {
    if (!s.morphPlaying && s.frame.morphing.t >= 4) s.frame.morphing.t = 0;
    s.morphPlaying = !s.morphPlaying;
  }
  ImGui::SameLine();
  for (auto [label, value] : {std::pair{"MC", 0.0}, {"WC", 1.0}, {"VRC", 2.0}, {"NPC h", 2.5}, {"NPC", 3.0}, {"DC", 4.0}}) {
    if (ImGui::SmallButton(label)) {
      s.frame.morphing.t = value;
      s.morphPlaying = false;
    }
    ImGui::SameLine();
  }
  ImGui::NewLine();
  float speed = float(s.morphSpeed);
  if (ImGui::SliderFloat("speed (stages/s)", &speed, 0.1f, 2.f, "%.2f")) s.morphSpeed = speed;
}

void stepThroughSection(ViewerState& s) {
  StepThrough& st = s.stepThrough;
  ImGui::Checkbox("step through the clipping of a polygon", &st.active);
  tooltip("Sutherland–Hodgman one plane at a time in homogeneous NPC: each vertex's boundary coordinate for "
          "the plane, and the vertices each pass creates (seed 002). Shift+click a polygon in the camera view "
          "to choose it.",
          "Sutherland–Hodgman Ebene für Ebene; Randkoordinaten der Ecken und neue Ecken.");
  if (!st.active) return;
  const Scene& scene = s.doc.shown();
  if (scene.objects.empty()) return;
  st.object = std::clamp(st.object, 0, int(scene.objects.size()) - 1);
  if (ImGui::BeginCombo("object", scene.objects[size_t(st.object)].name.c_str())) {
    for (int i = 0; i < int(scene.objects.size()); ++i)
      if (ImGui::Selectable(scene.objects[size_t(i)].name.c_str(), i == st.object)) st.object = i;
    ImGui::EndCombo();
  }
  const ObjectRun* o = runOf(s, st.object);
  if (!o || o->faceCount() == 0) {
    ImGui::TextDisabled("(the object is hidden)");
    return;
  }
  st.face = std::clamp(st.face, 0, int(o->faceCount()) - 1);
  ImGui::SliderInt("polygon", &st.face, 0, int(o->faceCount()) - 1);
  ImGui::SameLine();
  ImGui::TextDisabled("%s", std::string(toString(o->fate[size_t(st.face)])).c_str());
  const std::vector<ClipStep> steps = clipSteps(s.run, *o, size_t(st.face));
  const int last = int(steps.size());
  st.step = std::clamp(st.step, 0, last);
  if (ImGui::Button("< back") && st.step > 0) --st.step;
  ImGui::SameLine();
  if (ImGui::Button("next >") && st.step < last) ++st.step;
  ImGui::SameLine();
  ImGui::SliderInt("##step", &st.step, 0, last);
  recordRect(s, "step.slider");

  if (st.step == 0) {
    ImGui::TextWrapped("The polygon as it enters stage 4: %zu vertices in homogeneous NPC.", steps[0].input.size());
    return;
  }
  const ClipStep& step = steps[size_t(st.step - 1)];
  ImGui::Text("pass %d: %s plane, keep %s", st.step, std::string(planeName(step.plane)).c_str(),
              std::string(planeInequality(step.plane)).c_str());
  if (step.skipped) ImGui::TextDisabled("no vertex outside this plane: the pass changes nothing");
  if (ImGui::BeginTable("bc", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
    ImGui::TableSetupColumn("vertex");
    ImGui::TableSetupColumn("boundary coordinate");
    ImGui::TableSetupColumn("");
    ImGui::TableHeadersRow();
    for (size_t i = 0; i < step.input.size(); ++i) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("%zu", i);
      ImGui::TableNextColumn();
      const double b = step.boundary[i];
      ImGui::TextColored(b < 0 ? ImVec4(1, 0.4f, 0.35f, 1) : ImVec4(0.55f, 0.9f, 0.5f, 1), "%.5g", b);
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", b < 0 ? "outside" : "inside");
    }
    ImGui::EndTable();
  }
  const long created = std::count(step.created.begin(), step.created.end(), true);
  ImGui::Text("%zu vertices in, %zu out, %ld new (yellow in the views)", step.input.size(), step.output.size(), created);
}

void vanishingSection(ViewerState& s) {
  ImGui::Checkbox("vanishing points of the selected object", &s.frame.overlays.vanishingPoints);
  tooltip("In a perspective projection, edges parallel to an axis that is not parallel to the view plane meet "
          "in one image point (seed 14.2): one, two or three of them.",
          "Fluchtpunkte: parallele Kanten treffen sich im Bild in einem Punkt (14.2).");
  if (!s.frame.overlays.vanishingPoints) return;
  const ObjectRun* o = runOf(s, s.selectedObject);
  if (!o) return;
  const auto vps = vanishingPoints(s.run, o->wcFromMc);
  ImGui::Text("%s: %d-point perspective", o->name.c_str(), vanishingPointCount(vps));
  const char* axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (vps[size_t(i)].finite) ImGui::BulletText("%s axis: DC (%.1f, %.1f)", axes[i], vps[size_t(i)].dc.x, vps[size_t(i)].dc.y);
    else ImGui::BulletText("%s axis: parallel to the view plane, no vanishing point", axes[i]);
  }
}

void lectureModeSection(ViewerState& s) {
  float scale = s.uiScale;
  if (ImGui::SliderFloat("UI scale", &scale, 0.8f, 2.5f, "%.2f")) s.uiScale = scale;
  tooltip("Larger fonts, labels and handles for a projector.", "Größere Schrift und Griffe für den Beamer.");
  const char* names[] = {"world", "camera", "NPC", "stage morph"};
  const ViewKind kinds[] = {ViewKind::world, ViewKind::camera, ViewKind::npc, ViewKind::morph};
  int current = 0;
  for (int i = 0; i < 4; ++i)
    if (kinds[i] == s.lectureView) current = i;
  if (ImGui::Combo("full-screen view", &current, names, 4)) s.lectureView = kinds[current];
  if (ImGui::Button("lecture mode (F11)")) s.lectureMode = true;
  tooltip("One view fills the window, without panels; F11 or Esc returns.", "Eine Ansicht füllt das Fenster; F11 oder Esc beendet.");
}

}  // namespace

void lecturePanel(ViewerState& s) {
  section("stage morph");
  morphSection(s);
  section("clipping step-through");
  stepThroughSection(s);
  section("vanishing points");
  vanishingSection(s);
  section("lecture mode");
  lectureModeSection(s);
}

// The depth plot: NPC z and GL's window depth against VRC z between B and F, the objects' depth
// ranges, equal VRC steps and where they land in NPC (crowding near the back plane, seed 15.2.4),
// and what 16- and 24-bit depth buffers can resolve.
void depthPanel(ViewerState& s) {
  const Camera& c = s.run.camera;
  const ViewFrame& f = s.run.frame;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = std::max(160.f, ImGui::GetContentRegionAvail().x);
  const float height = std::clamp(ImGui::GetContentRegionAvail().y - 120.f, 120.f, 320.f);
  const float pad = 34.f;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p0 = origin + ImVec2(pad, 8), p1 = origin + ImVec2(width - 8, height - pad);
  auto at = [&](double vrcZ, double depth) {  // x: VRC z from B (left) to F (right); y: 0..1 upwards
    const float x = p0.x + float((vrcZ - c.back) / (c.front - c.back)) * (p1.x - p0.x);
    return ImVec2(x, p1.y - float(depth) * (p1.y - p0.y));
  };
  const ImU32 grid = IM_COL32(90, 95, 110, 255), text = IM_COL32(200, 205, 215, 255);
  dl->AddRect(p0, p1, grid);
  // The objects' depth ranges (VRC z of their vertices), as bands along the axis.
  float band = p1.y + 4;
  for (const ObjectRun& o : s.run.objects) {
    if (o.vertexCount() == 0) continue;
    double lo = 1e300, hi = -1e300;
    for (uint32_t v = 0; v < o.vertexCount(); ++v) {
      const double z = o.vrc(v).z;
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
    lo = std::clamp(lo, c.back, c.front);
    hi = std::clamp(hi, c.back, c.front);
    const ImU32 col = ImGui::ColorConvertFloat4ToU32(ImVec4(float(o.color.r), float(o.color.g), float(o.color.b), 0.9f));
    dl->AddRectFilled(ImVec2(at(lo, 0).x, band), ImVec2(std::max(at(hi, 0).x, at(lo, 0).x + 2), band + 4), col);
    band += 5;
  }
  // Equal VRC steps and their NPC depth: the ticks crowd at the back plane.
  for (int i = 0; i <= 10; ++i) {
    const double z = c.back + (c.front - c.back) * i / 10.0;
    const double d = npcDepthOfVrcZ(c, f, z);
    dl->AddLine(ImVec2(at(z, 0).x, p1.y), at(z, d), IM_COL32(90, 95, 110, 120));
    dl->AddLine(ImVec2(p0.x, at(z, d).y), at(z, d), IM_COL32(120, 200, 230, 110));
  }
  // NPC z (solid) and GL's window depth 1 − z (dashed look: dotted polyline).
  ImVec2 prev = at(c.back, npcDepthOfVrcZ(c, f, c.back)), prevGl = at(c.back, 1 - npcDepthOfVrcZ(c, f, c.back));
  for (int i = 1; i <= 120; ++i) {
    const double z = c.back + (c.front - c.back) * i / 120.0;
    const ImVec2 p = at(z, npcDepthOfVrcZ(c, f, z)), q = at(z, 1 - npcDepthOfVrcZ(c, f, z));
    dl->AddLine(prev, p, IM_COL32(140, 220, 255, 255), 2.f);
    if (i % 2) dl->AddLine(prevGl, q, IM_COL32(255, 200, 90, 255), 1.5f);
    prev = p;
    prevGl = q;
  }
  dl->AddText(p0 + ImVec2(4, 2), IM_COL32(140, 220, 255, 255), "NPC z");
  dl->AddText(p0 + ImVec2(4, 18), IM_COL32(255, 200, 90, 255), "GL window depth = 1 − z");
  char buf[64];
  std::snprintf(buf, sizeof buf, "B = %.3g", c.back);
  dl->AddText(ImVec2(p0.x, p1.y + band - p1.y + 2), text, buf);
  std::snprintf(buf, sizeof buf, "F = %.3g", c.front);
  dl->AddText(ImVec2(p1.x - ImGui::CalcTextSize(buf).x, p1.y + band - p1.y + 2), text, buf);
  dl->AddText(ImVec2(origin.x, p0.y), text, "1");
  dl->AddText(ImVec2(origin.x, p1.y - 14), text, "0");
  ImGui::Dummy(ImVec2(width, height + float(s.run.objects.size()) * 5 + 8));
  recordRect(s, "depth.plot");
  ImGui::TextDisabled("VRC z (the eye is at z = VPD = %.3g, beyond F)", f.vpd);
  if (ImGui::BeginTable("resolution", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
    ImGui::TableSetupColumn("depth buffer");
    ImGui::TableSetupColumn("at F");
    ImGui::TableSetupColumn("half way");
    ImGui::TableSetupColumn("at B");
    ImGui::TableHeadersRow();
    for (int bits : {16, 24}) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("%d bit: smallest VRC step", bits);
      for (double z : {c.front, (c.front + c.back) / 2, c.back}) {
        ImGui::TableNextColumn();
        ImGui::Text("%.3g", depthResolution(c, f, z, bits));
      }
    }
    ImGui::EndTable();
  }
}

}  // namespace vplab::ui
