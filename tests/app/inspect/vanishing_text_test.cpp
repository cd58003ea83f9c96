// The vanishing points' text (app/inspect/vanishing_text.h, lecture notes ch. 14): what it says follows
// the geometry in every bundled scene.
#include "app/inspect/vanishing_text.h"
#include "io/scene_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace vplab {
namespace {

// For every bundled scene and object: an axis is called parallel to the view plane exactly when
// its VRC z component is 0, a parallel or oblique projection names no vanishing point, and the
// vanishing-N scenes show N.
TEST(VanishingText, VanishingTextFollowsTheGeometryInEveryBundledScene) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(VPLAB_ASSETS) / "scenes")) {
    if (entry.path().extension() != ".json" || entry.path().stem() == "large-mesh") continue;
    SCOPED_TRACE(entry.path().filename().string());
    const Scene scene = loadScene(entry.path());
    const PipelineRun run = runPipeline(scene);
    ++scenes;
    for (const ObjectRun& o : run.objects) {
      const VanishingText t = vanishingText(run, o);
      int points = 0;
      for (int a = 0; a < 3; ++a) {
        const Vec3 axisVrc = Vec3(run.vrcFromWc * o.wcFromMc * Vec4(a == 0, a == 1, a == 2, 0));
        const bool parallel = std::abs(axisVrc.z) <= 1e-9 * glm::length(axisVrc);
        EXPECT_EQ(t.axes[size_t(a)].find("parallel to the view plane") != std::string::npos &&
                      t.axes[size_t(a)].find("not parallel") == std::string::npos,
                  parallel)
            << t.axes[size_t(a)];
        points += t.axes[size_t(a)].find("meet at DC") != std::string::npos;
        if (scene.camera.projection != Projection::perspective) {
          EXPECT_EQ(t.axes[size_t(a)].find("meet"), std::string::npos) << t.axes[size_t(a)];
        }
      }
      const std::string stem = entry.path().stem().string();
      if (stem.rfind("vanishing-", 0) == 0 && o.name == run.objects.front().name) {
        EXPECT_EQ(points, stem.back() - '0') << t.headline;
      }
    }
  }
  EXPECT_GE(scenes, 10);
}

TEST(VanishingText, CavalierZAxisIsNotParallelToTheViewPlane) {
  const Scene scene = loadScene(std::filesystem::path(VPLAB_ASSETS) / "scenes" / "oblique-cavalier.json");
  const PipelineRun run = runPipeline(scene);
  ASSERT_FALSE(run.objects.empty());
  const VanishingText t = vanishingText(run, run.objects.front());
  EXPECT_NE(t.axes[2].find("not parallel to the view plane"), std::string::npos) << t.axes[2];
  EXPECT_NE(t.headline.find("oblique"), std::string::npos) << t.headline;
}

}  // namespace
}  // namespace vplab
