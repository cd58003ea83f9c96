#include "app/views/observer.h"

#include "pipeline/view_mapping.h"

#include <algorithm>

namespace vplab {

namespace {

Vec3 eyeDirection(const Orbit& o) {
  const double yaw = radians(o.yawDeg), pitch = radians(o.pitchDeg);
  return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

}  // namespace

Camera observerCamera(const Orbit& o, double aspect) {
  Camera c;
  c.vrp = o.target;
  c.prp = o.target + o.distance * eyeDirection(o);
  c.vup = {0, 1, 0};
  // The field of view spans the shorter side: a view taller than wide (a phone upright) sees as much
  // across as a square one, and more above and below (set vertically, it cut the NPC cube off left
  // and right).
  const double half = o.distance * std::tan(radians(o.fovDeg) / 2);
  const double halfH = aspect >= 1 ? half : half / aspect;
  const double halfW = halfH * aspect;
  c.window = {-halfW, halfW, -halfH, halfH};
  c.front = o.distance * 0.99;  // VRC z: the front plane 1% of the distance in front of the eye
  c.back = -o.distance * 99.0;
  c.projection = Projection::perspective;
  return c;
}

namespace {

// The view volume's corners in WC: the unit cube taken back from NPC (exact for every projection);
// none for an invalid camera.
std::vector<Vec3> viewVolumeCorners(const Camera& camera) {
  std::vector<Vec3> corners;
  if (cameraError(camera)) return corners;
  const Mat4 wcFromNpc = glm::inverse(npcFromVrc(camera) * vrcFromWc(camera));
  for (int i = 0; i < 8; ++i) {
    const Vec4 p = wcFromNpc * Vec4(i & 1, (i >> 1) & 1, (i >> 2) & 1, 1.0);
    if (p.w > 0) corners.push_back(Vec3(p) / p.w);
  }
  return corners;
}

// What the world view must show: VRP, PRP, the objects' boxes and the view volume's corners.
std::vector<Vec3> worldPoints(const Scene& scene) {
  std::vector<Vec3> points{scene.camera.vrp, scene.camera.prp};
  for (const SceneObject& o : scene.objects) {
    if (!o.mesh || !o.visible) continue;
    const Mat4 m = wcFromMc(o.transform);
    // A small mesh by its vertices (a polygon's bounding box has corners far from it, which would
    // frame empty space), a large one by its bounding box.
    constexpr size_t kFramedByVertices = 64;
    if (o.mesh->positions.size() <= kFramedByVertices)
      for (const Vec3& v : o.mesh->positions) points.push_back(transformAffine(m, v));
    else
      for (const Vec3& c : bounds(*o.mesh).corners()) points.push_back(transformAffine(m, c));
  }
  const std::vector<Vec3> volume = viewVolumeCorners(scene.camera);
  points.insert(points.end(), volume.begin(), volume.end());
  return points;
}

}  // namespace

Orbit defaultWorldOrbit(const Scene& scene, double aspect) {
  const std::vector<Vec3> points = worldPoints(scene);
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  Orbit o;
  o.target = (lo + hi) * 0.5;
  double radius = 1e-3;
  for (const Vec3& p : points) radius = std::max(radius, glm::length(p - o.target));
  // Seen from the side and above, relative to the scene camera's own direction of view.
  const Vec3 n = glm::normalize(scene.camera.prp - scene.camera.vrp);
  o.yawDeg = std::atan2(n.x, n.z) * 180 / kPi + 55;
  o.pitchDeg = 28;
  o.distance = radius / std::tan(radians(o.fovDeg) / 2);
  return framed(o, points, aspect);
}

Orbit viewVolumeOrbit(const Scene& scene, double aspect) {
  const Orbit standard = defaultWorldOrbit(scene, aspect);
  if (cameraError(scene.camera)) return standard;
  const std::vector<Vec3> points = worldPoints(scene), volume = viewVolumeCorners(scene.camera);
  // The share of the view the volume's projection covers (its box, in the view's proportions).
  auto volumeArea = [&](const Orbit& o) {
    const Camera c = observerCamera(o, aspect);
    const Mat4 npcFromWc = npcFromVrc(c) * vrcFromWc(c);
    Vec2 lo(1e300), hi(-1e300);
    for (const Vec3& p : volume) {
      const Vec4 h = npcFromWc * Vec4(p, 1.0);
      if (h.w <= 0) return 0.0;
      lo = glm::min(lo, Vec2(h) / h.w), hi = glm::max(hi, Vec2(h) / h.w);
    }
    return (hi.x - lo.x) * (hi.y - lo.y);
  };
  // Still from the side and above (a view along N would hide the volume's depth): the standard
  // angles turned by up to 25° either way, the pitch 18° to 40°.
  Orbit best = standard;
  double bestArea = volumeArea(standard);
  for (double yaw : {-25.0, -15.0, 15.0, 25.0})
    for (double pitch : {18.0, 28.0, 40.0}) {
      Orbit o = standard;
      o.yawDeg += yaw, o.pitchDeg = pitch;
      o = framed(o, points, aspect);
      if (const double area = volumeArea(o); area > bestArea) best = o, bestArea = area;
    }
  return best;
}

Orbit framed(Orbit o, const std::vector<Vec3>& points, double aspect, double fill) {
  if (points.empty()) return o;
  // Centre the points' projection and scale the distance until they fill the view (a few rounds,
  // since moving changes the perspective a little).
  for (int round = 0; round < 4; ++round) {
    const Camera c = observerCamera(o, aspect);
    const Mat4 npcFromWc = npcFromVrc(c) * vrcFromWc(c);
    Vec2 pmin(1e300), pmax(-1e300);
    for (const Vec3& p : points) {
      const Vec4 h = npcFromWc * Vec4(p, 1.0);
      if (h.w <= 0) continue;
      pmin = glm::min(pmin, Vec2(h) / h.w);
      pmax = glm::max(pmax, Vec2(h) / h.w);
    }
    const Vec2 centre = (pmin + pmax) * 0.5, extent = pmax - pmin;
    if (!(pmax.x > pmin.x)) break;  // nothing in front of the observer
    // NPC spans the view; panBy counts in its shorter side (observerCamera).
    panBy(o, (centre.x - 0.5) * std::max(aspect, 1.0) * -1.0, (centre.y - 0.5) * std::max(1.0, 1.0 / aspect));
    zoomBy(o, std::max({extent.x, extent.y, 1e-9}) / fill);
  }
  return o;
}

Orbit defaultNpcOrbit() {
  Orbit o;
  o.target = {0.5, 0.5, 0.5};
  o.yawDeg = 38;
  o.pitchDeg = 24;
  o.distance = 3.3;
  o.fovDeg = 40;
  return o;
}

void orbitBy(Orbit& o, double dxDeg, double dyDeg) {
  o.yawDeg = std::fmod(o.yawDeg - dxDeg, 360.0);
  o.pitchDeg = std::clamp(o.pitchDeg + dyDeg, -89.0, 89.0);
}

void panBy(Orbit& o, double dxFraction, double dyFraction) {
  const Vec3 n = eyeDirection(o);
  const Vec3 u = glm::normalize(glm::cross(Vec3(0, 1, 0), n));
  const Vec3 v = glm::cross(n, u);
  const double shorterSide = 2 * o.distance * std::tan(radians(o.fovDeg) / 2);
  o.target += (-dxFraction * u + dyFraction * v) * shorterSide;
}

void zoomBy(Orbit& o, double factor) { o.distance = std::clamp(o.distance * factor, 1e-3, 1e6); }

}  // namespace vplab
