// The light theme (issue 21: sheets that print): a white ground, and the view volume, the window,
// the projectors and the objects' edges told apart by dashes and widths, not only by colour, so that
// a sheet printed in grey keeps them apart; labels outlined in white, dark; the polygon's vertices
// named P1 … Pn; the labels in the sheet's language. The dark theme stays as it was.
#include "app/views/theme.h"
#include "io/build_mesh.h"
#include "io/scene_io.h"
#include "tests/views/view_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace vplab {
namespace {

using namespace draw;

Scene preset(const char* name) { return loadScene(std::string(VPLAB_ASSETS) + "/scenes/" + name + ".json"); }

// A quadrilateral partly inside the default camera's view volume (an exercise's polygon).
Scene withPolygon() {
  Scene s = preset("default");
  SceneObject quad;
  quad.name = "P";
  quad.shape = Shape::polygon;
  quad.vertices = {{-1, -1, 0}, {3, -1, 0}, {3, 2, 0}, {-1, 2, 0}};
  quad.color = {0.86, 0.33, 0.27};
  buildMesh(quad, ".");
  s.objects = {quad};
  return s;
}

struct LineStyle {
  float widthPx = -1, dashPx = -1;
};
// The width and dash of the lines drawn in `color`, −1 when none is.
LineStyle styleOf(const DisplayList& list, const glm::vec4& color) {
  for (const Lines* l : test::batchesOf<Lines>(list))
    for (const Vertex& v : test::segmentsOf(*l))
      if (v.color == color) return {l->widthPx, l->dashPx};
  return {};
}

// The perceived brightness a grey-scale printer keeps of a colour (ITU-R BT.601 luma).
float luma(const glm::vec4& c) { return 0.299f * c.r + 0.587f * c.g + 0.114f * c.b; }

std::vector<std::string> labelTexts(const DisplayList& list) {
  std::vector<std::string> out;
  for (const PlacedLabel& l : list.labels()) out.push_back(l.text);
  return out;
}
bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

TEST(Theme, LightWorldViewTellsItsLinesApartWithoutColour) {
  test::ViewFixture f(withPolygon(), Style::hiddenLine);
  f.settings.theme = Theme::light;
  const DisplayList list = worldView(f.input());
  const theme::Palette& p = theme::kLight;
  EXPECT_EQ(list.background, glm::vec3(1, 1, 1));
  const LineStyle frustum = styleOf(list, p.frustum), window = styleOf(list, p.window);
  ASSERT_GT(frustum.widthPx, 0) << "the view volume is drawn";
  ASSERT_GT(window.widthPx, 0) << "the window is drawn";
  EXPECT_EQ(frustum.dashPx, 0.f) << "the view volume: solid";
  EXPECT_GT(window.dashPx, 0.f) << "the window: dashed";
  EXPECT_GE(window.widthPx, 2 * frustum.widthPx) << "and twice as wide";
  // The polygon's edges (its ink), solid and wider than the view volume.
  const LineStyle polygon = styleOf(list, theme::ink(p, glm::vec4(glm::vec3(f.scene.objects[0].color), 1)));
  ASSERT_GT(polygon.widthPx, 0) << "the polygon's edges are drawn";
  EXPECT_EQ(polygon.dashPx, 0.f);
  EXPECT_GT(polygon.widthPx, frustum.widthPx);
  // The projectors from PRP: dotted, unlike both.
  const LineStyle projectors = styleOf(list, glm::vec4(glm::vec3(p.frustum), 0.6f));
  EXPECT_GT(projectors.dashPx, 0.f);
  EXPECT_LT(projectors.dashPx, window.dashPx / 2);
  // Dark enough on white to print: every line colour at most 60 % of white's luma.
  for (const glm::vec4& c : {p.frustum, p.window, p.u, p.v, p.n, p.vup, p.vrp, p.prp, p.text, p.newEdge, p.cube})
    EXPECT_LE(luma(c), 0.6f);
  for (const Text* t : test::batchesOf<Text>(list)) EXPECT_EQ(t->outline, glm::vec3(1, 1, 1));
}

TEST(Theme, DarkThemeKeepsItsLook) {
  test::ViewFixture f(withPolygon(), Style::hiddenLine);
  const DisplayList list = worldView(f.input());
  EXPECT_EQ(list.background, theme::kDark.viewBackground);
  const LineStyle window = styleOf(list, theme::kDark.window);
  EXPECT_EQ(window.dashPx, 0.f);
  EXPECT_EQ(window.widthPx, theme::kLineWidth);
  for (const Text* t : test::batchesOf<Text>(list)) EXPECT_EQ(t->outline, glm::vec3(0, 0, 0));
}

TEST(Theme, VertexNamesAndLabelsInTheSheetsLanguage) {
  test::ViewFixture f(withPolygon(), Style::hiddenLine);
  f.settings.theme = Theme::light;
  std::vector<std::string> labels = labelTexts(worldView(f.input()));
  EXPECT_FALSE(has(labels, "P1")) << "names only when asked for";
  EXPECT_TRUE(has(labels, "window"));
  f.settings.overlays.vertexNames = true;
  f.settings.language = Language::de;
  labels = labelTexts(worldView(f.input()));
  for (const char* name : {"P1", "P2", "P3", "P4", "Fenster", "vordere Ebene F", "hintere Ebene B"})
    EXPECT_TRUE(has(labels, name)) << name;
  EXPECT_FALSE(has(labels, "window"));
  // The NPC view names the vertices inside the view volume (the others were clipped away).
  const std::vector<std::string> npc = labelTexts(npcView(f.input()));
  EXPECT_TRUE(has(npc, "vorne z = 1"));
  const auto names = std::count_if(npc.begin(), npc.end(), [](const std::string& s) { return s[0] == 'P'; });
  EXPECT_GE(names, 1);
  EXPECT_LE(names, 4);
}

TEST(Theme, ThemesByName) {
  EXPECT_EQ(fromString<Theme>("light"), Theme::light);
  EXPECT_EQ(fromString<Theme>("dark"), Theme::dark);
  EXPECT_EQ(fromString<Theme>("sepia"), std::nullopt);
  EXPECT_EQ(toString(Theme::light), "light");
}

}  // namespace
}  // namespace vplab
