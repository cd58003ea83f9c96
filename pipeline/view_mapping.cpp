#include "pipeline/view_mapping.h"

namespace vplab {

Mat4 perspectiveNpcFromVrc(const ViewWindow& w, double vpd, double front, double back) {
  const double d = vpd;
  const double dmin = vpd - front;
  const double dmax = vpd - back;
  const double dx = w.xmax - w.xmin;
  const double dy = w.ymax - w.ymin;
  const double k = dmin / (dmax - dmin);
  // x' = (d·x − xmin·ze)/Δx, y' = (d·y − ymin·ze)/Δy, z' = dmin·(dmax − ze)/(dmax − dmin), w' = ze
  // with ze = VPD − z. The seed's last mirror (its left-handed z) is already folded in.
  // clang-format off
  return matrixFromRows(
      d / dx, 0,      w.xmin / dx, -w.xmin * vpd / dx,
      0,      d / dy, w.ymin / dy, -w.ymin * vpd / dy,
      0,      0,      k,            k * (dmax - vpd),
      0,      0,      -1,           vpd);
  // clang-format on
}

Mat4 obliqueShear(const ObliqueParams& ob) {
  const double phi = radians(ob.phiDeg);
  const double sx = ob.d * std::cos(phi);
  const double sy = -ob.d * std::sin(phi);
  // A point one unit behind the view plane (z = −1) moves to (x − d·cos φ, y + d·sin φ).
  // clang-format off
  return matrixFromRows(
      1, 0, sx, 0,
      0, 1, sy, 0,
      0, 0, 1,  0,
      0, 0, 0,  1);
  // clang-format on
}

Mat4 parallelNpcFromVrc(const ViewWindow& w, double front, double back, const ObliqueParams& ob) {
  const double dx = w.xmax - w.xmin;
  const double dy = w.ymax - w.ymin;
  const double dz = front - back;
  // clang-format off
  const Mat4 toCube = matrixFromRows(
      1 / dx, 0,      0,      -w.xmin / dx,
      0,      1 / dy, 0,      -w.ymin / dy,
      0,      0,      1 / dz, -back / dz,
      0,      0,      0,      1);
  // clang-format on
  return toCube * obliqueShear(ob);
}

Mat4 npcFromVrc(const Camera& c, const VrcAxes& f) {
  switch (c.projection) {
    case Projection::perspective: return perspectiveNpcFromVrc(c.window, f.vpd, c.front, c.back);
    case Projection::parallel: return parallelNpcFromVrc(c.window, c.front, c.back, {0.0, 0.0});
    case Projection::oblique: return parallelNpcFromVrc(c.window, c.front, c.back, c.oblique);
  }
  return Mat4(1.0);
}

Mat4 npcFromVrc(const Camera& camera) { return npcFromVrc(camera, vrcAxes(camera)); }

double npcDepthOfVrcZ(const Camera& c, const VrcAxes& f, double vrcZ) {
  if (c.projection != Projection::perspective) return (vrcZ - c.back) / (c.front - c.back);
  const double ze = f.vpd - vrcZ;
  return f.dmin * (f.dmax - ze) / ((f.dmax - f.dmin) * ze);
}

double depthResolution(const Camera& c, const VrcAxes& f, double vrcZ, int bits) {
  const double step = 1.0 / (std::ldexp(1.0, bits) - 1.0);
  if (c.projection != Projection::perspective) return step * (c.front - c.back);
  const double ze = f.vpd - vrcZ;
  return step * (f.dmax - f.dmin) * ze * ze / (f.dmin * f.dmax);
}

}  // namespace vplab
