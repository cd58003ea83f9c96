// One render request for every way of asking for a picture (app/views/render_request.h): its size
// and frame settings, and that both consumers, renderImage (PNG) and svgOfRequest (SVG), draw what
// it says: the viewer's settings when it carries them (its export), its scale (lecture mode), and
// `vplab render --ui-scale` for the views as the library draws them.
#include "app/export/svg.h"
#include "app/render/headless.h"
#include "app/views/render_request.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace vplab {
namespace {

TEST(RenderRequest, SizeIsTheDevicesUnlessGiven) {
  const Scene scene = defaultScene();
  const PixelSize device = pixelSizeOf(RenderRequest{}, scene);
  EXPECT_EQ(device.width, scene.device.width);
  EXPECT_EQ(device.height, scene.device.height);
  RenderRequest r;
  r.width = 200;
  r.height = 150;
  EXPECT_EQ(pixelSizeOf(r, scene).width, 200);
  EXPECT_EQ(pixelSizeOf(r, scene).height, 150);
}

TEST(RenderRequest, FrameSettingsAreTheViewersWhenGivenElseRendersOwn) {
  const Scene scene = defaultScene();
  RenderRequest r;
  r.style = Style::hiddenLine;
  r.width = 400;
  r.height = 200;
  r.morphT = 2.5;
  DisplaySettings expected = displaySettingsFor(scene, Style::hiddenLine, 2.0);  // the request's aspect ratio
  expected.morphing.t = 2.5;
  EXPECT_EQ(displaySettingsOf(r, scene), expected);
  DisplaySettings viewer;
  viewer.world.style = Style::wire;
  viewer.overlays.labels = false;
  r.display = viewer;
  EXPECT_EQ(displaySettingsOf(r, scene), viewer);  // style and morph t are then the frame's
}

// renderImage draws the request's frame settings and scale exactly as the renderer draws them
// itself, and a later request at scale 1 is drawn at scale 1 again.
TEST(RenderRequest, RenderImageDrawsTheRequestsSettingsAndScale) {
  const Scene scene = defaultScene();
  ViewRenderer& renderer = *test::egl().renderer;
  RenderRequest r;
  r.view = ViewKind::world;
  r.style = Style::wire;
  r.width = 320;
  r.height = 240;
  const Image plain = renderImage(renderer, scene, r);

  RenderRequest noLabels = r;
  noLabels.display = displaySettingsOf(r, scene);
  noLabels.display->overlays.labels = false;
  const Image withoutLabels = renderImage(renderer, scene, noLabels);
  EXPECT_GT(test::differingPixels(plain, withoutLabels), 100u) << "the labels are left out";
  const PipelineRun run = runPipeline(scene, r.pipeline);
  EXPECT_EQ(test::differingPixels(withoutLabels, renderer.render(r.view, scene, run, *noLabels.display, {}, 320, 240)), 0u);

  RenderRequest large = r;
  large.scale = 2;
  const Image scaled = renderImage(renderer, scene, large);
  EXPECT_EQ(renderer.scale(), 2.f);
  EXPECT_GT(test::differingPixels(plain, scaled), 100u) << "larger text, lines and markers";
  {
    ViewRenderer atTwo(*test::egl().context, 2.f);
    EXPECT_EQ(test::differingPixels(scaled, atTwo.render(r.view, scene, run, displaySettingsOf(r, scene), {}, 320, 240)), 0u);
  }
  EXPECT_EQ(test::differingPixels(renderImage(renderer, scene, r), plain), 0u) << "back at scale 1";
  EXPECT_EQ(renderer.scale(), 1.f);
}

// svgOfRequest likewise: the SVG of the request is svgOfView of its run, settings, size and scale.
TEST(RenderRequest, SvgOfRequestDrawsTheRequestsSettingsAndScale) {
  const Scene scene = defaultScene();
  RenderRequest r;
  r.view = ViewKind::npc;
  r.style = Style::hiddenLine;
  r.width = 300;
  r.height = 200;
  r.scale = 1.5f;
  r.display = displaySettingsOf(r, scene);
  r.display->overlays.cube = false;
  r.display->npc.style = Style::wire;
  const PipelineRun run = runPipeline(scene, r.pipeline);
  const std::string svg = svgOfRequest(scene, r);
  EXPECT_EQ(svg, svgOfView(ViewKind::npc, scene, run, *r.display, {}, 300, 200, 1.5f));
  EXPECT_NE(svg, svgOfView(ViewKind::npc, scene, run, *r.display, {}, 300, 200, 1.f)) << "the scale counts";
  RenderRequest withoutFrame = r;
  withoutFrame.display.reset();
  EXPECT_NE(svg, svgOfRequest(scene, withoutFrame)) << "the frame settings count";
}

// `vplab render --ui-scale` scales the views (not only --view ui), as the request's scale does.
TEST(RenderRequest, CommandLineUiScaleScalesTheViews) {
  const std::filesystem::path out = test::outputDir() / "render-request-world-scale-2.png";
  const std::string command =
      std::string(VPLAB_EXE) + " render --view world --style wire --size 320x240 --ui-scale 2 --out " + out.string();
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  RenderRequest r;
  r.view = ViewKind::world;
  r.style = Style::wire;
  r.width = 320;
  r.height = 240;
  r.scale = 2;
  const Image library = renderImage(*test::egl().renderer, defaultScene(), r);
  EXPECT_EQ(test::differingPixels(readPng(out), library), 0u);
  r.scale = 1;
  EXPECT_GT(test::differingPixels(readPng(out), renderImage(*test::egl().renderer, defaultScene(), r)), 100u);
}

}  // namespace
}  // namespace vplab
