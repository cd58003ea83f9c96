#include "app/lessons/lesson_transition.h"

#include "base/error.h"
#include "pipeline/modeling.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace vplab {

namespace {

double lerp(double a, double b, double t) { return a + (b - a) * t; }
Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return a + (b - a) * t; }

/// The rotation taking WC's axes to U, V, N (its columns).
glm::dquat orientationOf(const VrcAxes& f) { return glm::quat_cast(glm::dmat3(f.u, f.v, f.n)); }

/// A scale factor's blend keeps its sign: geometric when both have one sign (never 0, which would
/// flatten the object), else a jump halfway.
double scaleBetween(double a, double b, double t) {
  if ((a > 0) == (b > 0)) return std::copysign(std::pow(std::abs(a), 1 - t) * std::pow(std::abs(b), t), a);
  return t < 0.5 ? a : b;
}

ModelTransform transformBetween(const ModelTransform& a, const ModelTransform& b, double t) {
  ModelTransform m = t < 0.5 ? a : b;
  m.translate = lerp(a.translate, b.translate, t);
  m.scale = {scaleBetween(a.scale.x, b.scale.x, t), scaleBetween(a.scale.y, b.scale.y, t),
             scaleBetween(a.scale.z, b.scale.z, t)};
  // Rotations about the same axes turn by their blended angles; others are no rotation between two.
  bool sameAxes = a.rotations.size() == b.rotations.size();
  for (size_t i = 0; sameAxes && i < a.rotations.size(); ++i)
    sameAxes = a.rotations[i].axis == b.rotations[i].axis && a.rotations[i].through == b.rotations[i].through;
  if (sameAxes)
    for (size_t i = 0; i < m.rotations.size(); ++i) m.rotations[i].deg = lerp(a.rotations[i].deg, b.rotations[i].deg, t);
  return m;
}

/// A user clip plane's point moves straight, its normal turns (normalized blend); a normal turned
/// half round has no between and flips halfway.
UserClipPlane planeBetween(const UserClipPlane& a, const UserClipPlane& b, double t) {
  UserClipPlane p = t < 0.5 ? a : b;
  p.point = lerp(a.point, b.point, t);
  const Vec3 na = glm::normalize(a.normal), nb = glm::normalize(b.normal);
  if (glm::dot(na, nb) > -0.99) {
    const Vec3 n = lerp(na, nb, t);
    p.normal = n / glm::length(n);
  }
  return p;
}

}  // namespace

double easeInOut(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

Camera cameraBetween(const Camera& a, const Camera& b, double t) {
  if (t <= 0) return a;
  if (t >= 1) return b;
  const VrcAxes fa = vrcAxes(a), fb = vrcAxes(b);
  const glm::dquat q = glm::slerp(orientationOf(fa), orientationOf(fb), t);
  const glm::dmat3 r = glm::mat3_cast(q);  // columns U, V, N
  Camera c = b.projection == Projection::perspective ? a : b;
  c.vrp = lerp(a.vrp, b.vrp, t);
  c.prp = c.vrp + lerp(fa.vpd, fb.vpd, t) * glm::normalize(r[2]);
  c.vup = r[1];  // V itself: perpendicular to N, so never parallel to it
  c.window = {lerp(a.window.xmin, b.window.xmin, t), lerp(a.window.xmax, b.window.xmax, t),
              lerp(a.window.ymin, b.window.ymin, t), lerp(a.window.ymax, b.window.ymax, t)};
  c.front = lerp(a.front, b.front, t);
  c.back = lerp(a.back, b.back, t);
  c.oblique = {lerp(a.oblique.d, b.oblique.d, t), lerp(a.oblique.phiDeg, b.oblique.phiDeg, t)};
  return c;
}

Orbit orbitBetween(const Orbit& a, const Orbit& b, double t) {
  if (t <= 0) return a;
  if (t >= 1) return b;
  Orbit o;
  o.target = lerp(a.target, b.target, t);
  const double turn = std::remainder(b.yawDeg - a.yawDeg, 360.0);  // the shorter way, within ±180°
  o.yawDeg = a.yawDeg + turn * t;
  o.pitchDeg = lerp(a.pitchDeg, b.pitchDeg, t);
  o.distance = std::pow(a.distance, 1 - t) * std::pow(b.distance, t);  // zooms at an even pace
  o.fovDeg = lerp(a.fovDeg, b.fovDeg, t);
  return o;
}

bool sameSceneObjects(const Scene& a, const Scene& b) {
  if (a.objects.size() != b.objects.size() || a.path != b.path) return false;
  for (size_t i = 0; i < a.objects.size(); ++i)
    if (a.objects[i].mesh != b.objects[i].mesh || a.objects[i].name != b.objects[i].name) return false;
  return true;
}

namespace {

/// A valid camera and valid transforms: the numbers a blend starts or ends at (meshes play no part).
bool hasValidGeometry(const Scene& s) {
  if (cameraError(s.camera)) return false;
  for (const SceneObject& o : s.objects) {
    try {
      wcFromMc(o.transform);
    } catch (const Error&) {
      return false;
    }
  }
  return true;
}

}  // namespace

bool blendable(const LessonState& a, const LessonState& b) {
  return sameSceneObjects(a.scene, b.scene) && hasValidGeometry(a.scene) && hasValidGeometry(b.scene);
}

LessonState stateBetween(const LessonState& a, const LessonState& b, double t) {
  if (t <= 0) return a;
  if (t >= 1 || !blendable(a, b)) return b;
  LessonState s = t < 0.5 ? a : b;
  s.scene.camera = cameraBetween(a.scene.camera, b.scene.camera, t);
  for (size_t i = 0; i < s.scene.objects.size(); ++i)
    s.scene.objects[i].transform = transformBetween(a.scene.objects[i].transform, b.scene.objects[i].transform, t);
  if (a.scene.clipPlanes.size() == b.scene.clipPlanes.size())
    for (size_t i = 0; i < s.scene.clipPlanes.size(); ++i)
      s.scene.clipPlanes[i] = planeBetween(a.scene.clipPlanes[i], b.scene.clipPlanes[i], t);
  DisplaySettings& d = s.display;
  d.world.orbit = orbitBetween(a.display.world.orbit, b.display.world.orbit, t);
  d.npc.orbit = orbitBetween(a.display.npc.orbit, b.display.npc.orbit, t);
  d.morph.orbit = orbitBetween(a.display.morph.orbit, b.display.morph.orbit, t);
  d.morphing.t = lerp(a.display.morphing.t, b.display.morphing.t, t);
  return s;
}

}  // namespace vplab
