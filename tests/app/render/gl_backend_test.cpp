// The GL backend (app/render/gl_backend.h) on lists built by hand: what it does with a picture's
// panels, with batches in a space the view does not look at, and with a run of x-ray batches. The
// views' lists themselves are checked through ViewRenderer (goldens, parity, view_renderer_test):
// before ViewRenderer became "build, then draw", every view × style of the default scene and every
// asset scene drew byte-identical pixels both ways (see the commit that added the backend).
#include "app/render/gl_backend.h"
#include "tests/support/gl_test_support.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vplab {
namespace {

using ::testing::HasSubstr;

GlBackend& backend() {
  static GlBackend b(*test::egl().context);
  test::egl();
  return b;
}

draw::DisplayList emptyList(int w, int h, glm::vec3 background) {
  draw::DisplayList list;
  list.width = w;
  list.height = h;
  list.background = background;
  list.observer.space = draw::Space::wc;
  list.observer.camera.vrcFromWc = Mat4(1.0);
  list.observer.camera.npcFromVrc = Mat4(1.0);
  return list;
}

TEST(GlBackend, PanelsGoAtTheirPlacesOnThePicturesBackground) {
  draw::Picture picture;
  picture.width = 100;
  picture.height = 50;
  picture.background = {1, 0, 0};
  picture.panels.push_back({60, 10, emptyList(20, 30, {0, 0, 1})});
  picture.panels.push_back({5, 5, emptyList(10, 10, {0, 1, 0})});
  picture.panels[1].list.antialiased = true;
  const Image image = backend().render(picture);
  ASSERT_EQ(image.width, 100);
  ASSERT_EQ(image.height, 50);
  EXPECT_EQ(image.at(0, 0), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(image.at(60, 10), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(image.at(79, 39), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(image.at(80, 39), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(image.at(59, 10), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(image.at(5, 5), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(image.at(14, 14), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(image.at(15, 15), (Rgba{255, 0, 0, 255}));
  EXPECT_NO_THROW(test::egl().context->checkErrors("rendering the picture"));
}

TEST(GlBackend, ABatchInASpaceTheViewDoesNotLookAtIsAnError) {
  draw::DisplayList list = emptyList(16, 16, {0, 0, 0});
  draw::Lines lines;
  lines.space = draw::Space::npc;
  lines.line({0, 0, 0}, {1, 1, 1}, {1, 1, 1, 1});
  list.add(lines);
  gl::RenderTarget target(test::egl().context->gl());
  target.resize(16, 16, 1);
  const std::string message = test::errorOf([&] { backend().draw(list, target); });
  EXPECT_THAT(message, HasSubstr("a batch in NPC in a view of WC"));
}

// Identity matrices: the observer sees NPC (x, y in [0, 1], z = 1 in front). A white opaque
// rectangle over the left half at z = 0.8 hides half of a red line and one of two green markers at
// z = 0.3: the hidden parts show faint (alpha × kXrayAlpha) over white, the others as they are.
TEST(GlBackend, ARunOfXrayBatchesDrawsTheHiddenPartsFaintly) {
  draw::DisplayList list = emptyList(40, 40, {0, 0, 0});
  draw::Fill square;
  square.polygons.push_back({{1, 1, 1}, {{0, 0, 0.8}, {0.5, 0, 0.8}, {0.5, 1, 0.8}, {0, 1, 0.8}}, {4}, nullptr, false, {}});
  list.add(square);
  draw::Lines red;
  red.widthPx = 4;
  red.depth = draw::Depth::xray;
  red.line({0.05, 0.75, 0.3}, {0.95, 0.75, 0.3}, {1, 0, 0, 1});
  list.add(red);
  draw::Points green;
  green.sizePx = 8;
  green.depth = draw::Depth::xray;
  green.points.push_back({{0.75, 0.25, 0.3}, {0, 1, 0, 1}});
  green.points.push_back({{0.25, 0.25, 0.3}, {0, 1, 0, 1}});
  list.add(green);
  gl::RenderTarget target(test::egl().context->gl());
  target.resize(40, 40, 1);
  backend().draw(list, target);
  const Image image = target.read();
  // NPC y = 0.75 is row 10 from the top, y = 0.25 row 30; the rectangle covers columns < 20.
  const Rgba hiddenRed = image.at(8, 10), visibleRed = image.at(32, 10);
  EXPECT_EQ(visibleRed, (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(hiddenRed.r, 255);  // white under a faint red: red stays full, green and blue drop
  EXPECT_GT(hiddenRed.g, 150);
  EXPECT_LT(hiddenRed.g, 200);  // 255 · (1 − 0.3) = 178.5
  const Rgba hiddenGreen = image.at(10, 30), visibleGreen = image.at(30, 30);
  EXPECT_EQ(hiddenGreen.g, 255);
  EXPECT_GT(hiddenGreen.r, 150);
  EXPECT_LT(hiddenGreen.r, 200);
  EXPECT_EQ(visibleGreen.r, visibleGreen.b);
  EXPECT_LT(visibleGreen.r, 100);  // the disc's rim is darker: the centre is the colour
  EXPECT_GT(visibleGreen.g, 80);
  EXPECT_NO_THROW(test::egl().context->checkErrors("drawing the x-ray list"));
}

// CPU polygons carry no normal: the fragment shader lights each by its plane's (scene.frag,
// FACE_NORMAL), turned to the side it is seen from. A tilted square covering the view, lit by one
// light, against Blinn–Phong worked out here for its plane's normal at each pixel centre (the
// observer is parallel, looking down −z: the eye's direction is +z). Tolerance 2 of 255: the
// shader's single precision and the rounding to 8 bits; the normal of an untilted square would miss
// by tens. Both windings give the same picture.
TEST(GlBackend, PolygonsAreLitByTheirPlanesNormalFromTheSideTheyAreSeenFrom) {
  const int size = 32;
  const Vec3 n = glm::normalize(Vec3(0.35, -0.25, 1));  // the plane n · p = n · (0.5, 0.5, 0.5)
  const double d = glm::dot(n, Vec3(0.5));
  auto zAt = [&](double x, double y) { return (d - n.x * x - n.y * y) / n.z; };
  std::vector<Vec3> square;
  for (const auto& [x, y] : {std::pair{-0.1, -0.1}, {1.1, -0.1}, {1.1, 1.1}, {-0.1, 1.1}}) square.push_back({x, y, zAt(x, y)});
  const glm::vec3 color(0.8f, 0.5f, 0.3f);
  const Light light{{0.2, 1.4, 1.6}, {1, 1, 1}};
  const float ambient = 0.3f;
  auto expected = [&](int px, int py) {
    const double x = (px + 0.5) / size, y = 1 - (py + 0.5) / size;
    const Vec3 p(x, y, zAt(x, y)), toEye(0, 0, 1), l = glm::normalize(light.position - p);
    const double diffuse = std::max(glm::dot(n, l), 0.0);
    const double h = std::max(glm::dot(n, glm::normalize(l + toEye)), 0.0);
    const double specular = diffuse > 0 ? std::pow(h, 48) : 0;
    return glm::min(Vec3(color) * double(ambient) + light.color * (diffuse * Vec3(color) + 0.3 * specular), Vec3(1));
  };
  for (bool reversed : {false, true}) {
    draw::DisplayList list = emptyList(size, size, {0, 0, 0});
    list.observer.space = draw::Space::npc;
    draw::Fill fill;
    fill.space = draw::Space::npc;
    fill.lit = true;
    fill.lights = {light};
    fill.ambient = ambient;
    draw::PolygonSet set;
    set.color = color;
    std::vector<Vec3> corners = square;
    if (reversed) std::reverse(corners.begin(), corners.end());
    set.add(corners);
    fill.polygons.push_back(set);
    list.add(fill);
    gl::RenderTarget target(test::egl().context->gl());
    target.resize(size, size, 1);
    backend().draw(list, target);
    const Image image = target.read();
    int worst = 0, missedByUntilted = 0;
    for (int py = 0; py < size; ++py)
      for (int px = 0; px < size; ++px) {
        const Vec3 e = expected(px, py) * 255.0;
        const Rgba got = image.at(px, py);
        worst = std::max({worst, int(std::lround(std::abs(got.r - e.r))), int(std::lround(std::abs(got.g - e.g))),
                          int(std::lround(std::abs(got.b - e.b)))});
      }
    EXPECT_LE(worst, 2) << (reversed ? "reversed" : "as given");
    // the normal matters: the untilted square's light differs by more than the tolerance
    const Vec3 flat = [&] {
      const Vec3 p(0.5, 0.5, 0.5), l = glm::normalize(light.position - p), up(0, 0, 1);
      const double diffuse = std::max(glm::dot(up, l), 0.0);
      return Vec3(color) * double(ambient) + diffuse * Vec3(color);
    }() * 255.0;
    missedByUntilted = int(std::abs(image.at(size / 2, size / 2).r - flat.r));
    EXPECT_GT(missedByUntilted, 10);
  }
  EXPECT_NO_THROW(test::egl().context->checkErrors("drawing the lit square"));
}

}  // namespace
}  // namespace vplab
