// Shared by the GL suites (test_render, test_ui, test_cli): one headless context per backend for the whole test binary
// (made on first use, debug output on, so any GL error makes the rendering call throw), a
// ViewRenderer on it, and small image helpers. ctest runs each test case in its own process, so
// "one per binary" means one per process: a test never pays for a second context of a backend.
#pragma once

#include "app/context/context.h"
#include "app/views/image.h"
#include "app/render/view_renderer.h"
#include "base/error.h"
#include "pipeline/primitives.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <set>
#include <string>

namespace vplab::test {

/// The default scene with its objects replaced by (or, with `keepObjects`, joined by) a finely
/// tessellated sphere (120 segments, 14 400 faces) cut by the right, top and front planes: thousands
/// of faces on both sides of the view volume, hundreds of them crossing, slivers at its poles.
inline Scene cutSphereScene(bool keepObjects = false) {
  Scene s = defaultScene();
  SceneObject o = s.objects[0];
  if (!keepObjects) s.objects.clear();
  o.name = "sphere";
  o.shape = Shape::sphere;
  o.segments = 120;
  o.mesh = std::make_shared<const Mesh>(sphere(120));
  o.transform = {};
  o.transform.translate = {1.6, 1.0, 1.5};
  o.transform.scale = {1.6, 1.6, 1.6};
  s.objects.push_back(std::move(o));
  return s;
}

/// A context and the renderer made on it, torn down with the context current (the renderer's GL
/// objects belong to it, whichever context the test made current last).
struct GlFixture {
  std::unique_ptr<GlContext> context;
  std::unique_ptr<ViewRenderer> renderer;

  explicit GlFixture(Backend backend) : context(createHeadlessContext(backend, /*debug=*/true)) {
    renderer = std::make_unique<ViewRenderer>(*context);
  }
  ~GlFixture() {
    context->makeCurrent();
    renderer.reset();
  }
  GlFixture(const GlFixture&) = delete;
  GlFixture& operator=(const GlFixture&) = delete;
};

/// The EGL fixture of this process, made current. EGL is the default headless backend and the only
/// one ImGui's OpenGL3 backend runs on (it loads GL through libGL.so.1).
inline GlFixture& egl() {
  static GlFixture fixture(Backend::egl);
  fixture.context->makeCurrent();
  return fixture;
}

/// The OSMesa fixture of this process, made current (for the backend comparisons).
inline GlFixture& osmesa() {
  static GlFixture fixture(Backend::osmesa);
  fixture.context->makeCurrent();
  return fixture;
}

/// Where failing tests leave their pictures (the build tree, see tests/CMakeLists.txt).
inline std::filesystem::path outputDir() {
  std::filesystem::path dir = VPLAB_TEST_OUTPUT;
  std::filesystem::create_directories(dir);
  return dir;
}

/// The part of an image inside [x, x + w) × [y, y + h), clamped to the image.
inline Image crop(const Image& image, int x, int y, int w, int h) {
  const int x0 = std::max(0, x), y0 = std::max(0, y);
  const int x1 = std::min(image.width, x + w), y1 = std::min(image.height, y + h);
  Image out(std::max(0, x1 - x0), std::max(0, y1 - y0));
  for (int yy = y0; yy < y1; ++yy)
    for (int xx = x0; xx < x1; ++xx) out.at(xx - x0, yy - y0) = image.at(xx, yy);
  return out;
}

/// How many different colours an image has (a blank or garbage-free picture of a scene has many,
/// a cleared one has one).
inline size_t distinctColours(const Image& image) {
  std::set<uint32_t> colours;
  for (const Rgba& p : image.pixels) colours.insert(uint32_t(p.r) << 24 | uint32_t(p.g) << 16 | uint32_t(p.b) << 8 | p.a);
  return colours.size();
}

/// How many pixels differ at all between two images of the same size.
/// The default scene's camera with one sphere of `segments` segments in place of its objects: 512
/// gives 512 · 254 quads and 1 024 triangles at the poles, about 260 000 triangles on the GPU (a
/// quarter of assets/scenes/large-mesh.json): views that take seconds on llvmpipe, a pipeline run
/// of tens of milliseconds.
inline Scene sphereScene(int segments) {
  Scene scene = defaultScene();
  SceneObject sphere;
  sphere.name = "sphere";
  sphere.shape = Shape::sphere;
  sphere.segments = segments;
  sphere.mesh = primitiveMesh(sphere);
  scene.objects = {sphere};
  return scene;
}

inline size_t differingPixels(const Image& a, const Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  if (a.width != b.width || a.height != b.height) return std::max(a.pixels.size(), b.pixels.size());
  size_t n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i];
  return n;
}

}  // namespace vplab::test
