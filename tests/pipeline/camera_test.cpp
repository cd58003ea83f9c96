// The synthetic camera and stage 2, view orientation WC → VRC (lecture notes 15.1, 15.2.2; docs/conventions.md
// stage 2), and every invalid camera of docs/conventions.md with its message.
#include "pipeline/camera.h"

#include "pipeline/view_mapping.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

namespace vplab {
namespace {

using test::checkCamera;
using test::errorOf;
using testing::HasSubstr;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Camera, ProjectionNames) {
  for (Projection p : {Projection::perspective, Projection::parallel, Projection::oblique})
    EXPECT_EQ(fromString<Projection>(toString(p)), p);
  EXPECT_EQ(fromString<Projection>("Perspective"), std::nullopt);
  EXPECT_EQ(fromString<Projection>(""), std::nullopt);
}

// U, V, N orthonormal and right-handed, the eye on +N at distance VPD, V in the plane of VUP and N
// on VUP's side; random cameras with a fixed seed. Tolerance 1e-12: normalized vectors and
// cross products of unit vectors, a few roundings each.
TEST(Camera, FrameIsRightHandedAndOrthonormal) {
  test::Rng rng(1);
  for (int k = 0; k < 200; ++k) {
    const Camera c = test::randomCamera(rng, Projection::perspective);
    const VrcAxes f = vrcAxes(c);
    EXPECT_NEAR(glm::length(f.u), 1, 1e-12);
    EXPECT_NEAR(glm::length(f.v), 1, 1e-12);
    EXPECT_NEAR(glm::length(f.n), 1, 1e-12);
    EXPECT_NEAR(glm::dot(f.u, f.v), 0, 1e-12);
    EXPECT_NEAR(glm::dot(f.v, f.n), 0, 1e-12);
    EXPECT_NEAR(glm::dot(f.n, f.u), 0, 1e-12);
    EXPECT_NEAR(glm::length(glm::cross(f.u, f.v) - f.n), 0, 1e-12);  // right-handed
    EXPECT_NEAR(f.vpd, glm::length(c.prp - c.vrp), 1e-12 * f.vpd);
    EXPECT_NEAR(glm::length(c.vrp + f.vpd * f.n - c.prp), 0, 1e-12 * (1 + glm::length(c.prp)));
    EXPECT_DOUBLE_EQ(f.dmin, f.vpd - c.front);
    EXPECT_DOUBLE_EQ(f.dmax, f.vpd - c.back);
    // V is VUP projected into the view plane: no U component, a positive VUP component.
    EXPECT_NEAR(glm::dot(f.u, c.vup), 0, 1e-12 * glm::length(c.vup));
    EXPECT_GT(glm::dot(f.v, c.vup), 0);
  }
}

// vrcFromWc takes VRP to the origin, PRP to (0, 0, VPD), and VRP + U/V/N to the unit axes.
TEST(Camera, VrcFromWcPlacesTheCamera) {
  Camera c;
  c.vrp = {1, -2, 3};
  c.prp = {4, 2, 3};  // N = (0.6, 0.8, 0), VPD 5
  c.vup = {0, 0, 7};
  const Mat4 m = vrcFromWc(c);
  const VrcAxes f = vrcAxes(c);
  EXPECT_EQ(f.n, Vec3(0.6, 0.8, 0));
  EXPECT_EQ(f.vpd, 5);
  // U = VUP × N / |…| = (−0.8, 0.6, 0), V = N × U = (0, 0, 1). Tolerance 1e-15: unit values.
  EXPECT_NEAR(glm::length(f.u - Vec3(-0.8, 0.6, 0)), 0, 1e-15);
  EXPECT_NEAR(glm::length(f.v - Vec3(0, 0, 1)), 0, 1e-15);
  auto at = [&](const Vec3& wc) { return Vec3(m * Vec4(wc, 1)); };
  // 1e-14: coordinates of order 5.
  EXPECT_NEAR(glm::length(at(c.vrp)), 0, 1e-14);
  EXPECT_NEAR(glm::length(at(c.prp) - Vec3(0, 0, 5)), 0, 1e-14);
  EXPECT_NEAR(glm::length(at(c.vrp + f.u) - Vec3(1, 0, 0)), 0, 1e-14);
  EXPECT_NEAR(glm::length(at(c.vrp + f.v) - Vec3(0, 1, 0)), 0, 1e-14);
  EXPECT_NEAR(glm::length(at(c.vrp + Vec3(0, 0, 1)) - Vec3(0, 1, 0)), 0, 1e-14);  // up is up
  EXPECT_EQ(row(m, 3), Vec4(0, 0, 0, 1));
}

// Only VUP's direction matters, and only its component in the view plane.
TEST(Camera, VupLengthAndTiltDoNotMatter) {
  Camera a = checkCamera();
  a.prp = {1, 2, 5};
  Camera b = a;
  b.vup = {0, 12, 0};
  Camera tilted = a;
  tilted.vup = a.vup + 3.0 * glm::normalize(a.prp - a.vrp);  // plus a multiple of N
  const Mat4 ma = vrcFromWc(a), mb = vrcFromWc(b), mt = vrcFromWc(tilted);
  for (int col = 0; col < 4; ++col)
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(ma[col][r], mb[col][r], 1e-15);  // unit-vector entries, a rounding or two
      EXPECT_NEAR(ma[col][r], mt[col][r], 1e-14);
    }
}

struct BadCamera {
  const char* what;
  Camera camera;
  std::vector<std::string> messageParts;  // each must appear in the message
};

std::vector<BadCamera> badCameras() {
  std::vector<BadCamera> list;
  auto add = [&](const char* what, auto edit, std::vector<std::string> parts) {
    Camera c = checkCamera();
    edit(c);
    list.push_back({what, c, std::move(parts)});
  };
  add("PRP = VRP", [](Camera& c) { c.vrp = c.prp = {1, 2, 3}; },
      {"PRP (1, 2, 3) equals VRP (1, 2, 3)"});
  add("VUP = 0", [](Camera& c) { c.vup = {0, 0, 0}; }, {"VUP (0, 0, 0) is the zero vector"});
  add("VUP parallel to N", [](Camera& c) { c.vup = {0, 0, 2}; },
      {"VUP (0, 0, 2) is parallel to the view plane normal N (0, 0, 1)"});
  add("VUP antiparallel to N", [](Camera& c) { c.vup = {0, 0, -0.5}; }, {"VUP (0, 0, -0.5) is parallel"});
  add("VUP parallel to N within 1e-12", [](Camera& c) { c.vup = {1e-12, 0, 1}; }, {"is parallel"});
  add("xmin = xmax", [](Camera& c) { c.window.xmin = c.window.xmax = 0.5; }, {"xmin = 0.5, xmax = 0.5"});
  add("xmin > xmax", [](Camera& c) { c.window = {1, -1, -1, 1}; }, {"xmin < xmax", "xmin = 1, xmax = -1"});
  add("ymin = ymax", [](Camera& c) { c.window.ymin = c.window.ymax = -2; }, {"ymin = -2, ymax = -2"});
  add("ymin > ymax", [](Camera& c) { c.window = {-1, 1, 3, 2}; }, {"ymin < ymax", "ymin = 3, ymax = 2"});
  add("F = B", [](Camera& c) { c.front = c.back = 0.25; }, {"B < F", "B = 0.25, F = 0.25"});
  add("F < B", [](Camera& c) { c.front = -3; c.back = 1; }, {"B = 1, F = -3"});
  add("perspective F = VPD", [](Camera& c) { c.front = 5; }, {"F < VPD", "F = 5", "VPD = |PRP − VRP| = 5"});
  add("perspective F > VPD", [](Camera& c) { c.front = 6; c.back = 5.5; }, {"F = 6", "dmin = VPD − F = -1"});
  add("NaN VRP", [](Camera& c) { c.vrp.y = kNaN; }, {"VRP (0, nan, 0)", "must be finite"});
  add("infinite PRP", [](Camera& c) { c.prp.z = kInf; }, {"PRP (0, 0, inf)", "must be finite"});
  add("NaN VUP", [](Camera& c) { c.vup.x = -kNaN; }, {"VUP", "must be finite"});
  add("infinite window", [](Camera& c) { c.window.xmax = kInf; }, {"window", "finite"});
  add("NaN front", [](Camera& c) { c.front = kNaN; }, {"front and back planes must be finite"});
  add("oblique d < 0", [](Camera& c) { c.projection = Projection::oblique; c.oblique = {-1, 30}; },
      {"d ≥ 0", "d = -1, phi = 30"});
  add("oblique phi NaN", [](Camera& c) { c.projection = Projection::oblique; c.oblique = {0.5, kNaN}; },
      {"phi = nan"});
  add("window 1e-300 wide, far eye", [](Camera& c) { c.prp = {0, 0, 1e10}; c.window = {0, 1e-300, -1, 1}; },
      {"not finite", "VPD 1e+10"});
  add("parallel, window 1e-300 wide, far VRP",
      [](Camera& c) {
        c.projection = Projection::parallel;
        c.vrp = {1e10, 0, 0};
        c.prp = {1e10, 0, 5};
        c.window = {0, 1e-300, -1, 1};
      },
      {"not finite", "window 0..1e-300"});
  return list;
}

TEST(Camera, InvalidCamerasAreRefusedWithTheirValues) {
  for (const BadCamera& b : badCameras()) {
    SCOPED_TRACE(b.what);
    const auto e = cameraError(b.camera);
    ASSERT_TRUE(e.has_value());
    for (const std::string& part : b.messageParts) EXPECT_THAT(*e, HasSubstr(part));
    const std::string thrown = errorOf([&] { vrcAxes(b.camera); });
    EXPECT_EQ(thrown, "invalid camera: " + *e);
    EXPECT_EQ(errorOf([&] { vrcFromWc(b.camera); }), thrown);
    EXPECT_EQ(errorOf([&] { npcFromVrc(b.camera); }), thrown);
  }
}

// The same checks do not refuse valid neighbours of the invalid cameras (the tests above can fail
// for the right reason only): parallel projections may put F beyond the eye, VUP may be nearly
// parallel to N, a window may be tiny when the matrices stay finite.
TEST(Camera, ValidNeighboursAreAccepted) {
  Camera c = checkCamera();
  c.projection = Projection::parallel;
  c.front = 6;
  EXPECT_EQ(cameraError(c), std::nullopt);
  c.projection = Projection::oblique;
  c.oblique = {0, 0};
  EXPECT_EQ(cameraError(c), std::nullopt);
  c = checkCamera();
  c.vup = {1e-6, 0, 1};  // 1e-6 rad from N: allowed (the limit is 1e-9)
  EXPECT_EQ(cameraError(c), std::nullopt);
  c = checkCamera();
  c.front = 4.999;
  EXPECT_EQ(cameraError(c), std::nullopt);
  c = checkCamera();
  c.window = {-1e-300, 1e-300, -1, 1};  // d/Δx = 2.5e300: finite, so valid
  EXPECT_EQ(cameraError(c), std::nullopt);
}

// "A valid camera never leads to NaN or infinity in any stage matrix": for cameras with extreme
// values (random magnitudes from 1e-300 to 1e300), either cameraError names a problem or every
// matrix is finite. And no message ever claims PRP equals VRP when they differ by a lot.
TEST(Camera, ExtremeCamerasAreRefusedOrFinite) {
  test::Rng rng(99);
  auto extreme = [&] {
    const double mag = std::pow(10.0, rng.uniform(-300, 300));
    return (rng.chance(0.5) ? -1 : 1) * mag * rng.uniform(0.5, 1);
  };
  auto extremeVec = [&] {  // sequenced, so the same numbers with every compiler
    const double x = extreme(), y = extreme(), z = extreme();
    return Vec3(x, y, z);
  };
  // max |component|: unlike glm::length it does not overflow for components above 1e154.
  auto size = [](const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); };
  int refused = 0, accepted = 0;
  for (int k = 0; k < 2000; ++k) {
    Camera c;
    c.projection = Projection(rng.integer(0, 2));
    c.vrp = rng.chance(0.5) ? Vec3(0) : extremeVec();
    c.prp = rng.chance(0.3) ? c.vrp + Vec3(0, 0, extreme()) : extremeVec();
    c.vup = rng.chance(0.5) ? Vec3(0, 1, 0) : extremeVec();
    c.window.xmin = extreme();
    c.window.xmax = c.window.xmin + std::abs(extreme());
    c.window.ymin = extreme();
    c.window.ymax = c.window.ymin + std::abs(extreme());
    c.front = extreme();
    c.back = c.front - std::abs(extreme());
    c.oblique = {std::abs(extreme()), rng.uniform(-90, 90)};
    if (auto e = cameraError(c)) {
      ++refused;
      if (size(c.prp - c.vrp) > 1e-6 * (1 + size(c.vrp))) {
        EXPECT_THAT(*e, testing::Not(HasSubstr("equals VRP"))) << "PRP " << format(c.prp) << " VRP " << format(c.vrp);
      }
      continue;
    }
    ++accepted;
    const VrcAxes f = vrcAxes(c);
    EXPECT_TRUE(isFinite(f.u) && isFinite(f.v) && isFinite(f.n) && isFinite(f.vpd)) << k;
    EXPECT_TRUE(isFinite(vrcFromWc(c))) << k;
    EXPECT_TRUE(isFinite(npcFromVrc(c))) << k;
    EXPECT_TRUE(isFinite(npcFromVrc(c) * vrcFromWc(c))) << k;
  }
  // Both branches are exercised (with this seed 45 of the 2000 are valid).
  EXPECT_GT(refused, 1000);
  EXPECT_GT(accepted, 20);
}

}  // namespace
}  // namespace vplab
