// The divide-first comparison's display list: the divide-first run's clipped polygons in the view's
// pixels, and Hill 7.4's triangle through the eye plane drawn where the lecture shows it, flipped.
#include "tests/support/test_util.h"
#include "tests/views/view_test_support.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace vplab {
namespace {

using namespace draw;

struct DivideFirstFixture {
  Scene scene;
  PipelineRun run;
  DisplaySettings settings;
  Highlights highlights;
  test::FixedMetrics text;
  explicit DivideFirstFixture(Scene s, ClipStrategy strategy = ClipStrategy::divideFirst)
      : scene(std::move(s)), run(runPipeline(scene, {strategy})) {}
  ViewInput input(int w, int h) const { return {scene, run, settings, highlights, w, h, text}; }
};

// Every clipped polygon of the run, object by object and face by face (the raster's order, which
// decides depth ties), in DC as the run has them, in the object's colour; the observer puts DC onto
// the view's pixels (scaled to its size) and keeps z_dc as NPC z, the depth.
TEST(DivideFirstView, PolygonsAreTheDivideFirstRunsInDc) {
  const DivideFirstFixture f(defaultScene());
  const int w = 2 * f.scene.device.width, h = 3 * f.scene.device.height;  // unequal scales: x × 2, y × 3
  const DisplayList list = divideFirstView(f.input(w, h));
  EXPECT_EQ(list.width, w);
  EXPECT_EQ(list.height, h);
  EXPECT_EQ(list.background, glm::vec3(f.scene.background));
  EXPECT_EQ(list.observer.space, Space::dc);
  EXPECT_FALSE(list.antialiased);
  ASSERT_EQ(list.batches.size(), 1u);
  const Fill& fill = std::get<Fill>(list.batches[0]);
  EXPECT_EQ(fill.space, Space::dc);
  EXPECT_FALSE(fill.lit);
  EXPECT_FALSE(fill.depthOnly);
  EXPECT_EQ(fill.alpha, 1.f);
  ASSERT_EQ(fill.polygons.size(), f.run.objects.size());
  const Mat4 npcFromDc = list.observer.camera.npcFromWc();
  size_t polygons = 0;
  for (size_t k = 0; k < f.run.objects.size(); ++k) {
    const ObjectRun& o = f.run.objects[k];
    const PolygonSet& set = fill.polygons[k];
    EXPECT_EQ(set.color, glm::vec3(o.color)) << o.name;
    size_t i = 0;
    for (size_t face = 0; face < o.faceCount(); ++face) {
      const auto refs = o.clippedFace(face);
      if (refs.size() < 3) continue;
      ASSERT_LT(i, set.polygonCount()) << o.name;
      std::vector<Vec3> scratch;
      const auto polygon = set.polygon(i++, scratch);
      ASSERT_EQ(polygon.size(), refs.size()) << o.name << " face " << face;
      for (size_t v = 0; v < refs.size(); ++v) {
        const Vec3 dc = o.clippedDc(refs[v]);
        EXPECT_EQ(polygon[v], dc) << o.name << " face " << face << " vertex " << v;
        // Through the observer: the clipped NPC point (z_npc = z_dc, the depth), and DC × (2, 3) in pixels.
        const Vec3 npc = Vec3(npcFromDc * Vec4(dc, 1.0)), clippedNpc = o.clippedNpc(refs[v]);
        EXPECT_NEAR(glm::length(npc - clippedNpc), 0, 1e-12) << o.name << " face " << face << " vertex " << v;
        const Projected p = projectToPixels(list.observer.camera, dc, w, h);
        EXPECT_TRUE(p.visible);
        EXPECT_NEAR(glm::length(p.pixel - Vec2(dc.x * 2, dc.y * 3)), 0, 1e-9);
      }
    }
    EXPECT_EQ(i, set.polygonCount()) << o.name;
    polygons += i;
  }
  EXPECT_GT(polygons, 10u);
  // buildPicture gives the same list as the only panel.
  const Picture picture = buildPicture(ViewKind::divideFirst, f.input(w, h));
  ASSERT_EQ(picture.panels.size(), 1u);
  EXPECT_EQ(std::get<Fill>(picture.panels[0].list.batches[0]).polygons[0].points, fill.polygons[0].points);
}

// The view shows what dividing first draws: a run of a correct strategy is refused, not mislabelled.
TEST(DivideFirstView, RefusesARunOfACorrectStrategy) {
  const DivideFirstFixture f(defaultScene(), ClipStrategy::npc);
  try {
    divideFirstView(f.input(320, 240));
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("npc"), std::string::npos) << e.what();
  }
}

// Hill 7.4's triangle (tests/pipeline/strategies_test.cpp, DivideFirstWrapsAroundBehindTheEye):
// A = (0.5, −0.2, 0), B = (0.5, 0.2, 0) and C = (1, 0, 8) behind the eye at z = 5. Clipped right, it
// is a wedge from A and B (NPC x = 0.75) to the window's right edge; divided first, C flips to
// NPC x = −1/3 and the polygon drawn lies left of A and B, where the right picture is empty.
TEST(DivideFirstView, APointBehindTheEyeLandsFlipped) {
  const Scene s = test::sceneWith(test::checkCamera(), {test::polygonObject("through the eye plane",
                                                                            {{0.5, -0.2, 0}, {0.5, 0.2, 0}, {1, 0, 8}})});
  const DivideFirstFixture wrong(s), right(s, ClipStrategy::npc);
  ASSERT_LT(right.run.objects[0].npcH[2].w, 0) << "C is behind the eye";
  const int w = s.device.width, h = s.device.height;
  const DisplayList list = divideFirstView(wrong.input(w, h));
  const PolygonSet& set = std::get<Fill>(list.batches[0]).polygons.at(0);
  ASSERT_EQ(set.polygonCount(), 1u);
  double lo = 1e9, hi = -1e9;
  std::vector<Vec3> scratch;
  for (const Vec3& p : set.polygon(0, scratch)) {
    lo = std::min(lo, p.x);
    hi = std::max(hi, p.x);
    EXPECT_GE(p.x, 0);  // clipped to the window after the division, wrongly but inside
  }
  EXPECT_LT(lo, 0.7 * w) << "drawn left of A and B";
  EXPECT_LE(hi, 0.75 * w + 1e-9) << "and never toward the right edge";
  // The right picture (the camera view beside it) lies wholly at x ≥ 0.75 W and reaches the edge.
  const ObjectRun& o = right.run.objects[0];
  double rightLo = 1e9, rightHi = -1e9;
  for (uint32_t ref : o.clippedFace(0)) {
    rightLo = std::min(rightLo, o.clippedDc(ref).x);
    rightHi = std::max(rightHi, o.clippedDc(ref).x);
  }
  EXPECT_GE(rightLo, 0.75 * w - 1e-9);
  EXPECT_EQ(rightHi, w);
}

}  // namespace
}  // namespace vplab
