// GLSL programs from the files in shaders/ (embedded into the executable at build time, so vplab
// runs from any working directory). Compile and link errors throw vplab::Error with the file name
// and the driver's info log, as ImGui's OpenGL3 backend reports them.
#pragma once

#include "app/gl/objects.h"
#include "pipeline/math.h"

#include <initializer_list>
#include <string>
#include <string_view>
#include <unordered_map>

namespace vplab::gl {

/// The text of an embedded shader file, e.g. "scene.vert". Throws vplab::Error when unknown.
std::string_view embeddedShader(std::string_view fileName);

struct ShaderStage {
  GLenum type;           // GL_VERTEX_SHADER, GL_GEOMETRY_SHADER, GL_FRAGMENT_SHADER
  std::string_view name; // file name, for messages
  std::string_view source;
};

class Program {
 public:
  Program() = default;
  /// Compiles and links the stages. Throws vplab::Error "shaders/NAME: compile failed: LOG".
  Program(const GladGLContext& gl, std::initializer_list<ShaderStage> stages);
  /// The same from embedded files, by name ("scene.vert", "scene.frag", …), stage by extension.
  /// `defines` ("#define X\n…") go right after each file's #version line.
  static Program fromFiles(const GladGLContext& gl, std::initializer_list<std::string_view> files,
                           std::string_view defines = {});

  void use() const { gl_->UseProgram(id_.id()); }
  GLint location(const char* name) const;

  void set(const char* name, int v) const { gl_->Uniform1i(location(name), v); }
  void set(const char* name, float v) const { gl_->Uniform1f(location(name), v); }
  void set(const char* name, const glm::vec2& v) const { gl_->Uniform2f(location(name), v.x, v.y); }
  void set(const char* name, const glm::vec3& v) const { gl_->Uniform3f(location(name), v.x, v.y, v.z); }
  void set(const char* name, const glm::vec4& v) const { gl_->Uniform4f(location(name), v.x, v.y, v.z, v.w); }
  /// Matrices of the CPU pipeline, handed over as they are (converted to float).
  void set(const char* name, const Mat4& m) const;
  void set(const char* name, const Mat3& m) const;
  void set(const char* name, const Vec3& v) const { set(name, glm::vec3(v)); }

 private:
  const GladGLContext* gl_ = nullptr;
  ProgramId id_;
  mutable std::unordered_map<std::string, GLint> locations_;
};

}  // namespace vplab::gl
