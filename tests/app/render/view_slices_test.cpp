// Views drawn in slices across frames (the page: no render thread; issue 24 item 3). A view drawn in
// many slices, with other views drawn between them, must be the view drawn whole, pixel for pixel: a
// slice's GL state is its own, the depth buffer and the polygon buffers carry over, and the world
// view's volume partition is the one made for its own draw. ViewImages shows a view's last complete
// image, busy, until the new one is finished, and never a half-drawn one.
#include "app/gl/render_target.h"
#include "app/gl/texture_io.h"
#include "app/render/view_images.h"
#include "app/views/render_request.h"
#include "pipeline/primitives.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

namespace vplab {
namespace {

// The cut sphere (test::cutSphereScene) beside the default scene's objects: meshes on both sides of
// the volume, clipped polygons, labels, overlays.
Scene cutSphereScene() { return test::cutSphereScene(/*keepObjects=*/true); }

Image drawWhole(ViewRenderer& renderer, ViewKind kind, const Scene& scene, const PipelineRun& run,
                const DisplaySettings& settings, int samples) {
  gl::RenderTarget target(renderer.context().gl());
  target.resize(400, 300, samples);
  switch (kind) {
    case ViewKind::world: renderer.drawWorld(scene, run, settings, {}, target); break;
    case ViewKind::npc: renderer.drawNpc(scene, run, settings, {}, target); break;
    case ViewKind::morph: renderer.drawMorph(scene, run, settings, {}, target); break;
    default: renderer.drawCamera(scene, run, settings, {}, target); break;
  }
  target.resolve();
  return target.read();
}

// `kind` drawn into a 400 × 300 target in slices of 1000 triangles, a mesh the renderer has not seen
// going to the GPU in chunks of 2048 corners (1024 edges): the picture, and the slices it took.
struct Sliced {
  Image image;
  int slices = 0;
};
Sliced drawInSlicesWithSmallChunks(ViewRenderer& renderer, ViewKind kind, const Scene& scene, const PipelineRun& run,
                                   const DisplaySettings& settings) {
  gl::RenderTarget target(renderer.context().gl());
  target.resize(400, 300, 1);
  renderer.setMeshChunkCorners(2048);
  ViewRenderer::Slices slices;
  renderer.startSlices(kind, scene, run, settings, {}, target, slices);
  Sliced out;
  for (bool done = false; !done; ++out.slices) {
    size_t triangles = 1000;
    done = renderer.drawSlice(slices, target, triangles);
    if (out.slices >= 10000) {
      ADD_FAILURE() << "the slices never end";
      break;
    }
  }
  renderer.setMeshChunkCorners(GpuMeshCache::kChunkCorners);
  out.image = target.read();
  return out;
}

// The pacing rule on made-up frame times (no clock): slow frames halve the slices down to the floor,
// fast ones let them grow by a quarter, frames between keep them.
TEST(SlicePacing, HalvesOnASlowFrameGrowsOnAFastOneAndKeepsBetween) {
  using P = SlicePacing;
  const double fast = P::kAimSeconds * 0.5, ok = (P::kAimSeconds + P::kMostSeconds) / 2, slow = P::kMostSeconds * 1.5;
  const P p{80000};
  EXPECT_EQ(p.after(slow).triangles, 40000u);
  EXPECT_EQ(p.after(ok).triangles, 80000u);
  EXPECT_EQ(p.after(fast).triangles, 100000u);

  P falling = p;
  for (int i = 0; i < 20; ++i) falling = falling.after(slow);
  EXPECT_EQ(falling.triangles, P::kMinTriangles);            // never under the floor...
  EXPECT_EQ(P{1000}.after(slow).triangles, 1000u);          // ...unless it started under it
  EXPECT_EQ(P{P::kMaxTriangles - 10}.after(fast).triangles, P::kMaxTriangles);  // capped
  // Fast frames grow it geometrically: from the floor to 10x in about 10 frames.
  P rising{P::kMinTriangles};
  int frames = 0;
  while (rising.triangles < 10 * P::kMinTriangles) rising = rising.after(fast), ++frames;
  EXPECT_GE(frames, 9);
  EXPECT_LE(frames, 12);

  // A slice whose own work took the frame too long is too large however fast the GPU was (a browser's
  // upload behind a busy GPU waits for it, issue 42); one of more than half the most grows no more.
  EXPECT_EQ(p.after(fast, P::kMostOwnSeconds * 1.5).triangles, 40000u);
  EXPECT_EQ(p.after(fast, P::kMostOwnSeconds * 0.75).triangles, 80000u);
  EXPECT_EQ(p.after(fast, P::kMostOwnSeconds * 0.25).triangles, 100000u);
}

TEST(ViewSlices, AViewDrawnInSlicesIsTheViewDrawnWholeWithOtherViewsBetween) {
  ViewRenderer& renderer = *test::egl().renderer;
  const Scene scene = cutSphereScene();
  const PipelineRun run = runPipeline(scene, {ClipStrategy::npc, false, true});
  for (Style style : {Style::shaded, Style::flat, Style::wire, Style::hiddenLine}) {
    DisplaySettings settings = displaySettingsFor(scene, style, 400.0 / 300.0);
    orbitBy(settings.world.orbit, 70, -15);
    settings.morphing.t = 2.5;
    for (ViewKind kind : {ViewKind::camera, ViewKind::world, ViewKind::npc, ViewKind::morph}) {
      for (int samples : {1, 4}) {
        const Image whole = drawWhole(renderer, kind, scene, run, settings, samples);
        ASSERT_GE(test::distinctColours(whole), 4u) << toString(kind);
        gl::RenderTarget target(renderer.context().gl());
        target.resize(400, 300, samples);
        ViewRenderer::Slices slices;
        renderer.startSlices(kind, scene, run, settings, {}, target, slices);
        // 1000 triangles a slice: the sphere alone takes dozens. Between two slices another view is
        // drawn whole (its own state, partition and polygon buffers), as the page draws its views.
        int count = 0;
        for (bool done = false; !done; ++count) {
          size_t triangles = 1000;
          done = renderer.drawSlice(slices, target, triangles);
          // A slice ends when its triangles run out, or before a clipped polygon whose fan does
          // not fit any more (polygons go whole: a quad cut by six planes has at most 10 corners,
          // 8 triangles), or a line, point or mesh edge (two).
          if (!done) {
            EXPECT_LT(triangles, 8u) << "a slice stopped before its triangles ran out";
          }
          drawWhole(renderer, kind == ViewKind::world ? ViewKind::npc : ViewKind::world, scene, run, settings, 1);
          ASSERT_LT(count, 10000) << "the slices never end";
        }
        target.resolve();
        // The camera and world views fill the sphere's 28 800 triangles (meshes), the NPC and morph
        // views its clipped polygons' 7 000 or so: dozens of slices, or 8. The wireframe styles draw
        // its 14 280 edges or their clipped parts as lines, two triangles each.
        EXPECT_GE(count, 6) << toString(kind) << ": drawn in " << count << " slices";
        EXPECT_EQ(test::differingPixels(whole, target.read()), 0u)
            << toString(kind) << ", " << toString(style) << ", " << samples << " samples, " << count << " slices";
      }
    }
  }
}

// A mesh the renderer has not seen goes to the GPU in slices too (the page: a million triangles'
// upload held one frame for a second), a chunk of consecutive faces at a time (GpuMeshCache), and the
// world view's volume partition is made in slices as well. With chunks of 2048 corners the world
// view's first slices upload the sphere's 14 160 triangles (at least 14 slices of 1000), the next
// partition and draw them (as many again), and the picture is the one drawn whole from another copy
// of the same mesh. (The camera view draws the CPU's clipped polygons, not the mesh.)
TEST(ViewSlices, ANewMeshIsUploadedAndPartitionedInSlices) {
  ViewRenderer& renderer = *test::egl().renderer;
  const Scene fresh = test::cutSphereScene(), copy = test::cutSphereScene();
  ASSERT_NE(fresh.objects.back().mesh, copy.objects.back().mesh);
  const PipelineRun freshRun = runPipeline(fresh), copyRun = runPipeline(copy);
  const DisplaySettings settings = displaySettingsFor(fresh, Style::shaded, 400.0 / 300.0);
  const Image whole = drawWhole(renderer, ViewKind::world, copy, copyRun, settings, 1);
  ASSERT_GE(test::distinctColours(whole), 4u);
  const auto [picture, count] = drawInSlicesWithSmallChunks(renderer, ViewKind::world, fresh, freshRun, settings);
  EXPECT_GE(count, 2 * 14) << "uploaded and drawn in " << count << " slices";
  const auto [inside, outside] = renderer.partitionedTriangles(fresh.objects.size() - 1);
  EXPECT_GT(inside + outside, 0u) << "the sphere was drawn whole, not partitioned";
  EXPECT_EQ(test::differingPixels(whole, picture), 0u) << count << " slices";
}

// The camera view's wireframe draws the mesh's edges from the GPU (GpuMesh's edge chunks): a mesh
// whose edges the renderer has not uploaded gets them a chunk a slice (with chunks of 2048 corners,
// 1024 edges: the sphere's 14 280 edges in at least 14 slices of 1000 triangles), and they are then
// drawn 500 a slice, parts of a chunk included: the picture is the one drawn whole from another copy.
TEST(ViewSlices, ANewMeshsEdgesAreUploadedAndDrawnInSlices) {
  ViewRenderer& renderer = *test::egl().renderer;
  const Scene fresh = test::cutSphereScene(), copy = test::cutSphereScene();
  const PipelineRun freshRun = runPipeline(fresh), copyRun = runPipeline(copy);
  for (Style style : {Style::wire, Style::hiddenLine}) {
    const DisplaySettings settings = displaySettingsFor(fresh, style, 400.0 / 300.0);
    const Image whole = drawWhole(renderer, ViewKind::camera, copy, copyRun, settings, 1);
    ASSERT_GE(test::distinctColours(whole), 3u);
    const auto [picture, count] = drawInSlicesWithSmallChunks(renderer, ViewKind::camera, fresh, freshRun, settings);
    const size_t edges = uniqueEdges(*fresh.objects.back().mesh).size();
    ASSERT_GT(edges, 10000u);
    // Uploaded a chunk a slice (in the first style; the second finds them uploaded), then drawn 500
    // edges a slice (hidden-line: twice, solid and dashed).
    EXPECT_GE(count, int(edges / 1024 + edges / 500)) << toString(style) << ": " << count << " slices";
    EXPECT_EQ(test::differingPixels(whole, picture), 0u) << toString(style) << ", " << count << " slices";
  }
}

// The three views of a page draw their slices in turn: two world views (two observers) whose slices
// interleave each find their own partition again and finish, each the picture drawn whole.
TEST(ViewSlices, InterleavedWorldViewsEachKeepTheirPartition) {
  ViewRenderer& renderer = *test::egl().renderer;
  const Scene scene = cutSphereScene();
  const PipelineRun run = runPipeline(scene, {ClipStrategy::npc, false, true});
  std::array<DisplaySettings, 2> settings{displaySettingsFor(scene, Style::shaded, 400.0 / 300.0),
                                          displaySettingsFor(scene, Style::flat, 400.0 / 300.0)};
  orbitBy(settings[1].world.orbit, 160, 40);
  std::array<Image, 2> whole;
  std::array<gl::RenderTarget, 2> targets{gl::RenderTarget(renderer.context().gl()), gl::RenderTarget(renderer.context().gl())};
  std::array<ViewRenderer::Slices, 2> slices;
  for (size_t v = 0; v < 2; ++v) {
    whole[v] = drawWhole(renderer, ViewKind::world, scene, run, settings[v], 1);
    targets[v].resize(400, 300, 1);
    renderer.startSlices(ViewKind::world, scene, run, settings[v], {}, targets[v], slices[v]);
  }
  std::array<bool, 2> done{false, false};
  for (int count = 0; !(done[0] && done[1]); ++count) {
    for (size_t v = 0; v < 2; ++v) {
      size_t triangles = 700;
      if (!done[v]) done[v] = renderer.drawSlice(slices[v], targets[v], triangles);
    }
    ASSERT_LT(count, 10000) << "the slices never end";
  }
  for (size_t v = 0; v < 2; ++v) EXPECT_EQ(test::differingPixels(whole[v], targets[v].read()), 0u) << "view " << v;
}

// The frames of a page: each draws what is left of its slice budget, the view is asked for again.
TEST(ViewSlices, ViewImagesShowTheLastCompleteImageBusyUntilTheNewOneIsDone) {
  test::GlFixture& gl = test::egl();
  ViewImages images(*gl.context, *gl.renderer);
  // 1000 triangles in the first frame, then at most a quarter more a frame however fast the frames
  // are (and never more when they are slow): the world view's thousands of triangles take many.
  images.drawInSlices(1000);
  auto scene = std::make_shared<const Scene>(cutSphereScene());
  auto run = std::make_shared<const PipelineRun>(runPipeline(*scene, {ClipStrategy::npc, false, true}));
  ViewRequest request{ViewKind::world, scene, run, displaySettingsFor(*scene, Style::shaded, 400.0 / 300.0), {}, 400, 300, 1, 1.f};
  auto frame = [&](const ViewRequest& r, unsigned revision) {
    images.beginFrame();
    const GLuint texture = images.image(r, revision);
    images.endFrame();
    if (const auto error = images.takeError()) ADD_FAILURE() << *error;
    return texture;
  };

  int frames = 1;
  GLuint first = frame(request, 1);
  for (; first == 0; ++frames) {
    EXPECT_TRUE(images.busy(ViewKind::world));
    EXPECT_EQ(images.wakeIn(0.1), 0.0) << "a view drawn in slices asks for the next frame at once";
    ASSERT_LT(frames, 1000);
    first = frame(request, 1);
  }
  EXPECT_GT(frames, 3) << "drawn in one frame: no slices";
  EXPECT_FALSE(images.busy(ViewKind::world));
  EXPECT_EQ(images.wakeIn(0.1), std::nullopt);
  const Image firstImage = readTexture(gl.context->gl(), first);
  EXPECT_EQ(test::differingPixels(firstImage, drawWhole(*gl.renderer, ViewKind::world, *scene, *run, request.settings, 1)), 0u);
  EXPECT_EQ(frame(request, 1), first) << "the same request draws nothing again";

  // The observer turns: the old image stays shown, unchanged, until the new one is complete. (From
  // 1000 triangles again: the first image's many fast frames grew the slices.)
  images.drawInSlices(1000);
  ViewRequest turned = request;
  orbitBy(turned.settings.world.orbit, 40, 10);
  GLuint shown = frame(turned, 1);
  int busyFrames = 0;
  for (; images.busy(ViewKind::world); ++busyFrames) {
    EXPECT_EQ(test::differingPixels(readTexture(gl.context->gl(), shown), firstImage), 0u) << "a half-drawn image was shown";
    ASSERT_LT(busyFrames, 1000);
    shown = frame(turned, 1);
  }
  EXPECT_GT(busyFrames, 1);
  EXPECT_EQ(test::differingPixels(readTexture(gl.context->gl(), shown),
                                  drawWhole(*gl.renderer, ViewKind::world, *scene, *run, turned.settings, 1)), 0u);
}

// The page's frames (issue 42): a view's new list (a million triangles' takes the page 20-50 ms) is
// built in a frame where no other list was and that has not spent SlicePacing::kListStartSeconds yet;
// one put off is built in the next frame whatever it spent, so every view is drawn in the end.
TEST(ViewSlices, OneNewListAFrameAndNoneInALongFrameButNeverPutOffTwice) {
  test::GlFixture& gl = test::egl();
  ViewImages images(*gl.context, *gl.renderer);
  images.drawInSlices(1000);
  auto scene = std::make_shared<const Scene>(cutSphereScene());
  auto run = std::make_shared<const PipelineRun>(runPipeline(*scene, {ClipStrategy::npc, false, true}));
  const DisplaySettings settings = displaySettingsFor(*scene, Style::shaded, 400.0 / 300.0);
  auto request = [&](ViewKind kind, const DisplaySettings& s) { return ViewRequest{kind, scene, run, s, {}, 400, 300, 1, 1.f}; };
  const auto spent = std::chrono::milliseconds(int(SlicePacing::kListStartSeconds * 1000) + 5);
  auto frame = [&](const DisplaySettings& s, bool longFrame) {
    images.beginFrame();
    if (longFrame) std::this_thread::sleep_for(spent);  // a pipeline step before the views
    images.image(request(ViewKind::world, s), 1);
    images.image(request(ViewKind::npc, s), 1);
    images.endFrame();
    if (const auto error = images.takeError()) ADD_FAILURE() << *error;
  };

  frame(settings, false);
  EXPECT_TRUE(images.listPutOff()) << "two new lists in one frame";
  EXPECT_TRUE(images.busy(ViewKind::world));
  EXPECT_TRUE(images.busy(ViewKind::npc));
  frame(settings, false);
  EXPECT_FALSE(images.listPutOff()) << "the list put off was not built in the next frame";
  for (int i = 0; i < 1000 && (images.busy(ViewKind::world) || images.busy(ViewKind::npc)); ++i) frame(settings, false);
  ASSERT_FALSE(images.busy(ViewKind::world) || images.busy(ViewKind::npc));

  // Turned, in long frames only: the first puts both off, the next builds one, the one after the other;
  // a list built in a frame past its share is sliced from the next frame on (no slice after a list).
  std::vector<std::string> parts;  // this frame's, in order
  FrameParts timer;
  timer.setSink([&](const char* part, double) { parts.emplace_back(part); });
  images.timeParts(timer);
  int slicedAfterAList = 0, listsInLongFrames = 0;
  auto longFrame = [&](const DisplaySettings& s) {
    parts.clear();
    frame(s, true);
    const auto list = std::find(parts.begin(), parts.end(), "view list");
    listsInLongFrames += list != parts.end();
    slicedAfterAList += std::find(list, parts.end(), "view slice") != parts.end();
  };
  DisplaySettings turned = settings;
  orbitBy(turned.world.orbit, 40, 10);
  orbitBy(turned.npc.orbit, 40, 10);
  longFrame(turned);
  EXPECT_TRUE(images.listPutOff()) << "a new list in a frame that had spent its share";
  int frames = 1;
  for (; frames < 1000 && (images.busy(ViewKind::world) || images.busy(ViewKind::npc)); ++frames) longFrame(turned);
  EXPECT_FALSE(images.busy(ViewKind::world) || images.busy(ViewKind::npc)) << "long frames starved a view";
  EXPECT_GE(frames, 4);
  EXPECT_EQ(listsInLongFrames, 2);
  EXPECT_EQ(slicedAfterAList, 0) << "a slice drawn after a list in a frame past its share";
  EXPECT_EQ(test::differingPixels(readTexture(gl.context->gl(), images.texture(ViewKind::npc)),
                                  drawWhole(*gl.renderer, ViewKind::npc, *scene, *run, turned, 1)), 0u);
}

}  // namespace
}  // namespace vplab
