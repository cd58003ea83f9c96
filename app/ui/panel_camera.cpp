// The camera panel: the synthetic camera's parameters (lecture notes 15.1–15.2) and what follows from them.
#include "app/ui/panels.h"
#include "app/inspect/camera_text.h"
#include "app/inspect/picking.h"
#include "app/ui/widgets.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

namespace vplab::ui {

namespace {

void derived(const Widgets& w, const RunPart& r) {
  const VrcAxes& f = r.run().vrc;
  ImGui::TextDisabled("%s", tr(w, "derived"));
  ImGui::TextWrapped("U = %s", vecText(f.u).c_str());
  tooltip(w, "U = normalize(VUP × N): the view plane's x axis.");
  ImGui::TextWrapped("V = %s", vecText(f.v).c_str());
  tooltip(w, "V = N × U: the view plane's y axis, VUP projected into the view plane.");
  ImGui::TextWrapped("N = %s", vecText(f.n).c_str());
  tooltip(w, "N = normalize(PRP − VRP): the view plane normal; the eye lies on +N.");
  // Broken between the three, never inside one ("dmax =" above "11.63" on a tablet): no-break spaces
  // (U+00A0, which ImGui's word wrap does not break at) within each.
  ImGui::TextWrapped("VPD\u00a0=\u00a0%s   dmin\u00a0=\u00a0%s   dmax\u00a0=\u00a0%s", num(f.vpd).c_str(), num(f.dmin).c_str(),
                     num(f.dmax).c_str());
  tooltip(w, "VPD = |PRP − VRP|, the view plane distance. dmin = VPD − F and dmax = VPD − B: the distances "
             "of the front and back planes from the eye.");
}

/// The fields that make the camera invalid (their rects' ids): what the student must change.
std::vector<std::string_view> offendingFields(const CameraProblem& p, const Camera& c) {
  auto finite = [](const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  std::vector<std::string_view> ids;
  using K = CameraProblem::Kind;
  switch (p.kind) {
    case K::vectorsNotFinite:
      for (const auto& [id, v] : {std::pair{"camera.vrp", c.vrp}, {"camera.prp", c.prp}, {"camera.vup", c.vup}})
        if (!finite(v)) ids.push_back(id);
      break;
    case K::planesNotFinite:
      for (const auto& [id, v] : {std::pair{"camera.xmin", c.window.xmin}, {"camera.xmax", c.window.xmax},
                                  {"camera.ymin", c.window.ymin}, {"camera.ymax", c.window.ymax},
                                  {"camera.front", c.front}, {"camera.back", c.back}})
        if (!std::isfinite(v)) ids.push_back(id);
      break;
    case K::prpOnVrp: ids = {"camera.vrp", "camera.prp"}; break;
    case K::vupZero: ids = {"camera.vup"}; break;
    case K::vupAlongN: ids = {"camera.vup", "camera.prp", "camera.vrp"}; break;
    case K::windowX: ids = {"camera.xmin", "camera.xmax"}; break;
    case K::windowY: ids = {"camera.ymin", "camera.ymax"}; break;
    case K::backNotBehindFront: ids = {"camera.front", "camera.back"}; break;
    case K::frontBehindEye: ids = {"camera.front", "camera.prp"}; break;
    case K::obliqueFactors: ids = {"camera.oblique.d", "camera.oblique.phi"}; break;
    case K::mappingNotFinite: ids = {"camera.vrp", "camera.prp", "camera.front", "camera.back"}; break;
  }
  return ids;
}

}  // namespace

void cameraPanel(Widgets& w, DocumentPart& d, const RunPart& r, LayoutPart& l) {
  Camera& c = d.doc.scene().camera;
  const std::optional<CameraProblem> problem = cameraProblem(c);
  const std::vector<std::string_view> offending = problem ? offendingFields(*problem, c) : std::vector<std::string_view>{};
  // An offending field gets a red frame, drawn over the field just drawn (its rect, recorded by the widget).
  auto mark = [&](const char* id) {
    if (std::find(offending.begin(), offending.end(), std::string_view(id)) == offending.end()) return;
    const RectLog* log = rectLog();
    if (!log) return;
    const auto it = log->rects.find(id);
    if (it == log->rects.end()) return;
    // Inside the field's sides (the panel clips at them) and just outside its top and bottom.
    const ImVec4& field = it->second;
    const float thick = std::max(2.f, ImGui::GetFontSize() / 8), pad = ImGui::GetStyle().ItemSpacing.y * 0.4f;
    ImGui::GetWindowDrawList()->AddRect(ImVec2(field.x + thick * 0.5f, field.y - pad),
                                        ImVec2(field.x + field.z - thick * 0.5f, field.y + field.w + pad), errorColour(), 0, 0, thick);
  };
  scrollAnchor(w, "camera.points");
  dragVec3(w, "VRP", "camera.vrp", c.vrp);
  mark("camera.vrp");
  tooltip(w, "View reference point: the point looked at, origin of VRC (WC).");
  dragVec3(w, "PRP", "camera.prp", c.prp);
  mark("camera.prp");
  tooltip(w, "Projection reference point: the eye, the centre of projection (WC).");
  dragVec3(w, "VUP", "camera.vup", c.vup);
  mark("camera.vup");
  tooltip(w, "View up vector: which way is up; projected into the view plane it gives V.");

  scrollAnchor(w, "camera.window");
  section(tr(w, "window (view plane, VRC)"));
  ViewWindow& win = c.window;
  const double aspect = d.doc.scene().device.aspect();
  bool xChanged = dragDouble(w, "xmin", "camera.xmin", win.xmin);
  mark("camera.xmin");
  xChanged |= dragDouble(w, "xmax", "camera.xmax", win.xmax);
  mark("camera.xmax");
  bool yChanged = dragDouble(w, "ymin", "camera.ymin", win.ymin);
  mark("camera.ymin");
  yChanged |= dragDouble(w, "ymax", "camera.ymax", win.ymax);
  mark("camera.ymax");
  if (checkbox(tr(w, "keep the device's aspect ratio"), &l.keepAspect) && l.keepAspect) xChanged = true;
  if (l.keepAspect && (xChanged || yChanged)) keepWindowAspect(win, aspect, xChanged);
  tooltip(w, "The window's width : height stays the device's W : H, so nothing is stretched.");

  scrollAnchor(w, "camera.planes");
  section(tr(w, "front and back planes (VRC z)"));
  dragDouble(w, tr(w, "front F"), "camera.front", c.front);
  mark("camera.front");
  tooltip(w, "F: the front (near) plane z = F in VRC; maps to NPC z = 1. Needs B < F (< VPD in perspective).");
  dragDouble(w, tr(w, "back B"), "camera.back", c.back);
  mark("camera.back");
  tooltip(w, "B: the back (far) plane z = B in VRC; maps to NPC z = 0.");

  section(tr(w, "projection"));
  int p = int(c.projection);
  radio(tr(w, "perspective"), &p, int(Projection::perspective));
  ImGui::SameLine();
  radio(tr(w, "parallel"), &p, int(Projection::parallel));
  ImGui::SameLine();
  radio(tr(w, "oblique"), &p, int(Projection::oblique));
  c.projection = Projection(p);
  if (c.projection == Projection::oblique) {
    dragDouble(w, "d", "camera.oblique.d", c.oblique.d, 0.01f, 0.0, 4.0);
    mark("camera.oblique.d");
    tooltip(w, "d = 1 / tan α: how much a unit of depth is shortened (lecture notes 14.3.2).");
    dragDouble(w, tr(w, "phi (deg)"), "camera.oblique.phi", c.oblique.phiDeg, 0.5f, -180.0, 180.0, "%.1f");
    mark("camera.oblique.phi");
    tooltip(w, "φ: the angle under which depth is drawn in the view plane.");
    if (ImGui::Button(tr(w, "cavalier (d = 1, φ = 35°)"))) c.oblique = kCavalier;
    sameLineIfFits(tr(w, "cabinet (d = 0.5, φ = 50°)"));
    if (ImGui::Button(tr(w, "cabinet (d = 0.5, φ = 50°)"))) c.oblique = kCabinet;
  }
  ImGui::Separator();
  if (!d.doc.error().empty()) {
    // The camera's own problem in the viewer's language; another of the scene as the document says it.
    errorText(problem ? cameraProblemText(*problem, c, w.language()) : d.doc.error());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", tr(w, "The views show the last valid camera."));
    ImGui::PopStyleColor();
  } else {
    scrollAnchor(w, "camera.derived");
    derived(w, r);
  }
}

}  // namespace vplab::ui
