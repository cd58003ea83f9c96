// The SVG backend (app/export/svg.h) on hand-made display lists: the document's structure, and its
// rasterisation by rsvg-convert shows what the lists say (fills in painter's order, depth-tested,
// hidden-only and x-ray lines against the faces drawn before them, markers, text).
#include <gtest/gtest.h>

#include "app/export/svg.h"
#include "app/fonts/font_atlas.h"
#include "base/error.h"
#include "tests/support/svg_test_support.h"
#include "tests/support/hand_made_lists.h"

namespace vplab {
namespace {

using namespace draw;
using draw::lists::square;

// 400 × 300 of WC through the pipeline's default camera on black (tests/support/hand_made_lists.h).
DisplayList wcList() {
  DisplayList list = lists::wcList();
  list.background = {0, 0, 0};
  return list;
}

Picture onePanel(DisplayList list) {
  Picture p;
  p.width = list.width;
  p.height = list.height;
  p.panels.push_back({0, 0, std::move(list)});
  return p;
}

const FontAtlas& fonts() {
  static const FontAtlas atlas(1.f);
  return atlas;
}

bool near(const Rgba& p, const Rgba& q, int tolerance = 8) {
  return std::abs(p.r - q.r) <= tolerance && std::abs(p.g - q.g) <= tolerance &&
         std::abs(p.b - q.b) <= tolerance;
}

TEST(SvgBackend, PanelsAreNestedAtTheirOffsetsOnTheirBackgrounds) {
  Picture p;
  p.width = 300;
  p.height = 120;
  p.background = {0, 1, 0};
  for (int i = 0; i < 2; ++i) {
    DisplayList list = wcList();
    list.width = 100;
    list.height = 100;
    list.background = i ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    p.panels.push_back({150 * i, 20, list});
  }
  const std::string svg = svgOfPicture(p, fonts(), "a <b> & c");
  EXPECT_NE(svg.find("<title>a &lt;b&gt; &amp; c</title>"), std::string::npos);
  EXPECT_NE(svg.find("<svg class=\"panel\" x=\"150\" y=\"20\" width=\"100\" height=\"100\""),
            std::string::npos);
  const Image image = test::rasteriseSvg(svg, "panels");
  ASSERT_EQ(image.width, 300);
  ASSERT_EQ(image.height, 120);
  EXPECT_TRUE(near(image.at(50, 10), {0, 255, 0}));   // the title strip: the picture's background
  EXPECT_TRUE(near(image.at(50, 70), {255, 0, 0}));   // panel 0
  EXPECT_TRUE(near(image.at(125, 70), {0, 255, 0}));  // the gap
  EXPECT_TRUE(near(image.at(200, 70), {0, 0, 255}));  // panel 1
}

TEST(SvgBackend, NearerFacesArePaintedOverFartherOnes) {
  DisplayList list = wcList();
  Fill f;
  f.polygons.push_back(square(1, 0.2, {1, 0, 0}));   // near and small, listed first
  f.polygons.push_back(square(-1, 0.6, {0, 0, 1}));  // far and large
  list.add(std::move(f));
  const Image image = test::rasteriseSvg(svgOfPicture(onePanel(list), fonts(), "painter"), "painter");
  EXPECT_TRUE(near(image.at(200, 150), {255, 0, 0}));       // the near face wins in the overlap
  EXPECT_TRUE(near(image.at(200 + 75, 150), {0, 0, 255}));  // the near face ends at 250, the far at 300
  EXPECT_TRUE(near(image.at(5, 5), {0, 0, 0}));
}

// A face at z = 0 over pixels [160, 240] × [110, 190]; a line at z = −1 (behind it) across the view.
DisplayList faceAndLineBehind(Depth depth, float dashPx = 0) {
  DisplayList list = wcList();
  Fill f;
  f.polygons.push_back(square(0, 0.2, {1, 0, 0}));
  list.add(std::move(f));
  Lines l;
  l.widthPx = 3;
  l.dashPx = dashPx;
  l.depth = depth;
  l.line({-0.8, 0, -1}, {0.8, 0, -1}, {1, 1, 1, 1});
  list.add(std::move(l));
  return list;
}

TEST(SvgBackend, DepthTestedLinesStopBehindTheFaces) {
  // Behind z = −1 the line spans x = ±0.8 · 5/6 … in pixels 200 ± 133; the face covers 160 … 240.
  const Image test =
      test::rasteriseSvg(svgOfPicture(onePanel(faceAndLineBehind(Depth::test)), fonts(), "t"), "test");
  EXPECT_TRUE(near(test.at(100, 150), {255, 255, 255}));
  EXPECT_TRUE(near(test.at(200, 150), {255, 0, 0}));  // hidden: the face shows
  const Image ignore =
      test::rasteriseSvg(svgOfPicture(onePanel(faceAndLineBehind(Depth::ignore)), fonts(), "i"), "ignore");
  EXPECT_TRUE(near(ignore.at(200, 150), {255, 255, 255}));  // over everything
  const Image xray =
      test::rasteriseSvg(svgOfPicture(onePanel(faceAndLineBehind(Depth::xray)), fonts(), "x"), "xray");
  // Faint where hidden: white at 30 % over red.
  EXPECT_TRUE(near(xray.at(200, 150), {255, 77, 77}, 10)) << int(xray.at(200, 150).g);
  EXPECT_TRUE(near(xray.at(100, 150), {255, 255, 255}));
}

TEST(SvgBackend, HiddenOnlyLinesAreTheHiddenPartsInPhaseWithTheDashes) {
  const std::string svg = svgOfPicture(onePanel(faceAndLineBehind(Depth::hiddenOnly, 5)), fonts(), "h");
  const Image image = test::rasteriseSvg(svg, "hidden");
  EXPECT_TRUE(near(image.at(100, 150), {0, 0, 0}));  // visible part: not drawn
  int white = 0, red = 0;
  for (int x = 165; x < 235; ++x) (near(image.at(x, 150), {255, 255, 255}, 60) ? white : red) += 1;
  EXPECT_GT(white, 20);                                         // dashes …
  EXPECT_GT(red, 20);                                           // … and gaps
  EXPECT_NE(svg.find("stroke-dashoffset"), std::string::npos);  // the piece starts mid-pattern
}

TEST(SvgBackend, MarkersAndTextAreWhereTheListPutsThem) {
  DisplayList list = wcList();
  list.add(Points{Space::pixels, {{{50, 60, 0}, {0, 1, 0, 1}}}, 12.f, Depth::ignore});
  Text t;
  t.labels.push_back({{100, 200}, {60, 15}, "VRP & <PRP>", {1, 1, 0, 1}, TextSize::label, true});
  list.add(std::move(t));
  const std::string svg = svgOfPicture(onePanel(list), fonts(), "marks");
  EXPECT_NE(svg.find("<circle cx=\"50\" cy=\"60\" r=\"5.25\""), std::string::npos) << svg;
  EXPECT_NE(svg.find(">VRP &amp; &lt;PRP&gt;</text>"), std::string::npos);
  EXPECT_NE(svg.find(std::string("font-family=\"") + fonts().cssFamily()), std::string::npos);
  const Image image = test::rasteriseSvg(svg, "marks");
  EXPECT_TRUE(near(image.at(50, 60), {0, 255, 0}));
  int yellow = 0;  // the glyphs: yellow pixels within the label's box
  for (int y = 200; y < 215; ++y)
    for (int x = 100; x < 160; ++x) yellow += near(image.at(x, y), {255, 255, 0}, 40);
  EXPECT_GT(yellow, 20);
}

TEST(SvgBackend, RefusesAHugeDocumentBeforeBuildingIt) {
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (size_t i = 0; i <= kMaxSvgFaces; ++i) mesh->addFace({0, 1, 2});
  DisplayList list = wcList();
  Fill f;
  f.meshes.push_back({mesh, Mat4(1.0), {1, 1, 1, 1}});
  list.add(f);
  try {
    svgOfPicture(onePanel(list), fonts(), "huge");
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(std::to_string(kMaxSvgFaces + 1)), std::string::npos) << what;
    EXPECT_NE(what.find(std::to_string(kMaxSvgFaces)), std::string::npos) << what;
    EXPECT_NE(what.find("PNG"), std::string::npos) << what;
  }
  // Depth-only faces (hidden-line styles) are not drawn, so not counted.
  std::get<Fill>(list.batches[0]).depthOnly = true;
  EXPECT_EQ(svgFaceCount(onePanel(list)), 0u);
}

}  // namespace
}  // namespace vplab
