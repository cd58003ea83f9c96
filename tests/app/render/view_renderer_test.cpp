// The view renderer's shortcuts must not change a pixel. The world view draws its two passes
// (inside the scene camera's view volume solid, outside faded) from only the faces that can show
// in each (ViewRenderer::partitionByVolume): the picture must be byte for byte the one drawn with
// every face in both passes, in every scene and style, from several observers.
#include "app/render/headless.h"
#include "app/gl/render_target.h"
#include "pipeline/primitives.h"
#include "io/scene_io.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

namespace vplab {
namespace {

namespace fs = std::filesystem;

// The world view as the viewer draws it on a software renderer: one sample per pixel.
Image drawWorld(ViewRenderer& renderer, const Scene& scene, const DisplaySettings& settings, bool partitioned) {
  const PipelineRun run = runPipeline(scene, {ClipStrategy::npc, false, true});
  gl::RenderTarget target(renderer.context().gl());
  target.resize(400, 300, 1);
  renderer.setPartitionedWorld(partitioned);
  renderer.drawWorld(scene, run, settings, {}, target);
  renderer.setPartitionedWorld(true);
  return target.read();
}

// Every observer of `orbits` (yaw, pitch steps) and both filled styles: identical pictures.
void expectSamePictures(const Scene& scene, const std::string& name) {
  ViewRenderer& renderer = *test::egl().renderer;
  for (Style style : {Style::shaded, Style::flat}) {
    for (const auto& [yaw, pitch] : {std::pair{0.0, 0.0}, {70.0, -15.0}, {160.0, 40.0}}) {
      DisplaySettings settings = displaySettingsFor(scene, style, 400.0 / 300.0);
      orbitBy(settings.world.orbit, yaw, pitch);
      const Image all = drawWorld(renderer, scene, settings, false);
      const Image parts = drawWorld(renderer, scene, settings, true);
      ASSERT_GE(test::distinctColours(parts), 4u) << name;
      EXPECT_EQ(test::differingPixels(all, parts), 0u)
          << name << ", " << toString(style) << ", observer turned by " << yaw << "°, " << pitch << "°";
    }
  }
}

// A face of 70 000 corners: its chunk has more vertices than 16-bit indices reach, so its own indices
// and the partition's lists are 32-bit (every other test's chunks are 16-bit): the same pixels,
// partitioned or not.
Scene tiltedDisc(int corners) {
  Scene scene = test::cutSphereScene();
  std::vector<Vec3> ring;
  for (int k = 0; k < corners; ++k) {
    const double t = 2 * kPi * k / corners;
    ring.push_back({std::cos(t), std::sin(t), 0.5 * std::cos(t)});  // on the plane z = x / 2
  }
  scene.objects[0].name = "disc";
  scene.objects[0].shape = Shape::mesh;
  scene.objects[0].mesh = std::make_shared<const Mesh>(polygon(ring));
  return scene;
}

TEST(WorldViewPartition, SamePixelsForAFaceBeyondSixteenBitIndices) {
  expectSamePictures(tiltedDisc(70000), "a disc of 70 000 corners");
}

// Translucent batches blend their colour but accumulate alpha: every pixel of every view's picture is
// opaque, so a PNG pasted on a white or a dark slide shows the same colours (before the fix, faded
// parts, lines' smooth edges and labels left alpha as low as 61 in the morph view).
TEST(ViewRenderer, EveryPictureIsOpaque) {
  ViewRenderer& renderer = *test::egl().renderer;
  const Scene scene = defaultScene();
  const PipelineRun run = runPipeline(scene, {ClipStrategy::npc, false, true});
  for (ViewKind kind : {ViewKind::camera, ViewKind::world, ViewKind::npc, ViewKind::morph, ViewKind::all}) {
    for (Style style : {Style::shaded, Style::hiddenLine}) {
      DisplaySettings settings = displaySettingsFor(scene, style, 400.0 / 300.0);
      settings.morphing.t = 2.5;
      const Image image = renderer.render(kind, scene, run, settings, {}, 400, 300);
      size_t translucent = 0;
      for (const Rgba& p : image.pixels) translucent += p.a != 255;
      EXPECT_EQ(translucent, 0u) << toString(kind) << ", " << toString(style);
    }
  }
}

TEST(WorldViewPartition, SamePixelsInEveryPreset) {
  for (const auto& entry : fs::directory_iterator(fs::path(VPLAB_ASSETS) / "scenes")) {
    if (entry.path().extension() != ".json" || entry.path().stem() == "large-mesh") continue;  // slow
    expectSamePictures(loadScene(entry.path()), entry.path().stem().string());
  }
}

Scene cutSphere() { return test::cutSphereScene(); }

TEST(WorldViewPartition, SamePixelsOnACutSphere) { expectSamePictures(cutSphere(), "cut sphere"); }

// A mesh goes to the GPU in chunks of consecutive faces (GpuMeshCache), and the partition's lists are
// made per chunk: with chunks of 256 corners (the sphere's 14 160 triangles in about 110 chunks) the
// pictures, partitioned or not, are the ones drawn from meshes in one chunk.
TEST(WorldViewPartition, SamePixelsAcrossChunkBoundaries) {
  ViewRenderer& renderer = *test::egl().renderer;
  DisplaySettings settings = displaySettingsFor(cutSphere(), Style::shaded, 400.0 / 300.0);
  orbitBy(settings.world.orbit, 70, -15);
  const Image oneChunk = drawWorld(renderer, cutSphere(), settings, true);
  ASSERT_GE(test::distinctColours(oneChunk), 4u);
  renderer.setMeshChunkCorners(256);
  const Scene chunked = cutSphere();  // a new mesh: uploaded in the small chunks
  const Image parts = drawWorld(renderer, chunked, settings, true);
  const auto [inside, outside] = renderer.partitionedTriangles(0);
  const Image all = drawWorld(renderer, chunked, settings, false);
  renderer.setMeshChunkCorners(GpuMeshCache::kChunkCorners);
  EXPECT_EQ(test::differingPixels(oneChunk, parts), 0u);
  EXPECT_EQ(test::differingPixels(oneChunk, all), 0u);
  EXPECT_GT(inside, 0u);
  EXPECT_GT(outside, 0u);
}

TEST(WorldViewPartition, EachPassDrawsAboutTheFacesOnItsSide) {
  const Scene scene = cutSphere();
  ViewRenderer& renderer = *test::egl().renderer;
  drawWorld(renderer, scene, displaySettingsFor(scene, Style::shaded, 400.0 / 300.0), true);
  size_t triangles = 0;
  const Mesh& mesh = *scene.objects[0].mesh;
  for (size_t f = 0; f < mesh.faceCount(); ++f) triangles += mesh.face(f).size() - 2;
  const auto [inside, outside] = renderer.partitionedTriangles(0);
  EXPECT_GT(inside, 0u);
  EXPECT_GT(outside, 0u);
  // Each face in at least one pass; only faces near a plane (within the margin) in both.
  EXPECT_GE(inside + outside, triangles);
  EXPECT_LT(inside + outside, triangles + triangles / 5) << inside << " + " << outside << " of " << triangles;
}

}  // namespace
}  // namespace vplab

namespace vplab {
namespace {

// The GPU buffers' bytes (`vplab bench --memory`) against the meshes: a GPU vertex is a position and
// a normal (six floats), one per distinct (mesh vertex, normal) pair: a smooth sphere's corners share
// their vertex's (its normal is its position), a cube's 24 corners each have their face's normal. A
// fan triangle is three 16-bit indices here, an edge its two end points (six floats); the corner map one
// 16-bit index a corner. The edges are uploaded only once a wireframe style draws them.
TEST(ViewRenderer, TheGpuBuffersHoldEachVertexNormalPairTriangleAndEdgeOnce) {
  test::GlFixture& gl = test::egl();
  gl.context->makeCurrent();
  ViewRenderer renderer(*gl.context);  // its own mesh cache: nothing of other tests' meshes
  Scene scene = defaultScene();
  scene.objects.resize(2);
  scene.objects[0].shape = Shape::sphere;
  scene.objects[0].segments = 24;
  scene.objects[0].mesh = std::make_shared<const Mesh>(sphere(24));
  scene.objects[1].shape = Shape::cube;
  scene.objects[1].mesh = std::make_shared<const Mesh>(cube());
  const Mesh &ball = *scene.objects[0].mesh, &box = *scene.objects[1].mesh;
  ASSERT_TRUE(ball.smooth()) << "the sphere is smooth";
  ASSERT_FALSE(box.smooth()) << "the cube is flat";
  ASSERT_EQ(box.indices.size(), 24u);
  size_t triangles = 0, corners = 0, edges = 0;
  for (const Mesh* mesh : {&ball, &box}) {
    for (size_t f = 0; f < mesh->faceCount(); ++f) triangles += mesh->face(f).size() - 2;
    corners += mesh->indices.size();
    edges += uniqueEdges(*mesh).size();
  }
  const size_t gpuVertices = ball.vertexCount() + box.indices.size();
  ASSERT_LT(gpuVertices, corners) << "the sphere's corners share vertices";
  // Every chunk here has fewer than 65 536 vertices: 16-bit indices.
  const size_t faceBytes = gpuVertices * 6 * sizeof(float) + triangles * 3 * sizeof(uint16_t);
  const size_t edgeBytes = edges * 6 * sizeof(float);
  const PipelineRun run = runPipeline(scene, {ClipStrategy::npc, false, true});

  renderer.render(ViewKind::all, scene, run, displaySettingsFor(scene, Style::shaded, 4.0 / 3), {}, 400, 300);
  MemoryUse use = renderer.gpuMemoryUse();
  ASSERT_EQ(use.size(), 3u);
  EXPECT_EQ(use[0].bytes, faceBytes) << use[0].name;
  EXPECT_EQ(use[1].bytes, 0u) << use[1].name;
  EXPECT_EQ(use[2].bytes, corners * sizeof(uint16_t)) << use[2].name;

  renderer.render(ViewKind::all, scene, run, displaySettingsFor(scene, Style::wire, 4.0 / 3), {}, 400, 300);
  use = renderer.gpuMemoryUse();
  EXPECT_EQ(use[0].bytes, faceBytes) << "the faces uploaded again";
  EXPECT_EQ(use[1].bytes, edgeBytes) << use[1].name;
}

// A face of more corners than 16-bit indices reach: its chunk's indices are 32-bit.
TEST(ViewRenderer, AFaceBeyondSixteenBitIndicesHasThirtyTwoBitOnes) {
  test::GlFixture& gl = test::egl();
  gl.context->makeCurrent();
  ViewRenderer renderer(*gl.context);
  constexpr size_t kCorners = 70000;
  const Scene scene = tiltedDisc(int(kCorners));
  const PipelineRun run = runPipeline(scene, {ClipStrategy::npc, false, true});
  renderer.render(ViewKind::camera, scene, run, displaySettingsFor(scene, Style::flat, 4.0 / 3), {}, 400, 300);
  const MemoryUse use = renderer.gpuMemoryUse();
  EXPECT_EQ(use[0].bytes, kCorners * 6 * sizeof(float) + (kCorners - 2) * 3 * sizeof(uint32_t));
  EXPECT_EQ(use[2].bytes, kCorners * sizeof(uint32_t)) << use[2].name;
}

}  // namespace
}  // namespace vplab

namespace vplab {
namespace {

// The NPC view's polygons by reference (the run's faces, drawn as indices into the run's vertices)
// against the same polygons as points (fan-triangulated corners): the same triangles from the same
// float positions through the same program, so the same pixels, byte for byte; the polygon
// buffer's slot, each run's first vertex and the fans' indices are what this checks. With the
// keepObjects sphere the inside and faded fills refer to seven runs each; the faded fill's sets
// alternate between whole faces by reference and cut ones as points.
draw::DisplayList asPoints(draw::DisplayList list) {
  for (draw::Batch& b : list.batches) {
    auto* fill = std::get_if<draw::Fill>(&b);
    if (!fill) continue;
    for (draw::PolygonSet& set : fill->polygons) {
      if (!set.npcOf) continue;
      draw::PolygonSet points;
      points.color = set.color;
      std::vector<Vec3> scratch;
      for (size_t i = 0; i < set.polygonCount(); ++i) points.add(set.polygon(i, scratch));
      set = std::move(points);
    }
  }
  return list;
}

TEST(NpcViewPolygons, ByReferenceTheyDrawTheSamePixelsAsTheirPoints) {
  ViewRenderer& renderer = *test::egl().renderer;
  const Scene scene = test::cutSphereScene(true);
  const PipelineRun run = runPipeline(scene, {ClipStrategy::npc, false, true});
  for (Style style : {Style::shaded, Style::flat, Style::hiddenLine}) {
    for (const auto& [yaw, pitch] : {std::pair{0.0, 0.0}, {70.0, -15.0}, {200.0, 40.0}}) {
      DisplaySettings settings = displaySettingsFor(scene, style, 400.0 / 300.0);
      orbitBy(settings.npc.orbit, yaw, pitch);
      const ViewInput in{scene, run, settings, {}, 400, 300, renderer.textMetrics()};
      draw::DisplayList list;
      npcView(in, list);
      size_t byReference = 0;
      for (const draw::Batch& b : list.batches)
        if (const auto* fill = std::get_if<draw::Fill>(&b))
          for (const draw::PolygonSet& set : fill->polygons) byReference += set.npcOf ? set.polygonCount() : 0;
      ASSERT_GT(byReference, 2000u) << "the sphere's faces by reference";
      auto picture = [&](const draw::DisplayList& l) {
        draw::Picture p{400, 300, {0, 0, 0}, {draw::Panel{0, 0, l}}};
        return renderer.render(p);
      };
      const Image indexed = picture(list), points = picture(asPoints(list));
      ASSERT_GE(test::distinctColours(indexed), 4u);
      EXPECT_EQ(test::differingPixels(indexed, points), 0u)
          << toString(style) << ", observer turned by " << yaw << "°, " << pitch << "°";
    }
  }
}

}  // namespace
}  // namespace vplab
