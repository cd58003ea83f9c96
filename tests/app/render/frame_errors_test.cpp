// A frame's GL errors (app/render/frame_errors.h): read at the frame's end where that costs nothing, and
// where reading them waits for the GPU (WebGL) at the start of a later frame, once the GPU has passed
// the frame before: late, but neither lost nor read twice.
#include "app/render/frame_errors.h"
#include "base/error.h"
#include "tests/support/gl_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace vplab {
namespace {

using ::testing::HasSubstr;

/// A deliberate GL error: GL_INVALID_ENUM.
void makeAnError(const GladGLContext& gl) { gl.Enable(0xFFFF); }

std::string thrownBy(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(FrameErrors, AtOnceTheFramesErrorsAreThrownAtItsEnd) {
  GlContext& context = *test::egl().context;
  context.discardErrors();
  FrameErrors errors(context, /*deferred=*/false);
  errors.frameStarts();
  errors.frameEnds();  // a frame without an error
  errors.frameStarts();
  makeAnError(context.gl());
  EXPECT_THAT(thrownBy([&] { errors.frameEnds(); }), HasSubstr("GL_INVALID_ENUM"));
  errors.frameStarts();
  EXPECT_EQ(thrownBy([&] { errors.frameEnds(); }), "") << "an error read twice";
}

TEST(FrameErrors, DeferredTheyAreThrownAtALaterFramesStartOnceTheGpuPassedTheFrameBefore) {
  GlContext& context = *test::egl().context;
  context.discardErrors();
  FrameErrors errors(context, /*deferred=*/true);
  errors.frameStarts();  // no fence yet: nothing read
  makeAnError(context.gl());
  EXPECT_EQ(thrownBy([&] { errors.frameEnds(); }), "") << "read at the frame's end: that waits for the GPU";
  context.gl().Finish();  // the GPU has passed the frame
  EXPECT_THAT(thrownBy([&] { errors.frameStarts(); }), HasSubstr("GL_INVALID_ENUM"));
  // Read once: the next frames see none.
  errors.frameEnds();
  context.gl().Finish();
  EXPECT_EQ(thrownBy([&] { errors.frameStarts(); }), "");
  errors.frameEnds();
  // A lost context's fence is forgotten, not deleted; the next frame's end puts a new one.
  errors.forgetFence();
  EXPECT_EQ(thrownBy([&] { errors.frameStarts(); }), "");
  makeAnError(context.gl());
  errors.frameEnds();
  context.gl().Finish();
  EXPECT_THAT(thrownBy([&] { errors.frameStarts(); }), HasSubstr("GL_INVALID_ENUM"));
}

}  // namespace
}  // namespace vplab
