// An independent cross-check of stages 2 and 3 against GLM's lookAt / frustum / ortho, for random
// valid cameras (fixed seed). The derivation of the GLM equivalent:
//
//   glm::lookAtRH(eye, centre, up) builds f = normalize(centre − eye), s = normalize(f × up),
//   u = s × f, and maps p ↦ [s; u; −f]·(p − eye). With eye = PRP and centre = VRP, f = −N,
//   s = normalize(VUP × N) = U and u = U × (−N) = V: the same axes as VRC, but the origin at the
//   eye. Since R·(p − PRP) = R·(p − VRP) − R·(PRP − VRP) = vrc − (0, 0, VPD),
//
//       vrcFromWc = T(0, 0, VPD) · lookAtRH(PRP, VRP, VUP).
//
//   In GL's eye space the front plane is at distance dmin and the back plane at dmax; the window
//   (in the view plane, distance VPD) seen from the eye and scaled to the near plane is
//   l = xmin·dmin/VPD, r = xmax·dmin/VPD, b = ymin·dmin/VPD, t = ymax·dmin/VPD. frustumRH_NO gives
//   GL clip coordinates with w_c = −z_eye = VPD − z_vrc (the same w as ours) and near → z_c = −w_c.
//   NPC is then the inverse of docs/conventions.md's glClipFromNpc: x = (x_c + w)/2, y = (y_c + w)/2,
//   z = (w − z_c)/2. So in exact arithmetic the two matrices are equal, not just proportional.
//
//   Parallel: the eye of lookAt at VRP (centre VRP − N), then orthoRH_NO(xmin, xmax, ymin, ymax,
//   −F, −B): ortho's near and far are distances along −z, so the front plane z = F is near = −F
//   and the back plane z = B is far = −B (near < far because B < F); it maps z = −near → −1.
#include "pipeline/camera.h"
#include "pipeline/device_mapping.h"
#include "pipeline/view_mapping.h"
#include "tests/support/test_util.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include <gtest/gtest.h>

namespace vplab {
namespace {

// x = (x_c + w)/2, y = (y_c + w)/2, z = (w − z_c)/2: the inverse of glClipFromNpc, written out.
glm::dmat4 npcFromGlClip() {
  return matrixFromRows(0.5, 0, 0, 0.5,  //
                        0, 0.5, 0, 0.5,  //
                        0, 0, -0.5, 0.5,  //
                        0, 0, 0, 1);
}

double maxAbs(const Mat4& m) {
  double a = 0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) a = std::max(a, std::abs(m[c][r]));
  return a;
}

// Tolerance: relative 1e-9 of the largest entry. Both sides are products of three or four matrices
// whose entries reach ~1e3 (VPD/Δx ≤ 200, translations ≤ 30); each entry is a sum of a few products,
// so rounding contributes ~1e-15 relative to the largest entry. A convention error (a sign, a swapped
// near/far, the missing T(0, 0, VPD)) changes entries by O(1) relative; 1e-9 separates the two
// with six orders of magnitude to spare either way.
constexpr double kRelTol = 1e-9;

void expectMatricesNear(const Mat4& ours, const Mat4& glm, const std::string& what) {
  const double tol = kRelTol * std::max(maxAbs(ours), maxAbs(glm));
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(ours[c][r], glm[c][r], tol) << what << " row " << r << " col " << c;
}

TEST(GlmCrossCheck, NpcFromGlClipInvertsGlClipFromNpc) {
  EXPECT_EQ(npcFromGlClip() * glClipFromNpc(), Mat4(1.0));
}

TEST(GlmCrossCheck, PerspectiveMatchesLookAtAndFrustum) {
  test::Rng rng(20240611);
  int checkedPoints = 0;
  for (int k = 0; k < 200; ++k) {
    const Camera c = test::randomCamera(rng, Projection::perspective);
    SCOPED_TRACE("camera " + std::to_string(k));
    ASSERT_FALSE(cameraError(c).has_value()) << *cameraError(c);
    const double vpd = glm::length(c.prp - c.vrp);
    const double dmin = vpd - c.front, dmax = vpd - c.back;

    const glm::dmat4 view = glm::lookAtRH(c.prp, c.vrp, c.vup);
    const glm::dmat4 vrcFromEye = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, vpd));
    expectMatricesNear(vrcFromWc(c), vrcFromEye * view, "vrcFromWc");

    const double s = dmin / vpd;
    const glm::dmat4 proj = glm::frustumRH_NO(c.window.xmin * s, c.window.xmax * s, c.window.ymin * s,
                                              c.window.ymax * s, dmin, dmax);
    const Mat4 ours = npcFromVrc(c) * vrcFromWc(c);
    const glm::dmat4 theirs = npcFromGlClip() * proj * view;
    expectMatricesNear(ours, theirs, "npcFromWc");

    // Divided points in and around the view volume (in front of the eye: ze from 0.2·dmin to
    // 2·dmax), generated in VRC and taken to WC by the test's own frame.
    for (int i = 0; i < 5; ++i) {
      const double ze = rng.uniform(0.2 * dmin, 2 * dmax);
      const Vec3 vrc(rng.uniform(c.window.xmin - 1, c.window.xmax + 1) * ze / vpd,
                     rng.uniform(c.window.ymin - 1, c.window.ymax + 1) * ze / vpd, vpd - ze);
      const Vec3 wc = test::wcOfVrc(c, vrc);
      const Vec4 a = ours * Vec4(wc, 1), b = theirs * Vec4(wc, 1);
      ASSERT_GT(a.w, 0);
      const Vec3 pa = Vec3(a) / a.w, pb = Vec3(b) / b.w;
      // Same 1e-9, relative to the size of the NPC point (≥ 1), for the same reason as above.
      const double tol = kRelTol * std::max(1.0, glm::length(pa));
      EXPECT_NEAR(pa.x, pb.x, tol);
      EXPECT_NEAR(pa.y, pb.y, tol);
      EXPECT_NEAR(pa.z, pb.z, tol);
      ++checkedPoints;
    }
  }
  EXPECT_EQ(checkedPoints, 1000);
}

TEST(GlmCrossCheck, ParallelMatchesLookAtAndOrtho) {
  test::Rng rng(77);
  for (int k = 0; k < 200; ++k) {
    const Camera c = test::randomCamera(rng, Projection::parallel);
    SCOPED_TRACE("camera " + std::to_string(k));
    ASSERT_FALSE(cameraError(c).has_value()) << *cameraError(c);
    const Vec3 n = glm::normalize(c.prp - c.vrp);
    const glm::dmat4 view = glm::lookAtRH(c.vrp, c.vrp - n, c.vup);  // the eye of lookAt at VRP
    expectMatricesNear(vrcFromWc(c), view, "vrcFromWc");

    const glm::dmat4 proj = glm::orthoRH_NO(c.window.xmin, c.window.xmax, c.window.ymin, c.window.ymax,
                                            -c.front, -c.back);
    const Mat4 ours = npcFromVrc(c) * vrcFromWc(c);
    const glm::dmat4 theirs = npcFromGlClip() * proj * view;
    expectMatricesNear(ours, theirs, "npcFromWc");

    for (int i = 0; i < 5; ++i) {
      const Vec3 wc = c.vrp + rng.inBox(-20, 20);
      const Vec4 a = ours * Vec4(wc, 1), b = theirs * Vec4(wc, 1);
      EXPECT_EQ(a.w, 1);
      // Same 1e-9, relative to the size of the NPC point.
      const double tol = kRelTol * std::max(1.0, glm::length(Vec3(a)));
      EXPECT_NEAR(a.x, b.x / b.w, tol);
      EXPECT_NEAR(a.y, b.y / b.w, tol);
      EXPECT_NEAR(a.z, b.z / b.w, tol);
    }
  }
}

// Not a tautology: a sign error in the derivation (e.g. near = F instead of −F, or lookAt from the
// eye for the parallel case) is caught. This checks that the comparison is sensitive.
TEST(GlmCrossCheck, WrongDerivationsAreDetected) {
  const Camera c = test::checkCamera();
  Camera par = c;
  par.projection = Projection::parallel;
  const Mat4 oursPar = npcFromVrc(par) * vrcFromWc(par);
  const glm::dmat4 view = glm::lookAtRH(c.vrp, c.vrp - Vec3(0, 0, 1), c.vup);
  const glm::dmat4 wrongSign = npcFromGlClip() * glm::orthoRH_NO(-1.0, 1.0, -0.75, 0.75, c.front, c.back) * view;
  EXPECT_GT(maxAbs(oursPar - wrongSign), 0.1);
  const glm::dmat4 fromEye = npcFromGlClip() * glm::orthoRH_NO(-1.0, 1.0, -0.75, 0.75, -c.front, -c.back) *
                             glm::lookAtRH(c.prp, c.vrp, c.vup);
  EXPECT_GT(maxAbs(oursPar - fromEye), 0.1);
  const glm::dmat4 noShift = glm::lookAtRH(c.prp, c.vrp, c.vup);
  EXPECT_GT(maxAbs(vrcFromWc(c) - noShift), 1);
}

}  // namespace
}  // namespace vplab
