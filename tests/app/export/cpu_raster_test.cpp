// The CPU rasterizer (app/export/cpu_raster.h), the oracle for the GLSL path: coverage by pixel
// centres, GL's edge rule mirrored into DC, the depth test, and the colour conversion.
#include "app/export/cpu_raster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pipeline/pipeline.h"
#include "tests/support/test_util.h"

namespace vplab {
namespace {

const Vec3 kBackground{0, 0, 0};
const Rgba kBackgroundRgba{0, 0, 0, 255};
const Vec3 kRed{1, 0, 0}, kBlue{0, 0, 1};

/// A parallel camera whose window is the device: WC (x, y, z) lands at DC (x, H − y, z), exactly for
/// the dyadic values the tests use (the window scales by 1/W and W, the depth range is [0, 1]), so
/// the tests can place polygons directly in DC (docs/conventions.md stages 3 and 5).
Camera pixelCamera(int width, int height) {
  Camera c;
  c.vrp = {0, 0, 0};
  c.prp = {0, 0, 5};
  c.vup = {0, 1, 0};
  c.window = {0, double(width), 0, double(height)};
  c.front = 1;
  c.back = 0;
  c.projection = Projection::parallel;
  return c;
}

/// A polygon object given by its DC vertices (x right, y down, z_dc) on a device `height` pixels high.
SceneObject dcPolygon(const std::string& name, int height, const std::vector<Vec3>& dc, const Vec3& color) {
  std::vector<Vec3> wc;
  for (const Vec3& p : dc) wc.push_back({p.x, height - p.y, p.z});
  SceneObject o = test::polygonObject(name, wc);
  o.color = color;
  return o;
}

/// The axis-aligned rectangle [x0, x1] × [y0, y1] in DC at depth z, listed clockwise on screen.
SceneObject dcRect(const std::string& name, int height, double x0, double y0, double x1, double y1, double z,
                   const Vec3& color) {
  return dcPolygon(name, height, {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, color);
}

Scene dcScene(int width, int height, std::vector<SceneObject> objects) {
  Scene s = test::sceneWith(pixelCamera(width, height), std::move(objects));
  s.device = {width, height};
  s.background = kBackground;
  return s;
}

Image render(const Scene& scene) {
  return rasterizeClippedPolygons(runPipeline(scene), scene.background, scene.device.width,
                                  scene.device.height);
}

/// The image as rows of '#' (not the background) and '.' (the background), top row first, so a
/// failing comparison prints a picture.
std::vector<std::string> coverage(const Image& image) {
  std::vector<std::string> rows;
  for (int y = 0; y < image.height; ++y) {
    std::string row;
    for (int x = 0; x < image.width; ++x) row += image.at(x, y) == kBackgroundRgba ? '.' : '#';
    rows.push_back(row);
  }
  return rows;
}

size_t coveredCount(const Image& image) {
  size_t n = 0;
  for (const Rgba& p : image.pixels) n += p != kBackgroundRgba;
  return n;
}

TEST(CpuRaster, TestCameraMapsDcPolygonsOntoDcExactly) {
  const std::vector<Vec3> dc = {{0.5, 0.5, 0.25}, {7.75, 1.5, 0.5}, {3.5, 6.25, 1}};
  const PipelineRun run = runPipeline(dcScene(8, 8, {dcPolygon("t", 8, dc, kRed)}));
  ASSERT_EQ(run.objects.size(), 1u);
  const ObjectRun& o = run.objects[0];
  ASSERT_EQ(o.clippedFace(0).size(), 3u);
  for (uint32_t i = 0; i < 3; ++i) EXPECT_EQ(o.clippedDc(o.clippedFace(0)[i]), dc[i]) << i;
}

TEST(CpuRaster, EmptySceneGivesTheBackground) {
  Scene scene = dcScene(5, 3, {});
  scene.background = {0.12, 0.12, 0.14};  // Scene's default: 30.6, 30.6, 35.7
  const Image image = render(scene);
  ASSERT_EQ(image.width, 5);
  ASSERT_EQ(image.height, 3);
  for (const Rgba& p : image.pixels) EXPECT_EQ(p, (Rgba{31, 31, 36, 255}));
}

// Centres x + 0.5 in [1.2, 4.7] and y + 0.5 in [2.3, 5.1]: columns 1..4, rows 2..4. No centre lies
// on an edge, so no tie rule is involved.
TEST(CpuRaster, RectangleFillsThePixelsWhoseCentresItContains) {
  const Image image = render(dcScene(8, 8, {dcRect("r", 8, 1.2, 2.3, 4.7, 5.1, 0.5, kRed)}));
  // clang-format off
  const std::vector<std::string> expected = {
      "........",
      "........",
      ".####...",
      ".####...",
      ".####...",
      "........",
      "........",
      "........",
  };
  // clang-format on
  EXPECT_EQ(coverage(image), expected);
  EXPECT_EQ(image.at(1, 2), (Rgba{255, 0, 0, 255}));
}

// Every edge runs through pixel centres. GL (llvmpipe) covers a centre on the edge nearest its
// window origin (bottom left, y up); mirrored into DC that is a bottom-left rule: the left edge
// x = 0.5 and the bottom edge y = 3.5 own their centres, the right edge x = 3.5 and the top edge
// y = 0.5 do not. llvmpipe drew the same square in GL window coordinates as GL rows 0..2 and
// columns 0..2, which are DC rows H − 3 .. H − 1: the rows touching the bottom edge.
TEST(CpuRaster, CentresOnEdgesFollowGlsRuleMirroredIntoDc) {
  const Image image = render(dcScene(6, 6, {dcRect("r", 6, 0.5, 0.5, 3.5, 3.5, 0.5, kRed)}));
  // clang-format off
  const std::vector<std::string> expected = {
      "......",
      "###...",
      "###...",
      "###...",
      "......",
      "......",
  };
  // clang-format on
  EXPECT_EQ(coverage(image), expected);
}

/// How many of the given polygons (each rendered alone) cover each pixel.
std::vector<int> coverCounts(int width, int height, const std::vector<std::vector<Vec3>>& polygons) {
  std::vector<int> counts(size_t(width) * size_t(height), 0);
  for (const std::vector<Vec3>& polygon : polygons) {
    const Image image = render(dcScene(width, height, {dcPolygon("p", height, polygon, kRed)}));
    for (size_t i = 0; i < counts.size(); ++i) counts[i] += image.pixels[i] != kBackgroundRgba;
  }
  return counts;
}

std::vector<int> coverCounts(const Image& image) {
  std::vector<int> counts;
  for (const Rgba& p : image.pixels) counts.push_back(p != kBackgroundRgba);
  return counts;
}

// The square [0.5, 8.5]² cut along either diagonal: each diagonal passes through 8 centres. The two
// halves together cover each pixel of the whole square exactly once, for both cuts and both
// windings of the halves.
TEST(CpuRaster, TwoTrianglesSharingAnEdgeCoverEachPixelExactlyOnce) {
  const Vec3 a{0.5, 0.5, 0.5}, b{8.5, 0.5, 0.5}, c{8.5, 8.5, 0.5}, d{0.5, 8.5, 0.5};
  const std::vector<int> whole =
      coverCounts(render(dcScene(10, 10, {dcPolygon("q", 10, {a, b, c, d}, kRed)})));
  EXPECT_EQ(std::count(whole.begin(), whole.end(), 1), 64);
  const std::vector<std::vector<std::vector<Vec3>>> cuts = {
      {{a, b, c}, {a, c, d}}, {{a, b, d}, {b, c, d}}, {{c, b, a}, {a, c, d}}, {{b, a, d}, {d, c, b}}};
  for (size_t k = 0; k < cuts.size(); ++k) EXPECT_EQ(coverCounts(10, 10, cuts[k]), whole) << "cut " << k;
}

/// Twice the signed area of (a, b, p) in DC. The polygons below are listed with increasing angle
/// measured in DC's axes (clockwise on screen), so it is positive inside them.
double cross(const Vec3& a, const Vec3& b, double px, double py) {
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

/// Whether the centre is strictly inside (+1), strictly outside (−1) or within `margin` of the
/// boundary (0) of a convex polygon listed with increasing angle (all crosses positive inside).
int sideOfConvex(const std::vector<Vec3>& rim, double px, double py, double margin) {
  int side = 1;
  for (size_t i = 0; i < rim.size(); ++i) {
    const Vec3& a = rim[i];
    const Vec3& b = rim[(i + 1) % rim.size()];
    const double e = cross(a, b, px, py) / std::hypot(b.x - a.x, b.y - a.y);  // distance to the line
    if (e < -margin) return -1;
    if (e <= margin) side = 0;
  }
  return side;
}

/// The pinwheel of a convex polygon around an inner point: triangles (centre, rim i, rim i + 1).
std::vector<std::vector<Vec3>> pinwheel(const Vec3& centre, const std::vector<Vec3>& rim) {
  std::vector<std::vector<Vec3>> triangles;
  for (size_t i = 0; i < rim.size(); ++i) triangles.push_back({centre, rim[i], rim[(i + 1) % rim.size()]});
  return triangles;
}

/// Checks that the triangles of a pinwheel cover each pixel at most once, every centre strictly
/// inside the rim exactly once and none strictly outside; and that together they cover the same
/// pixels as the rim as one polygon (fanned from its first vertex: other diagonals, same pixels).
void expectWatertight(int size, const Vec3& centre, const std::vector<Vec3>& rim, const std::string& what) {
  const std::vector<int> counts = coverCounts(size, size, pinwheel(centre, rim));
  const std::vector<int> whole =
      coverCounts(render(dcScene(size, size, {dcPolygon("rim", size, rim, kRed)})));
  EXPECT_EQ(counts, whole) << what;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const int count = counts[size_t(y) * size_t(size) + size_t(x)];
      const int side = sideOfConvex(rim, x + 0.5, y + 0.5, 1e-9);
      EXPECT_LE(count, 1) << what << " at " << x << ", " << y;
      if (side != 0) {  // strictly inside: once; strictly outside: never
        EXPECT_EQ(count, side > 0 ? 1 : 0) << what << " at " << x << ", " << y;
      }
    }
  }
}

// An octagon around a pixel centre: the spokes run horizontally, vertically and diagonally through
// pixel centres, and the slanted rim edges (slope 2) through centres too, so every kind of tie
// occurs: centres on a vertex shared by 8 triangles, on edges in all 8 directions.
TEST(CpuRaster, PinwheelAroundAPixelCentreCoversEachPixelExactlyOnce) {
  const Vec3 c{8.5, 8.5, 0.5};
  std::vector<Vec3> rim;
  const double offsets[8][2] = {{6, 0}, {4, 4}, {0, 6}, {-4, 4}, {-6, 0}, {-4, -4}, {0, -6}, {4, -4}};
  for (const auto& o : offsets) rim.push_back({c.x + o[0], c.y + o[1], 0.5});
  expectWatertight(18, c, rim, "octagon");
}

// Random convex polygons with vertices on the half-pixel grid (edges through many centres, many
// exact ties) around an inner grid point, at random depths.
TEST(CpuRaster, RandomPinwheelsCoverEachPixelExactlyOnce) {
  test::Rng rng(20240611);
  const int size = 20;
  int tested = 0;
  while (tested < 40) {
    const int n = rng.integer(3, 8);
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(rng.uniform(0, 2 * kPi));
    std::sort(angles.begin(), angles.end());
    const double cx = rng.uniform(6, 14), cy = rng.uniform(6, 14);
    std::vector<Vec3> rim;
    for (double angle : angles) {  // increasing angle in DC's axes: positive crosses inside
      const double r = rng.uniform(2, 9);
      rim.push_back({std::round(2 * (cx + r * std::cos(angle))) / 2,
                     std::round(2 * (cy + r * std::sin(angle))) / 2, rng.uniform(0.1, 0.9)});
    }
    // Snapping may have broken convexity or made the inner point fall on the rim: draw again.
    bool convex = true;
    for (size_t i = 0; i < rim.size(); ++i) {
      const Vec3& next = rim[(i + 2) % rim.size()];
      convex = convex && cross(rim[i], rim[(i + 1) % rim.size()], next.x, next.y) > 0;
    }
    const Vec3 centre{std::round(2 * cx) / 2, std::round(2 * cy) / 2, 0.5};
    if (!convex || sideOfConvex(rim, centre.x, centre.y, 1e-9) <= 0) continue;
    expectWatertight(size, centre, rim, "polygon " + std::to_string(tested));
    ++tested;
  }
}

// z_dc is larger in front (1 at the front plane): red at 0.75 hides blue at 0.25 whichever is drawn
// first.
TEST(CpuRaster, NearerPolygonWinsWhicheverIsDrawnFirst) {
  const SceneObject nearRed = dcRect("near", 8, 1, 1, 5, 5, 0.75, kRed);
  const SceneObject farBlue = dcRect("far", 8, 3, 3, 7, 7, 0.25, kBlue);
  for (const bool nearFirst : {true, false}) {
    const Image image =
        render(dcScene(8, 8, nearFirst ? std::vector{nearRed, farBlue} : std::vector{farBlue, nearRed}));
    EXPECT_EQ(image.at(4, 4), (Rgba{255, 0, 0, 255})) << nearFirst;  // the overlap
    EXPECT_EQ(image.at(6, 6), (Rgba{0, 0, 255, 255})) << nearFirst;  // blue only
    EXPECT_EQ(image.at(1, 1), (Rgba{255, 0, 0, 255})) << nearFirst;  // red only
  }
}

// A slope from z = 0.1 at x = 0 to z = 0.9 at x = 16 (z = 0.1 + 0.05·x) through a flat square at
// z = 0.5: the slope is in front exactly from the column whose centre passes x = 8.
TEST(CpuRaster, DepthIsInterpolatedLinearlyAcrossThePolygon) {
  const SceneObject flat = dcRect("flat", 4, 0, 0, 16, 4, 0.5, kBlue);
  const SceneObject slope =
      dcPolygon("slope", 4, {{0, 0, 0.1}, {16, 0, 0.9}, {16, 4, 0.9}, {0, 4, 0.1}}, kRed);
  const Image image = render(dcScene(16, 4, {flat, slope}));
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 16; ++x)
      EXPECT_EQ(image.at(x, y), x < 8 ? (Rgba{0, 0, 255, 255}) : (Rgba{255, 0, 0, 255})) << x;
}

// GL_LESS on window depth: a fragment must be strictly nearer than the stored one, so of two
// coplanar polygons the first drawn stays.
TEST(CpuRaster, EqualDepthKeepsTheFirstPolygonLikeGlLess) {
  const Image image = render(dcScene(
      8, 8, {dcRect("first", 8, 0, 0, 6, 6, 0.5, kRed), dcRect("second", 8, 2, 2, 8, 8, 0.5, kBlue)}));
  EXPECT_EQ(image.at(3, 3), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(image.at(7, 7), (Rgba{0, 0, 255, 255}));
}

// The back plane is z_dc = 0, GL's window depth 1 − 0 = 1, the value the depth buffer is cleared
// to: GL_LESS fails there, so GL draws nothing, and neither does the oracle. A hair in front of it
// is drawn.
TEST(CpuRaster, PolygonOnTheBackPlaneIsNotDrawnLikeGl) {
  EXPECT_EQ(coveredCount(render(dcScene(8, 8, {dcRect("back", 8, 0, 0, 8, 8, 0, kRed)}))), 0u);
  EXPECT_EQ(coveredCount(render(dcScene(8, 8, {dcRect("near back", 8, 0, 0, 8, 8, 1e-6, kRed)}))), 64u);
  // The front plane is inside the cube (docs/conventions.md stage 4: on a plane counts as inside).
  EXPECT_EQ(coveredCount(render(dcScene(8, 8, {dcRect("front", 8, 0, 0, 8, 8, 1, kRed)}))), 64u);
}

TEST(CpuRaster, PolygonsFacingAwayAreFilledToo) {
  const std::vector<Vec3> square = {{1.2, 2.3, 0.5}, {4.7, 2.3, 0.5}, {4.7, 5.1, 0.5}, {1.2, 5.1, 0.5}};
  const std::vector<Vec3> reversed(square.rbegin(), square.rend());
  const Image front = render(dcScene(8, 8, {dcPolygon("front", 8, square, kRed)}));
  const Image back = render(dcScene(8, 8, {dcPolygon("back", 8, reversed, kRed)}));
  EXPECT_EQ(coveredCount(front), 12u);
  EXPECT_EQ(coverage(back), coverage(front));
  // Also with ties: the reversed square of the edge-rule test covers the same pixels.
  const Image tieFront = render(dcScene(6, 6, {dcRect("r", 6, 0.5, 0.5, 3.5, 3.5, 0.5, kRed)}));
  const Image tieBack = render(dcScene(
      6, 6, {dcPolygon("r", 6, {{0.5, 3.5, 0.5}, {3.5, 3.5, 0.5}, {3.5, 0.5, 0.5}, {0.5, 0.5, 0.5}}, kRed)}));
  EXPECT_EQ(coverage(tieBack), coverage(tieFront));
}

// round(c · 255) as llvmpipe computes it (checked against llvmpipe): ties, and values within float
// precision of one, round to even. 0.3 · 255 = 76.5 → 76, 0.7 · 255 = 178.5 → 178,
// 0.9 · 255 = 229.5 → 230, 0.5 · 255 = 127.5 → 128, 0.1 · 255 = 25.5 → 26.
TEST(CpuRaster, ColoursConvertAsGlConvertsFloatsToUnorm8) {
  EXPECT_EQ(unorm8(0), 0);
  EXPECT_EQ(unorm8(1), 255);
  EXPECT_EQ(unorm8(0.2), 51);
  EXPECT_EQ(unorm8(0.3), 76);
  EXPECT_EQ(unorm8(0.7), 178);
  EXPECT_EQ(unorm8(0.9), 230);
  EXPECT_EQ(unorm8(0.5), 128);
  EXPECT_EQ(unorm8(0.1), 26);
  EXPECT_EQ(unorm8(0.12), 31);      // 30.6
  EXPECT_EQ(unorm8(0.5 / 255), 0);  // 0.5: a tie, to even
  EXPECT_EQ(unorm8(1.5 / 255), 2);  // 1.5: a tie, to even
  EXPECT_EQ(unorm8(-0.2), 0);       // clamped
  EXPECT_EQ(unorm8(1.7), 255);
  EXPECT_EQ(unorm8(std::nan("")), 0);
  for (int k = 0; k <= 255; ++k) EXPECT_EQ(unorm8(k / 255.0), k) << k;

  const Image image = render(dcScene(4, 4, {dcRect("c", 4, 0, 0, 4, 4, 0.5, {0.3, 0.7, 0.9})}));
  EXPECT_EQ(image.at(2, 2), (Rgba{76, 178, 230, 255}));
  EXPECT_EQ(rgbaFromColor({0.5, 0.2, 1.0}), (Rgba{128, 51, 255, 255}));
}

TEST(CpuRaster, DegeneratePolygonsAreSkipped) {
  const Image image = render(dcScene(
      8, 8,
      {
          dcPolygon("collinear", 8, {{0.5, 0.5, 0.5}, {4.5, 4.5, 0.5}, {7.5, 7.5, 0.5}}, kRed),
          dcPolygon("point", 8, {{2.5, 2.5, 0.5}, {2.5, 2.5, 0.5}, {2.5, 2.5, 0.5}}, kRed),
          dcPolygon("horizontal", 8, {{0, 3.5, 0.5}, {8, 3.5, 0.5}, {4, 3.5, 0.5}, {1, 3.5, 0.5}}, kRed),
      }));
  EXPECT_EQ(coveredCount(image), 0u);
  // A quad with a repeated vertex is a triangle: its degenerate fan triangle is skipped, the other
  // one drawn.
  const Image quad =
      render(dcScene(8, 8, {dcPolygon("q", 8, {{0, 0, 0.5}, {8, 0, 0.5}, {8, 0, 0.5}, {0, 8, 0.5}}, kRed)}));
  EXPECT_EQ(coveredCount(quad), 28u);  // row y covers the 7 − y centres with x + y + 1 < 8
}

// The square reaches out of the window on the left and top: the CPU pipeline clips it (creating
// vertices on the left and top planes) and only the centres in x + 0.5 ≤ 4.2, y + 0.5 ≤ 3.7 remain.
TEST(CpuRaster, ClippedPolygonsFillTheirVisiblePart) {
  Scene scene = dcScene(8, 8, {dcRect("r", 8, -5, -5, 4.2, 3.7, 0.5, kRed)});
  const PipelineRun run = runPipeline(scene);
  ASSERT_EQ(run.objects[0].fate[0], Fate::clipped);
  const Image image = rasterizeClippedPolygons(run, scene.background, 8, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      EXPECT_EQ(image.at(x, y) != kBackgroundRgba, x <= 3 && y <= 3) << x << ", " << y;
}

TEST(CpuRaster, ImageSmallerOrLargerThanTheDeviceCutsOffOrLeavesBackground) {
  const Scene scene = dcScene(8, 8, {dcRect("r", 8, 2, 2, 8, 8, 0.5, kRed)});
  const PipelineRun run = runPipeline(scene);
  const Image small = rasterizeClippedPolygons(run, scene.background, 4, 3);
  EXPECT_EQ(coveredCount(small), 2u);  // columns 2, 3 of row 2
  const Image large = rasterizeClippedPolygons(run, scene.background, 12, 12);
  EXPECT_EQ(coveredCount(large), 36u);
  EXPECT_TRUE(rasterizeClippedPolygons(run, scene.background, 0, 0).empty());
}

// GL_SUBPIXEL_BITS = 8 (llvmpipe): a left edge 1/1024 pixel right of a column of centres snaps onto
// them and, being a left edge, owns them; unsnapped, or on a grid fine enough to hold the edge, the
// centres stay outside.
TEST(CpuRaster, SubpixelSnappingRoundsVerticesToTheGrid) {
  const Scene scene = dcScene(4, 4, {dcRect("r", 4, 0.5 + 1.0 / 1024, 0, 4, 4, 0.5, kRed)});
  const PipelineRun run = runPipeline(scene);
  EXPECT_EQ(coveredCount(rasterizeClippedPolygons(run, scene.background, 4, 4)), 12u);
  EXPECT_EQ(coveredCount(rasterizeClippedPolygons(run, scene.background, 4, 4, 8)), 16u);
  EXPECT_EQ(coveredCount(rasterizeClippedPolygons(run, scene.background, 4, 4, 10)), 12u);
}

// Perspective, with docs/conventions.md's check camera on 320 × 240: a WC point (x, y, 0) lands at
// DC (160 + 160·x, 120 − 160·y). For each pixel, a ray from the eye through its centre decides
// independently which of two polygons it meets first: a square in the view plane and a rectangle
// tilted through it (z = x / 0.6). Centres within 1e-6 of an edge or with a near tie are left out.
TEST(CpuRaster, PerspectiveDepthOrderMatchesRayCasting) {
  const Camera camera = test::checkCamera();
  std::vector<SceneObject> objects = {
      test::polygonObject("flat", {{-0.6, -0.6, 0}, {0.6, -0.6, 0}, {0.6, 0.6, 0}, {-0.6, 0.6, 0}}),
      test::polygonObject("tilted", {{-0.6, -0.3, -1}, {0.6, -0.3, 1}, {0.6, 0.3, 1}, {-0.6, 0.3, -1}})};
  objects[0].color = kBlue;
  objects[1].color = kRed;
  Scene scene = test::sceneWith(camera, objects);
  scene.background = kBackground;
  const Image image = render(scene);

  const Vec3 eye = camera.prp;
  int checked = 0;
  for (int py = 0; py < 240; ++py) {
    for (int px = 0; px < 320; ++px) {
      const Vec3 onViewPlane{-1 + 2 * (px + 0.5) / 320, 0.75 - 1.5 * (py + 0.5) / 240, 0};
      const Vec3 dir = onViewPlane - eye;
      const double tFlat = (0 - eye.z) / dir.z;  // the plane z = 0
      const Vec3 hitFlat = eye + tFlat * dir;
      const double tTilted = (0.6 * eye.z - eye.x) / (dir.x - 0.6 * dir.z);  // the plane x = 0.6·z
      const Vec3 hitTilted = eye + tTilted * dir;
      const double m = 1e-6;
      const double flatIn = std::min(0.6 - std::abs(hitFlat.x), 0.6 - std::abs(hitFlat.y));
      const double tiltedIn = std::min(0.6 - std::abs(hitTilted.x), 0.3 - std::abs(hitTilted.y));
      if (std::abs(flatIn) < m || std::abs(tiltedIn) < m || std::abs(tFlat - tTilted) < 1e-9) continue;
      Rgba expected = kBackgroundRgba;
      if (flatIn > 0 && (tiltedIn < 0 || tFlat < tTilted)) expected = {0, 0, 255, 255};
      if (tiltedIn > 0 && (flatIn < 0 || tTilted < tFlat)) expected = {255, 0, 0, 255};
      EXPECT_EQ(image.at(px, py), expected) << px << ", " << py;
      ++checked;
    }
  }
  EXPECT_GT(checked, 76000);
  // The flat square's corners (±0.6, ±0.6, 0) land at x = 64 .. 256, y = 24 .. 216 (check values).
  EXPECT_EQ(image.at(64, 24), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(image.at(63, 24), kBackgroundRgba);
  EXPECT_EQ(image.at(255, 215), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(image.at(256, 215), kBackgroundRgba);
}

}  // namespace
}  // namespace vplab
