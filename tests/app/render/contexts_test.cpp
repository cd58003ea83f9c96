// The headless contexts (app/context/context.h): both backends make an OpenGL 3.3 core context,
// and both draw the same images. EGL and OSMesa are two front ends of the same Mesa driver
// (llvmpipe), so the same draw calls give the same bytes: the comparisons below demand byte
// equality (no tolerance); a difference means a backend sets up different state (a different
// framebuffer format, sample count, depth precision or default state).
#include "app/render/headless.h"
#include "app/export/image_compare.h"
#include "tests/support/gl_test_support.h"
#include "tests/support/enum_table_check.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace vplab {
namespace {

using ::testing::HasSubstr;

TEST(Contexts, BackendNamesRoundTrip) {
  test::expectCompleteTable(kBackendNames, 3);  // automatic, egl, osmesa (base/enum_table.h)
  EXPECT_EQ(toString(Backend::automatic), "auto");
  EXPECT_FALSE(fromString<Backend>("vulkan"));
  EXPECT_FALSE(fromString<Backend>(""));
}

void expectCoreContext33(GlContext& context, std::string_view backend) {
  context.makeCurrent();
  EXPECT_EQ(context.backend(), backend);
  const GladGLContext& gl = context.gl();
  GLint major = 0, minor = 0, profile = 0;
  gl.GetIntegerv(GL_MAJOR_VERSION, &major);
  gl.GetIntegerv(GL_MINOR_VERSION, &minor);
  gl.GetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 33) << context.description();
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT) << context.description();
  EXPECT_THAT(context.description(), HasSubstr(" — "));  // renderer — version
  EXPECT_NO_THROW(context.checkErrors("querying the version"));
}

TEST(Contexts, EglMakesACoreContext) {
  test::GlFixture& f = test::egl();
  expectCoreContext33(*f.context, "egl");
  EXPECT_TRUE(f.context->debug());
}

TEST(Contexts, OsMesaMakesACoreContext) {
  test::GlFixture& f = test::osmesa();
  expectCoreContext33(*f.context, "osmesa");
  EXPECT_TRUE(f.context->debug());
}

TEST(Contexts, AutomaticPrefersEgl) {
  // EGL works here (the fixture above); automatic tries it first.
  const auto context = createHeadlessContext(Backend::automatic, false);
  EXPECT_EQ(context->backend(), "egl");
  EXPECT_FALSE(context->debug());
  test::egl();  // current again for whatever runs next in this process
}

// EGL gives every context of the process the same surfaceless display: destroying one context must
// not invalidate the others (the display is never terminated).
TEST(Contexts, TwoEglContextsCoexist) {
  test::GlFixture& first = test::egl();
  const Image before = renderImage(*first.renderer, defaultScene(), RenderRequest{});
  {
    const auto second = createHeadlessContext(Backend::egl, false);
    second->makeCurrent();
    EXPECT_NO_THROW(second->checkErrors("making a second context"));
  }
  Image after;
  EXPECT_NO_THROW({
    first.context->makeCurrent();
    after = renderImage(*first.renderer, defaultScene(), RenderRequest{});
  });
  EXPECT_EQ(test::differingPixels(after, before), 0u);
}

void expectSameOnBothBackends(const Scene& scene, const RenderRequest& request, const std::string& what) {
  const Image a = renderImage(*test::egl().renderer, scene, request);
  const Image b = renderImage(*test::osmesa().renderer, scene, request);
  const ImageComparison c = compareImages(a, b, 0);
  EXPECT_TRUE(c.passed()) << what << ": EGL (actual) against OSMesa (expected)\n" << describe(c);
  EXPECT_EQ(encodePng(a), encodePng(b)) << what;
}

// The flat camera view of the default scene and of random scenes: byte-identical.
TEST(Contexts, EglAndOsMesaDrawTheSameFlatCameraView) {
  expectSameOnBothBackends(defaultScene(), RenderRequest{}, "default scene");
  test::Rng rng(4242);
  for (int k = 0; k < 6; ++k) {
    const Camera camera = test::randomCamera(rng, k % 2 ? Projection::parallel : Projection::perspective);
    expectSameOnBothBackends(test::randomPolygonScene(rng, camera, 10, true), RenderRequest{},
                             "random scene " + std::to_string(k));
  }
  test::egl();
}

// Every view and style of the default scene (text, lines, MSAA resolve included): byte-identical.
TEST(Contexts, EglAndOsMesaDrawTheSameViewsInEveryStyle) {
  for (ViewKind view : {ViewKind::camera, ViewKind::world, ViewKind::npc, ViewKind::all}) {
    for (Style style : {Style::flat, Style::shaded, Style::wire, Style::hiddenLine, Style::hiddenRemoved}) {
      RenderRequest request;
      request.view = view;
      request.style = style;
      request.width = 320;
      request.height = 240;
      expectSameOnBothBackends(defaultScene(), request,
                               std::string(toString(view)) + " " + std::string(toString(style)));
    }
  }
  test::egl();
}

}  // namespace
}  // namespace vplab
