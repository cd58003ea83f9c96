// Stage 3, view mapping (lecture notes 14, 15.2.3–15.2.4; docs/conventions.md stage 3): known points of the view
// volume land on the known corners of the NPC cube, the depth non-linearity, the oblique presets.
#include "pipeline/view_mapping.h"

#include "base/error.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace vplab {
namespace {

using test::checkCamera;
using test::wcOfVrc;

struct NamedCamera {
  const char* name;
  Camera camera;
};

std::vector<NamedCamera> cameras() {
  std::vector<NamedCamera> list;
  list.push_back({"check values, perspective", checkCamera()});
  {
    Camera c;  // off-centre window (the frustum is oblique), general orientation
    c.vrp = {1, 2, 3};
    c.prp = {4, 6, 8};  // VPD = √50
    c.vup = {0, 1, 0};
    c.window = {0.5, 2.5, -1.5, -0.25};
    c.front = 1;
    c.back = -4;
    list.push_back({"perspective, off-centre window", c});
  }
  {
    Camera c;  // tilted VUP, front plane behind the view plane
    c.vrp = {-2, 0.5, 1};
    c.prp = {-5, 3, -2};
    c.vup = {1, 1, 0.3};
    c.window = {-2, 1, -1, 3};
    c.front = -1;
    c.back = -6;
    list.push_back({"perspective, front plane behind the view plane", c});
  }
  {
    Camera c = checkCamera();
    c.projection = Projection::parallel;
    list.push_back({"parallel, check camera", c});
  }
  {
    Camera c;  // parallel allows F beyond the eye
    c.vrp = {3, -1, 2};
    c.prp = {2, 1, 2.5};
    c.vup = {0, 0, 1};
    c.window = {-0.5, 3, 0.25, 1.75};
    c.front = 10;
    c.back = -3;
    c.projection = Projection::parallel;
    list.push_back({"parallel, off-centre window, F > VPD", c});
  }
  {
    Camera c = checkCamera();
    c.projection = Projection::oblique;
    c.oblique = kCavalier;
    list.push_back({"oblique cavalier", c});
  }
  {
    Camera c;
    c.vrp = {1, 1, 1};
    c.prp = {1, 4, 5};
    c.vup = {1, 0, 0};
    c.window = {-1, 2, 0.5, 1.5};
    c.front = 1.5;
    c.back = -2.5;
    c.projection = Projection::oblique;
    c.oblique = kCabinet;
    list.push_back({"oblique cabinet, off-centre window", c});
  }
  return list;
}

// A corner of the view volume in VRC, from the frustum geometry alone: the window corner (x, y) on
// the view plane, moved along its projector to the plane z = P.
Vec3 volumeCornerVrc(const Camera& c, double x, double y, double planeZ) {
  const double vpd = test::testFrame(c).vpd;
  switch (c.projection) {
    case Projection::perspective: {
      // Seen from the eye (0, 0, VPD), (x, y, 0) scales by the distance ratio (VPD − P) / VPD.
      const double s = (vpd - planeZ) / vpd;
      return {x * s, y * s, planeZ};
    }
    case Projection::parallel: return {x, y, planeZ};
    case Projection::oblique: {
      // docs/conventions.md: (x, y, z) lands at (x + z·d·cos φ, y − z·d·sin φ); solve for the point at z = P.
      const double phi = c.oblique.phiDeg * kPi / 180;
      return {x - planeZ * c.oblique.d * std::cos(phi), y + planeZ * c.oblique.d * std::sin(phi), planeZ};
    }
  }
  return {};
}

Vec3 npcOfWc(const Camera& c, const Vec3& wc) {
  const Vec4 h = npcFromVrc(c) * vrcFromWc(c) * Vec4(wc, 1.0);
  return Vec3(h) / h.w;
}

TEST(ViewMapping, ViewVolumeCornersLandOnCubeCorners) {
  for (const NamedCamera& nc : cameras()) {
    SCOPED_TRACE(nc.name);
    const Camera& c = nc.camera;
    ASSERT_FALSE(cameraError(c).has_value()) << *cameraError(c);
    for (int i = 0; i < 8; ++i) {
      const bool right = i & 1, top = i & 2, front = i & 4;
      const Vec3 vrc = volumeCornerVrc(c, right ? c.window.xmax : c.window.xmin,
                                       top ? c.window.ymax : c.window.ymin, front ? c.front : c.back);
      const Vec3 npc = npcOfWc(c, wcOfVrc(c, vrc));
      // 1e-12 absolute: the WC corners are at most ~20 from the origin, the matrices have entries
      // up to ~10; a few dozen roundings of relative size 1.1e-16 stay far below this.
      EXPECT_NEAR(npc.x, right ? 1 : 0, 1e-12) << "corner " << i;
      EXPECT_NEAR(npc.y, top ? 1 : 0, 1e-12) << "corner " << i;
      EXPECT_NEAR(npc.z, front ? 1 : 0, 1e-12) << "corner " << i;  // front → 1, back → 0
    }
  }
}

// VRP is the VRC origin; it projects onto the view plane point (0, 0), i.e. NPC
// (−xmin/Δx, −ymin/Δy) at the depth of the view plane: inside the cube whenever the window
// contains (0, 0) and B < 0 < F.
TEST(ViewMapping, VrpLandsWhereTheWindowPutsIt) {
  for (const NamedCamera& nc : cameras()) {
    SCOPED_TRACE(nc.name);
    const Camera& c = nc.camera;
    const Vec3 npc = npcOfWc(c, c.vrp);
    const ViewWindow& w = c.window;
    // 1e-12: as for the corners.
    EXPECT_NEAR(npc.x, -w.xmin / w.width(), 1e-12);
    EXPECT_NEAR(npc.y, -w.ymin / w.height(), 1e-12);
    EXPECT_NEAR(npc.z, npcDepthOfVrcZ(c, vrcAxes(c), 0), 1e-12);
    const bool windowHoldsOrigin = w.xmin < 0 && w.xmax > 0 && w.ymin < 0 && w.ymax > 0;
    if (windowHoldsOrigin && c.back < 0 && c.front > 0) {
      EXPECT_EQ(test::outsideCube(npc), 0) << format(npc);
      EXPECT_GT(npc.z, 0);
      EXPECT_LT(npc.z, 1);
    }
  }
}

// docs/conventions.md's homogeneous formulas, not only the divided result: w' = ze = VPD − z exactly, so a
// matrix off by a positive factor (same divided points) fails here.
TEST(ViewMapping, PerspectiveHomogeneousFormulas) {
  test::Rng rng(0x51ab);
  for (int k = 0; k < 200; ++k) {
    const Camera c = test::randomCamera(rng, Projection::perspective);
    const VrcAxes f = vrcAxes(c);
    const Mat4 m = npcFromVrc(c);
    const ViewWindow& w = c.window;
    const Vec3 p = rng.inBox(-20, 20);
    const double ze = f.vpd - p.z;
    const Vec4 h = m * Vec4(p, 1.0);
    const double x = (f.vpd * p.x - w.xmin * ze) / w.width();
    const double y = (f.vpd * p.y - w.ymin * ze) / w.height();
    const double z = f.dmin * (f.dmax - ze) / (f.dmax - f.dmin);
    // Relative 1e-12 of the largest term: both sides add a handful of products whose magnitudes are
    // bounded by `scale`; cancellation makes absolute, not relative, error the right measure.
    const double scale = std::max({1.0, std::abs(f.vpd * p.x), std::abs(w.xmin * ze), std::abs(f.vpd * p.y),
                                   std::abs(w.ymin * ze), f.dmin * (f.dmax + std::abs(ze))}) /
                         std::min({1.0, w.width(), w.height(), f.dmax - f.dmin});
    EXPECT_NEAR(h.x, x, 1e-12 * scale);
    EXPECT_NEAR(h.y, y, 1e-12 * scale);
    EXPECT_NEAR(h.z, z, 1e-12 * scale);
    EXPECT_NEAR(h.w, ze, 1e-12 * scale);
  }
}

// lecture notes 15.2.4: after the division NPC z is order-preserving but not linear; npcDepthOfVrcZ gives
// the divided matrix result, and equal VRC steps from front to back give shrinking NPC steps.
TEST(ViewMapping, PerspectiveDepthIsNonLinear) {
  const Camera c = checkCamera();
  const VrcAxes f = vrcAxes(c);
  const Mat4 m = npcFromVrc(c);
  EXPECT_DOUBLE_EQ(npcDepthOfVrcZ(c, f, c.front), 1);
  EXPECT_DOUBLE_EQ(npcDepthOfVrcZ(c, f, c.back), 0);
  EXPECT_DOUBLE_EQ(npcDepthOfVrcZ(c, f, 0), 0.3);  // the check value of the view plane
  double previous = 2, previousStep = 2;
  constexpr int kSteps = 16;
  for (int i = 0; i <= kSteps; ++i) {
    const double z = c.front + (c.back - c.front) * i / kSteps;
    const double depth = npcDepthOfVrcZ(c, f, z);
    const Vec4 h = m * Vec4(0.3, -0.2, z, 1);
    EXPECT_NEAR(depth, h.z / h.w, 1e-15) << z;  // two roundings on values ≤ 1
    if (i > 0) {
      const double step = previous - depth;
      EXPECT_GT(step, 0) << "order-preserving at z = " << z;
      if (i > 1) {
        EXPECT_LT(step, previousStep * (1 - 1e-3)) << "steps shrink toward the back at z = " << z;
      }
      previousStep = step;
    }
    previous = depth;
  }
  // The first step (at the front) is much larger than the last (at the back): (dmax/dmin)² ≈ 5.4
  // for the check camera in the limit of small steps.
  const double first = 1 - npcDepthOfVrcZ(c, f, c.front - 0.01);
  const double last = npcDepthOfVrcZ(c, f, c.back + 0.01);
  EXPECT_NEAR(first / last, (7.0 / 3.0) * (7.0 / 3.0), 0.05);  // 0.05: the steps have finite size
}

TEST(ViewMapping, ParallelDepthIsLinear) {
  for (Projection p : {Projection::parallel, Projection::oblique}) {
    Camera c = checkCamera();
    c.projection = p;
    const VrcAxes f = vrcAxes(c);
    const Mat4 m = npcFromVrc(c);
    for (int i = 0; i <= 8; ++i) {
      const double z = c.back + (c.front - c.back) * i / 8;
      EXPECT_NEAR(npcDepthOfVrcZ(c, f, z), i / 8.0, 1e-15);  // (z − B)/(F − B), exact up to an ulp
      const Vec4 h = m * Vec4(0.4, 0.1, z, 1);
      EXPECT_EQ(h.w, 1);
      EXPECT_NEAR(h.z, i / 8.0, 1e-15);
    }
  }
}

TEST(ViewMapping, ObliquePresets) {
  EXPECT_EQ(kCavalier.d, 1.0);
  EXPECT_EQ(kCavalier.phiDeg, 35.0);
  EXPECT_EQ(kCabinet.d, 0.5);
  EXPECT_EQ(kCabinet.phiDeg, 50.0);
  // d = 1/tan α: cavalier α = 45°, cabinet α = 63.43° (lecture notes 14.3.2).
  EXPECT_NEAR(std::atan(1 / kCavalier.d) * 180 / kPi, 45, 1e-12);
  EXPECT_NEAR(std::atan(1 / kCabinet.d) * 180 / kPi, 63.43, 0.005);  // the seed rounds to 0.01°
}

// A point one unit behind the view plane (VRC z = −1) lands at (x − d·cos φ, y + d·sin φ) before
// the window mapping (docs/conventions.md, lecture notes 14.3.2): through the shear alone and through npcFromVrc.
TEST(ViewMapping, ObliqueShearMovesAPointBehindTheViewPlane) {
  for (const ObliqueParams& ob : {kCavalier, kCabinet, ObliqueParams{0.8, -120}}) {
    const double phi = ob.phiDeg * kPi / 180;
    const Vec3 p(0.3, -0.4, -1);
    const Vec4 s = obliqueShear(ob) * Vec4(p, 1);
    // 1e-15: one product and one sum of values ≤ 1.
    EXPECT_NEAR(s.x, p.x - ob.d * std::cos(phi), 1e-15) << ob.d;
    EXPECT_NEAR(s.y, p.y + ob.d * std::sin(phi), 1e-15) << ob.d;
    EXPECT_EQ(s.z, -1);
    EXPECT_EQ(s.w, 1);
    // Points in the view plane do not move.
    EXPECT_EQ(obliqueShear(ob) * Vec4(0.3, -0.4, 0, 1), Vec4(0.3, -0.4, 0, 1));

    Camera c = checkCamera();
    c.window = {-1, 3, 0.5, 2};
    c.projection = Projection::oblique;
    c.oblique = ob;
    const Vec4 n = npcFromVrc(c) * Vec4(p, 1);
    const ViewWindow& w = c.window;
    EXPECT_NEAR(n.x, (p.x - ob.d * std::cos(phi) - w.xmin) / w.width(), 1e-15);
    EXPECT_NEAR(n.y, (p.y + ob.d * std::sin(phi) - w.ymin) / w.height(), 1e-15);
    EXPECT_NEAR(n.z, (-1 - c.back) / (c.front - c.back), 1e-15);
    EXPECT_EQ(n.w, 1);
  }
}

// Orthographic is oblique with d = 0; the shear with d = 0 is the identity.
TEST(ViewMapping, ParallelIsObliqueWithoutShear) {
  Camera par = checkCamera();
  par.projection = Projection::parallel;
  Camera obl = par;
  obl.projection = Projection::oblique;
  obl.oblique = {0, 35};
  EXPECT_EQ(npcFromVrc(par), npcFromVrc(obl));
  EXPECT_EQ(obliqueShear({0, 77}), Mat4(1.0));
  // And a non-zero d changes the matrix (the comparison above can fail).
  obl.oblique = kCavalier;
  EXPECT_NE(npcFromVrc(par), npcFromVrc(obl));
}

TEST(ViewMapping, InvalidCameraThrows) {
  Camera c = checkCamera();
  c.front = 6;  // beyond the eye at VPD = 5
  EXPECT_THAT(test::errorOf([&] { npcFromVrc(c); }), testing::HasSubstr("F < VPD"));
}

}  // namespace
}  // namespace vplab
