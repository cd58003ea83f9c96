// Helpers shared by the pipeline tests: error capture, a portable fixed-seed random source, cameras
// and polygons generated independently of the code under test, and small geometry measures.
#pragma once

#include "pipeline/camera.h"
#include "pipeline/clipping.h"
#include "base/error.h"
#include "pipeline/scene.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace vplab::test {

/// The message of the vplab::Error that `f` throws, or a text saying it threw nothing (or something
/// else), so that EXPECT_THAT(errorOf(...), HasSubstr(...)) fails at the call site with a clear text.
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("<not a vplab::Error: ") + e.what() + ">";
  }
  return "<no exception thrown>";
}

/// std::mt19937_64 with a fixed seed, turned into doubles by our own arithmetic (the standard
/// distributions are implementation-defined, this is the same sequence with every library).
class Rng {
 public:
  explicit Rng(uint64_t seed) : gen_(seed) {}
  double uniform() { return double(gen_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  int integer(int lo, int hi) { return lo + int(gen_() % uint64_t(hi - lo + 1)); }  // [lo, hi]
  bool chance(double p) { return uniform() < p; }
  Vec3 inBox(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
  Vec3 unitVector() {
    for (;;) {
      const Vec3 v = inBox(-1, 1);
      const double l = glm::length(v);
      if (l > 0.1 && l <= 1) return v / l;
    }
  }

 private:
  std::mt19937_64 gen_;
};

/// U, V, N and VPD by the formulas of docs/conventions.md stage 2, written again here (not pipeline code).
struct TestFrame {
  Vec3 u, v, n;
  double vpd;
};
inline TestFrame testFrame(const Camera& c) {
  TestFrame f;
  f.vpd = std::sqrt(glm::dot(c.prp - c.vrp, c.prp - c.vrp));
  f.n = (c.prp - c.vrp) / f.vpd;
  const Vec3 u = glm::cross(c.vup, f.n);
  f.u = u / std::sqrt(glm::dot(u, u));
  f.v = glm::cross(f.n, f.u);
  return f;
}
/// The WC point with VRC coordinates `vrc`: VRP + x·U + y·V + z·N.
inline Vec3 wcOfVrc(const Camera& c, const Vec3& vrc) {
  const TestFrame f = testFrame(c);
  return c.vrp + vrc.x * f.u + vrc.y * f.v + vrc.z * f.n;
}

/// A random valid camera: VRP in a box, the eye 0.5 to 20 away in a random direction, VUP at least
/// ~6° away from N, an off-centre window, and front and back planes that are valid for `p`
/// (perspective: 0.05·VPD ≤ dmin, so the front plane may also lie behind the view plane).
inline Camera randomCamera(Rng& rng, Projection p) {
  Camera c;
  c.projection = p;
  c.vrp = rng.inBox(-10, 10);
  const Vec3 n = rng.unitVector();
  const double vpd = rng.uniform(0.5, 20);
  c.prp = c.vrp + vpd * n;
  do c.vup = rng.unitVector() * rng.uniform(0.1, 10);
  while (glm::length(glm::cross(glm::normalize(c.vup), n)) < 0.1);
  c.window.xmin = rng.uniform(-3, 2);
  c.window.xmax = c.window.xmin + rng.uniform(0.1, 4);
  c.window.ymin = rng.uniform(-3, 2);
  c.window.ymax = c.window.ymin + rng.uniform(0.1, 4);
  if (p == Projection::perspective) {
    const double dmin = vpd * rng.uniform(0.05, 2);
    const double dmax = dmin + vpd * rng.uniform(0.1, 3);
    c.front = vpd - dmin;
    c.back = vpd - dmax;
  } else {
    c.front = rng.uniform(-5, 5);
    c.back = c.front - rng.uniform(0.1, 10);
  }
  if (p == Projection::oblique) c.oblique = {rng.uniform(0, 1.5), rng.uniform(-180, 180)};
  return c;
}

/// A planar polygon of n vertices around `centre` in the plane with normal `normal`, vertices at
/// increasing angles: convex (on an ellipse) or, with `starShaped`, with random radii (concave).
inline std::vector<Vec3> randomPlanarPolygon(Rng& rng, const Vec3& centre, const Vec3& normal,
                                             double radius, int n, bool starShaped) {
  const Vec3 helper = std::abs(normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 a = glm::normalize(glm::cross(normal, helper));
  const Vec3 b = glm::cross(normal, a);
  const double ra = radius * rng.uniform(0.5, 1), rb = radius * rng.uniform(0.5, 1);
  const double phase = rng.uniform(0, 2 * kPi);
  std::vector<Vec3> v;
  for (int i = 0; i < n; ++i) {
    const double angle = phase + 2 * kPi * (i + rng.uniform(0.1, 0.9)) / n;
    const double s = starShaped ? rng.uniform(0.3, 1) : 1.0;
    v.push_back(centre + s * (ra * std::cos(angle) * a + rb * std::sin(angle) * b));
  }
  return v;
}

/// A scene object of shape `polygon` with its mesh built.
inline SceneObject polygonObject(std::string name, std::vector<Vec3> vertices) {
  SceneObject o;
  o.name = std::move(name);
  o.shape = Shape::polygon;
  o.vertices = std::move(vertices);
  o.mesh = primitiveMesh(o);
  return o;
}

/// A scene object of a primitive shape with its mesh built.
inline SceneObject shapeObject(std::string name, Shape shape, ModelTransform t, int segments = 16) {
  SceneObject o;
  o.name = std::move(name);
  o.shape = shape;
  o.segments = segments;
  o.transform = std::move(t);
  o.mesh = primitiveMesh(o);
  return o;
}

inline Scene sceneWith(const Camera& camera, std::vector<SceneObject> objects) {
  Scene s;
  s.camera = camera;
  s.device = {320, 240};
  s.objects = std::move(objects);
  return s;
}

/// The camera of docs/conventions.md's check values.
inline Camera checkCamera() {
  Camera c;
  c.vrp = {0, 0, 0};
  c.prp = {0, 0, 5};
  c.vup = {0, 1, 0};
  c.window = {-1, 1, -0.75, 0.75};
  c.front = 2;
  c.back = -2;
  c.projection = Projection::perspective;
  return c;
}

/// A random scene of polygons around the camera's view volume: some inside, some outside, some
/// crossing planes and (perspective) some reaching behind the eye; plus a few primitives.
inline Scene randomPolygonScene(Rng& rng, const Camera& c, int polygons, bool withPrimitives) {
  const TestFrame f = testFrame(c);
  const ViewWindow& w = c.window;
  std::vector<SceneObject> objects;
  const double depth = c.front - c.back;
  for (int i = 0; i < polygons; ++i) {
    double z = rng.uniform(c.back - 0.5 * depth, c.front + 0.5 * depth);
    if (c.projection == Projection::perspective && rng.chance(0.25))
      z = rng.uniform(c.front, f.vpd + 0.5 * depth);  // between the front plane and behind the eye
    // Perspective: scale the window to the depth, so that a fair share lands inside.
    const double s = c.projection == Projection::perspective ? std::max(0.2, (f.vpd - z) / f.vpd) : 1.0;
    const Vec3 centreVrc(s * rng.uniform(w.xmin - 0.5 * w.width(), w.xmax + 0.5 * w.width()),
                         s * rng.uniform(w.ymin - 0.5 * w.height(), w.ymax + 0.5 * w.height()), z);
    const double radius = rng.uniform(0.05, 0.8) * std::max({w.width() * s, w.height() * s, 0.3 * depth});
    std::vector<Vec3> vrc = randomPlanarPolygon(rng, centreVrc, rng.unitVector(), radius,
                                                rng.integer(3, 7), rng.chance(0.3));
    for (Vec3& p : vrc) p = wcOfVrc(c, p);
    objects.push_back(polygonObject("polygon " + std::to_string(i), std::move(vrc)));
  }
  if (withPrimitives) {
    for (Shape shape : {Shape::cube, Shape::sphere, Shape::cylinder, Shape::tetrahedron}) {
      ModelTransform t;
      const double s = c.projection == Projection::perspective ? 0.5 : 1.0;
      t.translate = wcOfVrc(c, {s * rng.uniform(w.xmin, w.xmax), s * rng.uniform(w.ymin, w.ymax),
                                rng.uniform(c.back, c.front)});
      t.rotations.push_back({rng.unitVector(), rng.uniform(0, 360), {}});
      t.scale = Vec3(rng.uniform(0.3, 1.2) * std::max(w.width(), w.height()));
      objects.push_back(shapeObject(std::string(toString(shape)), shape, t, 12));
    }
  }
  return sceneWith(c, std::move(objects));
}

/// The vector area ½ Σ p_i × p_(i+1) of a closed polygon: its normal times its area when planar,
/// and additive when a polygon is cut into pieces along chords (the chords cancel).
inline Vec3 vectorArea(std::span<const Vec3> p) {
  Vec3 a(0);
  for (size_t i = 0; i < p.size(); ++i) a += glm::cross(p[i], p[(i + 1) % p.size()]);
  return 0.5 * a;
}

/// Largest amount by which p lies outside the unit cube (0 when inside).
inline double outsideCube(const Vec3& p) {
  double d = 0;
  for (int i = 0; i < 3; ++i) d = std::max({d, -p[i], p[i] - 1});
  return d;
}

/// A ClipVertex for a homogeneous NPC point with Blinn's boundary coordinates.
inline ClipVertex clipVertex(const Vec4& p, uint32_t source = 0) {
  return {p, clipValues(boundaryCoordinates(p)), source, 0};
}

}  // namespace vplab::test
