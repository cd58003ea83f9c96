// Owned OpenGL objects: each remembers the context that made it and deletes itself (RAII), so
// renderers hold them as plain members.
#pragma once

#include <glad/gl.h>

#include <utility>

namespace vplab::gl {

enum class Kind { buffer, vertexArray, texture, framebuffer, renderbuffer, program };

template <Kind K>
class Object {
 public:
  Object() = default;
  Object(const GladGLContext& gl, GLuint id) : gl_(&gl), id_(id) {}
  ~Object() { reset(); }
  Object(Object&& o) noexcept : gl_(o.gl_), id_(std::exchange(o.id_, 0)) {}
  Object& operator=(Object&& o) noexcept {
    if (this != &o) {
      reset();
      gl_ = o.gl_;
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }

  void reset() {
    if (!id_) return;
    switch (K) {
      case Kind::buffer: gl_->DeleteBuffers(1, &id_); break;
      case Kind::vertexArray: gl_->DeleteVertexArrays(1, &id_); break;
      case Kind::texture: gl_->DeleteTextures(1, &id_); break;
      case Kind::framebuffer: gl_->DeleteFramebuffers(1, &id_); break;
      case Kind::renderbuffer: gl_->DeleteRenderbuffers(1, &id_); break;
      case Kind::program: gl_->DeleteProgram(id_); break;
    }
    id_ = 0;
  }

 private:
  const GladGLContext* gl_ = nullptr;
  GLuint id_ = 0;
};

using Buffer = Object<Kind::buffer>;
using VertexArray = Object<Kind::vertexArray>;
using Texture = Object<Kind::texture>;
using Framebuffer = Object<Kind::framebuffer>;
using Renderbuffer = Object<Kind::renderbuffer>;
using ProgramId = Object<Kind::program>;

inline Buffer makeBuffer(const GladGLContext& gl) {
  GLuint id = 0;
  gl.GenBuffers(1, &id);
  return {gl, id};
}
inline VertexArray makeVertexArray(const GladGLContext& gl) {
  GLuint id = 0;
  gl.GenVertexArrays(1, &id);
  return {gl, id};
}
inline Texture makeTexture(const GladGLContext& gl) {
  GLuint id = 0;
  gl.GenTextures(1, &id);
  return {gl, id};
}
inline Framebuffer makeFramebuffer(const GladGLContext& gl) {
  GLuint id = 0;
  gl.GenFramebuffers(1, &id);
  return {gl, id};
}
inline Renderbuffer makeRenderbuffer(const GladGLContext& gl) {
  GLuint id = 0;
  gl.GenRenderbuffers(1, &id);
  return {gl, id};
}

}  // namespace vplab::gl
