// A texture's pixels to and from an Image (top row first): the views' textures are drawn by GL with
// the bottom row first.
#pragma once

#include "app/gl/objects.h"
#include "app/views/image.h"

namespace vplab {

/// Reads a view's texture (rows bottom first, as drawn) as an image with the top row first. Throws
/// vplab::Error on OpenGL ES, which cannot read a texture back.
Image readTexture(const GladGLContext& gl, GLuint texture);
/// Uploads `image` (top row first) into `texture` bottom row first, as the views' textures are;
/// makes the texture when it has none. Returns its name.
GLuint uploadImageTo(const GladGLContext& gl, gl::Texture& texture, const Image& image);

}  // namespace vplab
