// Between two steps of a lesson (app/lessons/lesson.h) the camera and every number move over a short
// time instead of jumping, so that the class sees what changed. Every state on the way is one the
// lab can show: every intermediate camera is valid (cameraError is empty), which a straight blend of
// the camera's vectors would not give (VUP may turn parallel to N, PRP may pass through VRP).
//
// The camera is blended as the lecture builds it (lecture notes 15.2.2): VRP moves on a straight
// line; the orientation U, V, N turns on the shortest rotation (a quaternion's slerp), so N and the
// up direction V stay perpendicular; the eye stays on N at a distance VPD blended linearly; the
// window, F and B are blended linearly. Linear blends keep strict inequalities that hold at both
// ends (xmin < xmax, B < F, F < VPD), so every intermediate camera keeps them too.
#pragma once

#include "app/lessons/lesson.h"

namespace vplab {

/// The camera at `t` (0: `a`, 1: `b`, exactly) between two valid cameras. The projection changes
/// where no constraint can break: to perspective only at the end (a parallel camera's F may lie
/// beyond the eye), away from it at once.
Camera cameraBetween(const Camera& a, const Camera& b, double t);

/// The observer at `t`: the target and distance blended, the yaw by the shorter way round.
Orbit orbitBetween(const Orbit& a, const Orbit& b, double t);

/// Whether a step's scene can be blended into the next's: the same scene (objects of the same shapes
/// and meshes, in the same order). Another scene is shown at once.
bool sameSceneObjects(const Scene& a, const Scene& b);

/// Whether a move from `a` to `b` can be shown as a blend: the same scene objects (sameSceneObjects)
/// and valid numbers at both ends (a valid camera, valid transforms). A class may leave
/// an invalid camera in a free step (VUP typed parallel to N); a blend from it has no valid first
/// half, so the move to the next step is a cut (issue 37: no lesson move may end the lecture).
bool blendable(const LessonState& a, const LessonState& b);

/// The state at `t` between two steps' states: the camera, the objects' transforms, the user clip
/// planes, the observers and the morph's t blended; what has no between (styles, overlays, the
/// strategy, visibility, the tab and the step's marks) is `a`'s until halfway, then `b`'s. With
/// states that cannot be blended (blendable), `b` at any t > 0. t = 0 is `a` and t = 1 is
/// `b`, exactly.
LessonState stateBetween(const LessonState& a, const LessonState& b, double t);

/// Slow in, slow out: the fraction of a transition shown at the fraction `x` of its time.
double easeInOut(double x);

}  // namespace vplab
