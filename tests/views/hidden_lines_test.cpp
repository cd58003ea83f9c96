#include "app/views/hidden_lines.h"

#include <gtest/gtest.h>

namespace vplab::draw {
namespace {

// A face over pixels [100, 300] × [100, 200] at NPC z 0.6 (flat: no depth slope).
DepthField fieldWithFace(double z = 0.6) {
  DepthField d(400, 300);
  const PixelPoint face[4] = {{100, 100, z}, {300, 100, z}, {300, 200, z}, {100, 200, z}};
  d.addFan(face);
  return d;
}

TEST(HiddenLines, AFaceHidesOnlyWhatLiesBehindIt) {
  const DepthField d = fieldWithFace();
  EXPECT_TRUE(d.hides({200, 150, 0.5}));   // behind (smaller z is farther)
  EXPECT_FALSE(d.hides({200, 150, 0.7}));  // in front
  EXPECT_FALSE(d.hides({50, 150, 0.1}));   // beside it
  // On the face itself: the face's polygon offset (2 steps of 2^−24 here) keeps its own edges visible.
  EXPECT_FALSE(d.hides({200, 150, 0.6}));
  EXPECT_FALSE(d.hides({200, 150, 0.6 - 1.5 * std::ldexp(1.0, -24)}));
  EXPECT_TRUE(d.hides({200, 150, 0.6 - 3 * std::ldexp(1.0, -24)}));
}

TEST(HiddenLines, AFaceInColourIsNotPushedBack) {
  // A steep face (depth slope 0.001 per pixel): pushed back (depth only) it spares a point 0.0009
  // behind it, drawn in colour it hides it, as GL's plain depth test does.
  const PixelPoint face[3] = {{0, 0, 0.5}, {400, 0, 0.9}, {0, 300, 0.5}};
  DepthField pushed(400, 300), plain(400, 300);
  pushed.addFan(face, true);
  plain.addFan(face, false);
  const PixelPoint behind{100, 50, 0.6 - 0.0009};
  EXPECT_FALSE(pushed.hides(behind));
  EXPECT_TRUE(plain.hides(behind));
  EXPECT_FALSE(plain.hides({100, 50, 0.6}));  // on it: not hidden
}

TEST(HiddenLines, APushedBackPointLosesTheTie) {
  const DepthField d = fieldWithFace();
  EXPECT_FALSE(d.hides({200, 150, 0.6}));
  EXPECT_TRUE(d.hides({200, 150, 0.6}, 1e-6));
}

TEST(HiddenLines, TheSlopeOfAFaceWidensItsOffset) {
  // A face whose z changes by 0.001 per pixel in x: factor 1 of glPolygonOffset adds that slope.
  DepthField d(400, 300);
  const PixelPoint face[3] = {{0, 0, 0.5}, {400, 0, 0.9}, {0, 300, 0.5}};
  d.addFan(face);
  EXPECT_NEAR(DepthField::polygonOffset(face[0], face[1], face[2]), 0.001 + 2 * std::ldexp(1.0, -24), 1e-12);
  const double zFace = 0.5 + 0.001 * 100;  // at x = 100
  EXPECT_FALSE(d.hides({100, 50, zFace - 0.0009}));
  EXPECT_TRUE(d.hides({100, 50, zFace - 0.0011}));
}

TEST(HiddenLines, ASegmentIsCutWhereItPassesBehindTheFace) {
  const DepthField d = fieldWithFace();
  const auto pieces = d.pieces({0, 150, 0.5}, {400, 150, 0.5});
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_FALSE(pieces[0].hidden);
  EXPECT_TRUE(pieces[1].hidden);
  EXPECT_FALSE(pieces[2].hidden);
  // The cuts at x = 100 and 300, to far better than a pixel (bisection to 0.5 / 2^16 px).
  EXPECT_NEAR(pieces[0].t1 * 400, 100, 1e-3);
  EXPECT_NEAR(pieces[1].t1 * 400, 300, 1e-3);
  // A segment piercing the face: hidden only beyond the point where it passes behind.
  const auto piercing = d.pieces({200, 120, 0.8}, {200, 180, 0.4});
  ASSERT_EQ(piercing.size(), 2u);
  EXPECT_NEAR(piercing[0].t1, 0.5, 1e-4);
  EXPECT_TRUE(piercing[1].hidden);
  // Nothing drawn before: all visible.
  const DepthField none(400, 300);
  ASSERT_EQ(none.pieces({0, 0, 0}, {10, 10, 0}).size(), 1u);
  EXPECT_FALSE(none.pieces({0, 0, 0}, {10, 10, 0})[0].hidden);
}

TEST(HiddenLines, APolygonIsSplitOnlyWhereItsVisibilityChanges) {
  const DepthField d = fieldWithFace();
  const PixelPoint apart[3] = {{10, 10, 0.1}, {60, 10, 0.1}, {10, 60, 0.1}};
  ASSERT_EQ(d.parts(apart).size(), 1u);  // beside the face: whole
  EXPECT_FALSE(d.parts(apart)[0].hidden);
  const PixelPoint behind[3] = {{150, 120, 0.1}, {250, 120, 0.1}, {150, 180, 0.1}};
  ASSERT_EQ(d.parts(behind).size(), 1u);
  EXPECT_TRUE(d.parts(behind)[0].hidden);
  // Half behind the face: the hidden parts' area is the overlap, to within the 2 px the split stops at.
  const PixelPoint across[4] = {{0, 120, 0.1}, {200, 120, 0.1}, {200, 180, 0.1}, {0, 180, 0.1}};
  double hidden = 0, visible = 0;
  for (const auto& part : d.parts(across)) {
    const auto& p = part.polygon;
    double area = 0;
    for (size_t i = 0; i < p.size(); ++i)
      area += p[i].x * p[(i + 1) % p.size()].y - p[(i + 1) % p.size()].x * p[i].y;
    (part.hidden ? hidden : visible) += std::abs(area) / 2;
  }
  EXPECT_NEAR(hidden, 100 * 60, 2 * 60);
  EXPECT_NEAR(visible, 100 * 60, 2 * 60);
}

}  // namespace
}  // namespace vplab::draw
