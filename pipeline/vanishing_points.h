// Vanishing points (lecture notes 14.2): in a perspective projection, lines parallel to a direction d that is
// not parallel to the view plane meet in one image point, the image of the point at infinity
// (d, 0). With homogeneous coordinates that is simply npcFromWc · (d, 0), divided by its w. A box
// seen with one, two or three of its axes not parallel to the view plane shows one, two or three
// vanishing points (lecture notes figure 14.2).
#pragma once

#include "pipeline/pipeline.h"

#include <array>

namespace vplab {

struct VanishingPoint {
  Vec3 directionWc;  // the object's MC axis in WC
  bool finite = false;  // false: the axis is parallel to the view plane (its lines stay parallel)
  Vec3 npc{0};       // after the division
  Vec2 dc{0};
};

/// The vanishing points of an object's principal (MC x, y, z) axes for the run's camera. All are
/// infinite (finite = false) for parallel projections.
std::array<VanishingPoint, 3> vanishingPoints(const PipelineRun& run, const Mat4& wcFromMc);

/// How many of them are finite: 1, 2 or 3 point perspective (0 for parallel projections).
int vanishingPointCount(const std::array<VanishingPoint, 3>& points);

}  // namespace vplab
