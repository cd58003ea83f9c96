// The image tests run on Mesa's llvmpipe, whatever GPU the machine has: the goldens, the CPU/GPU
// parity and the EGL/OSMesa byte equality were made with it and depend on its rasterisation
// rules. tests/CMakeLists.txt pins it for every test of test_app (and the real-window tests)
// through the environment (VPLAB_SOFTWARE_GL_ENVIRONMENT: LIBGL_ALWAYS_SOFTWARE=1,
// GALLIUM_DRIVER=llvmpipe, libglvnd's Mesa vendor); this test fails when a context of the tests
// is made on anything else (a GPU's driver, or softpipe). Run outside ctest with
// GALLIUM_DRIVER=softpipe it fails, under ctest it passes: the pin overrides the caller's choice.
#include "tests/support/gl_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace vplab {
namespace {

using ::testing::HasSubstr;

std::string rendererOf(GlContext& context) {
  context.makeCurrent();
  const auto* name = reinterpret_cast<const char*>(context.gl().GetString(GL_RENDERER));
  return name ? name : "(no GL_RENDERER)";
}

TEST(SoftwareRenderer, EglContextsOfTheTestsRunOnLlvmpipe) {
  EXPECT_THAT(rendererOf(*test::egl().context), HasSubstr("llvmpipe"));
  EXPECT_TRUE(test::egl().context->softwareRenderer());
}

TEST(SoftwareRenderer, OsMesaContextsOfTheTestsRunOnLlvmpipe) {
  EXPECT_THAT(rendererOf(*test::osmesa().context), HasSubstr("llvmpipe"));
  test::egl();  // current again for whatever runs next in this process
}

// `vplab render`'s automatic choice (EGL, then OSMesa), as the command-line tests use it.
TEST(SoftwareRenderer, TheAutomaticHeadlessContextRunsOnLlvmpipe) {
  const auto context = createHeadlessContext(Backend::automatic, false);
  EXPECT_THAT(rendererOf(*context), HasSubstr("llvmpipe"));
  test::egl();
}

}  // namespace
}  // namespace vplab
