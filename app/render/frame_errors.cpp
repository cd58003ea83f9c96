#include "app/render/frame_errors.h"

namespace vplab {

FrameErrors::~FrameErrors() {
  if (fence_) ctx_.gl().DeleteSync(fence_);
}

void FrameErrors::frameStarts() {
  if (!deferred_ || !fence_) return;
  const GladGLContext& gl = ctx_.gl();
  GLint status = GL_SIGNALED;  // the status never waits (ViewImages::passedSliceFence)
  gl.GetSynciv(fence_, GL_SYNC_STATUS, 1, nullptr, &status);
  if (status == GL_UNSIGNALED) return;
  gl.DeleteSync(fence_);
  fence_ = nullptr;
  ctx_.checkErrors("drawing the viewer's last frames");
}

void FrameErrors::frameEnds() {
  if (!deferred_) {
    ctx_.checkErrors("drawing the viewer's frame");
    return;
  }
  // After this frame, the last one: when the GPU has passed it at the next frame's start, nothing is
  // queued, and reading the errors waits for nothing.
  const GladGLContext& gl = ctx_.gl();
  if (fence_) gl.DeleteSync(fence_);
  fence_ = gl.FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

}  // namespace vplab
