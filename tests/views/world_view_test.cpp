// The world view's display list: the objects inside the view volume solid and outside faded (with
// their runs, for the backend's partition), the frustum, the camera, the step-through, the labels.
#include "app/views/theme.h"
#include "io/scene_io.h"
#include "tests/views/view_test_support.h"

#include <gtest/gtest.h>

#include <bit>
#include <set>

namespace vplab {
namespace {

using namespace draw;

Scene preset(const char* name) { return loadScene(std::string(VPLAB_ASSETS) + "/scenes/" + name + ".json"); }

// The corner of the unit cube that p (WC) is in the scene camera's NPC, or −1.
int cubeCornerOf(const PipelineRun& run, const Vec3& p) {
  const Vec4 h = run.npcFromWc * Vec4(p, 1.0);
  const Vec3 npc = Vec3(h) / h.w;
  int corner = 0;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(npc[i] - 1) < 1e-9) corner |= 1 << i;
    else if (std::abs(npc[i]) > 1e-9) return -1;
  }
  return corner;
}

TEST(WorldView, FrustumLinesJoinTheViewVolumesCorners) {
  for (const char* name : {"default", "parallel", "oblique-cavalier", "off-centre-window"}) {
    test::ViewFixture f(preset(name), Style::shaded);
    const DisplayList list = worldView(f.input());
    std::set<std::pair<int, int>> edges;
    size_t fromPrp = 0;
    for (const Lines* l : test::batchesOf<Lines>(list))
      for (size_t i = 0; i < l->segments.size(); i += 2) {
        const Vertex &a = l->segments[i], &b = l->segments[i + 1];
        if (glm::vec3(a.color) != glm::vec3(theme::kDark.frustum)) continue;
        EXPECT_EQ(l->depth, Depth::xray);
        if (a.color.a == theme::kDark.frustum.a) {
          const int ca = cubeCornerOf(f.run, a.position), cb = cubeCornerOf(f.run, b.position);
          ASSERT_GE(ca, 0) << name;
          ASSERT_GE(cb, 0) << name;
          EXPECT_EQ(std::popcount(unsigned(ca ^ cb)), 1) << name << ": not a cube edge";
          edges.insert({std::min(ca, cb), std::max(ca, cb)});
        } else {
          EXPECT_EQ(a.position, f.scene.camera.prp) << name;  // dashed, from PRP to the front corners
          EXPECT_EQ(cubeCornerOf(f.run, b.position) & 4, 4) << name;
          ++fromPrp;
        }
      }
    EXPECT_EQ(edges.size(), 12u) << name;
    EXPECT_EQ(fromPrp, f.scene.camera.projection == Projection::perspective ? 4u : 0u) << name;
  }
}

TEST(WorldView, FilledObjectsInsideSolidOutsideFadedWithTheirRuns) {
  test::ViewFixture f(preset("clip-planes"), Style::shaded);
  const DisplayList list = worldView(f.input());
  EXPECT_TRUE(list.antialiased);
  EXPECT_EQ(list.observer.space, Space::wc);
  const auto fills = test::batchesOf<Fill>(list);
  ASSERT_EQ(fills.size(), 2u);
  ASSERT_EQ(&std::get<Fill>(list.batches[0]), fills[0]);  // the objects first
  const Fill &inside = *fills[0], &outside = *fills[1];
  EXPECT_EQ(inside.volume.keep, VolumeTest::Keep::inside);
  EXPECT_EQ(inside.volume.npcFromSpace, f.run.npcFromWc);
  EXPECT_EQ(inside.alpha, 1.f);
  EXPECT_EQ(inside.clipPlanes.size(), 2u);
  EXPECT_EQ(outside.volume.keep, VolumeTest::Keep::outside);
  EXPECT_FLOAT_EQ(outside.alpha, theme::kDark.fadedAlpha);
  EXPECT_TRUE(outside.clipPlanes.empty());
  ASSERT_EQ(inside.meshes.size(), f.run.objects.size());
  for (size_t k = 0; k < inside.meshes.size(); ++k) {
    EXPECT_EQ(inside.meshes[k].run, &f.run.objects[k]);
    EXPECT_EQ(outside.meshes[k].run, &f.run.objects[k]);
  }
  // A run that is not this scene's (an object moved since) is not offered for the partition.
  f.scene.objects[0].transform.translate.x += 1;
  EXPECT_EQ(std::get<Fill>(worldView(f.input()).batches[0]).meshes[0].run, nullptr);

  f.settings.overlays.fadeOutside = false;
  EXPECT_EQ(test::batchesOf<Fill>(worldView(f.input())).size(), 1u);
}

TEST(WorldView, HiddenLineEdgesFromTheCpuClipperAfterTheOccluder) {
  test::ViewFixture f(defaultScene(), Style::hiddenLine);
  const DisplayList list = worldView(f.input());
  const Fill& occluder = std::get<Fill>(list.batches[0]);
  EXPECT_TRUE(occluder.depthOnly);
  // faded (all of each edge), visible parts solid, visible parts dashed where hidden
  const Lines& faded = std::get<Lines>(list.batches[1]);
  const Lines& solid = std::get<Lines>(list.batches[2]);
  const Lines& dashed = std::get<Lines>(list.batches[3]);
  size_t edges = 0, visible = 0;
  for (const ObjectRun& o : f.run.objects) {
    edges += o.edges.size();
    for (size_t e = 0; e < o.edges.size(); ++e) visible += o.edgeVisible(e);
  }
  // by reference to the run's edges (issue 42: a million edges are not copied into the list)
  for (const Lines* l : {&faded, &solid, &dashed}) {
    EXPECT_TRUE(l->segments.empty());
    ASSERT_EQ(l->runEdges.size(), f.run.objects.size());
  }
  EXPECT_EQ(test::segmentsOf(faded).size(), 2 * edges);
  EXPECT_EQ(faded.depth, Depth::test);
  EXPECT_FLOAT_EQ(test::segmentsOf(faded)[0].color.a, theme::kDark.fadedAlpha);
  EXPECT_EQ(test::segmentsOf(solid).size(), 2 * visible);
  EXPECT_EQ(solid.depth, Depth::test);
  EXPECT_EQ(test::segmentsOf(dashed).size(), 2 * visible);
  EXPECT_EQ(dashed.depth, Depth::hiddenOnly);
  EXPECT_EQ(dashed.dashPx, theme::kDashPx);
}

TEST(WorldView, StepThroughPolygonIsTakenBackFromNpc) {
  test::ViewFixture f(defaultScene(), Style::shaded);
  f.settings.overlays = {false, false, false, false, false, false, false};
  f.highlights.step = Highlights::Step{{{0.2, 0.2, 0.5}, {1, 0.2, 0.5}, {0.5, 0.9, 0.5}}, {false, true, false}, 1};
  const DisplayList list = worldView(f.input());
  const auto triangles = test::batchesOf<Triangles>(list);
  ASSERT_EQ(triangles.size(), 1u);  // the plane x = 1 as a face of the frustum
  for (const Vertex& v : triangles[0]->vertices) EXPECT_EQ(cubeCornerOf(f.run, v.position) & 1, 1);
  const auto points = test::batchesOf<Points>(list);
  ASSERT_EQ(points.size(), 2u);  // by size: 9 px the old vertices, 13 px the created one
  EXPECT_FLOAT_EQ(points[0]->sizePx, 9.f);
  ASSERT_EQ(points[1]->points.size(), 1u);
  const Vec4 h = f.run.npcFromWc * Vec4(points[1]->points[0].position, 1.0);
  EXPECT_NEAR(h.x / h.w, 1, 1e-9);
  EXPECT_NEAR(h.y / h.w, 0.2, 1e-9);
}

TEST(WorldView, ALessonsHighlightedPlaneIsAFaceOfTheFrustumOutlinedAndItsAxesAreDrawnOver) {
  test::ViewFixture f(defaultScene(), Style::shaded);
  f.settings.overlays = {false, false, false, false, false, false, false};
  f.highlights.planes = {5};  // front: z = 1 in NPC
  f.highlights.axes = {2, 0};  // N and U
  const DisplayList list = worldView(f.input());
  const auto triangles = test::batchesOf<Triangles>(list);
  ASSERT_EQ(triangles.size(), 1u);
  for (const Vertex& v : triangles[0]->vertices) EXPECT_EQ(cubeCornerOf(f.run, v.position) & 4, 4) << "a corner of z = 1";
  size_t outline = 0, axis = 0;
  const glm::vec3 hot(theme::kDark.handleHot);
  for (const Lines* l : test::batchesOf<Lines>(list))
    for (size_t i = 0; i < l->segments.size(); i += 2) {
      if (glm::vec3(l->segments[i].color) != hot) continue;
      const Vec3 a = l->segments[i].position, b = l->segments[i + 1].position;
      if (cubeCornerOf(f.run, a) >= 0 && cubeCornerOf(f.run, b) >= 0) ++outline;
      // The axes: from VRP along N and U.
      const Vec3 along = glm::normalize(b - a);
      if (glm::length(a - f.run.camera.vrp) < 1e-9 &&
          (glm::length(along - f.run.vrc.n) < 1e-9 || glm::length(along - f.run.vrc.u) < 1e-9))
        ++axis;
    }
  EXPECT_EQ(outline, 4u) << "the face's four edges";
  EXPECT_EQ(axis, 2u) << "N and U, each drawn over";
}

}  // namespace
}  // namespace vplab
