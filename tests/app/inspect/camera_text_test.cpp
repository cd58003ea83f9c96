// What makes a camera invalid, in the viewer's language (app/inspect/camera_text.h): in English word for
// word cameraError's text (the pipeline's, which files and the command line show), in German with the
// same values.
#include "app/inspect/camera_text.h"
#include "pipeline/scene.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>

namespace vplab {
namespace {

using ::testing::HasSubstr;
using K = CameraProblem::Kind;

TEST(CameraText, EveryProblemIsSaidAsThePipelineSaysItAndInGerman) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::map<K, std::function<void(Camera&)>> breaks = {
      {K::vectorsNotFinite, [&](Camera& c) { c.vup.x = nan; }},
      {K::planesNotFinite, [&](Camera& c) { c.window.xmax = INFINITY; }},
      {K::prpOnVrp, [](Camera& c) { c.prp = c.vrp; }},
      {K::vupZero, [](Camera& c) { c.vup = Vec3(0); }},
      {K::vupAlongN, [](Camera& c) { c.vup = 2.0 * (c.prp - c.vrp); }},
      {K::windowX, [](Camera& c) { c.window.xmin = 3; }},
      {K::windowY, [](Camera& c) { c.window.ymax = -2; }},
      {K::backNotBehindFront, [](Camera& c) { c.back = 4; }},
      {K::frontBehindEye, [](Camera& c) { c.front = 9; c.back = 1; }},
      {K::obliqueFactors, [](Camera& c) { c.projection = Projection::oblique; c.oblique.d = -1; }},
      {K::mappingNotFinite, [](Camera& c) { c.prp = {0, 0, 1e10}; c.window = {0, 1e-300, -1, 1}; }},  // camera_test.cpp
  };
  for (const auto& [kind, breakIt] : breaks) {
    Camera c = defaultScene().camera;
    ASSERT_FALSE(cameraProblem(c));
    breakIt(c);
    const std::optional<CameraProblem> p = cameraProblem(c);
    ASSERT_TRUE(p) << int(kind);
    EXPECT_EQ(int(p->kind), int(kind));
    const std::string english = cameraProblemText(*p, c, Language::en), german = cameraProblemText(*p, c, Language::de);
    EXPECT_EQ(english, cameraError(c).value_or("valid?")) << int(kind);
    EXPECT_NE(german, english) << int(kind);
    EXPECT_EQ(german.find('{'), std::string::npos) << german;  // every placeholder filled
    SCOPED_TRACE(german);
    if (kind == K::frontBehindEye) {
      EXPECT_THAT(german, HasSubstr("F = 9"));
      EXPECT_THAT(german, HasSubstr("vordere Clippingebene"));
    }
    if (kind == K::windowX) {
      EXPECT_THAT(german, HasSubstr("xmin = 3, xmax = 2.4"));
    }
  }
}

}  // namespace
}  // namespace vplab
