#include "pipeline/vanishing_points.h"

namespace vplab {

std::array<VanishingPoint, 3> vanishingPoints(const PipelineRun& run, const Mat4& wcFromMc) {
  std::array<VanishingPoint, 3> points;
  for (int axis = 0; axis < 3; ++axis) {
    VanishingPoint& vp = points[size_t(axis)];
    vp.directionWc = glm::normalize(Vec3(wcFromMc[axis]));  // column `axis`: the image of the MC axis
    const Vec4 h = run.npcFromWc * Vec4(vp.directionWc, 0.0);
    // |w| relative to the size of the direction's image: below this the lines are parallel in the
    // image up to rounding, and the point would lie beyond 1e9 window widths.
    const double scale = glm::length(Vec3(h));
    vp.finite = run.camera.projection == Projection::perspective && std::abs(h.w) > 1e-9 * std::max(scale, 1e-300);
    if (!vp.finite) continue;
    vp.npc = Vec3(h) / h.w;
    vp.dc = Vec2(run.dcFromNpc * Vec4(vp.npc, 1.0));
  }
  return points;
}

int vanishingPointCount(const std::array<VanishingPoint, 3>& points) {
  int n = 0;
  for (const VanishingPoint& p : points) n += p.finite;
  return n;
}

}  // namespace vplab
