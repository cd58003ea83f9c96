// docs/conventions.md "Check values": computed independently of the project.
#include "pipeline/camera.h"
#include "pipeline/device_mapping.h"
#include "pipeline/modeling.h"
#include "pipeline/pipeline.h"
#include "pipeline/view_mapping.h"
#include "tests/support/test_util.h"

#include <gtest/gtest.h>

namespace vplab {
namespace {

using test::checkCamera;  // VRP (0,0,0), PRP (0,0,5), VUP (0,1,0), window ±1 × ±0.75, F = 2, B = −2

Vec3 dcOf(const Camera& c, const Device& d, const Vec3& wc) {
  const Vec4 h = dcFromNpc(d) * npcFromVrc(c) * vrcFromWc(c) * Vec4(wc, 1.0);
  return Vec3(h) / h.w;
}

TEST(CheckValues, DerivedDistances) {
  const VrcAxes f = vrcAxes(checkCamera());
  EXPECT_DOUBLE_EQ(f.vpd, 5);
  EXPECT_DOUBLE_EQ(f.dmin, 3);
  EXPECT_DOUBLE_EQ(f.dmax, 7);
}

TEST(CheckValues, PointsLandInDc) {
  const Camera c = checkCamera();
  const Device d{320, 240};
  struct Case { Vec3 wc, dc; };
  // Tolerance 1e-12 absolute: a handful of double roundings on values of order 100.
  for (const Case& k : {Case{{0, 0, 0}, {160, 120, 0.3}}, Case{{1, 0.75, 0}, {320, 0, 0.3}},
                        Case{{-1, -0.75, 0}, {0, 240, 0.3}}, Case{{0, 0, 2}, {160, 120, 1}},
                        Case{{0, 0, -2}, {160, 120, 0}}, Case{{1.6, 1.2, -3}, {320, 0, -0.09375}}}) {
    const Vec3 got = dcOf(c, d, k.wc);
    EXPECT_NEAR(got.x, k.dc.x, 1e-12) << format(k.wc);
    EXPECT_NEAR(got.y, k.dc.y, 1e-12) << format(k.wc);
    EXPECT_NEAR(got.z, k.dc.z, 1e-12) << format(k.wc);
  }
}

// The same check values through runPipeline: a (degenerate) polygon through the three points on the
// axis, which lie exactly on the view plane, the front plane and the back plane, so it is accepted
// whole and every vertex is mapped to DC by the run itself.
TEST(CheckValues, RunPipelineMapsTheAxisPoints) {
  Scene scene = test::sceneWith(checkCamera(), {test::polygonObject("axis", {{0, 0, 0}, {0, 0, 2}, {0, 0, -2}})});
  const PipelineRun run = runPipeline(scene);
  ASSERT_EQ(run.objects.size(), 1u);
  const ObjectRun& o = run.objects[0];
  EXPECT_EQ(o.fate[0], Fate::accepted);
  const Vec3 expected[] = {{160, 120, 0.3}, {160, 120, 1}, {160, 120, 0}};
  for (uint32_t i = 0; i < 3; ++i) {
    EXPECT_EQ(o.outcodes[i], 0) << i;  // on the front / back plane counts as inside
    // 1e-12: as above, a few roundings on values of order 100.
    EXPECT_NEAR(o.dc(i).x, expected[i].x, 1e-12) << i;
    EXPECT_NEAR(o.dc(i).y, expected[i].y, 1e-12) << i;
    EXPECT_NEAR(o.dc(i).z, expected[i].z, 1e-12) << i;
  }
  // (1.6, 1.2, −3) is behind the back plane: its outcode has the back bit (4) set.
  Scene outside = test::sceneWith(checkCamera(), {test::polygonObject("far", {{1.6, 1.2, -3}, {0, 0, -3}, {0, 1, -3}})});
  const PipelineRun far = runPipeline(outside);
  EXPECT_TRUE(far.objects[0].outcodes[0] & (1u << kBack));
  EXPECT_EQ(far.objects[0].fate[0], Fate::rejected);
}

// lecture notes 13.4 (its text lost the multiplication dots): the basis B with x-axis (√½, √½), y-axis
// (−√½, √½) and origin (4, 1) given in A; the point (2·√2, 4·√2) in B is (2, 7) in A. In 3D with
// the z-axis (0, 0, 1) and z = 0.
TEST(CheckValues, Seed13_4ChangeOfBasis) {
  const double r = std::sqrt(0.5);
  const Mat4 m = aFromB({r, r, 0}, {-r, r, 0}, {0, 0, 1}, {4, 1, 0});
  const Vec4 inA = m * Vec4(2 * std::sqrt(2.0), 4 * std::sqrt(2.0), 0, 1);
  // 1e-14: √½·√2 is 1 up to an ulp or two; the sums are of order 10.
  EXPECT_NEAR(inA.x, 2, 1e-14);
  EXPECT_NEAR(inA.y, 7, 1e-14);
  EXPECT_NEAR(inA.z, 0, 1e-14);
  EXPECT_EQ(inA.w, 1);
  // The way back (lecture notes 13.4: p_B = p_A · (B_A)⁻¹ in its row form).
  const Vec4 inB = glm::inverse(m) * Vec4(2, 7, 0, 1);
  EXPECT_NEAR(inB.x, 2 * std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(inB.y, 4 * std::sqrt(2.0), 1e-14);
  // The seed's row-vector matrix is the transpose of ours: its rows are B's axes and origin.
  const Mat4 seedForm = glm::transpose(m);
  EXPECT_EQ(row(seedForm, 0), Vec4(r, r, 0, 0));
  EXPECT_EQ(row(seedForm, 1), Vec4(-r, r, 0, 0));
  EXPECT_EQ(row(seedForm, 3), Vec4(4, 1, 0, 1));
}

}  // namespace
}  // namespace vplab
