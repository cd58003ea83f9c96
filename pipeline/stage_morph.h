// The stage morph (docs/lecturers.md "The viewer": lecture features): one slider t from 0 to 4 moves a vertex
// through the stages, interpolating between neighbouring ones:
//   t = 0 MC → 1 WC → 2 VRC → 2.5 homogeneous NPC (before the division, drawn as its x, y, z)
//     → 3 NPC (after the division) → 4 DC
// The division by w is its own step (2.5 → 3): x, y, z are divided by a w that grows linearly from
// 1 to the vertex's w, so the frustum visibly turns into the cube (lecture notes 15.2.4). DC is drawn in
// units of the device height with y pointing down from the top-left origin: (x_dc / H, −y_dc / H, z).
#pragma once

#include "pipeline/device_mapping.h"
#include "pipeline/math.h"

#include <string_view>

namespace vplab {

/// A vertex in every stage (as a run keeps them).
struct StageValues {
  Vec3 mc, wc, vrc;
  Vec4 npcH;  // w > 0: morphed vertices are inside the view volume (clipped polygons)
  Vec3 dc;
};

inline constexpr double kMorphEnd = 4.0;

/// The position drawn at t ∈ [0, 4] (clamped).
Vec3 morphPosition(const StageValues& v, double t, const Device& device);

/// "MC", "MC → WC", "WC", …: the stage at t, or the step between two stages.
std::string_view morphStageName(double t);
/// The matrix (or operation) of the step at t, for the label: "wcFromMc", "vrcFromWc",
/// "npcFromVrc", "÷ w", "dcFromNpc".
std::string_view morphStepName(double t);

}  // namespace vplab
