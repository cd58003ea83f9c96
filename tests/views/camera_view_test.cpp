// The camera view's display list: the filled scene or its edges in WC through the scene camera, the
// hidden-line styles' occluder before their edges, the DC overlays in the view's pixels.
#include "app/views/theme.h"
#include "io/scene_io.h"
#include "pipeline/vanishing_points.h"
#include "tests/views/view_test_support.h"

#include <gtest/gtest.h>

namespace vplab {
namespace {

using namespace draw;

Scene preset(const char* name) { return loadScene(std::string(VPLAB_ASSETS) + "/scenes/" + name + ".json"); }

TEST(CameraView, FilledStylesAreOneFillOfTheVisibleObjectsClippedByTheUserPlanes) {
  test::ViewFixture f(preset("clip-planes"), Style::shaded);
  f.scene.objects[1].visible = false;
  const DisplayList list = cameraView(f.input());
  EXPECT_FALSE(list.antialiased);  // pixel-aligned with DC
  EXPECT_EQ(list.background, glm::vec3(f.scene.background));
  ASSERT_EQ(list.batches.size(), 1u);
  const Fill& fill = std::get<Fill>(list.batches[0]);
  ASSERT_EQ(fill.meshes.size(), 2u);
  EXPECT_EQ(fill.meshes[0].mesh, f.scene.objects[0].mesh);  // shared, not copied
  EXPECT_EQ(fill.meshes[1].mesh, f.scene.objects[2].mesh);
  EXPECT_EQ(fill.meshes[1].spaceFromMc, wcFromMc(f.scene.objects[2].transform));
  EXPECT_TRUE(fill.lit);
  ASSERT_EQ(fill.lights.size(), 1u);
  EXPECT_EQ(fill.lights[0].position, f.scene.lights[0].position);
  EXPECT_FLOAT_EQ(fill.ambient, 0.28f);
  ASSERT_EQ(fill.clipPlanes.size(), 2u);
  EXPECT_EQ(fill.clipPlanes[1], f.scene.clipPlanes[1].coefficients());

  // Without lights: one at the camera's PRP. Flat: unlit.
  f.scene.lights.clear();
  const Fill lit = std::get<Fill>(cameraView(f.input()).batches[0]);
  ASSERT_EQ(lit.lights.size(), 1u);
  EXPECT_EQ(lit.lights[0].position, f.scene.camera.prp);
  f.settings.camera.style = Style::flat;
  EXPECT_FALSE(std::get<Fill>(cameraView(f.input()).batches[0]).lit);
}

TEST(CameraView, HiddenLineFillsTheDepthFirstThenVisibleEdgesThenHiddenOnesDashed) {
  test::ViewFixture f(defaultScene(), Style::hiddenLine);
  const DisplayList list = cameraView(f.input());
  ASSERT_EQ(list.batches.size(), 3u);
  const Fill& occluder = std::get<Fill>(list.batches[0]);
  EXPECT_TRUE(occluder.depthOnly);
  EXPECT_EQ(occluder.meshes.size(), f.scene.objects.size());
  const Lines& visible = std::get<Lines>(list.batches[1]);
  EXPECT_EQ(visible.depth, Depth::test);
  EXPECT_EQ(visible.dashPx, 0.f);
  EXPECT_FLOAT_EQ(visible.widthPx, theme::kDark.edgeWidthPx);
  ASSERT_EQ(visible.meshEdges.size(), f.scene.objects.size());
  EXPECT_EQ(visible.meshEdges[0].color, glm::vec4(glm::vec3(f.scene.objects[0].color), 1.f));
  const Lines& hidden = std::get<Lines>(list.batches[2]);
  EXPECT_EQ(hidden.depth, Depth::hiddenOnly);
  EXPECT_EQ(hidden.dashPx, theme::kDashPx);
  EXPECT_FLOAT_EQ(hidden.meshEdges[0].color.a, 0.8f);

  f.settings.camera.style = Style::hiddenRemoved;
  const DisplayList removed = cameraView(f.input());
  ASSERT_EQ(removed.batches.size(), 2u);
  EXPECT_TRUE(std::get<Fill>(removed.batches[0]).depthOnly);
  EXPECT_EQ(std::get<Lines>(removed.batches[1]).depth, Depth::test);

  f.settings.camera.style = Style::wire;
  const DisplayList wire = cameraView(f.input());
  ASSERT_EQ(wire.batches.size(), 1u);
  EXPECT_EQ(std::get<Lines>(wire.batches[0]).depth, Depth::ignore);
}

// The vanishing points are computed in DC; the view's pixels are DC scaled to its size.
TEST(CameraView, VanishingPointsAreMarkedWhereTheyLieInTheViewsPixels) {
  for (int scaleDown : {1, 2}) {
    Scene scene = preset("vanishing-2");
    test::ViewFixture f(scene, Style::flat, scene.device.width / scaleDown, scene.device.height / scaleDown);
    f.settings.overlays.vanishingPoints = true;
    f.highlights.vanishingObject = 0;
    const DisplayList list = cameraView(f.input());
    const auto vps = vanishingPoints(f.run, f.run.objects[0].wcFromMc);
    ASSERT_EQ(vanishingPointCount(vps), 2);
    std::vector<Vec3> marks;
    for (const Points* p : test::batchesOf<Points>(list)) {
      EXPECT_EQ(p->space, Space::pixels);
      EXPECT_EQ(p->depth, Depth::ignore);
      for (const Vertex& v : p->points) marks.push_back(v.position);
    }
    ASSERT_EQ(marks.size(), 2u);
    size_t k = 0;
    for (const VanishingPoint& vp : vps) {
      if (!vp.finite) continue;
      EXPECT_NEAR(marks[k].x, vp.dc.x / scaleDown, 1e-9);
      EXPECT_NEAR(marks[k].y, vp.dc.y / scaleDown, 1e-9);
      ++k;
    }
    // Each edge along an axis is drawn on to its vanishing point, dashed, 1.2 px wide.
    const auto lines = test::batchesOf<Lines>(list);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_FLOAT_EQ(lines[0]->widthPx, 1.2f);
    EXPECT_EQ(lines[0]->dashPx, 4.f);
    EXPECT_EQ(list.labels().size(), 2u);
  }
}

TEST(CameraView, CpuPolygonsAreTheClippedFacesInPixels) {
  test::ViewFixture f(defaultScene(), Style::flat, 320, 240);  // half the device: pixels = DC / 2
  f.settings.overlays.cpuPolygons = true;
  const DisplayList list = cameraView(f.input());
  const auto lines = test::batchesOf<Lines>(list);
  ASSERT_EQ(lines.size(), 1u);
  size_t corners = 0;
  for (const ObjectRun& o : f.run.objects)
    for (size_t face = 0; face < o.faceCount(); ++face) corners += o.clippedFace(face).size();
  EXPECT_EQ(lines[0]->segments.size(), 2 * corners);
  const ObjectRun& o = f.run.objects[0];
  size_t first = 0;
  while (o.clippedFace(first).empty()) ++first;
  const Vec3 dc = o.clippedDc(o.clippedFace(first)[0]);
  EXPECT_NEAR(lines[0]->segments[0].position.x, dc.x / 2, 1e-9);
  EXPECT_NEAR(lines[0]->segments[0].position.y, dc.y / 2, 1e-9);
}

}  // namespace
}  // namespace vplab
