// No OpenGL error anywhere: every view in every style, with every overlay and highlight on, renders
// on a debug context (KHR_debug on, GlContext::checkErrors after each draw) without a single GL
// error or KHR_debug error message. And the check itself works: a deliberate error is caught,
// named, and cleared.
#include "app/render/headless.h"
#include "app/inspect/picking.h"
#include "io/scene_io.h"
#include "tests/support/gl_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace vplab {
namespace {

using ::testing::HasSubstr;

const ViewKind kViews[] = {ViewKind::camera, ViewKind::world, ViewKind::npc, ViewKind::all};
const Style kStyles[] = {Style::flat, Style::shaded, Style::wire, Style::hiddenLine, Style::hiddenRemoved};

/// Display settings with every overlay on.
DisplaySettings everythingOn(const Scene& scene, Style style, double aspect) {
  DisplaySettings s = displaySettingsFor(scene, style, aspect);
  s.overlays = OverlaySettings{};
  s.overlays.cpuPolygons = true;
  s.overlays.difference = true;
  return s;
}

/// Every mark a view draws: a probed vertex in each view's space and every camera handle, one of them hot.
Highlights everythingMarked(const PipelineRun& run) {
  Highlights h;
  if (!run.objects.empty() && run.objects[0].vertexCount() > 0) {
    const ObjectRun& o = run.objects[0];
    h.probeWc = o.wc(0);
    h.probeNpc = Vec3(o.npcH[0]) / o.npcH[0].w;
    h.probeDc = Vec3(run.dcFromNpc * Vec4(*h.probeNpc, 1.0));
  }
  for (Handle k : kHandles) h.handles.push_back({handlePosition(run, k), handleName(k), k == Handle::prp});
  return h;
}

/// Renders every view in every style; render() itself throws at the first GL error (it checks after
/// each view), and an explicit check afterwards catches anything left over.
void renderEverything(const Scene& scene, int width, int height, const std::string& what, size_t minColours = 3) {
  test::GlFixture& f = test::egl();
  ASSERT_TRUE(f.context->debug());
  PipelineOptions options;
  options.clipEdges = true;
  const PipelineRun run = runPipeline(scene, options);
  for (ViewKind view : kViews) {
    for (Style style : kStyles) {
      SCOPED_TRACE(what + ": " + std::string(toString(view)) + " view, " + std::string(toString(style)));
      Image image;
      EXPECT_NO_THROW(image = f.renderer->render(view, scene, run, everythingOn(scene, style, double(width) / height),
                                                 everythingMarked(run), width, height));
      EXPECT_NO_THROW(f.context->checkErrors("after rendering"));
      EXPECT_GE(test::distinctColours(image), minColours);  // something was drawn
    }
  }
}

TEST(GlErrors, DefaultSceneRendersEveryViewAndStyleWithoutErrors) {
  renderEverything(defaultScene(), 320, 240, "default scene");
  // At the device's size too (the camera view pixel-aligned with DC, the path of vplab render).
  renderEverything(defaultScene(), defaultScene().device.width, defaultScene().device.height, "default scene, device size");
}

TEST(GlErrors, EveryAssetSceneRendersEveryViewAndStyleWithoutErrors) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(VPLAB_ASSETS) / "scenes"))
    if (e.path().extension() == ".json" && e.path().filename() != "large-mesh.json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
  for (const auto& file : files) renderEverything(loadScene(file), 160, 120, file.filename().string());
}

// Nothing visible at all (every object outside), and no objects: empty draws must be clean too.
TEST(GlErrors, EmptyScenesRenderWithoutErrors) {
  Scene empty = defaultScene();
  empty.objects.clear();
  renderEverything(empty, 160, 120, "no objects", 1);  // the camera view: only the background
  Scene outside = defaultScene();
  for (SceneObject& o : outside.objects) o.transform.translate += Vec3(100, 0, 0);
  renderEverything(outside, 160, 120, "everything outside", 1);
}

TEST(GlErrors, DeliberateErrorIsCaughtNamedAndCleared) {
  GlContext& ctx = *test::egl().context;
  ASSERT_NO_THROW(ctx.checkErrors("before"));
  ctx.gl().Enable(GLenum(0x1234));  // no such capability: GL_INVALID_ENUM
  try {
    ctx.checkErrors("enabling nonsense");
    ADD_FAILURE() << "checkErrors did not throw";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_THAT(m, HasSubstr("enabling nonsense"));
    EXPECT_THAT(m, HasSubstr("GL_INVALID_ENUM"));
    EXPECT_THAT(m, HasSubstr("KHR_debug: "));  // the debug callback reported it as well
  }
  EXPECT_NO_THROW(ctx.checkErrors("after the error was reported"));  // reported once, then cleared

  ctx.gl().UseProgram(0x7fffffff);  // no such program: GL_INVALID_VALUE
  EXPECT_THROW(ctx.checkErrors("using a program that does not exist"), Error);
  EXPECT_NO_THROW(ctx.checkErrors("after"));
}

// A GL error pending when a view is rendered makes the rendering fail, naming the view: the views
// check after drawing, so an error of theirs cannot go unnoticed.
TEST(GlErrors, RenderingFailsOnAPendingError) {
  test::GlFixture& f = test::egl();
  for (ViewKind view : kViews) {
    f.context->gl().Enable(GLenum(0x1234));
    RenderRequest request;
    request.view = view;
    request.width = 160;
    request.height = 120;
    try {
      renderImage(*f.renderer, defaultScene(), request);
      ADD_FAILURE() << toString(view) << ": no error reported";
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr("GL_INVALID_ENUM")) << toString(view);
      // The view it was found after (`all` draws three, in an unspecified order).
      const std::string drawn = view == ViewKind::all ? "" : std::string(toString(view));
      EXPECT_THAT(e.what(), HasSubstr("rendering the " + drawn)) << toString(view);
    }
    EXPECT_NO_THROW(f.context->checkErrors("after")) << toString(view);
  }
}

}  // namespace
}  // namespace vplab
