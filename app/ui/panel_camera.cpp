// The camera panel: the synthetic camera's parameters (lecture notes 15.1–15.2) and what follows from them.
#include "app/ui/panels.h"
#include "app/core/camera_text.h"
#include "app/core/picking.h"
#include "app/ui/widgets.h"

namespace vplab::ui {

namespace {

void derived(const ViewerState& s) {
  const VrcAxes& f = s.run().vrc;
  ImGui::TextDisabled("%s", tr(s, "derived"));
  ImGui::TextWrapped("U = %s", vecText(f.u).c_str());
  tooltip(s, "U = normalize(VUP × N): the view plane's x axis.");
  ImGui::TextWrapped("V = %s", vecText(f.v).c_str());
  tooltip(s, "V = N × U: the view plane's y axis, VUP projected into the view plane.");
  ImGui::TextWrapped("N = %s", vecText(f.n).c_str());
  tooltip(s, "N = normalize(PRP − VRP): the view plane normal; the eye lies on +N.");
  ImGui::TextWrapped("VPD = %s   dmin = %s   dmax = %s", num(f.vpd).c_str(), num(f.dmin).c_str(), num(f.dmax).c_str());
  tooltip(s, "VPD = |PRP − VRP|, the view plane distance. dmin = VPD − F and dmax = VPD − B: the distances "
             "of the front and back planes from the eye.");
}

}  // namespace

void cameraPanel(ViewerState& s) {
  Camera& c = s.doc.scene().camera;
  dragVec3(s, "VRP", "camera.vrp", c.vrp);
  tooltip(s, "View reference point: the point looked at, origin of VRC (WC).");
  dragVec3(s, "PRP", "camera.prp", c.prp);
  tooltip(s, "Projection reference point: the eye, the centre of projection (WC).");
  dragVec3(s, "VUP", "camera.vup", c.vup);
  tooltip(s, "View up vector: which way is up; projected into the view plane it gives V.");

  section(tr(s, "window (view plane, VRC)"));
  ViewWindow& w = c.window;
  const double aspect = s.doc.scene().device.aspect();
  bool xChanged = dragDouble(s, "xmin", "camera.xmin", w.xmin);
  xChanged |= dragDouble(s, "xmax", "camera.xmax", w.xmax);
  bool yChanged = dragDouble(s, "ymin", "camera.ymin", w.ymin);
  yChanged |= dragDouble(s, "ymax", "camera.ymax", w.ymax);
  if (checkbox(tr(s, "keep the device's aspect ratio"), &s.keepAspect) && s.keepAspect) xChanged = true;
  if (s.keepAspect && (xChanged || yChanged)) keepWindowAspect(w, aspect, xChanged);
  tooltip(s, "The window's width : height stays the device's W : H, so nothing is stretched.");

  section(tr(s, "front and back planes (VRC z)"));
  dragDouble(s, tr(s, "front F"), "camera.front", c.front);
  tooltip(s, "F: the front (near) plane z = F in VRC; maps to NPC z = 1. Needs B < F (< VPD in perspective).");
  dragDouble(s, tr(s, "back B"), "camera.back", c.back);
  tooltip(s, "B: the back (far) plane z = B in VRC; maps to NPC z = 0.");

  section(tr(s, "projection"));
  int p = int(c.projection);
  radio(tr(s, "perspective"), &p, int(Projection::perspective));
  ImGui::SameLine();
  radio(tr(s, "parallel"), &p, int(Projection::parallel));
  ImGui::SameLine();
  radio(tr(s, "oblique"), &p, int(Projection::oblique));
  c.projection = Projection(p);
  if (c.projection == Projection::oblique) {
    dragDouble(s, "d", "camera.oblique.d", c.oblique.d, 0.01f, 0.0, 4.0);
    tooltip(s, "d = 1 / tan α: how much a unit of depth is shortened (lecture notes 14.3.2).");
    dragDouble(s, tr(s, "phi (deg)"), "camera.oblique.phi", c.oblique.phiDeg, 0.5f, -180.0, 180.0, "%.1f");
    tooltip(s, "φ: the angle under which depth is drawn in the view plane.");
    if (ImGui::Button(tr(s, "cavalier (d = 1, φ = 35°)"))) c.oblique = kCavalier;
    sameLineIfFits(tr(s, "cabinet (d = 0.5, φ = 50°)"));
    if (ImGui::Button(tr(s, "cabinet (d = 0.5, φ = 50°)"))) c.oblique = kCabinet;
  }
  ImGui::Separator();
  if (!s.doc.error().empty()) {
    // The camera's own problem in the viewer's language; another of the scene as the document says it.
    const std::optional<CameraProblem> problem = cameraProblem(c);
    errorText(problem ? cameraProblemText(*problem, c, s.display.language) : s.doc.error());
    ImGui::TextDisabled("%s", tr(s, "The views show the last valid camera."));
  } else {
    derived(s);
  }
}

}  // namespace vplab::ui
