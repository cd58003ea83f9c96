#include "app/gl/texture_io.h"

#include "base/error.h"

#include <algorithm>
#include <vector>

namespace vplab {

Image readTexture(const GladGLContext& gl, GLuint texture) {
  if (!gl.GetTexLevelParameteriv || !gl.GetTexImage)  // OpenGL ES and WebGL2 have neither
    throw Error("this OpenGL cannot read a view's texture back (OpenGL ES has no glGetTexImage)");
  GLint w = 0, h = 0;
  gl.BindTexture(GL_TEXTURE_2D, texture);
  gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
  if (w <= 0 || h <= 0) throw Error("the view has no image to export yet");
  std::vector<Rgba> rows(size_t(w) * size_t(h));
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  Image image;
  image.width = w;
  image.height = h;
  image.pixels.resize(rows.size());
  for (int y = 0; y < h; ++y)
    std::copy_n(rows.begin() + ptrdiff_t(h - 1 - y) * w, w, image.pixels.begin() + ptrdiff_t(y) * w);
  return image;
}

GLuint uploadImageTo(const GladGLContext& gl, gl::Texture& texture, const Image& image) {
  std::vector<Rgba> rows(image.pixels.size());
  for (int y = 0; y < image.height; ++y)
    std::copy_n(image.pixels.begin() + ptrdiff_t(y) * image.width, image.width,
                rows.begin() + ptrdiff_t(image.height - 1 - y) * image.width);
  if (!texture) texture = gl::makeTexture(gl);
  gl.BindTexture(GL_TEXTURE_2D, texture.id());
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                rows.data());
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return texture.id();
}

}  // namespace vplab
