#include "app/inspect/camera_text.h"

#include "app/text/catalogue.h"

namespace vplab {

std::string cameraProblemText(const CameraProblem& p, const Camera& c, Language lang) {
  using K = CameraProblem::Kind;
  const ViewWindow& w = c.window;
  auto say = [lang](text::Text t, std::initializer_list<std::string_view> values) { return text::fill(lang, t, values); };
  switch (p.kind) {
    case K::vectorsNotFinite:
      return say("VRP {1}, PRP {2} and VUP {3} must be finite numbers", {format(c.vrp), format(c.prp), format(c.vup)});
    case K::planesNotFinite: return say("the window and the front and back planes must be finite numbers", {});
    case K::prpOnVrp:
      return say("PRP {1} equals VRP {2}: the view plane normal N = PRP − VRP is undefined", {format(c.prp), format(c.vrp)});
    case K::vupZero: return say("VUP {1} is the zero vector: the camera has no up direction", {format(c.vup)});
    case K::vupAlongN:
      return say("VUP {1} is parallel to the view plane normal N {2} (PRP − VRP): U = VUP × N is undefined",
                 {format(c.vup), format(p.n)});
    case K::windowX: return say("the window needs xmin < xmax, but xmin = {1}, xmax = {2}", {format(w.xmin), format(w.xmax)});
    case K::windowY: return say("the window needs ymin < ymax, but ymin = {1}, ymax = {2}", {format(w.ymin), format(w.ymax)});
    case K::backNotBehindFront:
      return say("the back plane must lie behind the front plane (B < F), but B = {1}, F = {2}", {format(c.back), format(c.front)});
    case K::frontBehindEye:
      return say("perspective needs the front plane in front of the eye (F < VPD), but F = {1}, VPD = |PRP − VRP| = {2} "
                 "(dmin = VPD − F = {3} must be > 0)",
                 {format(c.front), format(p.vpd), format(p.vpd - c.front)});
    case K::obliqueFactors:
      return say("the oblique projection needs a finite shortening factor d ≥ 0 and a finite angle phi, but d = {1}, phi = {2}",
                 {format(c.oblique.d), format(c.oblique.phiDeg)});
    case K::mappingNotFinite:
      return say("the camera's values are too large or too small: the view mapping is not finite "
                 "(window {1}..{2} × {3}..{4}, VPD {5})",
                 {format(w.xmin), format(w.xmax), format(w.ymin), format(w.ymax), format(p.vpd)});
  }
  return "?";
}

}  // namespace vplab
