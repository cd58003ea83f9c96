// The views drawn on a render thread (app/render/view_worker.h, docs/lecturers.md "The viewer"): while a view
// of a large mesh is being drawn again, the window keeps producing frames, each short, with a busy mark
// on the view, and then shows the same image a synchronous viewer draws.
#include "app/ui/headless_viewer.h"
#include "app/gl/texture_io.h"
#include "app/render/view_worker.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

namespace vplab {
namespace {

constexpr int kWidth = 1280, kHeight = 720;
bool anyBusy(const Viewer& v) {
  for (ViewKind k : {ViewKind::world, ViewKind::camera, ViewKind::npc})
    if (v.images().busy(k)) return true;
  return false;
}

double seconds(std::chrono::steady_clock::duration d) { return std::chrono::duration<double>(d).count(); }

/// Draws frames (as the window does: one each time it wakes) until no view is busy; returns how many
/// were busy and the longest frame.
struct Frames {
  int busy = 0, total = 0;
  double longest = 0;
  std::vector<double> times;
  double median() {
    std::sort(times.begin(), times.end());
    return times.empty() ? 0 : times[times.size() / 2];
  }
};
Frames untilIdle(HeadlessViewer& v, double timeout) {
  Frames f;
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const auto t0 = std::chrono::steady_clock::now();
    v.frame();
    f.longest = std::max(f.longest, seconds(std::chrono::steady_clock::now() - t0));
    f.times.push_back(seconds(std::chrono::steady_clock::now() - t0));
    ++f.total;
    if (!anyBusy(v.viewer())) return f;
    ++f.busy;
    if (seconds(std::chrono::steady_clock::now() - start) > timeout) {
      ADD_FAILURE() << "the views were still busy after " << timeout << " s";
      return f;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void setStyle(HeadlessViewer& v, Style style) {
  DisplaySettings& f = v.state().display;
  f.camera.style = f.world.style = f.npc.style = style;
}

TEST(ViewWorker, TheWindowKeepsDrawingWhileAViewIsRedrawnThenShowsItsNewImage) {
  GlContext& context = *test::egl().context;
  const Scene scene = test::sphereScene(512);

  // The synchronous viewer (headless, as before the render thread): the frame that changes the
  // style waits for the hidden-line views.
  HeadlessViewer sync(context, scene, kWidth, kHeight);
  sync.frames(3);
  setStyle(sync, Style::hiddenLine);
  const auto t0 = std::chrono::steady_clock::now();
  sync.frame();
  const double blocking = seconds(std::chrono::steady_clock::now() - t0);
  sync.frames(2);
  EXPECT_FALSE(anyBusy(sync.viewer()));
  const Image expected = sync.image();

  HeadlessViewer async(context, scene, kWidth, kHeight);
  async.viewer().images().useWorker(context.createShared(), {});
  untilIdle(async, 120);
  const unsigned drawnBefore = async.viewer().images().drawn();
  setStyle(async, Style::hiddenLine);
  Frames f = untilIdle(async, 120);
  // The views take `blocking` seconds; meanwhile the window draws frames of a few ms (it waits up
  // to 30 ms only in the frame that asked for the images): the median is far below 50 ms. On Mesa's
  // llvmpipe both contexts share one rasterizer, whose queue of scenes makes a window frame now and
  // then wait for one of the render thread's draw calls (measured: at most ~0.4 of the whole
  // redraw); no frame may wait for the whole redraw (3/4 of it, for a machine shared with others).
  std::printf(
      "synchronous frame %.0f ms; with the render thread: %d frames while busy, median %.1f ms, "
      "longest %.0f ms\n",
      blocking * 1e3, f.busy, f.median() * 1e3, f.longest * 1e3);
  EXPECT_GE(f.busy, 5) << "the views finished too fast to show the window drawing meanwhile";
  EXPECT_LT(f.median(), 0.05);
  EXPECT_LT(f.longest, blocking * 0.75) << "a frame waited for a view";
  EXPECT_GT(async.viewer().images().drawn(), drawnBefore);
  async.frames(2);  // the busy mark gone, ImGui settled
  const Image shown = async.image();

  ASSERT_EQ(shown.width, expected.width);
  size_t differ = 0;
  for (size_t i = 0; i < shown.pixels.size(); ++i) differ += shown.pixels[i] != expected.pixels[i];
  if (differ) {
    writePng(shown, (test::outputDir() / "view_worker_async.png").string());
    writePng(expected, (test::outputDir() / "view_worker_sync.png").string());
  }
  EXPECT_EQ(differ, 0u) << "the render thread's image differs from the synchronous one";
}

// File > Export reads the view's texture as shown (it may come from the render thread's context):
// the rows come back in the image's order, every pixel as uploaded.
TEST(ViewWorker, ReadingAViewTextureGivesItsImage) {
  GlContext& context = *test::egl().context;
  Image image(7, 5);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) image.at(x, y) = Rgba{uint8_t(30 * x), uint8_t(40 * y), 200, 255};
  gl::Texture texture;
  const GLuint id = uploadImageTo(context.gl(), texture, image);
  const Image back = readTexture(context.gl(), id);
  ASSERT_EQ(back.width, image.width);
  ASSERT_EQ(back.height, image.height);
  EXPECT_TRUE(back.pixels == image.pixels);
}

}  // namespace
}  // namespace vplab
