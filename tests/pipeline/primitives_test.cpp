// The primitives of lecture notes chapter 16 and the mesh helpers (mesh.h): counts, orientation (every face
// counter-clockwise seen from outside), closedness, sizes, and bad segment counts.
#include "pipeline/primitives.h"

#include "base/error.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace vplab {
namespace {

using test::errorOf;
using testing::HasSubstr;

Vec3 faceCentroid(const Mesh& m, size_t f) {
  Vec3 c(0);
  for (uint32_t i : m.face(f)) c += m.positions[i];
  return c / double(m.face(f).size());
}

// For these origin-centred convex shapes, a face is counter-clockwise seen from outside exactly
// when its Newell normal points away from the origin: faceNormal · centroid > 0.
void expectOutwardFaces(const Mesh& m) {
  for (size_t f = 0; f < m.faceCount(); ++f) {
    const Vec3 n = faceNormal(m, f);
    const Vec3 c = faceCentroid(m, f);
    EXPECT_GT(glm::dot(n, c), 1e-6 * glm::length(n) * glm::length(c)) << "face " << f;
  }
}

// A closed, consistently oriented surface uses every directed edge once and its reverse once.
void expectClosedAndConsistent(const Mesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t f = 0; f < m.faceCount(); ++f) {
    const auto face = m.face(f);
    for (size_t i = 0; i < face.size(); ++i) ++directed[{face[i], face[(i + 1) % face.size()]}];
  }
  for (const auto& [e, count] : directed) {
    EXPECT_EQ(count, 1) << e.first << "→" << e.second << " used twice in the same direction";
    EXPECT_EQ(directed.count({e.second, e.first}), 1u) << e.first << "→" << e.second << " has no twin";
  }
  // Euler: V − E + F = 2 for a sphere-like surface.
  EXPECT_EQ(int(m.vertexCount()) - int(uniqueEdges(m).size()) + int(m.faceCount()), 2);
}

// Every face lies in a plane: all its vertices at the same distance along its normal. 1e-12:
// unit-sized coordinates from sin and cos.
void expectPlanarFaces(const Mesh& m) {
  for (size_t f = 0; f < m.faceCount(); ++f) {
    const Vec3 n = glm::normalize(faceNormal(m, f));
    const auto face = m.face(f);
    const double d = glm::dot(n, m.positions[face[0]]);
    for (uint32_t i : face) EXPECT_NEAR(glm::dot(n, m.positions[i]), d, 1e-12) << "face " << f;
  }
}

TEST(Primitives, Cube) {
  const Mesh m = cube();
  EXPECT_EQ(m.vertexCount(), 8u);
  EXPECT_EQ(m.faceCount(), 6u);
  for (size_t f = 0; f < 6; ++f) EXPECT_EQ(m.face(f).size(), 4u);
  for (const Vec3& p : m.positions) {
    for (int i = 0; i < 3; ++i) EXPECT_EQ(std::abs(p[i]), 0.5);
  }
  EXPECT_EQ(uniqueEdges(m).size(), 12u);
  for (const Edge& e : uniqueEdges(m)) {
    EXPECT_LT(e.a, e.b);
    EXPECT_EQ(glm::length(m.positions[e.a] - m.positions[e.b]), 1.0);  // edge length 1
  }
  EXPECT_FALSE(m.smooth());  // flat shading
  const Bounds b = bounds(m);
  EXPECT_EQ(b.min, Vec3(-0.5));
  EXPECT_EQ(b.max, Vec3(0.5));
  expectOutwardFaces(m);
  expectClosedAndConsistent(m);
  expectPlanarFaces(m);
  // Face normals are the six axis directions, each with area 1 (Newell's normal has length 2·area).
  for (size_t f = 0; f < 6; ++f) EXPECT_EQ(glm::length(faceNormal(m, f)), 2.0);
}

TEST(Primitives, Tetrahedron) {
  const Mesh m = tetrahedron();
  EXPECT_EQ(m.vertexCount(), 4u);
  EXPECT_EQ(m.faceCount(), 4u);
  Vec3 centroid(0);
  for (const Vec3& p : m.positions) centroid += p / 4.0;
  EXPECT_NEAR(glm::length(centroid), 0, 1e-16);  // ±a sums: exact or one rounding
  for (uint32_t i = 0; i < 4; ++i)
    for (uint32_t j = i + 1; j < 4; ++j)
      EXPECT_NEAR(glm::length(m.positions[i] - m.positions[j]), 1, 1e-15) << i << " " << j;  // edge 1
  expectOutwardFaces(m);
  expectClosedAndConsistent(m);
}

TEST(Primitives, Cylinder) {
  for (int n : {3, 4, 7, 32}) {
    SCOPED_TRACE(n);
    const Mesh m = cylinder(n);
    EXPECT_EQ(m.vertexCount(), size_t(2 * n));
    ASSERT_EQ(m.faceCount(), size_t(n + 2));
    size_t quads = 0, caps = 0;
    for (size_t f = 0; f < m.faceCount(); ++f) {
      if (m.face(f).size() == 4) ++quads;
      if (m.face(f).size() == size_t(n)) ++caps;
    }
    if (n == 4) {
      EXPECT_EQ(quads, 6u);  // the caps are quads too
    } else {
      EXPECT_EQ(quads, size_t(n));
      EXPECT_EQ(caps, 2u);
    }
    for (const Vec3& p : m.positions) {
      EXPECT_NEAR(std::hypot(p.x, p.y), 1, 1e-15);  // radius 1
      EXPECT_EQ(std::abs(p.z), 1);                   // z = ±1
    }
    // n radial normals and the caps' two, named by every corner (a rim vertex has two normals).
    EXPECT_EQ(m.normals.size(), size_t(n) + 2);
    EXPECT_EQ(m.normalIndices.size(), m.indices.size());
    for (size_t f = 0; f < m.faceCount(); ++f) {
      const Vec3 faceN = glm::normalize(faceNormal(m, f));
      for (uint32_t k = m.faceStart[f]; k < m.faceStart[f + 1]; ++k) {
        const Vec3& cn = m.cornerNormal(k);
        EXPECT_NEAR(glm::length(cn), 1, 1e-15);  // cos² + sin², an ulp or two from 1
        EXPECT_GT(glm::dot(cn, faceN), 0.49) << "corner normal on the face's side (cos 60° for n = 3)";
        if (f < size_t(n)) {
          EXPECT_EQ(cn.z, 0);  // side: radial
        }
      }
    }
    expectOutwardFaces(m);
    expectClosedAndConsistent(m);
    expectPlanarFaces(m);
    EXPECT_EQ(m.maxFaceSize(), size_t(std::max(n, 4)));
  }
}

TEST(Primitives, Sphere) {
  for (int n : {4, 6, 8, 24}) {
    SCOPED_TRACE(n);
    const Mesh m = sphere(n);
    const size_t rings = size_t(n / 2 - 1);  // latitude circles
    EXPECT_EQ(m.vertexCount(), 2 + rings * size_t(n));
    size_t triangles = 0, quads = 0;
    for (size_t f = 0; f < m.faceCount(); ++f) {
      if (m.face(f).size() == 3) ++triangles;
      if (m.face(f).size() == 4) ++quads;
    }
    EXPECT_EQ(triangles, size_t(2 * n));                 // n at each pole
    EXPECT_EQ(quads, size_t(n * (n / 2 - 2)));           // n(n/2 − 2) between
    EXPECT_EQ(m.faceCount(), triangles + quads);
    for (const Vec3& p : m.positions) EXPECT_NEAR(glm::length(p), 1, 1e-15);  // radius 1
    // The latitude circles: n/2 − 1 distinct heights besides the poles, n vertices each.
    std::map<long long, int> heights;
    for (const Vec3& p : m.positions) ++heights[std::llround(p.z * 1e9)];
    EXPECT_EQ(heights.size(), rings + 2);
    EXPECT_TRUE(m.normalIndices.empty()) << "one normal a vertex";
    EXPECT_EQ(m.normals.size(), m.positions.size());
    for (size_t k = 0; k < m.indices.size(); ++k) EXPECT_EQ(m.cornerNormal(k), m.positions[m.indices[k]]);
    expectOutwardFaces(m);
    expectClosedAndConsistent(m);
    expectPlanarFaces(m);
  }
}

TEST(Primitives, Polygon) {
  const Mesh m = polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0.5, 0}});
  EXPECT_EQ(m.vertexCount(), 5u);
  ASSERT_EQ(m.faceCount(), 1u);
  const auto face = m.face(0);
  EXPECT_EQ(std::vector<uint32_t>(face.begin(), face.end()), (std::vector<uint32_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(faceNormal(m, 0), Vec3(0, 0, 2 * 1.5));  // area 1.5, counter-clockwise seen from +z
}

TEST(Primitives, BadSegmentCountsNameTheValue) {
  EXPECT_THAT(errorOf([] { cylinder(2); }), HasSubstr("a cylinder needs 3 to 2048 segments, not 2"));
  EXPECT_THAT(errorOf([] { cylinder(-5); }), HasSubstr("not -5"));
  EXPECT_THAT(errorOf([] { cylinder(kMaxSegments + 1); }), HasSubstr("not 2049"));
  EXPECT_THAT(errorOf([] { sphere(5); }), HasSubstr("a sphere needs an even number of segments from 4 to 2048, not 5"));
  EXPECT_THAT(errorOf([] { sphere(2); }), HasSubstr("not 2"));
  EXPECT_THAT(errorOf([] { sphere(0); }), HasSubstr("not 0"));
  EXPECT_THAT(errorOf([] { sphere(kMaxSegments + 2); }), HasSubstr("not 2050"));
  EXPECT_THAT(errorOf([] { polygon({{0, 0, 0}, {1, 0, 0}}); }), HasSubstr("at least 3 vertices, not 2"));
  EXPECT_EQ(errorOf([] { cylinder(kMaxSegments); }), "<no exception thrown>");
}

TEST(Mesh, TriangulatedKeepsOrientationAndArea) {
  for (const Mesh& m : {cube(), cylinder(9), sphere(10)}) {
    const Mesh t = triangulated(m);
    EXPECT_EQ(t.positions, m.positions);
    size_t expectedTriangles = 0;
    for (size_t f = 0; f < m.faceCount(); ++f) expectedTriangles += m.face(f).size() - 2;
    EXPECT_EQ(t.faceCount(), expectedTriangles);
    EXPECT_EQ(t.normals, m.normals);
    EXPECT_EQ(t.normalIndices.size(), m.normalIndices.empty() ? 0u : t.indices.size());
    // Each triangle's corners have the normals of the face's corners they came from (fanned from the first).
    if (m.smooth())
      for (size_t f = 0, tf = 0; f < m.faceCount(); ++f)
        for (size_t k = 1; k + 1 < m.face(f).size(); ++k, ++tf) {
          const uint32_t c = m.faceStart[f];
          EXPECT_EQ(t.cornerNormal(t.faceStart[tf]), m.cornerNormal(c)) << f;
          EXPECT_EQ(t.cornerNormal(t.faceStart[tf] + 1), m.cornerNormal(c + k)) << f;
          EXPECT_EQ(t.cornerNormal(t.faceStart[tf] + 2), m.cornerNormal(c + k + 1)) << f;
        }
    // Fan triangles of a planar convex face: their Newell normals sum to the face's.
    size_t tf = 0;
    for (size_t f = 0; f < m.faceCount(); ++f) {
      Vec3 sum(0);
      for (size_t k = 0; k + 2 < m.face(f).size(); ++k) sum += faceNormal(t, tf++);
      EXPECT_NEAR(glm::length(sum - faceNormal(m, f)), 0, 1e-12) << f;  // unit-sized values
    }
    expectOutwardFaces(t);
    expectClosedAndConsistent(t);
  }
}

// uniqueEdges, whole and in steps, against the plain definition (a set of the sides seen, in the order
// the faces give them) on random faces over few vertices (many repeated sides, degenerate sides a–a), and on a fan
// of 300 triangles around one vertex (a bucket too large to search by hand: the sorted path).
TEST(Mesh, UniqueEdgesEqualTheSetOfSidesInOrder) {
  auto reference = [](const Mesh& m) {
    std::set<std::pair<uint32_t, uint32_t>> seen;
    std::vector<std::pair<uint32_t, uint32_t>> out;
    for (size_t f = 0; f < m.faceCount(); ++f) {
      const auto face = m.face(f);
      for (size_t i = 0; i < face.size(); ++i) {
        const uint32_t a = std::min(face[i], face[(i + 1) % face.size()]), b = std::max(face[i], face[(i + 1) % face.size()]);
        if (a != b && seen.insert({a, b}).second) out.push_back({a, b});
      }
    }
    return out;
  };
  auto edgesOf = [](const Mesh& m) {
    std::vector<std::pair<uint32_t, uint32_t>> out;
    for (const Edge& e : uniqueEdges(m)) out.push_back({e.a, e.b});
    return out;
  };
  test::Rng rng(21);
  for (int trial = 0; trial < 50; ++trial) {
    Mesh m;
    const int vertices = rng.integer(1, 40);
    for (int v = 0; v < vertices; ++v) m.positions.push_back(Vec3(v, 0, 0));
    for (int f = rng.integer(0, 200); f > 0; --f) {
      std::vector<uint32_t> face(size_t(rng.integer(3, 6)));
      for (uint32_t& v : face) v = uint32_t(rng.integer(0, vertices - 1));
      m.addFace(face);
    }
    SCOPED_TRACE(trial);
    EXPECT_EQ(edgesOf(m), reference(m));
    // In steps (UniqueEdgesJob, the page's run across frames) of 1 to 30 units: the same list, and
    // a step never does much more than its budget (the whole job takes units(m) / budget steps at least).
    const uint64_t budget = uint64_t(rng.integer(1, 30));
    UniqueEdgesJob job(m);
    uint64_t steps = 1;
    for (; !job.step(budget); ++steps) ASSERT_LT(steps, 100000u) << "the steps never end";
    std::vector<std::pair<uint32_t, uint32_t>> stepped;
    for (const Edge& e : job.take()) stepped.push_back({e.a, e.b});
    EXPECT_EQ(stepped, reference(m)) << "steps of " << budget;
    EXPECT_GE(steps * (budget + 6), UniqueEdgesJob::units(m)) << "steps of " << budget << " did more than asked";
  }
  Mesh fan;
  fan.positions.push_back(Vec3(0));
  for (uint32_t k = 0; k < 300; ++k) {
    fan.positions.push_back(Vec3(std::cos(k * 0.02), std::sin(k * 0.02), 0));
    if (k > 0) fan.addFace({0, k, k + 1});
  }
  fan.addFace({0, 300, 1});  // closes the fan: its side 0–1 repeats the first face's
  EXPECT_EQ(edgesOf(fan), reference(fan));
  EXPECT_EQ(uniqueEdges(fan).size(), 2u * 300);
}

TEST(Mesh, UniqueEdgesAndBounds) {
  Mesh m;
  m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {0, 0, -1}};
  m.addFace({0, 1, 2});
  m.addFace({0, 2, 3});
  m.addFace({2, 2, 1});  // a degenerate face: the repeated corner is no edge
  const std::vector<Edge> e = uniqueEdges(m);
  ASSERT_EQ(e.size(), 5u);
  const std::pair<uint32_t, uint32_t> expected[] = {{0, 1}, {1, 2}, {0, 2}, {2, 3}, {0, 3}};
  for (size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(e[i].a, expected[i].first) << i;
    EXPECT_EQ(e[i].b, expected[i].second) << i;
  }
  const Bounds b = bounds(m);
  EXPECT_EQ(b.min, Vec3(0, 0, -1));
  EXPECT_EQ(b.max, Vec3(2, 3, 0));
  int cornersSeen = 0;
  for (const Vec3& c : b.corners()) {
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(c[i] == b.min[i] || c[i] == b.max[i]);
    ++cornersSeen;
  }
  EXPECT_EQ(cornersSeen, 8);
  EXPECT_EQ(m.maxFaceSize(), 3u);
}

}  // namespace
}  // namespace vplab
