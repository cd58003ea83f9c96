// An off-screen render target: an RGBA8 colour texture and a 24-bit depth buffer, optionally
// multisampled (resolved into the texture). Every view draws into one; the viewer shows the texture,
// `vplab render` reads it back.
#pragma once

#include "app/gl/objects.h"
#include "app/views/image.h"

namespace vplab::gl {

/// Reads width × height pixels of a framebuffer (0: the window) as an image, top row first.
Image readPixels(const GladGLContext& gl, GLuint framebuffer, int width, int height);

class RenderTarget {
 public:
  /// `checkComplete`: whether resize asks the driver if the framebuffer is complete. Not where that
  /// question waits for every draw queued (WebGL: GlContext::readingErrorsWaits): there a framebuffer
  /// that is not complete makes its draws GL_INVALID_FRAMEBUFFER_OPERATION, read with the frame's errors.
  explicit RenderTarget(const GladGLContext& gl, bool checkComplete = true) : gl_(&gl), checkComplete_(checkComplete) {}

  /// (Re)allocates for w × h pixels with `samples` per pixel (1: no multisampling).
  void resize(int width, int height, int samples = 1);
  /// Binds the framebuffer to draw into and sets the viewport to the whole target.
  void bind() const;
  /// Resolves the multisampled buffer into the colour texture (no-op without multisampling).
  void resolve() const;
  /// The resolved colour as an image with the top row first.
  Image read() const;

  GLuint colorTexture() const { return color_.id(); }
  /// The framebuffer holding the resolved colour (what the viewer draws its whole window into when
  /// headless).
  GLuint framebuffer() const { return resolved_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

 private:
  const GladGLContext* gl_;
  int width_ = 0, height_ = 0, samples_ = 1;
  bool checkComplete_;
  int checkedSamples_ = 0;  // the sample count found complete (0: none yet)
  Texture color_;
  Framebuffer resolved_;      // colour texture
  Framebuffer drawn_;         // the multisampled buffers, or == resolved_ when samples_ == 1
  Renderbuffer msColor_, depth_;
};

}  // namespace vplab::gl
