// The observers of the world and NPC views: an orbit (target, yaw, pitch, distance, field of view)
// turned into a synthetic camera of the pipeline itself, so these views use the very same stage
// functions as the scene camera (and no other projection matrix).
#pragma once

#include "pipeline/camera.h"
#include "pipeline/scene.h"

namespace vplab {

struct Orbit {
  Vec3 target{0, 0, 0};
  double yawDeg = 35;     // about the WC y axis, 0 looks along −z
  double pitchDeg = 22;   // above the xz plane, limited to ±89°
  double distance = 12;   // eye to target
  double fovDeg = 40;     // vertical field of view
  bool operator==(const Orbit&) const = default;
};

/// VRP = target, PRP on the orbit, VUP = +y, the window filling the field of view in the view plane
/// through the target (`fovDeg` spans the view's shorter side: its height, or its width in a view
/// taller than wide, `aspect` = width / height < 1), front and back planes at 1% and 10000% of the distance from the eye.
Camera observerCamera(const Orbit& orbit, double aspect);

/// An orbit that shows the scene camera's VRP, PRP, view volume and the objects, seen from the side
/// and above, framed to fill a view of the given aspect ratio.
Orbit defaultWorldOrbit(const Scene& scene, double aspect = 4.0 / 3.0);
/// The default world orbit turned (its yaw by up to ±25°, its pitch 18° to 40°) to where the scene
/// camera's view volume is drawn largest, everything still framed (the exercise sheets' figures,
/// issue 38: the view volume is the subject).
Orbit viewVolumeOrbit(const Scene& scene, double aspect = 4.0 / 3.0);
/// The orbit moved and zoomed (its angles kept) so the points fill `fill` of a view of the given
/// aspect ratio.
Orbit framed(Orbit orbit, const std::vector<Vec3>& points, double aspect, double fill = 0.88);

/// An orbit around the unit cube of NPC.
Orbit defaultNpcOrbit();

/// Orbit controls: drag by pixels (yaw and pitch), pan in the view plane, zoom by a factor.
void orbitBy(Orbit& orbit, double dxDeg, double dyDeg);
void panBy(Orbit& orbit, double dxFraction, double dyFraction);  // fractions of the view's shorter side
void zoomBy(Orbit& orbit, double factor);

}  // namespace vplab
