// GLSL programs from the files in shaders/ (embedded into the executable at build time, so vplab
// runs from any working directory). Compile and link errors throw vplab::Error with the file name
// and the driver's info log, as ImGui's OpenGL3 backend reports them.
//
// The files carry no #version line: one text serves desktop OpenGL 3.3 core ("#version 330 core")
// and OpenGL ES 3.0 / WebGL2 ("#version 300 es"), and the loader puts the line of the context's
// dialect first. Shaders mark what differs with GL_ES, which only GLSL ES predefines.
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

/// The GLSL a context compiles: 3.30 core on desktop OpenGL, ES 3.00 on OpenGL ES 3 (and WebGL2).
enum class GlslDialect { core330, es300 };
/// The dialect of the context whose functions `gl` holds (by its GL_VERSION, "OpenGL ES …" or not).
GlslDialect dialectOf(const GladGLContext& gl);
/// "#version 330 core" or "#version 300 es".
std::string_view versionLine(GlslDialect dialect);
/// The text handed to the compiler for embedded file `fileName`: the dialect's #version line,
/// `defines` ("#define X\n…"), a #line directive (so the driver's line numbers are the file's),
/// then the file.
std::string shaderText(std::string_view fileName, GlslDialect dialect, std::string_view defines = {});

struct ShaderStage {
  GLenum type;           // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER
  std::string_view name; // file name, for messages
  std::string_view source;
};

class Program {
 public:
  Program() = default;
  /// Compiles and links the stages. Throws vplab::Error "shaders/NAME: compile failed: LOG".
  Program(const GladGLContext& gl, std::initializer_list<ShaderStage> stages);
  /// The same from an embedded vertex and fragment file, by name ("scene.vert", "scene.frag", …),
  /// stage by extension, as shaderText gives them for the context's dialect.
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
