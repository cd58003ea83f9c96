// The five stages over a scene (pipeline.h; lecture notes 15.2.6, 15.3): each stage is its matrix, vertices
// are transformed and classified once and shared by their faces, the clipped output lies in the
// cube, the fates and statistics add up, the bounding-box test and edge clipping agree with the
// per-polygon work, and an invalid camera leaves a previous run unchanged.
#include "pipeline/pipeline.h"

#include "pipeline/device_mapping.h"
#include "pipeline/mesh.h"
#include "pipeline/parallel.h"
#include "pipeline/primitives.h"
#include "pipeline/view_mapping.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <functional>
#include <limits>
#include <map>

namespace vplab {
namespace {

using test::errorOf;
using testing::HasSubstr;

// For types without padding bytes (doubles, vectors and matrices of them, PipelineStats, Edge).
template <class T>
bool bitwiseEqual(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}
template <class T>
bool bitwiseEqual(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// Every result of a run, compared bit for bit.
void expectSameRun(const PipelineRun& a, const PipelineRun& b) {
  EXPECT_TRUE(bitwiseEqual(a.vrcFromWc, b.vrcFromWc));
  EXPECT_TRUE(bitwiseEqual(a.npcFromVrc, b.npcFromVrc));
  EXPECT_TRUE(bitwiseEqual(a.dcFromNpc, b.dcFromNpc));
  EXPECT_TRUE(bitwiseEqual(a.npcFromWc, b.npcFromWc));
  EXPECT_TRUE(bitwiseEqual(a.wcFromVrc, b.wcFromVrc));
  EXPECT_TRUE(bitwiseEqual(a.wcFromNpc, b.wcFromNpc));
  EXPECT_EQ(a.camera.prp, b.camera.prp);
  EXPECT_EQ(a.camera.front, b.camera.front);
  EXPECT_EQ(a.vrc.vpd, b.vrc.vpd);
  EXPECT_EQ(a.device.width, b.device.width);
  EXPECT_EQ(a.options.strategy, b.options.strategy);
  EXPECT_EQ(a.sceneIndex, b.sceneIndex);
  EXPECT_TRUE(bitwiseEqual(a.stats, b.stats));
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (size_t k = 0; k < a.objects.size(); ++k) {
    const ObjectRun &x = a.objects[k], &y = b.objects[k];
    SCOPED_TRACE(x.name);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.mesh, y.mesh);
    EXPECT_TRUE(bitwiseEqual(x.wcFromMc, y.wcFromMc));
    EXPECT_TRUE(bitwiseEqual(x.npcH, y.npcH));
    EXPECT_EQ(x.outcodes, y.outcodes);
    EXPECT_EQ(x.box, y.box);
    EXPECT_EQ(x.fate, y.fate);
    EXPECT_EQ(x.clippedFaces, y.clippedFaces);
    EXPECT_EQ(x.clippedStart, y.clippedStart);
    EXPECT_EQ(x.clippedRefs, y.clippedRefs);
    EXPECT_TRUE(bitwiseEqual(x.createdNpcH, y.createdNpcH));
    EXPECT_EQ(x.createdOnPlanes, y.createdOnPlanes);
    // DC is defined for the vertices inside (outcode 0): the clipped polygons use no other.
    for (uint32_t i = 0; i < x.vertexCount(); ++i)
      if (x.outcodes[i] == 0) {
        EXPECT_TRUE(bitwiseEqual(x.dc(i), y.dc(i))) << "vertex " << i;
      }
    for (uint32_t ref = uint32_t(x.vertexCount()); ref < x.vertexCount() + x.createdNpcH.size(); ++ref)
      EXPECT_TRUE(bitwiseEqual(x.clippedDc(ref), y.clippedDc(ref))) << "created vertex " << ref;
    EXPECT_TRUE(bitwiseEqual(x.edges, y.edges));
    EXPECT_EQ(x.edgeFate, y.edgeFate);
    EXPECT_EQ(x.clippedEdges, y.clippedEdges);
    ASSERT_EQ(x.clippedEdgeRanges.size(), y.clippedEdgeRanges.size());  // field by field: EdgeRange has padding
    for (size_t i = 0; i < x.clippedEdgeRanges.size(); ++i) {
      const EdgeRange &r = x.clippedEdgeRanges[i], &s = y.clippedEdgeRanges[i];
      EXPECT_TRUE(bitwiseEqual(r.t0, s.t0) && bitwiseEqual(r.t1, s.t1) && r.visible == s.visible);
    }
  }
}

std::vector<Camera> someCameras(test::Rng& rng) {
  std::vector<Camera> list;
  for (int i = 0; i < 4; ++i) list.push_back(test::randomCamera(rng, Projection::perspective));
  for (int i = 0; i < 2; ++i) list.push_back(test::randomCamera(rng, Projection::parallel));
  for (int i = 0; i < 2; ++i) list.push_back(test::randomCamera(rng, Projection::oblique));
  return list;
}

// The tolerance for "inside the cube" after the division (see clipping_test.cpp): created vertices
// are snapped onto their planes; the remaining coordinates carry interpolation roundings of order
// 1e-16 relative to homogeneous values up to ~1e3·w for these cameras. 1e-11 leaves a wide margin
// and is 1e-8 of a pixel on a 1000-pixel device.
constexpr double kCubeEps = 1e-11;

TEST(Pipeline, EachStageIsItsMatrix) {
  test::Rng rng(100);
  for (const Camera& c : someCameras(rng)) {
    const Scene scene = test::randomPolygonScene(rng, c, 10, true);
    const PipelineRun run = runPipeline(scene);
    EXPECT_EQ(run.vrcFromWc, vrcFromWc(c));
    EXPECT_EQ(run.npcFromVrc, npcFromVrc(c));
    EXPECT_EQ(run.dcFromNpc, dcFromNpc(scene.device));
    EXPECT_EQ(run.npcFromWc, run.npcFromVrc * run.vrcFromWc);
    ASSERT_EQ(run.objects.size(), scene.objects.size());
    for (size_t k = 0; k < run.objects.size(); ++k) {
      const ObjectRun& o = run.objects[k];
      EXPECT_EQ(o.name, scene.objects[k].name);
      EXPECT_EQ(o.wcFromMc, wcFromMc(scene.objects[k].transform));
      for (size_t i = 0; i < o.vertexCount(); ++i) {
        const Vec3 wc = Vec3(o.wcFromMc * Vec4(o.mesh->positions[i], 1));
        const Vec3 vrc = Vec3(run.vrcFromWc * Vec4(wc, 1));
        const Vec4 npcH = run.npcFromVrc * Vec4(vrc, 1);
        // Relative 1e-14: the batch code sums the same products in another order.
        EXPECT_NEAR(glm::length(o.wc(uint32_t(i)) - wc), 0, 1e-14 * (1 + glm::length(wc)));
        EXPECT_NEAR(glm::length(o.vrc(uint32_t(i)) - vrc), 0, 1e-13 * (1 + glm::length(vrc)));
        EXPECT_NEAR(glm::length(o.npcH[i] - npcH), 0, 1e-12 * (1 + glm::length(npcH)));
      }
    }
  }
}

// Hill 7.4: boundary coordinates and outcodes are computed once per vertex (one entry per mesh
// vertex, not per face corner) and shared by every face that uses the vertex.
TEST(Pipeline, VerticesAreClassifiedOnce) {
  Scene scene = test::sceneWith(test::checkCamera(), {test::shapeObject("sphere", Shape::sphere, {{0.8, 0, 0}, {}, {1, 1, 1}}, 12)});
  const Mesh& mesh = *scene.objects[0].mesh;
  ASSERT_GT(mesh.indices.size(), 2 * mesh.vertexCount());  // corners outnumber vertices
  for (ClipStrategy s : {ClipStrategy::npc, ClipStrategy::wc, ClipStrategy::divideFirst}) {
    const PipelineRun run = runPipeline(scene, {s});
    const ObjectRun& o = run.objects[0];
    EXPECT_EQ(o.outcodes.size(), mesh.vertexCount());
    EXPECT_EQ(o.npcH.size(), mesh.vertexCount());
    EXPECT_EQ(run.stats.verticesTransformed, mesh.vertexCount());
    EXPECT_EQ(run.stats.verticesClassified, mesh.vertexCount());
    for (size_t i = 0; i < o.vertexCount(); ++i) EXPECT_EQ(o.outcodes[i], outcodeOf(o.clipValuesOf(uint32_t(i))));
    if (s == ClipStrategy::npc) {
      for (size_t i = 0; i < o.vertexCount(); ++i)
        EXPECT_EQ(o.clipValuesOf(uint32_t(i)), clipValues(boundaryCoordinates(o.npcH[i])));
    }
    // WC: the frustum planes evaluated at the WC point, the same linear forms as Blinn's BCs of
    // npcH; relative 1e-12 covers the different summation orders on terms up to ~10·|npcH|.
    if (s == ClipStrategy::wc) {
      for (size_t i = 0; i < o.vertexCount(); ++i)
        for (int p = 0; p < kPlaneCount; ++p)
          EXPECT_NEAR(o.clipValuesOf(uint32_t(i))[size_t(p)], boundaryCoordinates(o.npcH[i])[p],
                      1e-12 * (1 + glm::length(o.npcH[i])));
    }
  }
}

double maxAbs(const Mat4& m) {
  double a = 0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) a = std::max(a, std::abs(m[c][r]));
  return a;
}

// The run keeps the inverses of vrcFromWc and npcFromWc (computed once, not in every view): each
// times its matrix is the identity, and a WC point goes to VRC or to NPC (divided by w) and back.
TEST(Pipeline, StoresTheInversesOfItsMatrices) {
  test::Rng rng(1212);
  for (const Camera& c : someCameras(rng)) {
    const Scene scene = test::randomPolygonScene(rng, c, 4, false);
    const PipelineRun run = runPipeline(scene);
    // The inverse carries a relative error of about cond(M)·ε; the product's entries add four
    // products each. 16·ε·|M|·|M⁻¹| (largest entries) bounds both with a margin: for these cameras
    // it is 2e-14 to 7e-13, and the products come out within 4e-15 of the identity.
    for (auto [m, inverse] : {std::pair{run.vrcFromWc, run.wcFromVrc}, {run.npcFromWc, run.wcFromNpc}}) {
      const double eps = 16 * std::numeric_limits<double>::epsilon() * maxAbs(m) * maxAbs(inverse);
      for (const Mat4& product : {m * inverse, inverse * m})
        for (int col = 0; col < 4; ++col)
          for (int r = 0; r < 4; ++r) EXPECT_NEAR(product[col][r], col == r ? 1 : 0, eps) << "entry " << r << ", " << col;
    }
    // VRC's origin is VRP (lecture notes 15.2.2).
    EXPECT_NEAR(glm::length(transformAffine(run.wcFromVrc, Vec3(0)) - c.vrp), 0, 1e-12 * (1 + glm::length(c.vrp)));
    for (int k = 0; k < 20; ++k) {
      const Vec3 wc = c.vrp + rng.inBox(-10, 10);
      const Vec4 npcH = run.npcFromWc * Vec4(wc, 1);
      if (npcH.w <= 1e-3) continue;  // on the eye's plane (perspective): the division is meaningless
      // Relative 1e-12: the round trips come out within 1e-15; the margin is for the division by a
      // small w (down to 1e-3), which magnifies the inverse's error.
      const double tolerance = 1e-12 * (1 + glm::length(wc));
      EXPECT_NEAR(glm::length(run.wcOfNpc(divideByW(npcH)) - wc), 0, tolerance) << "through NPC";
      EXPECT_NEAR(glm::length(transformAffine(run.wcFromVrc, transformAffine(run.vrcFromWc, wc)) - wc), 0, tolerance)
          << "through VRC";
    }
  }
}

TEST(Pipeline, FrustumPlanesInWc) {
  test::Rng rng(17);
  for (const Camera& c : someCameras(rng)) {
    const Mat4 m = npcFromVrc(c) * vrcFromWc(c);
    const auto planes = frustumPlanesWc(m);
    for (int k = 0; k < 20; ++k) {
      const Vec3 p = c.vrp + rng.inBox(-10, 10);
      const Boundary bc = boundaryCoordinates(m * Vec4(p, 1));
      for (int i = 0; i < kPlaneCount; ++i)  // relative 1e-13: dot products of ~1e3-sized terms
        EXPECT_NEAR(glm::dot(planes[i], Vec4(p, 1)), bc[i], 1e-13 * (1 + glm::length(m * Vec4(p, 1))));
    }
  }
}

// Fates follow the outcodes; accepted faces are passed on unchanged, rejected ones are empty; every
// output vertex of the correct strategies has w > 0 and lies in the cube; mesh vertices used by the
// output have outcode 0, created ones lie exactly on their planes; the statistics add up.
TEST(Pipeline, RandomScenesGiveCorrectOutput) {
  test::Rng rng(2024);
  std::map<Fate, int> seen;
  int behindEye = 0;
  for (int scene = 0; scene < 40; ++scene) {
    for (const Camera& c : someCameras(rng)) {
      const Scene s = test::randomPolygonScene(rng, c, 12, scene % 4 == 0);
      for (ClipStrategy strategy : {ClipStrategy::npc, ClipStrategy::wc}) {
        const PipelineRun run = runPipeline(s, {strategy});
        const double W = s.device.width, H = s.device.height;
        uint64_t polygons = 0, vertices = 0, created = 0, output = 0;
        std::map<Fate, uint64_t> fates;
        for (const ObjectRun& o : run.objects) {
          polygons += o.faceCount();
          vertices += o.vertexCount();
          created += o.createdNpcH.size();
          for (size_t i = 0; i < o.vertexCount(); ++i) {
            output += o.outcodes[i] == 0;
            behindEye += o.npcH[i].w <= 0;
            EXPECT_TRUE(isFinite(o.npcH[i]) && (o.outcodes[i] != 0 || isFinite(o.dc(i))));
          }
          for (size_t f = 0; f < o.faceCount(); ++f) {
            ++fates[o.fate[f]];
            ++seen[o.fate[f]];
            const auto mf = o.mesh->face(f);
            Outcode all = 0x3f, any = 0;
            for (uint32_t v : mf) {
              all &= o.outcodes[v];
              any |= o.outcodes[v];
            }
            const auto out = o.clippedFace(f);
            switch (o.fate[f]) {
              case Fate::accepted:
                EXPECT_EQ(any, 0);
                EXPECT_TRUE(std::equal(out.begin(), out.end(), mf.begin(), mf.end()));
                break;
              case Fate::rejected:
                EXPECT_NE(all, 0);
                EXPECT_TRUE(out.empty());
                break;
              case Fate::clipped:
                EXPECT_TRUE(all == 0 && any != 0);
                EXPECT_GE(out.size(), 3u);
                break;
              case Fate::clippedAway:
                EXPECT_TRUE(all == 0 && any != 0);
                EXPECT_TRUE(out.empty());
                break;
            }
            for (uint32_t ref : out) {
              const Vec4 h = o.clippedNpcH(ref);
              ASSERT_GT(h.w, 0) << toString(strategy);
              EXPECT_LE(test::outsideCube(o.clippedNpc(ref)), kCubeEps) << format(o.clippedNpc(ref));
              const Vec3 dc = o.clippedDc(ref);
              EXPECT_TRUE(dc.x >= -kCubeEps * W && dc.x <= W * (1 + kCubeEps) && dc.y >= -kCubeEps * H &&
                          dc.y <= H * (1 + kCubeEps) && dc.z >= -kCubeEps && dc.z <= 1 + kCubeEps)
                  << format(dc);
              if (!o.isCreated(ref)) {
                EXPECT_EQ(o.outcodes[ref], 0);
              } else {
                const uint8_t on = o.createdOnPlanes[ref - o.vertexCount()];
                EXPECT_NE(on, 0);
                const Boundary bc = boundaryCoordinates(h);
                for (int p = 0; p < kPlaneCount; ++p)
                  if (on >> p & 1) {
                    EXPECT_EQ(bc[p], 0) << "snapped onto " << planeName(p);
                  }
              }
            }
          }
        }
        const PipelineStats& st = run.stats;
        EXPECT_EQ(st.objects, s.objects.size());
        EXPECT_EQ(st.polygons, polygons);
        EXPECT_EQ(st.vertices, vertices);
        EXPECT_EQ(st.polygonsTriviallyAccepted + st.polygonsTriviallyRejected + st.polygonsClipped +
                      st.polygonsClippedAway,
                  st.polygons);
        EXPECT_EQ(st.polygonsTriviallyAccepted, fates[Fate::accepted]);
        EXPECT_EQ(st.polygonsTriviallyRejected, fates[Fate::rejected]);
        EXPECT_EQ(st.polygonsClipped, fates[Fate::clipped]);
        EXPECT_EQ(st.polygonsClippedAway, fates[Fate::clippedAway]);
        EXPECT_EQ(st.verticesCreated, created);
        EXPECT_EQ(st.verticesOutput, output + created);
        EXPECT_EQ(st.polygonsDecidedByBox, 0u);
      }
    }
  }
  // Every path was taken often (with this seed: 1144 accepted, 14772 rejected, 6066 clipped, 1058
  // clipped away; 2974 vertices behind the eye).
  for (Fate f : {Fate::accepted, Fate::rejected, Fate::clipped, Fate::clippedAway}) EXPECT_GT(seen[f], 100) << toString(f);
  EXPECT_GT(behindEye, 100);
}

// A cube straddling the right plane: each new vertex lies on an edge shared by two faces, and both
// faces computed it bit for bit the same (from the inside endpoint); the same for a sphere.
TEST(Pipeline, SharedEdgesGiveBitwiseIdenticalVertices) {
  ModelTransform cubeT{{0.9, 0.1, 0.2}, {{{1, 2, 3}, 25, {}}}, {0.7, 0.7, 0.7}};
  ModelTransform sphereT{{-0.85, 0.05, -0.3}, {}, {0.4, 0.4, 0.4}};
  // Several meshes: whether the two directions would round alike by accident varies per edge, so
  // many cut edges make the test sensitive (computing from the first endpoint instead of the inside
  // one leaves a few twins differing in the last bit with the 32- and 64-segment spheres).
  for (const SceneObject& obj : {test::shapeObject("cube", Shape::cube, cubeT), test::shapeObject("sphere 16", Shape::sphere, sphereT, 16),
                                 test::shapeObject("sphere 32", Shape::sphere, sphereT, 32),
                                 test::shapeObject("sphere 64", Shape::sphere, sphereT, 64)}) {
    for (ClipStrategy s : {ClipStrategy::npc, ClipStrategy::wc}) {
      SCOPED_TRACE(obj.name + " " + std::string(toString(s)));
      const PipelineRun run = runPipeline(test::sceneWith(test::checkCamera(), {obj}), {s});
      const ObjectRun& o = run.objects[0];
      Outcode any = 0;
      for (Outcode c : o.outcodes) any |= c;
      ASSERT_EQ(std::popcount(unsigned(any)), 1) << "crosses exactly one plane";
      ASSERT_FALSE(o.createdNpcH.empty());
      std::map<std::array<uint64_t, 4>, int> copies;  // keyed by the bits of the four coordinates
      for (const Vec4& p : o.createdNpcH)
        ++copies[{std::bit_cast<uint64_t>(p.x), std::bit_cast<uint64_t>(p.y), std::bit_cast<uint64_t>(p.z),
                  std::bit_cast<uint64_t>(p.w)}];
      for (const auto& [bytes, n] : copies) EXPECT_EQ(n, 2);  // each edge cut belongs to two faces
      EXPECT_EQ(copies.size() * 2, o.createdNpcH.size());
    }
  }
}

// The new edges of clipped faces are exactly those lying in the clip plane: for a cube crossing
// the right plane, one per cut face, with both ends at x = 1 exactly.
TEST(Pipeline, IsNewEdgeMarksEdgesOnClipPlanes) {
  const PipelineRun run = runPipeline(
      test::sceneWith(test::checkCamera(), {test::shapeObject("cube", Shape::cube, {{0.9, 0.1, 0.2}, {{{1, 2, 3}, 25, {}}}, {0.7, 0.7, 0.7}})}));
  const ObjectRun& o = run.objects[0];
  int clippedFaces = 0, newEdges = 0;
  for (size_t f = 0; f < o.faceCount(); ++f) {
    const auto face = o.clippedFace(f);
    int inFace = 0;
    for (size_t i = 0; i < face.size(); ++i) {
      const Vec3 a = o.clippedNpc(face[i]), b = o.clippedNpc(face[(i + 1) % face.size()]);
      const bool onPlane = a.x == 1 && b.x == 1;  // snapped: exactly 1
      EXPECT_EQ(o.isNewEdge(f, i), onPlane) << f << " " << i;
      inFace += o.isNewEdge(f, i);
    }
    if (o.fate[f] == Fate::clipped) {
      ++clippedFaces;
      EXPECT_EQ(inFace, 1) << f;
    } else {
      EXPECT_EQ(inFace, 0) << f;
    }
    newEdges += inFace;
  }
  EXPECT_GE(clippedFaces, 3);
  EXPECT_EQ(newEdges, clippedFaces);
}

// The parallel check camera maps WC x = 1 exactly onto NPC x = 1 (the right plane).
Camera parallelCheckCamera() {
  Camera c = test::checkCamera();
  c.projection = Projection::parallel;
  return c;
}

// A vertex exactly on a clip plane counts as inside and is kept as it is: no vertex is created for
// it, and the edge from it along the plane to the created vertex is a new edge.
TEST(Pipeline, VertexExactlyOnAPlane) {
  const Scene s = test::sceneWith(parallelCheckCamera(), {test::polygonObject("tri", {{1, 0, 0}, {2, 0.3, 0}, {0, 0.3, 0}})});
  const PipelineRun run = runPipeline(s);
  const ObjectRun& o = run.objects[0];
  ASSERT_EQ(o.npcH[0].x, o.npcH[0].w) << "the test needs the vertex exactly on x = w";
  EXPECT_EQ(o.outcodes[0], 0);
  EXPECT_EQ(o.outcodes[1], 1u << kRight);
  EXPECT_EQ(o.fate[0], Fate::clipped);
  const auto face = o.clippedFace(0);
  ASSERT_EQ(face.size(), 3u);
  EXPECT_EQ(face[0], 0u);
  EXPECT_TRUE(o.isCreated(face[1]));
  EXPECT_EQ(face[2], 2u);
  EXPECT_EQ(o.createdNpcH.size(), 1u);
  EXPECT_EQ(run.stats.verticesCreated, 1u);
  EXPECT_EQ(o.clippedNpc(face[1]).x, 1);
  EXPECT_TRUE(o.isNewEdge(0, 0)) << "from the vertex on the plane to the new vertex, along x = 1";
  EXPECT_FALSE(o.isNewEdge(0, 1)) << "part of the original edge";
  EXPECT_FALSE(o.isNewEdge(0, 2)) << "an original edge";
}

// Two kept vertices on a plane with the vertex between them cut away: the edge joining them is new.
TEST(Pipeline, NewEdgeBetweenTwoKeptVertices) {
  const Scene s = test::sceneWith(parallelCheckCamera(),
                                  {test::polygonObject("quad", {{1, -0.2, 0}, {1.5, 0, 0}, {1, 0.2, 0}, {0, 0, 0}})});
  const PipelineRun run = runPipeline(s);
  const ObjectRun& o = run.objects[0];
  ASSERT_EQ(o.fate[0], Fate::clipped);
  const auto face = o.clippedFace(0);
  ASSERT_EQ(face.size(), 3u);
  EXPECT_TRUE(o.createdNpcH.empty());
  EXPECT_EQ(std::vector<uint32_t>(face.begin(), face.end()), (std::vector<uint32_t>{0, 2, 3}));
  EXPECT_TRUE(o.isNewEdge(0, 0));
  EXPECT_FALSE(o.isNewEdge(0, 1));
  EXPECT_FALSE(o.isNewEdge(0, 2));
}

// A polygon lying in a clip plane (x = 0 of NPC) or with an edge in one is inside, accepted whole.
TEST(Pipeline, PolygonsInAPlaneAreInside) {
  const Scene s = test::sceneWith(parallelCheckCamera(),
                                  {test::polygonObject("in the left plane", {{-1, -0.5, -1}, {-1, 0.5, -1}, {-1, 0.5, 1}}),
                                   test::polygonObject("edge in the right plane", {{1, -0.5, 0}, {1, 0.5, 0}, {0, 0, 0}})});
  const PipelineRun run = runPipeline(s);
  for (const ObjectRun& o : run.objects) {
    EXPECT_EQ(o.fate[0], Fate::accepted) << o.name;
    for (size_t i = 0; i < 3; ++i) EXPECT_FALSE(o.isNewEdge(0, i)) << o.name;
  }
}

// lecture notes 15.3.4: deciding whole objects by their bounding box changes nothing visible; it counts the
// objects it decided.
TEST(Pipeline, BoundingBoxTestGivesTheSameOutput) {
  const Camera c = test::checkCamera();
  const Scene designed = test::sceneWith(
      c, {test::shapeObject("inside", Shape::sphere, {{0, 0, 0}, {}, {0.3, 0.3, 0.3}}, 8),
          test::shapeObject("outside", Shape::cube, {{-4, 0, 0}, {}, {1, 1, 1}}),
          test::shapeObject("crossing", Shape::cylinder, {{0.8, 0.2, 0}, {}, {0.5, 0.5, 0.5}}, 10)});
  const PipelineRun plain = runPipeline(designed, {ClipStrategy::npc, false});
  const PipelineRun boxed = runPipeline(designed, {ClipStrategy::npc, true});
  EXPECT_EQ(boxed.objects[0].box, BoxVerdict::inside);
  EXPECT_EQ(boxed.objects[1].box, BoxVerdict::outside);
  EXPECT_EQ(boxed.objects[2].box, BoxVerdict::crossing);
  EXPECT_EQ(plain.objects[0].box, BoxVerdict::notTested);
  EXPECT_EQ(boxed.stats.objectsAcceptedByBox, 1u);
  EXPECT_EQ(boxed.stats.objectsRejectedByBox, 1u);
  EXPECT_EQ(boxed.stats.polygonsDecidedByBox, designed.objects[0].mesh->faceCount() + 6);
  EXPECT_EQ(plain.stats.objectsAcceptedByBox + plain.stats.objectsRejectedByBox, 0u);
  // Only the crossing object's vertices were classified one by one.
  EXPECT_EQ(boxed.stats.verticesClassified, designed.objects[2].mesh->vertexCount());

  test::Rng rng(15);
  std::vector<Scene> scenes = {designed};
  for (const Camera& rc : someCameras(rng)) scenes.push_back(test::randomPolygonScene(rng, rc, 10, true));
  for (const Scene& s : scenes) {
    for (ClipStrategy strategy : {ClipStrategy::npc, ClipStrategy::wc}) {
      const PipelineRun a = runPipeline(s, {strategy, false});
      const PipelineRun b = runPipeline(s, {strategy, true});
      uint64_t accepted = 0, rejected = 0;
      for (size_t k = 0; k < a.objects.size(); ++k) {
        const ObjectRun &x = a.objects[k], &y = b.objects[k];
        accepted += y.box == BoxVerdict::inside;
        rejected += y.box == BoxVerdict::outside;
        EXPECT_EQ(x.fate, y.fate) << x.name;
        for (size_t f = 0; f < x.faceCount(); ++f) {
          const auto fx = x.clippedFace(f), fy = y.clippedFace(f);
          ASSERT_EQ(fx.size(), fy.size());
          for (size_t i = 0; i < fx.size(); ++i) EXPECT_EQ(x.clippedDc(fx[i]), y.clippedDc(fy[i])) << x.name;
        }
      }
      EXPECT_EQ(b.stats.objectsAcceptedByBox, accepted);
      EXPECT_EQ(b.stats.objectsRejectedByBox, rejected);
      const PipelineStats& st = b.stats;
      EXPECT_EQ(st.polygonsTriviallyAccepted + st.polygonsTriviallyRejected + st.polygonsClipped +
                    st.polygonsClippedAway + st.polygonsDecidedByBox,
                st.polygons);
      EXPECT_EQ(st.polygonsTriviallyAccepted + st.polygonsTriviallyRejected + st.polygonsDecidedByBox,
                a.stats.polygonsTriviallyAccepted + a.stats.polygonsTriviallyRejected);
      EXPECT_EQ(st.verticesCreated, a.stats.verticesCreated);
      EXPECT_EQ(st.verticesOutput, a.stats.verticesOutput);
    }
  }
}

// Edge clipping (wireframes): the visible parts of all unique edges; their ends lie in the cube,
// on its surface where the edge was cut, and agree with the vertices of the clipped polygon.
// Tolerance 1e-9 relative to the device size: the two compute the same intersections by different
// sequences of interpolations.
TEST(Pipeline, EdgeClippingAgreesWithPolygonClipping) {
  test::Rng rng(77);
  int cutEnds = 0;
  for (int round = 0; round < 10; ++round) {
    for (const Camera& c : someCameras(rng)) {
      const Scene s = test::randomPolygonScene(rng, c, 10, round % 3 == 0);
      const PipelineRun run = runPipeline(s, {ClipStrategy::npc, false, true});
      const double tol = 1e-9 * std::max(s.device.width, s.device.height);
      uint64_t edges = 0;
      for (const ObjectRun& o : run.objects) {
        const std::vector<Edge> expected = uniqueEdges(*o.mesh);
        ASSERT_EQ(o.edges.size(), expected.size());
        for (size_t i = 0; i < expected.size(); ++i) EXPECT_TRUE(o.edges[i].a == expected[i].a && o.edges[i].b == expected[i].b);
        ASSERT_EQ(o.edgeFate.size(), o.edges.size());
        // a range is kept only for the edges cut with something left, one each, ascending
        EXPECT_EQ(size_t(std::count(o.edgeFate.begin(), o.edgeFate.end(), Fate::clipped)), o.clippedEdges.size());
        EXPECT_EQ(o.clippedEdgeRanges.size(), o.clippedEdges.size());
        EXPECT_TRUE(std::adjacent_find(o.clippedEdges.begin(), o.clippedEdges.end(), std::greater_equal<>()) == o.clippedEdges.end());
        edges += o.edges.size();
        const bool singlePolygon = o.faceCount() == 1;
        std::vector<Vec3> polygonDc;
        if (singlePolygon)
          for (uint32_t ref : o.clippedFace(0)) polygonDc.push_back(o.clippedDc(ref));
        for (size_t i = 0; i < o.edges.size(); ++i) {
          const EdgeRange r = o.edgeRange(i);
          const Outcode a = o.outcodes[o.edges[i].a], b = o.outcodes[o.edges[i].b];
          if (a & b) {
            EXPECT_FALSE(r.visible);
          }
          if (!(a | b)) {
            EXPECT_TRUE(r.visible && r.t0 == 0 && r.t1 == 1);
          }
          if (!r.visible || r.t1 - r.t0 < 1e-9) continue;
          for (double t : {r.t0, r.t1}) {
            const Vec4 h = o.npcH[o.edges[i].a] + t * (o.npcH[o.edges[i].b] - o.npcH[o.edges[i].a]);
            ASSERT_GT(h.w, 0);
            const Vec3 npc = divideByW(h);
            EXPECT_LE(test::outsideCube(npc), 1e-9);
            if (t != 0 && t != 1) {
              ++cutEnds;
              double toFace = 1;
              for (int k = 0; k < 3; ++k) toFace = std::min({toFace, std::abs(npc[k]), std::abs(npc[k] - 1)});
              EXPECT_LE(toFace, 1e-9) << "a cut end lies on the cube";
            }
            if (singlePolygon && o.fate[0] != Fate::rejected) {
              const Vec3 dc = Vec3(run.dcFromNpc * Vec4(npc, 1));
              bool found = false;
              for (const Vec3& p : polygonDc) found = found || glm::length(p - dc) <= tol;
              EXPECT_TRUE(found) << o.name << " edge end " << format(dc) << " is no vertex of the clipped polygon";
            }
          }
        }
      }
      const PipelineStats& st = run.stats;
      EXPECT_EQ(st.edges, edges);
      EXPECT_EQ(st.edgesAccepted + st.edgesRejected + st.edgesClipped, st.edges);
    }
  }
  EXPECT_GT(cutEnds, 100);  // 1486 with this seed
}

// With the box test and edges on, a decided object's edges are decided with it.
TEST(Pipeline, EdgesOfObjectsDecidedByTheirBox) {
  const Scene s = test::sceneWith(test::checkCamera(), {test::shapeObject("inside", Shape::cube, {{0, 0, 0}, {}, {0.5, 0.5, 0.5}}),
                                                        test::shapeObject("outside", Shape::cube, {{9, 0, 0}, {}, {1, 1, 1}})});
  const PipelineRun run = runPipeline(s, {ClipStrategy::npc, true, true});
  ASSERT_EQ(run.objects[0].edgeFate.size(), 12u);
  for (size_t e = 0; e < 12; ++e) {
    const EdgeRange r = run.objects[0].edgeRange(e);
    EXPECT_TRUE(r.visible && r.t0 == 0 && r.t1 == 1);
    EXPECT_FALSE(run.objects[1].edgeRange(e).visible);
  }
  EXPECT_EQ(run.stats.edgesAccepted, 12u);
  EXPECT_EQ(run.stats.edgesRejected, 12u);
}

TEST(Pipeline, InvalidCameraLeavesThePreviousRunUnchanged) {
  test::Rng rng(5);
  const Scene good = test::randomPolygonScene(rng, test::checkCamera(), 8, true);
  PipelineRun run;
  runPipeline(good, {ClipStrategy::npc, true, true}, run);
  const PipelineRun before = run;
  for (auto edit : std::vector<std::function<void(Camera&)>>{
           [](Camera& c) { c.prp = c.vrp; }, [](Camera& c) { c.vup = {0, 0, 0}; },
           [](Camera& c) { c.front = 10; }, [](Camera& c) { c.window.xmax = c.window.xmin; },
           [](Camera& c) { c.prp.x = std::numeric_limits<double>::quiet_NaN(); }}) {
    Scene bad = good;
    edit(bad.camera);
    bad.device = {10, 10};  // would change dcFromNpc if anything were applied
    EXPECT_THAT(errorOf([&] { runPipeline(bad, {ClipStrategy::wc}, run); }), HasSubstr("invalid camera: "));
    expectSameRun(run, before);
  }
  // An invalid modeling transform: named by its object, and the run is unchanged too.
  Scene badObject = good;
  badObject.objects[2].transform.scale = {1, 0, 1};
  EXPECT_THAT(errorOf([&] { runPipeline(badObject, {}, run); }),
              HasSubstr("object \"" + good.objects[2].name + "\": scale (1, 0, 1)"));
  expectSameRun(run, before);
}

// Buffers are reused from run to run; a reused run ends exactly like a fresh one, whatever ran
// before (other scenes, fewer or more objects, other options).
TEST(Pipeline, ReusedRunEqualsAFreshRun) {
  test::Rng rng(6);
  std::vector<Scene> scenes;
  for (const Camera& c : someCameras(rng)) scenes.push_back(test::randomPolygonScene(rng, c, rng.integer(1, 12), rng.chance(0.5)));
  const std::vector<PipelineOptions> options = {{ClipStrategy::npc, false, false}, {ClipStrategy::wc, true, true},
                                                {ClipStrategy::divideFirst, false, true}, {ClipStrategy::npc, true, false},
                                                {ClipStrategy::wc, false, true}};
  PipelineRun reused;
  for (int k = 0; k < 60; ++k) {
    const Scene& s = scenes[size_t(rng.integer(0, int(scenes.size()) - 1))];
    const PipelineOptions& o = options[size_t(rng.integer(0, int(options.size()) - 1))];
    runPipeline(s, o, reused);
    SCOPED_TRACE(k);
    expectSameRun(reused, runPipeline(s, o));
  }
}

// A run in steps (PipelineJob: the page runs a large scene across frames) equals the whole run bit for
// bit, however the steps cut it: budgets of 1 to 40 units cut every pass in the middle of an object,
// at its ends and between objects; progress only grows and reaches 1 exactly when the run is done.
TEST(PipelineJob, StepsOfAnySizeEqualTheWholeRun) {
  test::Rng rng(11);
  std::vector<Scene> scenes;
  for (const Camera& c : someCameras(rng)) scenes.push_back(test::randomPolygonScene(rng, c, rng.integer(1, 12), rng.chance(0.5)));
  const std::vector<PipelineOptions> options = {{ClipStrategy::npc, false, false}, {ClipStrategy::wc, true, true},
                                                {ClipStrategy::divideFirst, false, true}, {ClipStrategy::npc, true, true},
                                                {ClipStrategy::wc, false, false}};
  PipelineRun stepped;
  for (int k = 0; k < 40; ++k) {
    SCOPED_TRACE(k);
    const Scene& s = scenes[size_t(rng.integer(0, int(scenes.size()) - 1))];
    const PipelineOptions& o = options[size_t(rng.integer(0, int(options.size()) - 1))];
    const PipelineRun whole = runPipeline(s, o);
    PipelineJob job(s, o, stepped);
    const uint64_t budget = uint64_t(rng.integer(1, 40));
    double last = job.progress();
    int steps = 0;
    while (!job.step(budget)) {
      ++steps;
      EXPECT_GE(job.progress(), last);
      EXPECT_LT(job.progress(), 1.0);
      last = job.progress();
      ASSERT_LT(steps, 1'000'000);
    }
    EXPECT_EQ(job.progress(), 1.0);
    EXPECT_TRUE(job.step(budget));  // a finished job stays finished and changes nothing
    // The vertices and the faces not decided by a box each take a unit (the edges more still).
    const uint64_t units = whole.stats.vertices + whole.stats.polygons - whole.stats.polygonsDecidedByBox;
    EXPECT_GE(uint64_t(steps + 1) * budget, units) << "a step did more than its budget";
    if (units > 2 * budget) {
      EXPECT_GT(steps, 0);
    }
    expectSameRun(stepped, whole);
  }
}

// The run on every core (PipelineOptions::parallel) is the serial run bit for bit. Two spheres of
// 300 segments (45 000 vertices, 45 000 quads and triangles; the same triangulated: 90 000
// triangles) cut by the cube's planes and by a user plane, so that every pass is shared out in
// several chunks (32 768 units) and crossing faces and edges lie in many of them; the three
// strategies, with and without the box test and the edges; whole, and in steps that end inside chunks.
TEST(Pipeline, EveryCoreEqualsOneCoreBitForBit) {
  ASSERT_TRUE(parallelAvailable()) << "the native build shares the stages' work between cores (oneTBB)";
  const ModelTransform cut{{0.6, 0.4, 0.5}, {{{1, 2, 3}, 20, {}}}, {1.1, 1.1, 1.1}};
  SceneObject quads = test::shapeObject("sphere", Shape::sphere, cut, 300);
  SceneObject triangles = quads;
  triangles.name = "triangulated sphere";
  triangles.transform.translate = {-0.7, -0.5, -0.4};
  triangles.mesh = std::make_shared<const Mesh>(triangulated(*quads.mesh));
  Scene s = test::sceneWith(test::checkCamera(), {quads, triangles});
  s.clipPlanes.push_back({glm::normalize(Vec3(1, 1, 0)), {0.2, 0.1, 0}, true});
  int crossingChunks = 0;
  for (const PipelineOptions& o : {PipelineOptions{ClipStrategy::npc, false, true}, PipelineOptions{ClipStrategy::wc, true, true},
                                   PipelineOptions{ClipStrategy::divideFirst, false, false},
                                   PipelineOptions{ClipStrategy::npc, true, false}}) {
    SCOPED_TRACE(std::string(toString(o.strategy)) + (o.boundingBoxTest ? " box" : "") + (o.clipEdges ? " edges" : ""));
    PipelineOptions serial = o, parallel = o;
    serial.parallel = false;
    parallel.parallel = true;
    const PipelineRun one = runPipeline(s, serial);
    for (const ObjectRun& r : one.objects) {
      ASSERT_GT(r.vertexCount(), 32768u);
      ASSERT_GT(r.clippedFaces.size(), 100u) << "faces crossing planes in many chunks";
      crossingChunks += r.clippedFaces.front() / 32768 != r.clippedFaces.back() / 32768;
    }
    expectSameRun(runPipeline(s, parallel), one);
    PipelineRun stepped;
    PipelineJob job(s, parallel, stepped);
    while (!job.step(50'001)) {
    }
    expectSameRun(stepped, one);
  }
  EXPECT_GT(crossingChunks, 0);
}

// The face pass decides whole clusters of faces where their vertices' outcodes agree (mesh.h
// FaceCluster): every face's fate is still its own outcodes' verdict (AND ≠ 0: rejected; OR = 0:
// accepted; else clipped or clipped away). Spheres of quads and of triangles (the two face loops),
// inside, outside and across the cube's planes, with and without a user plane, whole and in steps
// that cut clusters.
TEST(Pipeline, FacesDecidedByClusterKeepTheirOwnVerdicts) {
  const std::vector<std::shared_ptr<const Mesh>> meshes = {std::make_shared<const Mesh>(sphere(96)),
                                                           std::make_shared<const Mesh>(triangulated(sphere(96)))};
  const std::vector<ModelTransform> places = {{{0, 0, 0}, {}, {0.3, 0.3, 0.3}},
                                              {{6, 5, 4}, {}, {1, 1, 1}},
                                              {{0.8, 0.5, 0.3}, {{{1, 1, 0}, 30, {}}}, {0.9, 0.9, 0.9}}};
  size_t decidedWhole = 0;
  for (const auto& mesh : meshes)
    for (const ModelTransform& t : places)
      for (bool userPlane : {false, true}) {
        SceneObject o = test::shapeObject("sphere", Shape::sphere, t);
        o.mesh = mesh;
        Scene s = test::sceneWith(test::checkCamera(), {o});
        if (userPlane) s.clipPlanes.push_back({glm::normalize(Vec3(1, -1, 0.5)), {0.1, 0, 0}, true});
        PipelineRun stepped;
        PipelineJob job(s, {}, stepped);
        while (!job.step(1000)) {
        }
        const PipelineRun whole = runPipeline(s);
        expectSameRun(stepped, whole);
        const ObjectRun& r = whole.objects[0];
        ASSERT_EQ(r.faceClusters.size(), clusterCount(*mesh));
        for (size_t f = 0; f < r.faceCount(); ++f) {
          Outcode all = 0xffff, any = 0;
          for (uint32_t v : mesh->face(f)) {
            all &= r.outcodes[v];
            any |= r.outcodes[v];
          }
          const Fate want = all ? Fate::rejected : any ? Fate::clipped : Fate::accepted;
          if (want == Fate::clipped) EXPECT_TRUE(r.fate[f] == Fate::clipped || r.fate[f] == Fate::clippedAway) << f;
          else EXPECT_EQ(r.fate[f], want) << "face " << f;
        }
        for (const FaceCluster& k : r.faceClusters) {
          Outcode all = 0xffff, any = 0;
          for (uint32_t i = 0; i < k.runs; ++i)
            for (uint32_t v = k.first[i]; v <= k.last[i]; ++v) {
              all &= r.outcodes[v];
              any |= r.outcodes[v];
            }
          decidedWhole += k.runs > 0 && (all || !any);
        }
      }
  EXPECT_GT(decidedWhole, 100u) << "clusters decided their faces at once";
}

// A job dropped half way (a newer camera replaced it) leaves its run fit to be run into again.
TEST(PipelineJob, ADroppedJobLeavesTheRunReusable) {
  test::Rng rng(12);
  const Scene s = test::randomPolygonScene(rng, test::randomCamera(rng, Projection::perspective), 8, true);
  const PipelineOptions o{ClipStrategy::npc, false, true};
  PipelineRun run;
  for (uint64_t cut : {1u, 7u, 50u, 200u}) {
    {
      PipelineJob job(s, o, run);
      job.step(cut);
    }
    runPipeline(s, o, run);
    SCOPED_TRACE(cut);
    expectSameRun(run, runPipeline(s, o));
  }
}

TEST(Pipeline, HiddenObjectsAndObjectsWithoutMeshAreSkipped) {
  Scene s = test::sceneWith(test::checkCamera(), {test::shapeObject("a", Shape::cube, {}), test::shapeObject("b", Shape::cube, {}),
                                                  test::shapeObject("c", Shape::tetrahedron, {})});
  s.objects[0].visible = false;
  s.objects[1].mesh.reset();
  const PipelineRun run = runPipeline(s);
  ASSERT_EQ(run.objects.size(), 1u);
  EXPECT_EQ(run.objects[0].name, "c");
  EXPECT_EQ(run.sceneIndex, std::vector<size_t>{2});
  EXPECT_EQ(run.stats.objects, 1u);
  EXPECT_EQ(run.stats.polygons, 4u);
  const PipelineRun empty = runPipeline(test::sceneWith(test::checkCamera(), {}));
  EXPECT_TRUE(empty.objects.empty());
  EXPECT_EQ(empty.stats.polygons, 0u);
}

TEST(Pipeline, Names) {
  for (ClipStrategy s : {ClipStrategy::npc, ClipStrategy::wc, ClipStrategy::divideFirst})
    EXPECT_EQ(fromString<ClipStrategy>(toString(s)), s);
  EXPECT_EQ(toString(ClipStrategy::divideFirst), "divide-first");
  EXPECT_EQ(fromString<ClipStrategy>("NPC"), std::nullopt);
  EXPECT_TRUE(isCorrect(ClipStrategy::npc) && isCorrect(ClipStrategy::wc) && !isCorrect(ClipStrategy::divideFirst));
  EXPECT_EQ(toString(Fate::clippedAway), "clipped_away");
  for (Shape s : {Shape::cube, Shape::tetrahedron, Shape::cylinder, Shape::sphere, Shape::polygon, Shape::mesh})
    EXPECT_EQ(fromString<Shape>(toString(s)), s);
}

}  // namespace
}  // namespace vplab
