#include "pipeline/camera.h"

#include "base/error.h"
#include "pipeline/view_mapping.h"

#include <algorithm>

namespace vplab {

namespace {

// The largest |component|. Unlike glm::length it cannot overflow: glm::length squares the
// components and is infinite beyond about 1e154, which made large but valid values look like zero
// vectors after glm::normalize (and gave misleading messages such as "PRP equals VRP").
double maxAbs(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// lecture notes 15.2.2: N points from VRP to the eye, U = VUP × N, V = N × U. No checks here.
VrcAxes frameUnchecked(const Camera& c) {
  VrcAxes f{};
  const Vec3 toEye = c.prp - c.vrp;
  f.vpd = glm::length(toEye);
  f.n = toEye / f.vpd;
  f.u = glm::normalize(glm::cross(c.vup / maxAbs(c.vup), f.n));  // only VUP's direction matters
  f.v = glm::cross(f.n, f.u);
  f.dmin = f.vpd - c.front;
  f.dmax = f.vpd - c.back;
  return f;
}

// Relative tolerances: a camera closer than this to degenerate would give matrices dominated by
// rounding error, so it is refused with the same message as the exactly degenerate one.
constexpr double kDegenerate = 1e-12;
constexpr double kParallelSine = 1e-9;  // |VUP × N| / |VUP| below this: VUP parallel to N

std::optional<CameraProblem> inputProblem(const Camera& c) {
  using K = CameraProblem::Kind;
  if (!isFinite(c.vrp) || !isFinite(c.prp) || !isFinite(c.vup)) return CameraProblem{K::vectorsNotFinite};
  const ViewWindow& w = c.window;
  if (!isFinite(w.xmin) || !isFinite(w.xmax) || !isFinite(w.ymin) || !isFinite(w.ymax) ||
      !isFinite(c.front) || !isFinite(c.back))
    return CameraProblem{K::planesNotFinite};
  const double scale = std::max({1.0, maxAbs(c.vrp), maxAbs(c.prp)});
  if (glm::length(c.prp - c.vrp) <= kDegenerate * scale) return CameraProblem{K::prpOnVrp};
  if (glm::length(c.vup) <= kDegenerate) return CameraProblem{K::vupZero};
  const Vec3 n = glm::normalize((c.prp - c.vrp) / maxAbs(c.prp - c.vrp));
  if (glm::length(glm::cross(glm::normalize(c.vup / maxAbs(c.vup)), n)) <= kParallelSine)
    return CameraProblem{K::vupAlongN, n};
  if (!(w.xmax > w.xmin)) return CameraProblem{K::windowX};
  if (!(w.ymax > w.ymin)) return CameraProblem{K::windowY};
  if (!(c.back < c.front)) return CameraProblem{K::backNotBehindFront};
  if (c.projection == Projection::perspective) {
    const double vpd = glm::length(c.prp - c.vrp);
    if (!(c.front < vpd)) return CameraProblem{K::frontBehindEye, Vec3(0), vpd};
  }
  if (c.projection == Projection::oblique &&
      (!isFinite(c.oblique.d) || !isFinite(c.oblique.phiDeg) || c.oblique.d < 0))
    return CameraProblem{K::obliqueFactors};
  return std::nullopt;
}

/// The problem in English, naming the camera's values.
std::string englishText(const CameraProblem& p, const Camera& c) {
  const ViewWindow& w = c.window;
  switch (p.kind) {
    case CameraProblem::Kind::vectorsNotFinite:
      return "VRP " + format(c.vrp) + ", PRP " + format(c.prp) + " and VUP " + format(c.vup) + " must be finite numbers";
    case CameraProblem::Kind::planesNotFinite: return "the window and the front and back planes must be finite numbers";
    case CameraProblem::Kind::prpOnVrp:
      return "PRP " + format(c.prp) + " equals VRP " + format(c.vrp) + ": the view plane normal N = PRP − VRP is undefined";
    case CameraProblem::Kind::vupZero: return "VUP " + format(c.vup) + " is the zero vector: the camera has no up direction";
    case CameraProblem::Kind::vupAlongN:
      return "VUP " + format(c.vup) + " is parallel to the view plane normal N " + format(p.n) +
             " (PRP − VRP): U = VUP × N is undefined";
    case CameraProblem::Kind::windowX:
      return "the window needs xmin < xmax, but xmin = " + format(w.xmin) + ", xmax = " + format(w.xmax);
    case CameraProblem::Kind::windowY:
      return "the window needs ymin < ymax, but ymin = " + format(w.ymin) + ", ymax = " + format(w.ymax);
    case CameraProblem::Kind::backNotBehindFront:
      return "the back plane must lie behind the front plane (B < F), but B = " + format(c.back) + ", F = " + format(c.front);
    case CameraProblem::Kind::frontBehindEye:
      return "perspective needs the front plane in front of the eye (F < VPD), but F = " + format(c.front) +
             ", VPD = |PRP − VRP| = " + format(p.vpd) + " (dmin = VPD − F = " + format(p.vpd - c.front) + " must be > 0)";
    case CameraProblem::Kind::obliqueFactors:
      return "the oblique projection needs a finite shortening factor d ≥ 0 and a finite angle phi, but d = " +
             format(c.oblique.d) + ", phi = " + format(c.oblique.phiDeg);
    case CameraProblem::Kind::mappingNotFinite:
      return "the camera's values are too large or too small: the view mapping is not finite (window " + format(w.xmin) +
             ".." + format(w.xmax) + " × " + format(w.ymin) + ".." + format(w.ymax) + ", VPD " + format(p.vpd) + ")";
  }
  return "?";
}

}  // namespace

std::optional<CameraProblem> cameraProblem(const Camera& camera) {
  if (auto p = inputProblem(camera)) return p;
  // Finite inputs can still overflow (a window 1e-300 wide): check what the stages will use.
  const VrcAxes f = frameUnchecked(camera);
  const Mat4 m = npcFromVrc(camera, f) * vrcFromWc(f, camera.vrp);
  if (!isFinite(m) || !isFinite(f.u) || !isFinite(f.v) || !isFinite(f.n))
    return CameraProblem{CameraProblem::Kind::mappingNotFinite, Vec3(0), f.vpd};
  return std::nullopt;
}

std::optional<std::string> cameraError(const Camera& camera) {
  if (auto p = cameraProblem(camera)) return englishText(*p, camera);
  return std::nullopt;
}

VrcAxes vrcAxes(const Camera& camera) {
  if (auto e = cameraError(camera)) throw Error("invalid camera: " + *e);
  return frameUnchecked(camera);
}

Mat4 vrcFromWc(const VrcAxes& f, const Vec3& vrp) {
  // clang-format off
  const Mat4 rotate = matrixFromRows(
      f.u.x, f.u.y, f.u.z, 0,
      f.v.x, f.v.y, f.v.z, 0,
      f.n.x, f.n.y, f.n.z, 0,
      0,     0,     0,     1);
  const Mat4 translate = matrixFromRows(
      1, 0, 0, -vrp.x,
      0, 1, 0, -vrp.y,
      0, 0, 1, -vrp.z,
      0, 0, 0, 1);
  // clang-format on
  return rotate * translate;
}

Mat4 vrcFromWc(const Camera& camera) { return vrcFromWc(vrcAxes(camera), camera.vrp); }

}  // namespace vplab
