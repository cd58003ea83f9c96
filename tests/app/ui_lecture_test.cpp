// The viewer as a lecture uses it (issue 11): what the panels show is right side up, says what the
// geometry says, applies typed values once, and reads on a projector. Drives the headless viewer
// (app/ui/headless_viewer.h) with synthetic input, like ui_test.cpp.
#include "app/image.h"
#include "app/render/cpu_raster.h"
#include "app/ui/headless_viewer.h"
#include "app/ui/keys.h"
#include "tests/app/gl_test_support.h"

#include <gtest/gtest.h>

#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace vplab {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

std::unique_ptr<HeadlessViewer> makeViewer(Scene scene = defaultScene(), float scale = 1.f) {
  auto v = std::make_unique<HeadlessViewer>(*test::egl().context, std::move(scene), kWidth, kHeight, scale);
  v->frames(3);
  return v;
}

Image cropRect(const Image& image, const ImVec4& r) {
  return test::crop(image, int(std::lround(r.x)), int(std::lround(r.y)), int(r.z), int(r.w));
}

/// `image` resampled (nearest pixel) to width × height, upside down when `flip`.
Image resampled(const Image& image, int width, int height, bool flip) {
  Image out(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int sx = std::min(image.width - 1, int((x + 0.5) * image.width / width));
      int sy = std::min(image.height - 1, int((y + 0.5) * image.height / height));
      if (flip) sy = image.height - 1 - sy;
      out.at(x, y) = image.at(sx, sy);
    }
  return out;
}

/// The mean absolute difference of two images of the same size, per channel (0 … 255).
double meanDifference(const Image& a, const Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  double sum = 0;
  for (size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i)
    sum += std::abs(a.pixels[i].r - b.pixels[i].r) + std::abs(a.pixels[i].g - b.pixels[i].g) +
           std::abs(a.pixels[i].b - b.pixels[i].b);
  return sum / (3.0 * double(a.pixels.size()));
}

// ---------------------------------------------------------------- item 1: the divide-first comparison

// The "wrong" picture beside the camera view is the CPU's divide-first polygons (cpu_raster) as
// they are: the displayed panel matches them upright (a mean difference of a few levels from the
// scaling and the caption) and not upside down.
TEST(UiLecture, DivideFirstComparisonIsUpright) {
  auto v = makeViewer();
  v->key(keys::kC);
  v->key(keys::kC);
  ASSERT_EQ(v->state().pipeline.strategy, ClipStrategy::divideFirst);
  v->frames(2);
  const ImVec4 r = v->state().rects.at("view.divideFirst");
  const Image shown = cropRect(v->image(), r);
  const Device& d = v->state().doc.shown().device;
  const Image cpu = rasterizeClippedPolygons(v->state().run, v->state().doc.shown().background, d.width, d.height);
  const double upright = meanDifference(shown, resampled(cpu, shown.width, shown.height, false));
  const double flipped = meanDifference(shown, resampled(cpu, shown.width, shown.height, true));
  EXPECT_LT(upright, 12.0);
  EXPECT_LT(upright * 3, flipped) << "upright " << upright << ", flipped " << flipped;
}

// ---------------------------------------------------------------- item 5: `vplab render --view ui`

// The command line's ui view with --strategy divide-first is the viewer after the user chose that
// strategy (key C twice): the same pixels, the comparison included.
TEST(UiLecture, RenderUiShowsWhatTheViewerShowsForTheSameOptions) {
  const std::filesystem::path out = test::outputDir() / "render-ui-divide-first.png";
  const std::string command = std::string(VPLAB_EXE) + " render --view ui --strategy divide-first --out " + out.string();
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Image cli = readPng(out);
  auto v = makeViewer();
  const Image before = v->image();
  v->key(keys::kC);
  v->key(keys::kC);
  v->frames(3);
  const Image viewer = v->image();
  ASSERT_EQ(cli.width, viewer.width);
  EXPECT_GT(test::differingPixels(before, viewer), 1000u) << "the strategy changes the window";
  EXPECT_LT(meanDifference(cli, viewer), 0.5);
}

}  // namespace
}  // namespace vplab
