// Picking and dragging in the views (app/inspect/picking.h): pure geometry with the pipeline's matrices.
#include "app/inspect/picking.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vplab {
namespace {

// The window-edge handles honour "keep the aspect ratio" as the fields do.
TEST(Picking, WindowEdgeHandlesKeepTheAspectRatio) {
  const Scene scene = defaultScene();
  const PipelineRun run = runPipeline(scene);
  const ViewCamera observer = viewCameraOf(observerCamera(defaultWorldOrbit(scene, 1.6), 1.6));
  const double aspect = scene.device.aspect();
  for (Handle h : {Handle::windowLeft, Handle::windowRight, Handle::windowBottom, Handle::windowTop}) {
    Camera kept = scene.camera, free = scene.camera;
    dragHandle(kept, run, h, observer, 400, Vec2(25, -18), aspect);
    dragHandle(free, run, h, observer, 400, Vec2(25, -18));
    EXPECT_NE(free.window, scene.camera.window);
    EXPECT_NEAR(kept.window.width() / kept.window.height(), aspect, 1e-12);
    EXPECT_GT(std::abs(free.window.width() / free.window.height() - aspect), 1e-3) << "without: free";
  }
}

}  // namespace
}  // namespace vplab
