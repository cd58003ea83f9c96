#include "app/inspect/vanishing_text.h"

#include "app/text/catalogue.h"
#include "app/views/number_text.h"
#include "pipeline/vanishing_points.h"

namespace vplab {

bool parallelToViewPlane(const VrcAxes& frame, const Vec3& directionWc) {
  const double length = glm::length(directionWc);
  return length > 0 && std::abs(glm::dot(directionWc, frame.n)) <= 1e-9 * length;
}

VanishingText vanishingText(const PipelineRun& run, const ObjectRun& object, Language lang) {
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  const auto vps = vanishingPoints(run, object.wcFromMc);
  const Projection projection = run.camera.projection;
  VanishingText t;
  if (projection == Projection::perspective)
    t.headline =
        text::fill(lang, "{1}: {2}-point perspective", {nameIn(object, lang), std::to_string(vanishingPointCount(vps))});
  else if (projection == Projection::oblique)
    t.headline = text::fill(lang, "{1}: oblique parallel projection, no vanishing points", {nameIn(object, lang)});
  else
    t.headline = text::fill(lang, "{1}: orthographic parallel projection, no vanishing points", {nameIn(object, lang)});
  for (int i = 0; i < 3; ++i) {
    const VanishingPoint& vp = vps[size_t(i)];
    const bool parallel = parallelToViewPlane(run.vrc, vp.directionWc);
    t.parallelToViewPlane[size_t(i)] = parallel;
    std::string& s = t.axes[size_t(i)];
    const std::string_view axis = kAxis[i];
    if (parallel) {
      s = text::fill(lang, "{1} axis: parallel to the view plane, so its edges stay parallel in the image", {axis});
    } else if (projection != Projection::perspective) {
      s = text::fill(lang,
                     "{1} axis: not parallel to the view plane, but the projectors are parallel, so its edges stay "
                     "parallel in the image",
                     {axis});
    } else if (vp.finite) {
      const NumberFormat f{4};
      s = text::fill(lang, "{1} axis: not parallel to the view plane: its edges meet at DC ({2}, {3})",
                     {axis, formatNumber(vp.dc.x, f), formatNumber(vp.dc.y, f)});
    } else {
      s = text::fill(lang, "{1} axis: almost parallel to the view plane: its vanishing point lies too far out to show",
                     {axis});
    }
  }
  return t;
}

}  // namespace vplab
