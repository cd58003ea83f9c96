// A frame's GL errors read without waiting for the GPU (issue 42: no frame of the page's over 50 ms).
// glGetError is a round trip in WebGL: Chrome's GPU process first runs every draw queued before it
// (on SwiftShader a large view's slice: 100 ms and more, in the frame that asked). Errors are flags
// kept until read, so the page reads them later instead: at the start of a frame, when the GPU has
// passed the fence put after the frame before (nothing queued then, nothing to wait for). Elsewhere
// (a driver that answers at once) each frame's are read at its end.
#pragma once

#include "app/context/context.h"

#include <string_view>

namespace vplab {

class FrameErrors {
 public:
  /// Reads `context`'s errors at each frame's end, or when `deferred` as above.
  FrameErrors(GlContext& context, bool deferred) : ctx_(context), deferred_(deferred) {}
  ~FrameErrors();
  FrameErrors(const FrameErrors&) = delete;
  FrameErrors& operator=(const FrameErrors&) = delete;

  /// Before a frame's first GL call: deferred, throws vplab::Error (GlContext::checkErrors) for the
  /// errors of the frames the GPU has passed.
  void frameStarts();
  /// After a frame's last GL call: throws for its errors, or (deferred) puts a fence after it.
  void frameEnds();
  /// The context lost its objects (WebGL): the fence went with them.
  void forgetFence() { fence_ = nullptr; }

 private:
  GlContext& ctx_;
  bool deferred_;
  GLsync fence_ = nullptr;
};

}  // namespace vplab
