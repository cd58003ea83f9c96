#include "app/core/vanishing_text.h"

#include "app/views/number_text.h"
#include "pipeline/vanishing_points.h"

namespace vplab {

bool parallelToViewPlane(const VrcAxes& frame, const Vec3& directionWc) {
  const double length = glm::length(directionWc);
  return length > 0 && std::abs(glm::dot(directionWc, frame.n)) <= 1e-9 * length;
}

VanishingText vanishingText(const PipelineRun& run, const ObjectRun& object) {
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  const auto vps = vanishingPoints(run, object.wcFromMc);
  const Projection projection = run.camera.projection;
  VanishingText t;
  if (projection == Projection::perspective)
    t.headline = object.name + ": " + std::to_string(vanishingPointCount(vps)) + "-point perspective";
  else
    t.headline = object.name + ": " + (projection == Projection::oblique ? "oblique" : "orthographic") +
                 " parallel projection, no vanishing points";
  for (int i = 0; i < 3; ++i) {
    const VanishingPoint& vp = vps[size_t(i)];
    const bool parallel = parallelToViewPlane(run.vrc, vp.directionWc);
    t.parallelToViewPlane[size_t(i)] = parallel;
    std::string& s = t.axes[size_t(i)];
    s = std::string(kAxis[i]) + " axis: ";
    if (parallel) {
      s += "parallel to the view plane, so its edges stay parallel in the image";
    } else if (projection != Projection::perspective) {
      s += "not parallel to the view plane, but the projectors are parallel, so its edges stay parallel "
           "in the image";
    } else if (vp.finite) {
      const NumberFormat f{4};
      s += "not parallel to the view plane: its edges meet at DC (" + formatNumber(vp.dc.x, f) + ", " +
           formatNumber(vp.dc.y, f) + ")";
    } else {
      s += "almost parallel to the view plane: its vanishing point lies too far out to show";
    }
  }
  return t;
}

}  // namespace vplab
