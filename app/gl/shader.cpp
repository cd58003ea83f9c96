#include "app/gl/shader.h"

#include "base/error.h"

#include <glm/gtc/type_ptr.hpp>

#include <vector>

namespace vplab::gl {

namespace {

std::string infoLog(const GladGLContext& gl, GLuint object, bool isProgram) {
  GLint length = 0;
  (isProgram ? gl.GetProgramiv : gl.GetShaderiv)(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(size_t(std::max(length, 1)), '\0');
  (isProgram ? gl.GetProgramInfoLog : gl.GetShaderInfoLog)(object, length, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

GLenum stageOf(std::string_view file) {
  if (file.ends_with(".vert")) return GL_VERTEX_SHADER;
  if (file.ends_with(".frag")) return GL_FRAGMENT_SHADER;
  throw Error("shaders/" + std::string(file) + ": unknown shader stage (expected .vert or .frag)");
}

}  // namespace

GlslDialect dialectOf(const GladGLContext& gl) {
  const auto* version = reinterpret_cast<const char*>(gl.GetString(GL_VERSION));
  return version && std::string_view(version).starts_with("OpenGL ES") ? GlslDialect::es300 : GlslDialect::core330;
}

std::string_view versionLine(GlslDialect dialect) {
  return dialect == GlslDialect::es300 ? "#version 300 es" : "#version 330 core";
}

std::string shaderText(std::string_view fileName, GlslDialect dialect, std::string_view defines) {
  std::string text(versionLine(dialect));
  text += '\n';
  text += defines;
  if (!defines.empty() && !defines.ends_with('\n')) text += '\n';
  text += "#line 1\n";  // GLSL 3.30 and ES 3.00: the next line is line 1
  text += embeddedShader(fileName);
  return text;
}

Program::Program(const GladGLContext& gl, std::initializer_list<ShaderStage> stages) : gl_(&gl) {
  id_ = ProgramId(gl, gl.CreateProgram());
  std::vector<GLuint> shaders;
  auto cleanup = [&] {
    for (GLuint s : shaders) gl.DeleteShader(s);
  };
  std::string names;
  for (const ShaderStage& st : stages) {
    names += (names.empty() ? "" : " + ") + std::string("shaders/") + std::string(st.name);
    const GLuint s = gl.CreateShader(st.type);
    shaders.push_back(s);
    const GLchar* text = st.source.data();
    const GLint length = GLint(st.source.size());
    gl.ShaderSource(s, 1, &text, &length);
    gl.CompileShader(s);
    GLint ok = 0;
    gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      const std::string log = infoLog(gl, s, false);
      cleanup();
      throw Error("shaders/" + std::string(st.name) + ": compile failed:\n" + log);
    }
    gl.AttachShader(id_.id(), s);
  }
  gl.LinkProgram(id_.id());
  cleanup();
  GLint ok = 0;
  gl.GetProgramiv(id_.id(), GL_LINK_STATUS, &ok);
  if (!ok) throw Error(names + ": link failed:\n" + infoLog(gl, id_.id(), true));
}

Program Program::fromFiles(const GladGLContext& gl, std::initializer_list<std::string_view> files,
                           std::string_view defines) {
  std::vector<ShaderStage> stages;
  std::vector<std::string> sources;  // with #version and the defines; ShaderStage only views them
  sources.reserve(files.size());
  const GlslDialect dialect = dialectOf(gl);
  for (std::string_view f : files) {
    const GLenum stage = stageOf(f);  // an unknown extension is the first thing to report
    sources.push_back(shaderText(f, dialect, defines));
    stages.push_back({stage, f, sources.back()});
  }
  if (stages.size() != 2) throw Error("a program needs a vertex and a fragment shader file");
  return Program(gl, {stages[0], stages[1]});
}

GLint Program::location(const char* name) const {
  auto it = locations_.find(name);
  if (it != locations_.end()) return it->second;
  const GLint loc = gl_->GetUniformLocation(id_.id(), name);
  locations_.emplace(name, loc);
  return loc;
}

void Program::set(const char* name, const Mat4& m) const {
  const glm::mat4 f(m);
  gl_->UniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(f));
}

void Program::set(const char* name, const Mat3& m) const {
  const glm::mat3 f(m);
  gl_->UniformMatrix3fv(location(name), 1, GL_FALSE, glm::value_ptr(f));
}

}  // namespace vplab::gl
