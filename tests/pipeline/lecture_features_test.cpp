// The pure mathematics behind the lecture features: the stage morph, the clipping step-through,
// vanishing points (lecture notes 14.2) and the depth buffer's resolution (lecture notes 15.2.4).
#include "pipeline/clip_steps.h"
#include "pipeline/stage_morph.h"
#include "pipeline/vanishing_points.h"
#include "pipeline/view_mapping.h"
#include "tests/support/test_util.h"

#include <gtest/gtest.h>

namespace vplab {
namespace {

using test::Rng;

// Tolerance for stage values recomputed from the same doubles: a few roundings on values of
// order 1e2 (DC pixels), so 1e-9 absolute is generous and still catches any wrong stage.
constexpr double kEps = 1e-9;

void expectNear(const Vec3& a, const Vec3& b, double eps, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, eps) << what;
  EXPECT_NEAR(a.y, b.y, eps) << what;
  EXPECT_NEAR(a.z, b.z, eps) << what;
}

StageValues stagesOf(const ObjectRun& o, uint32_t v) {
  return {o.mesh->positions[v], o.wc(v), o.vrc(v), o.npcH[v], o.dc(v)};
}

TEST(StageMorph, IntegerTimesAreTheStages) {
  const Scene scene = defaultScene();
  const PipelineRun run = runPipeline(scene);
  int checked = 0;
  for (const ObjectRun& o : run.objects) {
    for (uint32_t v = 0; v < o.vertexCount(); ++v) {
      if (o.outcodes[v] != 0) continue;  // the morph shows what survives clipping
      const StageValues s = stagesOf(o, v);
      const Device& d = run.device;
      expectNear(morphPosition(s, 0, d), s.mc, kEps, "t = 0 is MC");
      expectNear(morphPosition(s, 1, d), s.wc, kEps, "t = 1 is WC");
      expectNear(morphPosition(s, 2, d), s.vrc, kEps, "t = 2 is VRC");
      expectNear(morphPosition(s, 2.5, d), Vec3(s.npcH), kEps, "t = 2.5 is homogeneous NPC, not divided");
      expectNear(morphPosition(s, 3, d), Vec3(s.npcH) / s.npcH.w, kEps, "t = 3 is NPC");
      expectNear(morphPosition(s, 4, d), {s.dc.x / d.height, -s.dc.y / d.height, s.dc.z}, kEps, "t = 4 is DC");
      ++checked;
    }
  }
  EXPECT_GT(checked, 50);
  EXPECT_EQ(morphStageName(0), "MC");
  EXPECT_EQ(morphStageName(3), "NPC");
  EXPECT_EQ(morphStageName(3.5), "NPC → DC");
  EXPECT_EQ(morphStepName(2.7), "÷ w");
}

TEST(StageMorph, TheDivisionIsItsOwnStepAndMonotone) {
  // Between 2.5 and 3 only the divisor changes: the point moves along the ray from the origin
  // through (x, y, z), monotonically from the homogeneous point to the divided one.
  const StageValues s{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {4, 2, 6, 4}, {0, 0, 0}};
  const Device d{640, 480};
  double previous = glm::length(morphPosition(s, 2.5, d));
  for (double t = 2.55; t <= 3.0001; t += 0.05) {
    const Vec3 p = morphPosition(s, t, d);
    EXPECT_NEAR(glm::length(glm::cross(p, Vec3(4, 2, 6))), 0, 1e-12) << "on the ray, t = " << t;
    EXPECT_LT(glm::length(p), previous) << "w grows from 1 to 4, so the point moves in, t = " << t;
    previous = glm::length(p);
  }
  expectNear(morphPosition(s, -1, d), s.mc, 0, "clamped below");
  expectNear(morphPosition(s, 9, d), morphPosition(s, 4, d), 0, "clamped above");
}

TEST(ClipSteps, LastStepEqualsTheClippersOutput) {
  Rng rng(20261121);
  int clippedFaces = 0;
  for (int k = 0; k < 30; ++k) {
    const Camera c = test::randomCamera(rng, k % 2 ? Projection::perspective : Projection::parallel);
    const Scene scene = test::randomPolygonScene(rng, c, 12, true);
    const PipelineRun run = runPipeline(scene);
    for (const ObjectRun& o : run.objects) {
      for (size_t f = 0; f < o.faceCount(); ++f) {
        const std::vector<ClipStep> steps = clipSteps(run, o, f);
        ASSERT_EQ(steps.size(), 6u);
        const auto clipped = o.clippedFace(f);
        if (o.fate[f] == Fate::rejected) continue;  // stepped through, but the clipper never ran
        ASSERT_EQ(steps.back().output.size(), clipped.size()) << "object " << o.name << " face " << f;
        for (size_t i = 0; i < clipped.size(); ++i) {
          Vec4 p = steps.back().output[i].p;
          snapToPlanes(p, steps.back().output[i].onPlanes);
          // Bitwise: the same kernel, the same order of operations.
          EXPECT_EQ(p, o.clippedNpcH(clipped[i])) << "vertex " << i;
        }
        clippedFaces += o.fate[f] == Fate::clipped;
      }
    }
  }
  EXPECT_GT(clippedFaces, 20) << "the random scenes must exercise the clipper";
}

TEST(ClipSteps, EachStepShowsBoundaryValuesAndNewVertices) {
  // A triangle sticking out of the right plane (x > w) only: one pass cuts, five are skipped.
  Scene scene = test::sceneWith(test::checkCamera(), {test::polygonObject("tri", {{0, 0, 0}, {2, 0.2, 0}, {0, 0.5, 0}})});
  const PipelineRun run = runPipeline(scene);
  const auto steps = clipSteps(run, run.objects[0], 0);
  for (const ClipStep& s : steps) {
    EXPECT_EQ(s.skipped, s.plane != kRight) << planeName(s.plane);
    for (size_t i = 0; i < s.input.size(); ++i) EXPECT_EQ(s.boundary[i], s.input[i].bc[s.plane]);
  }
  const ClipStep& right = steps[kRight];
  EXPECT_EQ(right.input.size(), 3u);
  EXPECT_EQ(right.output.size(), 4u) << "one vertex outside: cut off, two new vertices";
  EXPECT_EQ(std::count(right.created.begin(), right.created.end(), true), 2);
  EXPECT_LT(right.boundary[1], 0) << "(2, 0.2, 0) lies right of the window (x ≤ 1 violated)";
}

TEST(VanishingPoints, MatchTheIntersectionOfProjectedParallelEdges) {
  // A box with all three axes oblique to the view plane: three-point perspective.
  Scene scene = test::sceneWith(test::checkCamera(), {test::shapeObject("box", Shape::cube,
                                                       {{0.3, -0.2, 0}, {{{1, 1, 0}, 35, {}}, {{0, 1, 0}, 20, {}}}, {1, 1, 1}})});
  const PipelineRun run = runPipeline(scene);
  const ObjectRun& o = run.objects[0];
  const auto vps = vanishingPoints(run, o.wcFromMc);
  EXPECT_EQ(vanishingPointCount(vps), 3);
  auto dcOf = [&](const Vec3& wc) {
    const Vec4 h = run.npcFromWc * Vec4(wc, 1.0);
    return Vec2(run.dcFromNpc * Vec4(Vec3(h) / h.w, 1.0));
  };
  for (int axis = 0; axis < 3; ++axis) {
    // Two parallel lines along the axis, through two cube corners, projected: where they cross.
    const Vec3 d = Vec3(o.wcFromMc[axis]);
    const Vec3 a = transformAffine(o.wcFromMc, {-0.5, -0.5, -0.5});
    const Vec3 b = transformAffine(o.wcFromMc, axis == 0 ? Vec3(-0.5, 0.5, 0.5) : Vec3(0.5, -0.5, 0.5));
    const Vec2 a0 = dcOf(a), a1 = dcOf(a + d), b0 = dcOf(b), b1 = dcOf(b + d);
    const Vec2 r = a1 - a0, s = b1 - b0;
    const double t = ((b0.x - a0.x) * s.y - (b0.y - a0.y) * s.x) / (r.x * s.y - r.y * s.x);
    const Vec2 crossing = a0 + t * r;
    // Tolerance: the crossing of two nearly parallel image lines amplifies rounding by about the
    // inverse angle between them (here < 1e4), on coordinates of order 1e3 pixels.
    EXPECT_NEAR(vps[size_t(axis)].dc.x, crossing.x, 1e-6 * std::max(1.0, std::abs(crossing.x))) << "axis " << axis;
    EXPECT_NEAR(vps[size_t(axis)].dc.y, crossing.y, 1e-6 * std::max(1.0, std::abs(crossing.y))) << "axis " << axis;
  }
}

TEST(VanishingPoints, OneTwoThreePointPerspective) {
  auto count = [](ModelTransform t) {
    Scene scene = test::sceneWith(test::checkCamera(), {test::shapeObject("box", Shape::cube, t)});
    const PipelineRun run = runPipeline(scene);
    return vanishingPointCount(vanishingPoints(run, run.objects[0].wcFromMc));
  };
  // The check camera looks along −z with the view plane parallel to xy.
  EXPECT_EQ(count({}), 1) << "faces parallel to the view plane: only z converges";
  EXPECT_EQ(count({{0, 0, 0}, {{{0, 1, 0}, 30, {}}}, {1, 1, 1}}), 2) << "turned about y: x and z converge";
  EXPECT_EQ(count({{0, 0, 0}, {{{0, 1, 0}, 30, {}}, {{1, 0, 0}, 25, {}}}, {1, 1, 1}}), 3);
  Camera parallel = test::checkCamera();
  parallel.projection = Projection::parallel;
  Scene scene = test::sceneWith(parallel, {test::shapeObject("box", Shape::cube, {{0, 0, 0}, {{{0, 1, 0}, 30, {}}}, {1, 1, 1}})});
  const PipelineRun run = runPipeline(scene);
  EXPECT_EQ(vanishingPointCount(vanishingPoints(run, run.objects[0].wcFromMc)), 0) << "parallel lines stay parallel";
}

TEST(DepthResolution, MatchesTheSlopeOfNpcDepth) {
  const Camera c = test::checkCamera();  // VPD 5, dmin 3, dmax 7
  const VrcAxes f = vrcAxes(c);
  for (int bits : {16, 24}) {
    for (double z : {1.9, 0.0, -1.9}) {
      // The numeric slope of NPC z, by a central difference (h = 1e-5: error ~h² · z''' ≈ 1e-10).
      const double h = 1e-5;
      const double slope = (npcDepthOfVrcZ(c, f, z + h) - npcDepthOfVrcZ(c, f, z - h)) / (2 * h);
      const double expected = 1.0 / (std::ldexp(1.0, bits) - 1.0) / slope;
      EXPECT_NEAR(depthResolution(c, f, z, bits), expected, expected * 1e-6) << bits << " bits at z = " << z;
    }
    EXPECT_GT(depthResolution(c, f, -1.9, bits), depthResolution(c, f, 1.9, bits))
        << "coarser near the back plane: equal steps crowd there (lecture notes 15.2.4)";
  }
  Camera p = c;
  p.projection = Projection::parallel;
  EXPECT_DOUBLE_EQ(depthResolution(p, vrcAxes(p), 0.3, 16), 4.0 / 65535.0) << "(F − B) / (2^16 − 1)";
}

}  // namespace
}  // namespace vplab
