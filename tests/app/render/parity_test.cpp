// CPU–GPU parity: the CPU pipeline's clipped DC polygons, filled by the independent CPU rasterizer
// (app/export/cpu_raster.h), against the GLSL path's flat camera view (renderImage, ViewKind::camera,
// Style::flat, at the device's size so that it is pixel-aligned with DC) on random scenes.
//
// Tolerance: a pixel agrees only when it is exactly equal (channel threshold 0). In the flat style
// both sides colour a covered pixel with the object's colour converted once to 8 bits (the same
// unorm8 rounding, cpu_raster.h), and nothing is interpolated or blended, so any difference at all
// is a different decision about coverage or depth, which is what the test measures. Those decisions
// may legitimately differ for a centre within float precision of an edge (llvmpipe transforms in
// float and snaps to 1/256 pixel; the oracle imitates the snapping but computes in double) and where
// two polygons cross (24-bit float depth against double): about a pixel per scene. At least 99.5 %
// of the pixels must therefore be equal: 384 of 320 × 240, far below what a wrong matrix, a lost
// clip plane, a wrong edge rule along a whole edge (a row or column of pixels per polygon) or a
// wrong depth order produce.
#include "app/render/headless.h"
#include "app/export/image_compare.h"
#include "app/export/cpu_raster.h"
#include "tests/support/gl_test_support.h"
#include "tests/support/test_util.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace vplab {
namespace {

constexpr double kMinEqualShare = 0.995;
constexpr int kSceneCount = 20;

/// A random colour, bright enough to differ from the background and from each other.
Vec3 randomColour(test::Rng& rng) { return {rng.uniform(0.2, 1), rng.uniform(0.2, 1), rng.uniform(0.2, 1)}; }

/// A random scene of convex planar polygons and primitives (convex faces only: for a concave face
/// GL fans the unclipped face and the oracle the clipped one, which cover different pixels) around
/// the view volume: some inside, some outside, some crossing its planes, and in perspective some
/// reaching from in front of the eye to behind it.
Scene randomConvexScene(test::Rng& rng, Projection projection) {
  const Camera c = test::randomCamera(rng, projection);
  const test::TestFrame f = test::testFrame(c);
  const ViewWindow& w = c.window;
  const double depth = c.front - c.back;
  std::vector<SceneObject> objects;
  const int polygons = rng.integer(6, 14);
  for (int i = 0; i < polygons; ++i) {
    double z = rng.uniform(c.back - 0.3 * depth, c.front + 0.3 * depth);
    if (projection == Projection::perspective && rng.chance(0.2)) z = rng.uniform(c.front, f.vpd + 0.5 * depth);
    // Perspective: the window scaled to the depth, so that a fair share lands inside.
    const double s = projection == Projection::perspective ? std::max(0.2, (f.vpd - z) / f.vpd) : 1.0;
    const Vec3 centreVrc(s * rng.uniform(w.xmin - 0.3 * w.width(), w.xmax + 0.3 * w.width()),
                         s * rng.uniform(w.ymin - 0.3 * w.height(), w.ymax + 0.3 * w.height()), z);
    const double radius = rng.uniform(0.1, 0.7) * std::max({w.width() * s, w.height() * s, 0.3 * depth});
    std::vector<Vec3> vrc =
        test::randomPlanarPolygon(rng, centreVrc, rng.unitVector(), radius, rng.integer(3, 8), /*starShaped=*/false);
    for (Vec3& p : vrc) p = test::wcOfVrc(c, p);
    SceneObject o = test::polygonObject("polygon " + std::to_string(i), std::move(vrc));
    o.color = randomColour(rng);
    objects.push_back(std::move(o));
  }
  for (Shape shape : {Shape::cube, Shape::sphere, Shape::cylinder, Shape::tetrahedron}) {
    if (!rng.chance(0.7)) continue;
    ModelTransform t;
    const double s = projection == Projection::perspective ? 0.5 : 1.0;
    t.translate = test::wcOfVrc(c, {s * rng.uniform(w.xmin, w.xmax), s * rng.uniform(w.ymin, w.ymax),
                                    rng.uniform(c.back - 0.2 * depth, c.front + 0.2 * depth)});
    t.rotations.push_back({rng.unitVector(), rng.uniform(0, 360), {}});
    t.scale = Vec3(rng.uniform(0.15, 0.5) * std::max(w.width(), w.height()));
    SceneObject o = test::shapeObject(std::string(toString(shape)), shape, t, 2 * rng.integer(4, 12));
    o.color = randomColour(rng);
    objects.push_back(std::move(o));
  }
  Scene scene = test::sceneWith(c, std::move(objects));
  scene.device = {rng.integer(200, 400), rng.integer(150, 300)};
  return scene;
}

size_t nonBackground(const Image& image, const Rgba& background) {
  size_t n = 0;
  for (const Rgba& p : image.pixels) n += p != background;
  return n;
}

struct ParityResult {
  size_t pixels = 0, equal = 0, covered = 0, clippedFaces = 0;
  double share() const { return pixels ? double(equal) / double(pixels) : 0; }
};

TEST(Parity, CpuClippedPolygonsMatchTheGlslFlatCameraView) {
  test::Rng rng(0x5eed2024);
  ViewRenderer& renderer = *test::egl().renderer;
  const Projection projections[] = {Projection::perspective, Projection::parallel, Projection::oblique};
  size_t scenesWithClipping = 0;
  double worst = 1;
  for (int k = 0; k < kSceneCount; ++k) {
    // Half perspective, the rest parallel (orthographic and oblique).
    const Projection projection = k % 2 == 0 ? Projection::perspective : projections[1 + (k / 2) % 2];
    // Draw again until the scene shows something (the oracle decides, not the code under test):
    // at least 5 % of the pixels covered.
    Scene scene;
    PipelineRun run;
    Image cpu;
    for (int attempt = 0;; ++attempt) {
      ASSERT_LT(attempt, 50) << "no scene with enough coverage";
      scene = randomConvexScene(rng, projection);
      run = runPipeline(scene);
      cpu = rasterizeClippedPolygons(run, scene.background, scene.device.width, scene.device.height, 8);
      if (nonBackground(cpu, rgbaFromColor(scene.background)) > cpu.pixels.size() / 20) break;
    }
    RenderRequest request;  // camera, flat, at the device's size
    const Image gpu = renderImage(renderer, scene, request);
    ASSERT_EQ(gpu.width, scene.device.width);
    ASSERT_EQ(gpu.height, scene.device.height);

    ParityResult r;
    r.pixels = gpu.pixels.size();
    for (size_t i = 0; i < gpu.pixels.size(); ++i) r.equal += gpu.pixels[i] == cpu.pixels[i];
    r.covered = nonBackground(cpu, rgbaFromColor(scene.background));
    for (const ObjectRun& o : run.objects)
      for (Fate fate : o.fate) r.clippedFaces += fate == Fate::clipped;
    scenesWithClipping += r.clippedFaces > 0;
    worst = std::min(worst, r.share());

    char line[200];
    std::snprintf(line, sizeof line, "scene %2d %-11s %3d×%3d: %6zu of %6zu pixels equal (%.4f %%), %zu differ, %5.1f %% covered, %zu faces clipped",
                  k, std::string(toString(projection)).c_str(), gpu.width, gpu.height, r.equal, r.pixels,
                  100 * r.share(), r.pixels - r.equal, 100.0 * double(r.covered) / double(r.pixels), r.clippedFaces);
    std::cout << line << "\n";
    if (r.share() < kMinEqualShare) {
      const ImageComparison c = compareImages(gpu, cpu, 0);
      const auto dir = test::outputDir();
      const std::string stem = "parity-" + std::to_string(k);
      writePng(gpu, dir / (stem + ".gpu.png"));
      writePng(cpu, dir / (stem + ".cpu.png"));
      writePng(differenceImage(gpu, cpu, 0), dir / (stem + ".diff.png"));
      ADD_FAILURE() << line << "\n" << describe(c) << "\n  pictures: " << (dir / stem).string()
                    << ".{gpu,cpu,diff}.png";
    }
  }
  std::cout << "worst share of equal pixels: " << 100 * worst << " %\n";
  // The scenes must exercise clipping: most of them have faces cut by a plane of the volume.
  EXPECT_GE(scenesWithClipping, size_t(kSceneCount * 3 / 4));
}

// User clip planes (DGL wiki): the CPU pipeline clips with them in homogeneous NPC, the GLSL path
// with gl_ClipDistance in WC; both must cut the same pixels away. Same criterion as above.
TEST(Parity, UserClipPlanesAgreeBetweenCpuAndGlsl) {
  test::Rng rng(0xc1a9);
  ViewRenderer& renderer = *test::egl().renderer;
  size_t cut = 0;
  for (int k = 0; k < 8; ++k) {
    Scene scene;
    PipelineRun run;
    Image cpu;
    for (int attempt = 0;; ++attempt) {
      ASSERT_LT(attempt, 50) << "no scene with enough coverage";
      scene = randomConvexScene(rng, k % 2 ? Projection::parallel : Projection::perspective);
      // One to three planes through the middle of what the camera looks at, their normals across
      // the view direction so each splits the picture.
      const int planes = 1 + k % 3;
      const Vec3 n = glm::normalize(scene.camera.prp - scene.camera.vrp);
      for (int i = 0; i < planes; ++i) {
        Vec3 normal = rng.unitVector();
        normal -= glm::dot(normal, n) * n;
        if (glm::length(normal) < 0.2) normal = glm::normalize(glm::cross(n, Vec3(0.3, 1, 0.1)));
        scene.clipPlanes.push_back({normal, scene.camera.vrp + rng.inBox(-0.3, 0.3), true});
      }
      run = runPipeline(scene);
      cpu = rasterizeClippedPolygons(run, scene.background, scene.device.width, scene.device.height, 8);
      if (nonBackground(cpu, rgbaFromColor(scene.background)) > cpu.pixels.size() / 20) break;
    }
    // The planes really cut something: without them more is drawn.
    Scene unclipped = scene;
    unclipped.clipPlanes.clear();
    const Image without = rasterizeClippedPolygons(runPipeline(unclipped), scene.background, scene.device.width,
                                                   scene.device.height, 8);
    cut += nonBackground(without, rgbaFromColor(scene.background)) > nonBackground(cpu, rgbaFromColor(scene.background));

    const Image gpu = renderImage(renderer, scene, RenderRequest{});
    size_t equal = 0;
    for (size_t i = 0; i < gpu.pixels.size(); ++i) equal += gpu.pixels[i] == cpu.pixels[i];
    const double share = double(equal) / double(gpu.pixels.size());
    if (share < kMinEqualShare) {
      const auto dir = test::outputDir();
      const std::string stem = "parity-planes-" + std::to_string(k);
      writePng(gpu, dir / (stem + ".gpu.png"));
      writePng(cpu, dir / (stem + ".cpu.png"));
      ADD_FAILURE() << "scene " << k << ": " << 100 * share << " % equal\n"
                    << describe(compareImages(gpu, cpu, 0)) << "\n  pictures: " << (dir / stem).string()
                    << ".{gpu,cpu}.png";
    }
  }
  EXPECT_GE(cut, 6u) << "the planes must cut something away in most scenes";
}

// The oracle is not trivially satisfied: a camera one pixel off, or a different edge rule (no
// subpixel snapping changes only a few pixels, a shifted window a lot) must fail the same criterion.
TEST(Parity, CriterionCatchesAOnePixelShift) {
  test::Rng rng(77);
  Scene scene = randomConvexScene(rng, Projection::perspective);
  RenderRequest request;
  const Image gpu = renderImage(*test::egl().renderer, scene, request);
  // The window moved by one pixel's width along U.
  Scene shifted = scene;
  const double pixel = scene.camera.window.width() / scene.device.width;
  shifted.camera.window.xmin += pixel;
  shifted.camera.window.xmax += pixel;
  const Image cpu =
      rasterizeClippedPolygons(runPipeline(shifted), scene.background, scene.device.width, scene.device.height, 8);
  const ImageComparison c = compareImages(gpu, cpu, 0);
  EXPECT_GT(c.differingShare, 1 - kMinEqualShare) << describe(c);
}

}  // namespace
}  // namespace vplab
