// Stage 1, modeling MC → WC (lecture notes 13.1–13.5, 15.2.1; docs/conventions.md stage 1).
#include "pipeline/modeling.h"

#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

namespace vplab {
namespace {

using test::errorOf;
using testing::HasSubstr;

double maxAbsDiff(const Mat4& a, const Mat4& b) {
  double d = 0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
  return d;
}

Vec3 apply(const Mat4& m, const Vec3& p) {
  const Vec4 h = m * Vec4(p, 1);
  EXPECT_EQ(h.w, 1);  // modeling transforms are affine
  return Vec3(h);
}

TEST(Modeling, TranslationAndScaling) {
  EXPECT_EQ(apply(translation({1, -2, 3}), {4, 5, 6}), Vec3(5, 3, 9));
  EXPECT_EQ(apply(scaling({2, -1, 0.5}), {4, 5, 6}), Vec3(8, -5, 3));
  EXPECT_EQ(row(translation({1, -2, 3}), 0), Vec4(1, 0, 0, 1));  // column-vector form: t in column 3
}

// wcFromMc = T · R_k · … · R_1 · S: scale first, the first listed rotation next. Worked by hand:
// p = (1, 2, 3), S = (2, 1, 1) → (2, 2, 3); R_1 = 90° about x: (x, y, z) → (x, −z, y) = (2, −3, 2);
// R_2 = 90° about y: (x, y, z) → (z, y, −x) = (2, −3, −2); T = (10, 0, 0) → (12, −3, −2).
// The other order of the rotations would give (13, 2, 2).
TEST(Modeling, OrderIsTranslateRotationsScale) {
  ModelTransform m;
  m.translate = {10, 0, 0};
  m.rotations = {{{1, 0, 0}, 90, {}}, {{0, 1, 0}, 90, {}}};
  m.scale = {2, 1, 1};
  const Mat4 w = wcFromMc(m);
  const Vec3 p = apply(w, {1, 2, 3});
  // 1e-14: cos 90° is 6e-17, not 0; coordinates of order 10.
  EXPECT_NEAR(glm::length(p - Vec3(12, -3, -2)), 0, 1e-14) << format(p);
  // Against the explicit product.
  const Mat4 explicitProduct = translation(m.translate) * rotationAbout({0, 1, 0}, 90) *
                               rotationAbout({1, 0, 0}, 90) * scaling(m.scale);
  EXPECT_LT(maxAbsDiff(w, explicitProduct), 1e-15);  // the same products, at most a rounding apart
  // The rotations do not commute, so the order is observable.
  const Mat4 swapped = translation(m.translate) * rotationAbout({1, 0, 0}, 90) *
                       rotationAbout({0, 1, 0}, 90) * scaling(m.scale);
  EXPECT_GT(maxAbsDiff(w, swapped), 0.5);
  EXPECT_NEAR(glm::length(apply(swapped, {1, 2, 3}) - Vec3(13, 2, 2)), 0, 1e-14);
}

TEST(Modeling, ThreeRotationsInListedOrder) {
  test::Rng rng(5);
  for (int k = 0; k < 50; ++k) {
    ModelTransform m;
    m.translate = rng.inBox(-5, 5);
    m.scale = {rng.uniform(0.2, 3), rng.uniform(0.2, 3), rng.uniform(0.2, 3)};
    Mat4 expected = scaling(m.scale);
    for (int i = 0; i < 3; ++i) {
      Rotation r{rng.unitVector(), rng.uniform(-180, 180), {}};
      if (rng.chance(0.5)) r.through = rng.inBox(-3, 3);
      m.rotations.push_back(r);
      expected = rotation(r) * expected;  // each later rotation acts on the result so far
    }
    expected = translation(m.translate) * expected;
    // 1e-13: entries up to ~10, three rotations composed, each a few roundings.
    EXPECT_LT(maxAbsDiff(wcFromMc(m), expected), 1e-13);
  }
}

// rotationX/Y/Z agree with rotationAbout for the unit axes; they are right-handed.
TEST(Modeling, AxisRotationsAgreeWithRotationAbout) {
  for (double deg : {-270.0, -45.0, 0.0, 30.0, 90.0, 123.4, 180.0, 359.0}) {
    // 1e-15: the same cos and sin; Rodrigues adds (1 − c)·1 + c, an ulp or two away from 1.
    EXPECT_LT(maxAbsDiff(rotationX(deg), rotationAbout({1, 0, 0}, deg)), 1e-15) << deg;
    EXPECT_LT(maxAbsDiff(rotationY(deg), rotationAbout({0, 1, 0}, deg)), 1e-15) << deg;
    EXPECT_LT(maxAbsDiff(rotationZ(deg), rotationAbout({0, 0, 1}, deg)), 1e-15) << deg;
  }
  // Right-handed: 90° about z takes x to y, about x takes y to z, about y takes z to x.
  EXPECT_NEAR(glm::length(apply(rotationZ(90), {1, 0, 0}) - Vec3(0, 1, 0)), 0, 1e-15);
  EXPECT_NEAR(glm::length(apply(rotationX(90), {0, 1, 0}) - Vec3(0, 0, 1)), 0, 1e-15);
  EXPECT_NEAR(glm::length(apply(rotationY(90), {0, 0, 1}) - Vec3(1, 0, 0)), 0, 1e-15);
}

// lecture notes 13.3 composes a rotation about an arbitrary axis: rotate the axis into z, rotate about z,
// undo. With an orthonormal basis B = [e1 e2 a] (det 1) that is B · Rz · Bᵀ, independent of the
// closed form. Random axes (fixed seed); 1e-14: products of three rotations with unit entries.
TEST(Modeling, RotationAboutMatchesTheSeedsComposition) {
  test::Rng rng(13);
  for (int k = 0; k < 100; ++k) {
    const Vec3 a = rng.unitVector();
    const double deg = rng.uniform(-360, 360);
    const Vec3 helper = std::abs(a.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 e1 = glm::normalize(glm::cross(helper, a));
    const Vec3 e2 = glm::cross(a, e1);
    const Mat4 basis(Vec4(e1, 0), Vec4(e2, 0), Vec4(a, 0), Vec4(0, 0, 0, 1));  // columns
    const Mat4 seed = basis * rotationZ(deg) * glm::transpose(basis);
    EXPECT_LT(maxAbsDiff(rotationAbout(a, deg), seed), 1e-14);
    // A non-unit axis is normalized first.
    EXPECT_LT(maxAbsDiff(rotationAbout(a * rng.uniform(0.01, 100), deg), seed), 1e-14);
  }
}

// Rotating about the line through a point leaves the points of that line fixed and keeps distances.
TEST(Modeling, RotationAboutLineFixesTheAxis) {
  test::Rng rng(7);
  for (int k = 0; k < 100; ++k) {
    const Vec3 axis = rng.unitVector() * rng.uniform(0.5, 3);
    const Vec3 point = rng.inBox(-10, 10);
    const double deg = rng.uniform(10, 350);
    const Mat4 m = rotationAboutLine(axis, deg, point);
    // 1e-12: points up to ~40 from the origin, translations undone after a rotation.
    for (double t : {-5.0, 0.0, 0.7, 12.0}) {
      const Vec3 onAxis = point + t * axis;
      EXPECT_NEAR(glm::length(apply(m, onAxis) - onAxis), 0, 1e-12);
    }
    const Vec3 off = point + glm::normalize(glm::cross(axis, rng.unitVector()));  // 1 from the axis
    const Vec3 moved = apply(m, off);
    EXPECT_NEAR(glm::length(moved - point), 1, 1e-12);
    // It moves: by the chord 2·sin(deg/2) of the unit circle.
    EXPECT_NEAR(glm::length(moved - off), 2 * std::abs(std::sin(deg * kPi / 360)), 1e-12);
    // Rotation{axis, deg, through} is the same thing.
    EXPECT_LT(maxAbsDiff(rotation({axis, deg, point}), m), 1e-15);
  }
}

TEST(Modeling, ScalingAboutKeepsTheFixedPoint) {
  test::Rng rng(3);
  for (int k = 0; k < 100; ++k) {
    const Vec3 z = rng.inBox(-10, 10);
    const Vec3 s(rng.uniform(-3, 3), rng.uniform(0.1, 3), rng.uniform(-3, -0.1));
    const Mat4 m = scalingAbout(s, z);
    const Vec3 p = rng.inBox(-10, 10);
    // 1e-13: coordinates up to ~40, a translation there and back.
    EXPECT_NEAR(glm::length(apply(m, z) - z), 0, 1e-13);
    EXPECT_NEAR(glm::length(apply(m, p) - (z + s * (p - z))), 0, 1e-13);
  }
}

// lecture notes 13.5: normals map with the inverse transpose; under a non-uniform scale the plain matrix
// would tilt them, the normal matrix keeps them perpendicular to every transformed tangent.
TEST(Modeling, NormalMatrixKeepsNormalsPerpendicular) {
  test::Rng rng(135);
  int tiltedByPlainMatrix = 0;
  for (int k = 0; k < 200; ++k) {
    ModelTransform t;
    t.scale = {rng.uniform(0.1, 5), rng.uniform(0.1, 5), rng.uniform(0.1, 5)};
    t.rotations = {{rng.unitVector(), rng.uniform(0, 360), {}}};
    t.translate = rng.inBox(-5, 5);
    const Mat4 m = wcFromMc(t);
    const Vec3 n = rng.unitVector();
    const Vec3 tangent = glm::normalize(glm::cross(n, rng.unitVector()));
    const Vec3 tWc = Mat3(m) * tangent;
    const Vec3 nWc = normalMatrix(m) * n;
    // Relative 1e-12: |tWc|·|nWc| ≤ 5·10, each a few products of unit values.
    EXPECT_NEAR(glm::dot(tWc, nWc), 0, 1e-12 * glm::length(tWc) * glm::length(nWc));
    if (std::abs(glm::dot(tWc, Mat3(m) * n)) > 1e-3 * glm::length(tWc) * glm::length(Mat3(m) * n))
      ++tiltedByPlainMatrix;
  }
  EXPECT_GT(tiltedByPlainMatrix, 150);  // the property is not trivially true
  // A pure rotation: the normal matrix is the rotation itself (1e-15: unit entries).
  const Mat4 r = rotationAbout({1, 2, 3}, 40);
  const Mat3 nm = normalMatrix(r);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(nm[c][i], r[c][i], 1e-15);
}

TEST(Modeling, ABFromBHasTheAxesAsColumns) {
  const Mat4 m = aFromB({1, 2, 3}, {4, 5, 6}, {7, 8, 9}, {10, 11, 12});
  EXPECT_EQ(m[0], Vec4(1, 2, 3, 0));
  EXPECT_EQ(m[1], Vec4(4, 5, 6, 0));
  EXPECT_EQ(m[2], Vec4(7, 8, 9, 0));
  EXPECT_EQ(m[3], Vec4(10, 11, 12, 1));
}

TEST(Modeling, ErrorsNameTheValues) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  EXPECT_THAT(errorOf([] { rotationAbout({0, 0, 0}, 30); }),
              HasSubstr("non-zero axis and a finite angle, but axis = (0, 0, 0), deg = 30"));
  EXPECT_THAT(errorOf([] { rotationAbout({1e-13, 0, 0}, 30); }), HasSubstr("axis = (1e-13, 0, 0)"));
  EXPECT_THAT(errorOf([&] { rotationAbout({kNaN, 0, 1}, 30); }), HasSubstr("axis = (nan, 0, 1)"));
  EXPECT_THAT(errorOf([&] { rotationAbout({0, 0, 1}, kInf); }), HasSubstr("deg = inf"));
  EXPECT_THAT(errorOf([&] { rotationAboutLine({0, 0, 1}, 10, {0, kInf, 0}); }),
              HasSubstr("must be finite, but it is (0, inf, 0)"));
  EXPECT_THAT(errorOf([&] { rotation({{0, 0, 0}, 10, Vec3(1, 2, 3)}); }), HasSubstr("axis = (0, 0, 0)"));

  ModelTransform m;
  m.scale = {1, 0, 2};
  EXPECT_THAT(errorOf([&] { wcFromMc(m); }), HasSubstr("scale (1, 0, 2) must be finite and non-zero"));
  m.scale = {1, 1, kNaN};
  EXPECT_THAT(errorOf([&] { wcFromMc(m); }), HasSubstr("scale (1, 1, nan)"));
  m.scale = {1, 1, 1};
  m.translate = {kInf, 0, 0};
  EXPECT_THAT(errorOf([&] { wcFromMc(m); }), HasSubstr("translate (inf, 0, 0) must be finite"));
  m.translate = {0, 0, 0};
  m.rotations = {{{0, 1, 0}, 45, {}}, {{0, 0, 0}, 10, {}}};
  EXPECT_THAT(errorOf([&] { wcFromMc(m); }), HasSubstr("axis = (0, 0, 0), deg = 10"));
  // Valid again: no throw.
  m.rotations.pop_back();
  EXPECT_EQ(errorOf([&] { wcFromMc(m); }), "<no exception thrown>");
}

}  // namespace
}  // namespace vplab
