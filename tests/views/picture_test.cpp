// The pictures of the view kinds: one panel, or "all": three panels under a strip of titles.
#include "app/views/theme.h"
#include "tests/views/view_test_support.h"

#include <gtest/gtest.h>

namespace vplab {
namespace {

using namespace draw;

TEST(Picture, AllIsATitleStripOverThreePanelsSixPixelsApart) {
  test::ViewFixture f(defaultScene(), Style::shaded, 400, 300);
  const Picture p = buildPicture(ViewKind::all, f.input());
  const int title = 18 + 14;  // the title's height ("Ag", test::FixedMetrics) and 7 px above and below
  EXPECT_EQ(p.width, 3 * 400 + 2 * 6);
  EXPECT_EQ(p.height, title + 300);
  EXPECT_EQ(p.background, glm::vec3(20, 21, 26) / 255.f);
  ASSERT_EQ(p.panels.size(), 4u);
  const int at[4][2] = {{0, 0}, {0, title}, {406, title}, {812, title}};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(p.panels[i].x, at[i][0]) << i;
    EXPECT_EQ(p.panels[i].y, at[i][1]) << i;
  }
  const DisplayList& strip = p.panels[0].list;
  EXPECT_EQ(strip.width, p.width);
  EXPECT_EQ(strip.height, title);
  EXPECT_EQ(strip.background, theme::kDark.stripBackground);
  EXPECT_EQ(p.panels[1].list.observer.space, Space::wc);
  EXPECT_FALSE(p.panels[1].list.antialiased);  // the camera view
  EXPECT_TRUE(p.panels[2].list.antialiased);   // the world view
  EXPECT_EQ(p.panels[3].list.observer.space, Space::npc);
  for (size_t i = 1; i < 4; ++i) {
    EXPECT_EQ(p.panels[i].list.width, 400);
    EXPECT_EQ(p.panels[i].list.height, 300);
  }
  // 400 px panels: the long titles (43, 41 and 52 characters of 10 px) do not fit; each short one
  // centred over its panel.
  const std::vector<PlacedLabel> titles = strip.labels();
  ASSERT_EQ(titles.size(), 3u);
  EXPECT_EQ(titles[0].text, "camera (DC)");
  EXPECT_EQ(titles[2].text, "NPC");
  for (size_t i = 0; i < 3; ++i)
    EXPECT_NEAR(titles[i].topLeft.x + titles[i].extent.x / 2, i * 406 + 200, 1) << titles[i].text;
  EXPECT_FALSE(titles[0].shadow);
}

TEST(Picture, LongTitlesWhereTheyFit) {
  test::ViewFixture f(defaultScene(), Style::shaded, 500, 300);
  const std::vector<PlacedLabel> titles = buildPicture(ViewKind::all, f.input()).panels[0].list.labels();
  ASSERT_EQ(titles.size(), 3u);
  EXPECT_EQ(titles[0].text, "camera: what the synthetic camera sees (DC)");  // 430 ≤ 500 − 12
  EXPECT_EQ(titles[1].text, "world: scene, camera and view volume (WC)");
  EXPECT_EQ(titles[2].text, "NPC");  // 520 > 488
}

TEST(Picture, OneViewIsOnePanel) {
  test::ViewFixture f(defaultScene(), Style::flat, 320, 200);
  Picture p = buildPicture(ViewKind::all, f.input());
  buildPicture(ViewKind::world, f.input(), p);  // overwritten
  ASSERT_EQ(p.panels.size(), 1u);
  EXPECT_EQ(p.panels[0].x, 0);
  EXPECT_EQ(p.panels[0].y, 0);
  EXPECT_EQ(p.width, 320);
  EXPECT_EQ(p.height, 200);
  EXPECT_TRUE(p.panels[0].list.antialiased);
  EXPECT_EQ(p.background, p.panels[0].list.background);
}

}  // namespace
}  // namespace vplab
