// Stage 4 kernels (clipping.h): Blinn's boundary coordinates and outcodes, Sutherland–Hodgman in
// homogeneous coordinates, parametric edge clipping; on designed, random (fixed seed) and
// adversarial polygons (lecture notes 15.3, 15.2.4; Hill 7.4 and the DGL wiki; docs/conventions.md stage 4).
#include "pipeline/clipping.h"

#include "pipeline/view_mapping.h"
#include "tests/support/test_util.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <limits>

namespace vplab {
namespace {

using test::clipVertex;

std::vector<ClipVertex> polygonOf(std::initializer_list<Vec4> points) {
  std::vector<ClipVertex> v;
  uint32_t i = 0;
  for (const Vec4& p : points) v.push_back(clipVertex(p, i++));
  return v;
}

Outcode orOf(std::span<const ClipVertex> poly) {
  Outcode o = 0;
  for (const ClipVertex& v : poly) o |= outcodeOf(v.bc);
  return o;
}
Outcode andOf(std::span<const ClipVertex> poly) {
  Outcode o = 0x3f;
  for (const ClipVertex& v : poly) o &= outcodeOf(v.bc);
  return o;
}

std::vector<ClipVertex> clip(std::span<const ClipVertex> in, Outcode planes) {
  ClipScratch s;
  s.a.assign(in.begin(), in.end());
  const auto out = clipPolygon(planes, s);
  return {out.begin(), out.end()};
}

// What the pipeline does with a clipped vertex: snap it onto its planes, then divide.
Vec3 npcOf(const ClipVertex& v) {
  Vec4 p = v.p;
  snapToPlanes(p, v.onPlanes);
  return divideByW(p);
}

bool bitwiseEqual(const ClipVertex& a, const ClipVertex& b) {
  return std::memcmp(&a.p, &b.p, sizeof a.p) == 0 && std::memcmp(a.bc.data(), b.bc.data(), sizeof a.bc) == 0;
}

// A random planar polygon (convex, or star-shaped) in VRC in or around the view volume of a random
// perspective camera, taken to homogeneous NPC by its npcFromVrc: what the pipeline feeds the
// clipper. With `inFrontOfEye` every vertex has w = ze ≥ 0.05·VPD; otherwise about one polygon in
// six reaches behind the eye (w < 0).
std::vector<ClipVertex> randomPolygon(test::Rng& rng, bool inFrontOfEye, bool starShaped = false) {
  for (;;) {
    const Camera c = test::randomCamera(rng, Projection::perspective);
    const double vpd = glm::length(c.prp - c.vrp);
    const Mat4 m = npcFromVrc(c);
    const ViewWindow& w = c.window;
    const double depth = c.front - c.back;
    // Half the centres inside the view volume, the others around it (a quarter of those between
    // the front plane and behind the eye).
    const bool near = rng.chance(0.5);
    const double z = near ? rng.uniform(c.back, c.front)
                          : rng.chance(0.5) ? rng.uniform(c.front, vpd + depth) : rng.uniform(c.back - depth, c.front);
    const double s = std::max(0.2, (vpd - z) / vpd);
    const double margin = near ? 0 : 1;
    const Vec3 centre(s * rng.uniform(w.xmin - margin * w.width(), w.xmax + margin * w.width()),
                      s * rng.uniform(w.ymin - margin * w.height(), w.ymax + margin * w.height()), z);
    // A third small (log-uniform, 1/100 to 1/3 of the volume: often accepted whole), the rest large.
    const double size = rng.chance(0.33) ? std::pow(10.0, rng.uniform(-2, -0.5)) : rng.uniform(0.1, 1.0);
    const double radius = size * std::max({s * w.width(), s * w.height(), 0.5 * depth});
    const auto vrc = test::randomPlanarPolygon(rng, centre, rng.unitVector(), radius, rng.integer(3, 8), starShaped);
    std::vector<ClipVertex> poly;
    bool ok = true;
    for (const Vec3& p : vrc) {
      const Vec4 h = m * Vec4(p, 1);
      ok = ok && (!inFrontOfEye || h.w >= 0.05 * vpd);
      poly.push_back(clipVertex(h, uint32_t(poly.size())));
    }
    if (ok) return poly;
  }
}

// The tolerance for "inside the cube" after snapping and dividing. Created vertices lie exactly on
// their own planes (snapped); their other coordinates come from interpolations whose operands are
// of order |p| ≤ ~1e3·w for these cameras, each adding a rounding of ~1e-16 relative; 1e-11 after
// the division leaves a wide margin and is still far below anything visible (1e-11 of a pixel
// row on any realistic device).
constexpr double kCubeEps = 1e-11;

TEST(Clipping, BoundaryCoordinatesAndOutcodes) {
  const Vec4 p(0.25, -0.5, 3, 2);
  const Boundary bc = boundaryCoordinates(p);
  EXPECT_EQ(bc, (Boundary{0.25, 1.75, -0.5, 2.5, 3, -1}));
  EXPECT_EQ(outcodeOf(bc), (1u << kBottom) | (1u << kFront));
  // Each plane alone: just outside sets exactly its bit; exactly on it counts as inside.
  const Vec4 outside[kPlaneCount] = {{-0.1, .5, .5, 1}, {1.1, .5, .5, 1}, {.5, -0.1, .5, 1},
                                     {.5, 1.1, .5, 1},  {.5, .5, -0.1, 1}, {.5, .5, 1.1, 1}};
  const Vec4 on[kPlaneCount] = {{0, .5, .5, 1}, {1, .5, .5, 1}, {.5, 0, .5, 1},
                                {.5, 1, .5, 1}, {.5, .5, 0, 1}, {.5, .5, 1, 1}};
  for (int i = 0; i < kPlaneCount; ++i) {
    EXPECT_EQ(outcodeOf(boundaryCoordinates(outside[i])), 1u << i) << planeName(i);
    EXPECT_EQ(outcodeOf(boundaryCoordinates(on[i])), 0) << planeName(i);
    EXPECT_EQ(boundaryCoordinates(on[i])[i], 0) << planeName(i);
  }
  EXPECT_EQ(outcodeOf(boundaryCoordinates({0, 0, 0, 1})), 0);  // a cube corner
  EXPECT_EQ(outcodeOf(boundaryCoordinates({2, 2, 2, 2})), 0);  // the opposite corner, w = 2
}

TEST(Clipping, PlaneNames) {
  const char* names[] = {"left", "right", "bottom", "top", "back", "front"};
  const char* ineq[] = {"x ≥ 0", "x ≤ w", "y ≥ 0", "y ≤ w", "z ≥ 0", "z ≤ w"};
  for (int i = 0; i < kPlaneCount; ++i) {
    EXPECT_EQ(planeName(i), names[i]);
    EXPECT_EQ(planeInequality(i), ineq[i]);
  }
}

// A point behind the eye (w < 0) always fails a test by itself, because BC0 + BC1 = w < 0 (and
// likewise for y and z), even where its division lands inside the cube (Hill 7.4).
TEST(Clipping, PointsBehindTheEyeAreOutside) {
  const Vec4 mirrored(-0.5, -0.5, -0.5, -1);  // divides to (0.5, 0.5, 0.5), the cube's centre
  EXPECT_EQ(test::outsideCube(divideByW(mirrored)), 0);
  EXPECT_EQ(outcodeOf(boundaryCoordinates(mirrored)), 0x3f);
  test::Rng rng(2);
  for (int k = 0; k < 10000; ++k) {
    const Vec4 p(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5), -rng.uniform(1e-9, 5));
    const Outcode o = outcodeOf(boundaryCoordinates(p));
    EXPECT_TRUE((o & 0x03) && (o & 0x0c) && (o & 0x30)) << k;  // one bit of each pair
  }
}

TEST(Clipping, DivideByWIsFinite) {
  EXPECT_EQ(divideByW({2, 4, 6, 2}), Vec3(1, 2, 3));
  EXPECT_EQ(divideByW({2, 4, 6, -2}), Vec3(-1, -2, -3));
  const Vec3 eyePlane = divideByW({1, -1, 0, 0});
  EXPECT_TRUE(isFinite(eyePlane));
  EXPECT_EQ(eyePlane, Vec3(1e12, -1e12, 0));
  EXPECT_EQ(divideByW({1, 0, 0, -0.0}), Vec3(-1e12, 0, 0));  // w's sign is kept
}

TEST(Clipping, SnapToPlanes) {
  for (int i = 0; i < kPlaneCount; ++i) {
    Vec4 p(0.3, 0.4, 0.6, 2);
    snapToPlanes(p, uint8_t(1u << i));
    EXPECT_EQ(boundaryCoordinates(p)[i], 0) << planeName(i);
    for (int j = 0; j < kPlaneCount; ++j)
      if (j / 2 != i / 2) {
        EXPECT_EQ(p[j / 2], Vec4(0.3, 0.4, 0.6, 2)[j / 2]);  // other axes untouched
      }
    EXPECT_EQ(p.w, 2);
  }
  Vec4 corner(1e-17, 2.0000000001, 0.5, 2);
  snapToPlanes(corner, (1u << kLeft) | (1u << kTop));
  EXPECT_EQ(corner, Vec4(0, 2, 0.5, 2));
}

TEST(Clipping, LerpInterpolatesEverything) {
  ClipVertex a = clipVertex({0, 0, 0, 1}, 3), b = clipVertex({2, 4, 6, 3}, 4);
  a.onPlanes = 0b000101;
  b.onPlanes = 0b000110;
  const ClipVertex m = lerp(a, b, 0.25);
  EXPECT_EQ(m.p, Vec4(0.5, 1, 1.5, 1.5));
  EXPECT_EQ(m.bc, clipValues(boundaryCoordinates(m.p)));  // boundary values are linear in the point
  EXPECT_EQ(m.source, ClipVertex::kCreated);
  EXPECT_EQ(m.onPlanes, 0b000100);  // on a plane only when both ends are
}

// A square crossing the left plane: two vertices kept, two created exactly on the plane.
TEST(Clipping, OnePlaneCut) {
  const auto in = polygonOf({{-1, .2, .5, 1}, {1, .2, .5, 1}, {1, .8, .5, 1}, {-1, .8, .5, 1}});
  std::vector<ClipVertex> out;
  clipPolygonAgainstPlane(in, kLeft, out);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0].source, ClipVertex::kCreated);
  EXPECT_EQ(out[1].source, 1u);
  EXPECT_EQ(out[2].source, 2u);
  EXPECT_EQ(out[3].source, ClipVertex::kCreated);
  for (int i : {0, 3}) {
    EXPECT_EQ(out[i].bc[kLeft], 0);
    EXPECT_EQ(out[i].p.x, 0);  // t = 1/2 exactly here
    EXPECT_EQ(out[i].onPlanes, 1u << kLeft);
  }
  EXPECT_EQ(out[0].p, Vec4(0, .2, .5, 1));
  EXPECT_EQ(out[3].p, Vec4(0, .8, .5, 1));
  // Through clipPolygon with the polygon's outcodes: the same.
  const auto viaAll = clip(in, orOf(in));
  ASSERT_EQ(viaAll.size(), 4u);
  for (size_t i = 0; i < 4; ++i) EXPECT_TRUE(bitwiseEqual(viaAll[i], out[i])) << i;
}

// A vertex exactly on a plane counts as inside and is its own intersection: nothing is created twice.
TEST(Clipping, VertexExactlyOnAPlane) {
  {  // on the plane, one neighbour outside, one inside
    const auto in = polygonOf({{0, .5, .5, 1}, {-1, .2, .5, 1}, {.5, .2, .5, 1}});
    EXPECT_EQ(orOf(in), 1u << kLeft);
    const auto out = clip(in, orOf(in));
    ASSERT_EQ(out.size(), 3u);
    EXPECT_EQ(out[0].source, 0u);
    EXPECT_EQ(out[1].source, ClipVertex::kCreated);
    EXPECT_EQ(out[2].source, 2u);
    for (size_t i = 0; i < 3; ++i) EXPECT_FALSE(bitwiseEqual(out[i], out[(i + 1) % 3])) << "duplicate at " << i;
  }
  {  // touching the plane from outside at one vertex: only that vertex remains, too few for a polygon
    const auto in = polygonOf({{0, .5, .5, 1}, {-1, .2, .5, 1}, {-1, .8, .5, 1}});
    std::vector<ClipVertex> out;
    clipPolygonAgainstPlane(in, kLeft, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].source, 0u);
    EXPECT_TRUE(clip(in, orOf(in)).empty());
  }
  {  // both neighbours inside: unchanged
    const auto in = polygonOf({{0, .5, .5, 1}, {.3, .2, .5, 1}, {.6, .8, .5, 1}});
    EXPECT_EQ(orOf(in), 0);
    const auto out = clip(in, 0x3f);
    ASSERT_EQ(out.size(), 3u);
    for (size_t i = 0; i < 3; ++i) EXPECT_TRUE(bitwiseEqual(out[i], in[i]));
  }
}

// An edge lying in a plane: inside; a polygon that only touches the cube along it has no area left.
TEST(Clipping, EdgeLyingInAPlane) {
  const auto inside = polygonOf({{0, .2, .5, 1}, {0, .8, .5, 1}, {.5, .8, .5, 1}, {.5, .2, .5, 1}});
  EXPECT_EQ(orOf(inside), 0);
  EXPECT_EQ(clip(inside, 0x3f).size(), 4u);
  const auto outside = polygonOf({{0, .2, .5, 1}, {0, .8, .5, 1}, {-.5, .8, .5, 1}, {-.5, .2, .5, 1}});
  std::vector<ClipVertex> out;
  clipPolygonAgainstPlane(outside, kLeft, out);
  ASSERT_EQ(out.size(), 2u);  // the edge itself
  EXPECT_EQ(out[0].source, 0u);
  EXPECT_EQ(out[1].source, 1u);
  EXPECT_TRUE(clip(outside, orOf(outside)).empty());
  // A polygon lying wholly in a cube face is inside.
  const auto face = polygonOf({{0, 0, 0, 1}, {0, 1, 0, 1}, {0, 1, 1, 1}, {0, 0, 1, 1}});
  EXPECT_EQ(orOf(face), 0);
}

// A big square around the cube at z = 0.5 clips to the cube's cross-section, corners exact after
// snapping; each corner was created on two planes.
TEST(Clipping, BigSquareClipsToTheCrossSection) {
  const auto in = polygonOf({{-10, -10, .5, 1}, {10, -10, .5, 1}, {10, 10, .5, 1}, {-10, 10, .5, 1}});
  const auto out = clip(in, orOf(in));
  ASSERT_EQ(out.size(), 4u);
  std::vector<Vec3> corners;
  for (const ClipVertex& v : out) {
    EXPECT_EQ(v.source, ClipVertex::kCreated);
    EXPECT_EQ(std::popcount(unsigned(v.onPlanes)), 2);
    corners.push_back(npcOf(v));
  }
  for (const Vec3& expected : {Vec3(0, 0, .5), Vec3(1, 0, .5), Vec3(1, 1, .5), Vec3(0, 1, .5)})
    EXPECT_NE(std::find(corners.begin(), corners.end(), expected), corners.end()) << format(expected);
  EXPECT_NEAR(glm::length(test::vectorArea(corners)), 1, 1e-15);
}

// Trivially rejected (outcodes AND ≠ 0) ⇒ clipping anyway gives nothing; trivially accepted
// (OR = 0) ⇒ clipping anyway returns the polygon bit for bit. Random polygons, fixed seed.
TEST(Clipping, TrivialDecisionsAgreeWithClipping) {
  test::Rng rng(404);
  int rejected = 0, accepted = 0;
  for (int k = 0; k < 3000; ++k) {
    const auto in = randomPolygon(rng, false);
    if (andOf(in)) {
      ++rejected;
      EXPECT_TRUE(clip(in, 0x3f).empty()) << k;
      EXPECT_TRUE(clip(in, orOf(in)).empty()) << k;
    } else if (!orOf(in)) {
      ++accepted;
      const auto out = clip(in, 0x3f);
      ASSERT_EQ(out.size(), in.size()) << k;
      for (size_t i = 0; i < in.size(); ++i) {
        EXPECT_TRUE(bitwiseEqual(out[i], in[i])) << k;
        EXPECT_EQ(out[i].source, in[i].source) << k;
      }
    }
  }
  EXPECT_GT(rejected, 600);  // both cases occur often enough to mean something (1235 and 304)
  EXPECT_GT(accepted, 150);
}

// Random polygons, some reaching behind the eye: every output vertex has w > 0, all boundary
// values ≥ 0 (created vertices exactly 0 on their planes) and lies in the cube after the division.
// Clipping only against the planes in the OR of the outcodes gives the same as against all six.
TEST(Clipping, RandomPolygonsEndInsideTheCube) {
  test::Rng rng(8);
  int behindEye = 0, clippedNonEmpty = 0;
  double worst = 0;
  for (int k = 0; k < 5000; ++k) {
    const auto in = randomPolygon(rng, false, rng.chance(0.3));
    bool anyBehind = false;
    for (const ClipVertex& v : in) anyBehind = anyBehind || v.p.w < 0;
    behindEye += anyBehind;
    const auto out = clip(in, orOf(in));
    if (!out.empty()) ++clippedNonEmpty;
    EXPECT_TRUE(out.empty() || out.size() >= 3);
    for (const ClipVertex& v : out) {
      ASSERT_GT(v.p.w, 0) << k;
      for (int i = 0; i < kPlaneCount; ++i) {
        EXPECT_GE(v.bc[i], 0) << k;
        if (v.onPlanes >> i & 1) {
          EXPECT_EQ(v.bc[i], 0) << k;
        }
      }
      const double outside = test::outsideCube(npcOf(v));
      worst = std::max(worst, outside);
      EXPECT_LE(outside, kCubeEps) << k << " " << format(npcOf(v));
    }
    const auto all = clip(in, 0x3f);
    ASSERT_EQ(all.size(), out.size()) << k;
    for (size_t i = 0; i < out.size(); ++i) EXPECT_TRUE(bitwiseEqual(all[i], out[i])) << k;
  }
  EXPECT_GT(behindEye, 400);  // the paths are exercised: 862 and 2777 with this seed
  EXPECT_GT(clippedNonEmpty, 1400);
  RecordProperty("worst_outside_cube", format(worst));  // exactly 0 with this seed
}

// Complementary half-spaces partition a polygon: the part with BC_p ≥ 0 and the part with
// BC_p ≤ 0 (the same pass with that boundary value negated) have vector areas summing to the
// original's (measured in NPC after the division; all w > 0 here so the division is a projective
// map without a pole on the polygons). The vector area is additive even for non-planar and
// concave polygons because each intersection lies on its edge. Tolerance 1e-12·D²·n, D the largest
// divided coordinate: each of the O(n) cross products is of size D², and the two parts compute each
// intersection from different ends (the inside one), so they differ by a few roundings of D.
TEST(Clipping, ComplementaryHalfSpacesPartitionAPolygon) {
  test::Rng rng(31);
  int cut = 0;
  for (int k = 0; k < 3000; ++k) {
    const auto in = randomPolygon(rng, true, rng.chance(0.5));
    std::vector<Vec3> original;
    double d = 1;
    for (const ClipVertex& v : in) {
      original.push_back(divideByW(v.p));
      d = std::max({d, std::abs(original.back().x), std::abs(original.back().y), std::abs(original.back().z)});
    }
    const Vec3 whole = test::vectorArea(original);
    for (int plane = 0; plane < kPlaneCount; ++plane) {
      std::vector<ClipVertex> keep, other, negated(in.begin(), in.end());
      for (ClipVertex& v : negated) v.bc[plane] = -v.bc[plane];
      clipPolygonAgainstPlane(in, plane, keep);
      clipPolygonAgainstPlane(negated, plane, other);
      if (!keep.empty() && !other.empty() && keep.size() + other.size() > in.size()) ++cut;
      std::vector<Vec3> a, b;
      for (const ClipVertex& v : keep) {
        a.push_back(divideByW(v.p));
        EXPECT_GE(v.bc[plane], 0);
      }
      for (const ClipVertex& v : other) {
        b.push_back(divideByW(v.p));
        EXPECT_GE(-boundaryCoordinates(v.p)[plane], -1e-12 * std::abs(v.p.w) * d);  // on the other side
      }
      const Vec3 sum = test::vectorArea(a) + test::vectorArea(b);
      EXPECT_NEAR(glm::length(sum - whole), 0, 1e-12 * d * d * double(in.size())) << k << " " << planeName(plane);
    }
  }
  EXPECT_GT(cut, 2500);  // 5528 of the 18000 passes really cut the polygon with this seed
}

// The largest homogeneous coordinate of a polygon's vertices.
double maxCoordinate(std::span<const ClipVertex> poly) {
  double m = 0;
  for (const ClipVertex& v : poly)
    for (int i = 0; i < 4; ++i) m = std::max(m, std::abs(v.p[i]));
  return m;
}

// Multiplying the four homogeneous coordinates of a vertex by k > 0 does not move the point it
// stands for, nor (Hill 7.4) the segment between two such points: the set {a·P0 + b·P1 : a, b ≥ 0}
// is the same. So the divided clip output is unchanged. With k a power of two the scaling is exact
// and so is the agreement (bit for bit). With arbitrary k (1e-3..1e3, a different one per vertex,
// w < 0 vertices included) the interpolation parameters differ. A created vertex carries an absolute
// error of a few ε·M (M the largest input coordinate) per pass; dividing by its w turns that into
// ε·M/w. So the tolerance is 1e-13·(M/w + M'/w') for the two runs: 1e-13 ≈ 900 ε covers six passes
// with a handful of roundings each. (Near the eye plane M/w is large: an edge from w = +1 to
// w = −1 cut close to w = 0 is ill-conditioned in any floating-point clipper.)
TEST(Clipping, PositiveScalingChangesNothing) {
  test::Rng rng(64);
  for (int k = 0; k < 3000; ++k) {
    const auto in = randomPolygon(rng, false, rng.chance(0.3));
    const auto ref = clip(in, orOf(in));

    const double pow2 = std::ldexp(1.0, rng.integer(-20, 20));
    auto exact = in;
    for (ClipVertex& v : exact) v = clipVertex(v.p * pow2, v.source);
    const auto outExact = clip(exact, orOf(exact));
    ASSERT_EQ(outExact.size(), ref.size()) << k;
    for (size_t i = 0; i < ref.size(); ++i) EXPECT_EQ(npcOf(outExact[i]), npcOf(ref[i])) << k;

    auto scaled = in;
    for (ClipVertex& v : scaled) v = clipVertex(v.p * std::pow(10.0, rng.uniform(-3, 3)), v.source);
    EXPECT_EQ(orOf(scaled), orOf(in));
    EXPECT_EQ(andOf(scaled), andOf(in));
    const auto out = clip(scaled, orOf(scaled));
    ASSERT_EQ(out.size(), ref.size()) << k;
    const double m = maxCoordinate(in), mScaled = maxCoordinate(scaled);
    for (size_t i = 0; i < ref.size(); ++i) {
      const Vec3 a = npcOf(out[i]), b = npcOf(ref[i]);
      EXPECT_EQ(out[i].source, ref[i].source);
      EXPECT_NEAR(glm::length(a - b), 0, 1e-13 * (m / ref[i].p.w + mScaled / out[i].p.w)) << k;
    }
  }
}

// Two faces sharing an edge produce the same new vertex on it, bit for bit, because the
// intersection is always computed from the inside endpoint (whatever the direction of traversal).
TEST(Clipping, SharedEdgeGivesBitwiseIdenticalVertices) {
  test::Rng rng(2718);
  int sharedCuts = 0;
  for (int k = 0; k < 3000; ++k) {
    const auto p = randomPolygon(rng, false);  // borrow random homogeneous points
    const auto q = randomPolygon(rng, false);
    if (p.size() < 3 || q.size() < 2) continue;
    const Vec4 a = p[0].p, b = p[1].p, c = p[2].p, d = q[0].p;
    const std::vector<ClipVertex> t1 = {clipVertex(a, 0), clipVertex(b, 1), clipVertex(c, 2)};
    const std::vector<ClipVertex> t2 = {clipVertex(b, 1), clipVertex(a, 0), clipVertex(d, 3)};  // AB reversed
    const auto o1 = clip(t1, orOf(t1));
    const auto o2 = clip(t2, orOf(t2));
    // The points of AB where it enters or leaves the cube, from edge clipping.
    const Outcode oa = outcodeOf(t1[0].bc), ob = outcodeOf(t1[1].bc);
    if (!(oa | ob) || (oa & ob)) continue;
    const EdgeRange r = clipEdge(t1[0].bc, t1[1].bc, oa | ob);
    if (!r.visible || r.t1 - r.t0 < 1e-6) continue;
    for (double t : {r.t0, r.t1}) {
      if (t == 0 || t == 1) continue;  // an endpoint of AB, not a new vertex
      const Vec3 expected = divideByW(a + t * (b - a));
      const ClipVertex* in1 = nullptr;
      for (const ClipVertex& v : o1)
        if (v.source == ClipVertex::kCreated && glm::length(npcOf(v) - expected) < 1e-9 * (1 + glm::length(expected))) in1 = &v;
      ASSERT_NE(in1, nullptr) << k;
      bool twin = false;
      for (const ClipVertex& v : o2) twin = twin || bitwiseEqual(v, *in1);
      EXPECT_TRUE(twin) << k << " t = " << t;
      ++sharedCuts;
    }
  }
  EXPECT_GT(sharedCuts, 300);  // 592 with this seed
}

// Parametric edge clipping on designed edges.
TEST(Clipping, ClipEdgeDesignedCases) {
  auto bc = [](Vec4 p) { return boundaryCoordinates(p); };
  auto planes = [&](Vec4 p, Vec4 q) { return Outcode(outcodeOf(bc(p)) | outcodeOf(bc(q))); };
  {  // inside
    const Vec4 p(.2, .2, .2, 1), q(.8, .8, .8, 1);
    const EdgeRange r = clipEdge(bc(p), bc(q), 0x3f);
    EXPECT_TRUE(r.visible);
    EXPECT_EQ(r.t0, 0);
    EXPECT_EQ(r.t1, 1);
  }
  {  // leaving through the right plane at x = 1: t = 0.5 / 1
    const Vec4 p(.5, .5, .5, 1), q(1.5, .5, .5, 1);
    const EdgeRange r = clipEdge(bc(p), bc(q), planes(p, q));
    EXPECT_TRUE(r.visible);
    EXPECT_EQ(r.t0, 0);
    EXPECT_EQ(r.t1, 0.5);
  }
  {  // entering through the left, leaving through the right
    const Vec4 p(-1, .5, .5, 1), q(3, .5, .5, 1);
    const EdgeRange r = clipEdge(bc(p), bc(q), planes(p, q));
    EXPECT_TRUE(r.visible);
    EXPECT_EQ(r.t0, 0.25);
    EXPECT_EQ(r.t1, 0.5);
  }
  {  // both outside the same plane
    const Vec4 p(-1, .2, .5, 1), q(-2, .8, .5, 1);
    EXPECT_FALSE(clipEdge(bc(p), bc(q), planes(p, q)).visible);
  }
  {  // outside different planes, passing the cube's corner by: invisible
    const Vec4 p(-0.5, 0.8, .5, 1), q(0.8, 2.5, .5, 1);  // the line x − y ... misses (0, 1)
    EXPECT_EQ(outcodeOf(bc(p)) & outcodeOf(bc(q)), 0);
    EXPECT_FALSE(clipEdge(bc(p), bc(q), planes(p, q)).visible);
  }
  {  // from in front of the eye to behind it: cut where it leaves, never reaching w ≤ 0
    const Vec4 p(.5, .5, .5, 1), q(-.5, -.5, .5, -1);
    const EdgeRange r = clipEdge(bc(p), bc(q), planes(p, q));
    ASSERT_TRUE(r.visible);
    EXPECT_GT((p + r.t1 * (q - p)).w, 0);
    EXPECT_EQ(r.t0, 0);
  }
}

// Edge clipping agrees with polygon clipping of the degenerate polygon P0, P1, P0 (a segment
// traversed there and back): the distinct vertices of the polygon result are the endpoints of the
// visible range, and the endpoints lie on the cube. Random segments, some reaching behind the eye.
// Tolerance 1e-9 relative: the two compute the same intersections through different sequences of
// interpolations.
TEST(Clipping, ClipEdgeAgreesWithDegeneratePolygons) {
  test::Rng rng(555);
  int visible = 0, invisible = 0;
  for (int k = 0; k < 5000; ++k) {
    const auto poly = randomPolygon(rng, false);
    const ClipVertex p0 = clipVertex(poly[0].p, 0), p1 = clipVertex(poly[1].p, 1);
    const Outcode planes = outcodeOf(p0.bc) | outcodeOf(p1.bc);
    const EdgeRange r = clipEdge(p0.bc, p1.bc, planes);
    const std::vector<ClipVertex> there = {p0, p1, clipVertex(poly[0].p, 0)};
    const auto out = clip(there, planes);
    if (!r.visible || r.t1 - r.t0 < 1e-9) {
      ++invisible;
      if (!r.visible) {
        EXPECT_TRUE(out.empty()) << k;
      }
      continue;
    }
    ++visible;
    const Vec4 h0 = p0.p + r.t0 * (p1.p - p0.p), h1 = p0.p + r.t1 * (p1.p - p0.p);
    EXPECT_GT(h0.w, 0);
    EXPECT_GT(h1.w, 0);
    const Vec3 e0 = divideByW(h0), e1 = divideByW(h1);
    const double tol = 1e-9 * std::max({1.0, glm::length(e0), glm::length(e1)});
    EXPECT_LE(test::outsideCube(e0), tol);
    EXPECT_LE(test::outsideCube(e1), tol);
    if (r.t0 > 0) {  // entered through a face: on the cube's surface
      double onFace = 1;
      for (int i = 0; i < 3; ++i) onFace = std::min({onFace, std::abs(e0[i]), std::abs(e0[i] - 1)});
      EXPECT_LE(onFace, tol) << k;
    }
    ASSERT_FALSE(out.empty()) << k;
    bool saw0 = false, saw1 = false;
    for (const ClipVertex& v : out) {
      const Vec3 n = npcOf(v);
      const bool near0 = glm::length(n - e0) <= tol, near1 = glm::length(n - e1) <= tol;
      EXPECT_TRUE(near0 || near1) << k << " " << format(n) << " not at " << format(e0) << " or " << format(e1);
      saw0 = saw0 || near0;
      saw1 = saw1 || near1;
    }
    EXPECT_TRUE(saw0 && saw1) << k;
  }
  EXPECT_GT(visible, 800);  // 1586 and 3414 with this seed
  EXPECT_GT(invisible, 1500);
}

// One scratch for many polygons gives what a fresh scratch gives (buffers are reused, not stale).
TEST(Clipping, ScratchReuse) {
  test::Rng rng(9);
  ClipScratch shared;
  for (int k = 0; k < 1000; ++k) {
    const auto in = randomPolygon(rng, false);
    shared.a.assign(in.begin(), in.end());
    const auto out = clipPolygon(orOf(in), shared);
    const auto fresh = clip(in, orOf(in));
    ASSERT_EQ(out.size(), fresh.size());
    for (size_t i = 0; i < out.size(); ++i) EXPECT_TRUE(bitwiseEqual(out[i], fresh[i]));
  }
}

// Adversarial inputs: repeated vertices, vertices at infinity (w = 0), huge magnitudes, polygons
// through cube corners and along cube edges and faces, mirrored points behind the eye. Nothing may
// crash or produce NaN; every result is empty or a polygon of ≥ 3 vertices with w > 0 in the cube.
TEST(Clipping, AdversarialPolygons) {
  constexpr double kHuge = 1e150;
  const std::vector<std::vector<Vec4>> cases = {
      {{.5, .5, .5, 1}, {.5, .5, .5, 1}, {.5, .5, .5, 1}},                      // one point, inside
      {{2, .5, .5, 1}, {2, .5, .5, 1}, {2, .5, .5, 1}},                         // one point, outside
      {{.2, .2, .5, 1}, {.8, .2, .5, 1}, {.8, .2, .5, 1}, {.2, .8, .5, 1}},     // a repeated vertex
      {{.5, .5, .5, 1}, {1, 0, 0, 0}, {0, 1, 0, 0}},                            // two at infinity
      {{.5, .5, .5, 1}, {.5, .5, .5, 0}, {.2, .8, .3, 1}},                      // w = 0
      {{-.5, -.5, -.5, -1}, {-.2, -.5, -.5, -1}, {-.5, -.8, -.5, -1}},          // mirrored into the cube
      {{.5, .5, .5, 1}, {.2, .5, .5, -1}, {.7, .2, .5, 1}},                     // one vertex behind the eye
      {{0, 0, 0, 1}, {1, 1, 1, 1}, {1, 0, 1, 1}},                               // through cube corners
      {{-1, 0, 0, 1}, {2, 0, 0, 1}, {2, 0, 1, 1}, {-1, 0, 1, 1}},               // in the bottom plane
      {{-1, -1, .5, 1}, {2, 2, .5, 1}, {2, 2.0000001, .5, 1}},                  // a sliver along a diagonal
      {{-kHuge, -kHuge, .5, 1}, {kHuge, -kHuge, .5, 1}, {0, kHuge, .5, 1}},     // huge, around the cube
      {{.5, .5, 2, 1}, {.5, .5, 2, -1}, {.5, .6, -1, 1}},                       // through the eye plane
  };
  for (size_t k = 0; k < cases.size(); ++k) {
    std::vector<ClipVertex> in;
    for (const Vec4& p : cases[k]) in.push_back(clipVertex(p, uint32_t(in.size())));
    for (Outcode planes : {orOf(in), Outcode(0x3f)}) {
      const auto out = clip(in, planes);
      EXPECT_TRUE(out.empty() || out.size() >= 3) << k;
      for (const ClipVertex& v : out) {
        EXPECT_TRUE(isFinite(v.p)) << k;
        EXPECT_GT(v.p.w, 0) << k;
        const Vec3 n = npcOf(v);
        EXPECT_TRUE(isFinite(n)) << k;
        EXPECT_LE(test::outsideCube(n), kCubeEps) << k << " " << format(n);
      }
    }
  }
  // The mirrored triangle divides into the cube but is rejected whole before any division.
  std::vector<ClipVertex> mirrored;
  for (const Vec4& p : cases[5]) mirrored.push_back(clipVertex(p));
  EXPECT_EQ(andOf(mirrored), 0x3f);
  EXPECT_TRUE(clip(mirrored, 0x3f).empty());
}

// Inputs no WC polygon can produce through an invertible matrix (WC points have w = 1, so their
// homogeneous images never pass through (0, 0, 0, 0) nor differ in scale by 1e150): a vertex and its
// antipode, and vertices whose scales differ by 1e150. The interpolation P0 + t·(P1 − P0) loses the
// small vertex entirely there (e.g. t rounds to 1 and the result is 0 instead of P1), so only
// robustness is required: no crash, no NaN or infinity, a result of 0 or ≥ 3 vertices.
TEST(Clipping, UnreachableInputsStayFinite) {
  constexpr double kHuge = 1e150, kTiny = 1e-150;
  const std::vector<std::vector<Vec4>> cases = {
      {{.5, .5, .5, 1}, {-.5, -.5, -.5, -1}, {.7, .2, .5, 1}},  // the segment through the origin
      {{.5 * kTiny, .5 * kTiny, .5 * kTiny, kTiny}, {2 * kTiny, .5 * kTiny, .5 * kTiny, kTiny}, {.5, .9, .5, 1}},
      {{.5, .5, .5, kHuge}, {.5, .5, .5, -kHuge}, {.3, .3, .3, 1}},
  };
  for (size_t k = 0; k < cases.size(); ++k) {
    std::vector<ClipVertex> in;
    for (const Vec4& p : cases[k]) in.push_back(clipVertex(p, uint32_t(in.size())));
    const auto out = clip(in, 0x3f);
    EXPECT_TRUE(out.empty() || out.size() >= 3) << k;
    for (const ClipVertex& v : out) {
      EXPECT_TRUE(isFinite(v.p)) << k;
      EXPECT_GE(v.p.w, 0) << k;
      EXPECT_TRUE(isFinite(npcOf(v))) << k;
    }
  }
}

}  // namespace
}  // namespace vplab
