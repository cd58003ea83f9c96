// GLSL programs (app/gl/shader.h): every embedded shader the app uses compiles and links on the
// headless context; a compile or link error throws a vplab::Error that names the file(s) and carries
// the driver's info log (checked against the log the driver gives for the same source directly).
#include "app/gl/shader.h"
#include "tests/app/gl_test_support.h"
#include "tests/pipeline/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace vplab {
namespace {

using ::testing::HasSubstr;

constexpr std::string_view kGoodVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";

// An undeclared identifier: a compile error.
constexpr std::string_view kBrokenFragment = R"(#version 330 core
out vec4 fragColor;
void main() { fragColor = vec4(undeclaredColour, 1.0); }
)";

// Compiles (a declared function may be defined in another shader of the stage), but no shader
// defines it: a link error.
constexpr std::string_view kUnresolvedFragment = R"(#version 330 core
vec4 missingFunction();
out vec4 fragColor;
void main() { fragColor = missingFunction(); }
)";

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\0' || s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

/// A failed compile or link sets no GL error (glGetError), but Mesa also sends its log through
/// KHR_debug as an error message, which the context collects, so the next checkErrors would throw
/// with it. Such messages are dropped here (after checking that glGetError is clean).
void expectNoGlErrorAndDropCompilerMessages(GlContext& ctx) {
  EXPECT_EQ(ctx.gl().GetError(), GLenum(GL_NO_ERROR));
  try {
    ctx.checkErrors("a failed compile or link");
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::Not(HasSubstr("GL_INVALID"))) << e.what();
  }
}

/// The driver's compile log for `source`, straight from the GL API (not through gl::Program).
std::string compileLog(const GladGLContext& gl, GLenum type, std::string_view source, bool* ok) {
  const GLuint s = gl.CreateShader(type);
  const GLchar* text = source.data();
  const GLint length = GLint(source.size());
  gl.ShaderSource(s, 1, &text, &length);
  gl.CompileShader(s);
  GLint status = 0, logLength = 0;
  gl.GetShaderiv(s, GL_COMPILE_STATUS, &status);
  gl.GetShaderiv(s, GL_INFO_LOG_LENGTH, &logLength);
  std::string log(size_t(std::max(logLength, 1)), '\0');
  gl.GetShaderInfoLog(s, logLength, nullptr, log.data());
  gl.DeleteShader(s);
  *ok = status != 0;
  return trimmed(log);
}

/// The driver's link log for the two sources.
std::string linkLog(const GladGLContext& gl, std::string_view vertex, std::string_view fragment, bool* ok) {
  const GLuint p = gl.CreateProgram();
  GLuint shaders[2];
  const std::string_view sources[2] = {vertex, fragment};
  const GLenum types[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
  for (int i = 0; i < 2; ++i) {
    shaders[i] = gl.CreateShader(types[i]);
    const GLchar* text = sources[i].data();
    const GLint length = GLint(sources[i].size());
    gl.ShaderSource(shaders[i], 1, &text, &length);
    gl.CompileShader(shaders[i]);
    gl.AttachShader(p, shaders[i]);
  }
  gl.LinkProgram(p);
  GLint status = 0, logLength = 0;
  gl.GetProgramiv(p, GL_LINK_STATUS, &status);
  gl.GetProgramiv(p, GL_INFO_LOG_LENGTH, &logLength);
  std::string log(size_t(std::max(logLength, 1)), '\0');
  gl.GetProgramInfoLog(p, logLength, nullptr, log.data());
  for (GLuint s : shaders) gl.DeleteShader(s);
  gl.DeleteProgram(p);
  *ok = status != 0;
  return trimmed(log);
}

TEST(Shaders, EveryProgramTheAppUsesCompilesAndLinks) {
  GlContext& ctx = *test::egl().context;
  const std::vector<std::vector<std::string_view>> programs = {{"scene.vert", "scene.frag"},
                                                              {"overlay.vert", "line.geom", "line.frag"},
                                                              {"overlay.vert", "point.geom", "point.frag"},
                                                              {"overlay.vert", "color.frag"},
                                                              {"text.vert", "text.frag"}};
  for (const auto& files : programs) {
    SCOPED_TRACE(files.front());
    if (files.size() == 2) EXPECT_NO_THROW(gl::Program::fromFiles(ctx.gl(), {files[0], files[1]}));
    else EXPECT_NO_THROW(gl::Program::fromFiles(ctx.gl(), {files[0], files[1], files[2]}));
  }
  EXPECT_NO_THROW(ctx.checkErrors("building the programs"));
}

TEST(Shaders, CompileErrorNamesTheFileAndCarriesTheInfoLog) {
  GlContext& ctx = *test::egl().context;
  bool compiled = true;
  const std::string log = compileLog(ctx.gl(), GL_FRAGMENT_SHADER, kBrokenFragment, &compiled);
  ASSERT_FALSE(compiled);
  ASSERT_FALSE(log.empty());
  const std::string message = test::errorOf([&] {
    gl::Program(ctx.gl(), {{GL_VERTEX_SHADER, "good.vert", kGoodVertex}, {GL_FRAGMENT_SHADER, "broken.frag", kBrokenFragment}});
  });
  EXPECT_THAT(message, HasSubstr("shaders/broken.frag"));
  EXPECT_THAT(message, HasSubstr("compile failed"));
  EXPECT_THAT(message, HasSubstr(log));                 // the driver's whole log
  EXPECT_THAT(message, HasSubstr("undeclaredColour"));  // which names the culprit
  EXPECT_THAT(message, ::testing::Not(HasSubstr("good.vert")));
  expectNoGlErrorAndDropCompilerMessages(ctx);
}

TEST(Shaders, LinkErrorNamesTheFilesAndCarriesTheInfoLog) {
  GlContext& ctx = *test::egl().context;
  bool linked = true;
  const std::string log = linkLog(ctx.gl(), kGoodVertex, kUnresolvedFragment, &linked);
  ASSERT_FALSE(linked);
  ASSERT_FALSE(log.empty());
  const std::string message = test::errorOf([&] {
    gl::Program(ctx.gl(),
                {{GL_VERTEX_SHADER, "good.vert", kGoodVertex}, {GL_FRAGMENT_SHADER, "unresolved.frag", kUnresolvedFragment}});
  });
  EXPECT_THAT(message, HasSubstr("shaders/good.vert + shaders/unresolved.frag"));
  EXPECT_THAT(message, HasSubstr("link failed"));
  EXPECT_THAT(message, HasSubstr(log));
  EXPECT_THAT(message, HasSubstr("missingFunction"));
  expectNoGlErrorAndDropCompilerMessages(ctx);
}

TEST(Shaders, UnknownEmbeddedFilesAndStagesAreErrors) {
  GlContext& ctx = *test::egl().context;
  EXPECT_THAT(test::errorOf([] { gl::embeddedShader("nonexistent.frag"); }), HasSubstr("nonexistent.frag"));
  EXPECT_THAT(test::errorOf([&] { gl::Program::fromFiles(ctx.gl(), {"scene.vert", "scene.txt"}); }),
              HasSubstr("shaders/scene.txt: unknown shader stage"));
  EXPECT_FALSE(gl::embeddedShader("scene.vert").empty());
  EXPECT_THAT(std::string(gl::embeddedShader("scene.vert")), HasSubstr("#version 330 core"));
}

}  // namespace
}  // namespace vplab
