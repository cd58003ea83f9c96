// A lesson step's object, framed (issue 37: "the view that shows the step's object is framed on it
// and given the room"): a step that steps through a polygon's clipping shows it in the NPC view,
// turned to where it shows largest and zoomed to the polygon as the step's pass leaves it; a step that
// probes a vertex shows the probed object in the world view, its angles kept.
#pragma once

#include "app/lessons/lesson.h"

namespace vplab {

/// How much of a view's shorter side the framed object fills: enough to read it from the back row
/// (it covers a fifth of the view and more), and room around it for the cube's or the frustum's
/// edges that place it.
inline constexpr double kLessonFramingFill = 0.72;

/// Frames `state`'s views on its step's objects, in views of `aspect` (width / height). A view whose
/// orbit the step's file sets (`ownWorldOrbit`, `ownNpcOrbit`) keeps it.
void frameStepObjects(LessonState& state, double aspect, bool ownWorldOrbit, bool ownNpcOrbit);

/// The points the NPC view is framed on for a step-through: the polygon the step shows (as it
/// enters, or after the step's pass), in NPC where w > 0, held to the unit cube (the part the view
/// volume keeps). Empty when there are none.
std::vector<Vec3> steppedPolygonPoints(const Scene& scene, const LessonStepThrough& step);

/// The probed object's vertices in WC. Empty when it has none.
std::vector<Vec3> probedObjectPoints(const Scene& scene, const Probe& probe);

}  // namespace vplab
