#include "app/gl/render_target.h"

#include "base/error.h"

#include <algorithm>

namespace vplab::gl {

void RenderTarget::resize(int width, int height, int samples) {
  if (width == width_ && height == height_ && samples == samples_ && color_) return;
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw Error("a render target of " + std::to_string(width) + " × " + std::to_string(height) + " pixels is not possible");
  const GladGLContext& gl = *gl_;
  width_ = width;
  height_ = height;
  samples_ = std::max(1, samples);

  color_ = makeTexture(gl);
  gl.BindTexture(GL_TEXTURE_2D, color_.id());
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  resolved_ = makeFramebuffer(gl);
  gl.BindFramebuffer(GL_FRAMEBUFFER, resolved_.id());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.id(), 0);

  depth_ = makeRenderbuffer(gl);
  gl.BindRenderbuffer(GL_RENDERBUFFER, depth_.id());
  if (samples_ == 1) {
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    drawn_ = Framebuffer();
    msColor_ = Renderbuffer();
  } else {
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, width, height);
    msColor_ = makeRenderbuffer(gl);
    gl.BindRenderbuffer(GL_RENDERBUFFER, msColor_.id());
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width, height);
    drawn_ = makeFramebuffer(gl);
    gl.BindFramebuffer(GL_FRAMEBUFFER, drawn_.id());
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msColor_.id());
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  }
  // Completeness depends on the attachments' formats and sample count, always the same but the count,
  // not on the size (one the driver refuses is a GL error of the allocation above, read with the
  // frame's errors). So it is checked once a count: in WebGL the check is a round trip that waits
  // for every draw queued (issue 42), and the page's views are resized whenever their windows are.
  const bool known = !checkComplete_ || samples_ == checkedSamples_;
  const GLenum status = known ? GL_FRAMEBUFFER_COMPLETE : gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status == GL_FRAMEBUFFER_COMPLETE) checkedSamples_ = samples_;
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Error("the framebuffer for " + std::to_string(width) + " × " + std::to_string(height) + " × " +
                std::to_string(samples_) + " samples is incomplete (status " + std::to_string(status) + ")");
}

void RenderTarget::bind() const {
  gl_->BindFramebuffer(GL_FRAMEBUFFER, samples_ > 1 ? drawn_.id() : resolved_.id());
  gl_->Viewport(0, 0, width_, height_);
}

void RenderTarget::resolve() const {
  if (samples_ == 1) return;
  gl_->BindFramebuffer(GL_READ_FRAMEBUFFER, drawn_.id());
  gl_->BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_.id());
  gl_->BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
}

Image readPixels(const GladGLContext& gl, GLuint framebuffer, int width, int height) {
  Image image(width, height);
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<Rgba> rows(image.pixels.size());
  gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  // GL's window y points up, DC's down: GL row 0 is the bottom row.
  for (int y = 0; y < height; ++y)
    std::copy_n(rows.begin() + ptrdiff_t(y) * width, width, image.pixels.begin() + ptrdiff_t(height - 1 - y) * width);
  return image;
}

Image RenderTarget::read() const {
  resolve();
  return readPixels(*gl_, resolved_.id(), width_, height_);
}

}  // namespace vplab::gl
