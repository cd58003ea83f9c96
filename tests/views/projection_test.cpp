#include "app/views/projection.h"

#include <gtest/gtest.h>

#include "tests/support/hand_made_lists.h"
#include "base/error.h"

namespace vplab::draw {
namespace {

TEST(Projection, MapsTheObserversSpaceToPixelsYDown) {
  const DisplayList list = lists::wcList();
  const ViewProjection p(list, Space::wc);
  const PixelPoint centre = p.pixel(p.npcH(Vec3(0, 0, 0)));
  EXPECT_NEAR(centre.x, 200, 1e-9);
  EXPECT_NEAR(centre.y, 150, 1e-9);
  // The window's top-right corner (1, 0.75, 0) is the view's top-right pixel corner.
  const PixelPoint corner = p.pixel(p.npcH(Vec3(1, 0.75, 0)));
  EXPECT_NEAR(corner.x, 400, 1e-9);
  EXPECT_NEAR(corner.y, 0, 1e-9);
  // Nearer is larger z: the front plane z = 2 is NPC z 1, the back plane z = −2 is 0.
  EXPECT_NEAR(p.pixel(p.npcH(Vec3(0, 0, 2))).z, 1, 1e-9);
  EXPECT_NEAR(p.pixel(p.npcH(Vec3(0, 0, -2))).z, 0, 1e-9);
}

TEST(Projection, PixelsAreTheirOwnSpace) {
  const DisplayList list = lists::wcList();
  const ViewProjection p(list, Space::pixels);
  const auto s = p.segment(Vec3(10, 20, 0), Vec3(390, 280, 0));
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->a.x, 10, 1e-9);
  EXPECT_NEAR(s->a.y, 20, 1e-9);
  EXPECT_NEAR(s->b.x, 390, 1e-9);
  EXPECT_NEAR(s->b.y, 280, 1e-9);
  // Beyond the view's edge it is cut at the edge.
  const auto cut = p.segment(Vec3(-100, 150, 0), Vec3(100, 150, 0));
  ASSERT_TRUE(cut);
  EXPECT_NEAR(cut->a.x, 0, 1e-9);
  EXPECT_NEAR(cut->dashOrigin, 100, 1e-9);  // the dashes are measured from the start at x = −100
}

TEST(Projection, CutsWhatLiesBeforeTheFrontPlaneAndBehindTheEye) {
  const DisplayList list = lists::wcList();
  const ViewProjection p(list, Space::wc);
  // From the centre of the view volume to a point behind the eye (z = 8): after a naive division it
  // would land inside the view; clipped before the division it ends at the front plane z = 2.
  const auto s = p.segment(Vec3(0.3, 0, 0), Vec3(0.3, 0, 8));
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->b.z, 1, 1e-9);
  const PixelPoint front = p.pixel(p.npcH(Vec3(0.3, 0, 2)));
  EXPECT_NEAR(s->b.x, front.x, 1e-6);
  // Wholly behind the eye: nothing.
  EXPECT_FALSE(p.segment(Vec3(0, 0, 6), Vec3(1, 0, 9)));
  // Dashes are measured from where the segment crosses the front plane: coming from behind the eye,
  // the origin is the front-plane point, so the phase of the first visible point is 0.
  const auto in = p.segment(Vec3(0.3, 0, 8), Vec3(0.3, 0, 0));
  ASSERT_TRUE(in);
  EXPECT_NEAR(in->dashOrigin, 0, 1e-6);
  EXPECT_FALSE(p.point(Vec3(0, 0, 3)));  // before the front plane
  EXPECT_TRUE(p.point(Vec3(0, 0, 1)));
}

TEST(Projection, PolygonsAreClippedByTheUserPlanesToo) {
  const DisplayList list = lists::wcList();
  const Vec4 keepRight(1, 0, 0, 0);  // x ≥ 0 kept
  const ViewProjection p(list, Space::wc, std::span(&keepRight, 1));
  const std::vector<Vec4> square = {p.npcH(Vec3(-0.5, -0.5, 0)), p.npcH(Vec3(0.5, -0.5, 0)),
                                    p.npcH(Vec3(0.5, 0.5, 0)), p.npcH(Vec3(-0.5, 0.5, 0))};
  const std::vector<PixelPoint> half = p.polygon(square);
  ASSERT_EQ(half.size(), 4u);
  double minX = 1e9, maxX = -1e9;
  for (const PixelPoint& q : half) minX = std::min(minX, q.x), maxX = std::max(maxX, q.x);
  EXPECT_NEAR(minX, 200, 1e-9);            // x = 0
  EXPECT_NEAR(maxX, 300, 1e-9);            // x = 0.5
  const Vec4 keepFarLeft(-1, 0, 0, -0.9);  // x ≤ −0.9: misses the square
  EXPECT_TRUE(p.polygon(square, std::span(&keepFarLeft, 1)).empty());
}

TEST(Projection, RefusesABatchInAnotherSpace) {
  const DisplayList list = lists::wcList();
  try {
    ViewProjection(list, Space::npc);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("NPC"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("WC"), std::string::npos) << e.what();
  }
  DisplayList empty = lists::wcList(0, 0);
  EXPECT_THROW(ViewProjection(empty, Space::wc), Error);
}

}  // namespace
}  // namespace vplab::draw
