// The Lecture tab's explanation of an object's vanishing points (lecture notes 14.2), made from the actual
// geometry: which of the object's principal axes are parallel to the view plane for this camera,
// and whether the projection is a perspective one at all (parallel and oblique projections keep
// every set of parallel edges parallel, whatever their direction).
#pragma once

#include "base/language.h"
#include "pipeline/pipeline.h"

#include <array>
#include <string>

namespace vplab {

struct VanishingText {
  std::string headline;              // "cube: 2-point perspective", "cube: oblique parallel projection …"
  std::array<std::string, 3> axes;   // one sentence per MC axis x, y, z
  std::array<bool, 3> parallelToViewPlane{};  // the geometry the sentences say
};

/// Whether a WC direction is parallel to the view plane: its VRC z component is 0, relative to its
/// length (1e-9, far below anything a lecture shows, far above rounding of unit vectors).
bool parallelToViewPlane(const VrcAxes& frame, const Vec3& directionWc);

/// The sentences in `lang`.
VanishingText vanishingText(const PipelineRun& run, const ObjectRun& object, Language lang = Language::en);

}  // namespace vplab
