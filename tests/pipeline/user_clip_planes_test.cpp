// User clip planes (DGL wiki, glClipPlane): planes in WC that the pipeline clips with together with
// the view volume's six, in homogeneous NPC (each plane pulled back to a linear form on NPC).
#include "pipeline/clip_steps.h"
#include "pipeline/pipeline.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace vplab {
namespace {

using test::Rng;

Scene sceneWithPlanes(Rng& rng, int planes) {
  const Camera c = test::randomCamera(rng, rng.chance(0.5) ? Projection::perspective : Projection::parallel);
  Scene scene = test::randomPolygonScene(rng, c, 10, true);
  for (int i = 0; i < planes; ++i) scene.clipPlanes.push_back({rng.unitVector(), c.vrp + rng.inBox(-0.5, 0.5), true});
  return scene;
}

// WC of a clipped vertex, back from homogeneous NPC.
Vec3 wcOf(const PipelineRun& run, const ObjectRun& o, uint32_t ref) {
  const Vec4 p = run.wcFromNpc * o.clippedNpcH(ref);
  return Vec3(p) / p.w;
}

TEST(UserClipPlanes, OutputLiesOnTheKeptSideOfEveryPlane) {
  Rng rng(3003);
  int cutByAPlane = 0;
  for (int k = 0; k < 40; ++k) {
    const Scene scene = sceneWithPlanes(rng, 1 + k % 6);
    const PipelineRun run = runPipeline(scene);
    ASSERT_EQ(run.userPlanesWc.size(), scene.clipPlanes.size());
    for (const ObjectRun& o : run.objects) {
      for (size_t f = 0; f < o.faceCount(); ++f) {
        const auto face = o.clippedFace(f);
        for (size_t i = 0; i < face.size(); ++i) {
          const Vec3 wc = wcOf(run, o, face[i]);
          // Tolerance: plane values of order 1–10 computed through an inverse 4 × 4 (the check
          // goes NPC → WC): 1e-9 relative to the size of the point is ample and still far below
          // anything a lost or mirrored plane leaves.
          for (const UserClipPlane& p : scene.clipPlanes)
            EXPECT_GE(glm::dot(p.coefficients(), Vec4(wc, 1.0)), -1e-9 * std::max(1.0, glm::length(wc)));
        }
        for (size_t i = 0; i < face.size(); ++i)
          if (o.isCreated(face[i]) && (o.createdOnPlanes[face[i] - o.vertexCount()] >> kPlaneCount)) ++cutByAPlane;
      }
    }
  }
  EXPECT_GT(cutByAPlane, 100) << "the planes must create vertices";
}

// Each plane pulled back to homogeneous NPC (npcPlaneFromWcPlane = wcFromNpcᵀ) takes at a point's
// homogeneous NPC the value the WC plane takes at the point, in front of the eye and behind it.
TEST(UserClipPlanes, NpcFormsTakeTheWcPlanesValues) {
  Rng rng(1204);
  for (int k = 0; k < 20; ++k) {
    const Scene scene = sceneWithPlanes(rng, 1 + k % 6);
    const PipelineRun run = runPipeline(scene);
    ASSERT_EQ(run.userPlanesNpc.size(), run.userPlanesWc.size());
    for (int i = 0; i < 10; ++i) {
      const Vec4 wc(scene.camera.vrp + rng.inBox(-10, 10), 1);
      const Vec4 npcH = run.npcFromWc * wc;
      for (size_t p = 0; p < run.userPlanesWc.size(); ++p) {
        const double expected = glm::dot(run.userPlanesWc[p], wc);
        // Relative 1e-12 of the terms' size: two ways of summing products of the same matrices.
        const double size = glm::length(run.userPlanesWc[p]) * glm::length(wc) + glm::length(run.userPlanesNpc[p]) * glm::length(npcH);
        EXPECT_NEAR(glm::dot(run.userPlanesNpc[p], npcH), expected, 1e-12 * size) << "plane " << p;
      }
    }
  }
}

TEST(UserClipPlanes, WcAndNpcStrategiesAgree) {
  Rng rng(3004);
  for (int k = 0; k < 20; ++k) {
    const Scene scene = sceneWithPlanes(rng, 1 + k % 3);
    const PipelineRun npc = runPipeline(scene, {ClipStrategy::npc, false, false});
    const PipelineRun wc = runPipeline(scene, {ClipStrategy::wc, false, false});
    for (size_t i = 0; i < npc.objects.size(); ++i) {
      const ObjectRun &a = npc.objects[i], &b = wc.objects[i];
      ASSERT_EQ(a.fate, b.fate) << "scene " << k << " object " << i;
      for (size_t f = 0; f < a.faceCount(); ++f) {
        const auto fa = a.clippedFace(f), fb = b.clippedFace(f);
        ASSERT_EQ(fa.size(), fb.size());
        // 1e-9 of the device size: the strategies evaluate the same linear forms in different
        // spaces, so they differ by rounding only (random data keeps vertices off the planes).
        for (size_t v = 0; v < fa.size(); ++v) {
          EXPECT_NEAR(a.clippedDc(fa[v]).x, b.clippedDc(fb[v]).x, 1e-9 * npc.device.width);
          EXPECT_NEAR(a.clippedDc(fa[v]).y, b.clippedDc(fb[v]).y, 1e-9 * npc.device.height);
        }
      }
    }
  }
}

TEST(UserClipPlanes, DisabledPlanesAndPlanesKeepingEverythingChangeNothing) {
  Rng rng(3005);
  Scene scene = sceneWithPlanes(rng, 0);
  const PipelineRun before = runPipeline(scene);
  scene.clipPlanes.push_back({{1, 0, 0}, {0, 0, 0}, false});  // disabled
  scene.clipPlanes.push_back({{0, 1, 0}, {0, -1e6, 0}, true});  // everything lies above it
  const PipelineRun after = runPipeline(scene);
  EXPECT_EQ(after.userPlanesWc.size(), 1u);
  for (size_t i = 0; i < before.objects.size(); ++i) {
    EXPECT_EQ(before.objects[i].fate, after.objects[i].fate);
    EXPECT_EQ(before.objects[i].clippedRefs, after.objects[i].clippedRefs);
  }
}

TEST(UserClipPlanes, TheBoxTestRejectsAnObjectOnTheCutSide) {
  Scene scene = test::sceneWith(test::checkCamera(), {test::shapeObject("cube", Shape::cube, {})});
  scene.clipPlanes.push_back({{-1, 0, 0}, {-0.6, 0, 0}, true});  // keeps x ≤ −0.6: the cube is cut off
  const PipelineRun run = runPipeline(scene, {ClipStrategy::npc, true, false});
  EXPECT_EQ(run.objects[0].box, BoxVerdict::outside);
  for (Fate f : run.objects[0].fate) EXPECT_EQ(f, Fate::rejected);
  // And without the box test, each polygon is rejected by its outcodes (bit 6, the user plane).
  const PipelineRun plain = runPipeline(scene);
  EXPECT_EQ(plain.stats.polygonsTriviallyRejected, 6u);
  EXPECT_EQ(plain.objects[0].outcodes[0] & (1u << kPlaneCount), 1u << kPlaneCount);
}

TEST(UserClipPlanes, StepThroughIncludesThemAndEndsAtTheClippersOutput) {
  Rng rng(3006);
  int stepped = 0;
  for (int k = 0; k < 10; ++k) {
    const Scene scene = sceneWithPlanes(rng, 2);
    const PipelineRun run = runPipeline(scene);
    for (const ObjectRun& o : run.objects)
      for (size_t f = 0; f < o.faceCount(); ++f) {
        const auto steps = clipSteps(run, o, f);
        ASSERT_EQ(steps.size(), size_t(kPlaneCount + 2));
        EXPECT_EQ(steps.back().plane, kPlaneCount + 1);
        if (o.fate[f] == Fate::rejected) continue;
        const auto face = o.clippedFace(f);
        ASSERT_EQ(steps.back().output.size(), face.size());
        for (size_t i = 0; i < face.size(); ++i) {
          Vec4 p = steps.back().output[i].p;
          snapToPlanes(p, steps.back().output[i].onPlanes);
          EXPECT_EQ(p, o.clippedNpcH(face[i]));
        }
        ++stepped;
      }
  }
  EXPECT_GT(stepped, 50);
}

}  // namespace
}  // namespace vplab
