// GLSL programs (app/gl/shader.h): every embedded shader the app uses compiles and links on the
// headless context; a compile or link error throws a vplab::Error that names the file(s) and carries
// the driver's info log (checked against the log the driver gives for the same source directly).
#include "app/gl/shader.h"
#include "tests/support/gl_test_support.h"
#include "tests/support/test_util.h"

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

/// Every program the app builds, in each variant of defines it builds it with.
struct ProgramVariant {
  std::string_view vertex, fragment;
  std::string defines;
};
std::vector<ProgramVariant> appPrograms() {
  std::vector<ProgramVariant> v = {{"line.vert", "line.frag", ""},    {"line.vert", "line.frag", "#define USER_PLANES\n"},
                                   {"point.vert", "point.frag", ""},  {"overlay.vert", "color.frag", ""},
                                   {"text.vert", "text.frag", ""}};
  for (int volumeTest = 0; volumeTest < 2; ++volumeTest)
    for (int lights = 0; lights <= 4; ++lights)
      for (int planes = 0; planes < 2; ++planes) {
        std::string d;
        if (volumeTest) d += "#define VOLUME_TEST\n";
        if (lights > 0) d += "#define SHADED\n#define LIGHT_COUNT " + std::to_string(lights) + "\n";
        if (planes) d += "#define USER_PLANES\n";
        v.push_back({"scene.vert", "scene.frag", d});
      }
  return v;
}

void expectEveryProgramLinks(GlContext& ctx) {
  for (const ProgramVariant& p : appPrograms()) {
    SCOPED_TRACE(std::string(p.vertex) + " + " + std::string(p.fragment) + " with " + p.defines);
    EXPECT_NO_THROW(gl::Program::fromFiles(ctx.gl(), {p.vertex, p.fragment}, p.defines));
  }
  EXPECT_NO_THROW(ctx.checkErrors("building the programs"));
}

TEST(Shaders, EveryProgramTheAppUsesCompilesAndLinks) {
  GlContext& ctx = *test::egl().context;
  EXPECT_EQ(gl::dialectOf(ctx.gl()), gl::GlslDialect::core330);
  expectEveryProgramLinks(ctx);
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
}

// The files carry no #version line; the loader puts the context's first, then the defines, then
// resets the line count so that the driver's messages name the file's own lines.
TEST(Shaders, TheLoaderPutsTheDialectsVersionLineFirst) {
  for (std::string_view f : {"scene.vert", "scene.frag", "line.vert", "line.frag", "point.vert", "point.frag",
                             "overlay.vert", "color.frag", "text.vert", "text.frag"}) {
    SCOPED_TRACE(f);
    const std::string text = "\n" + std::string(gl::embeddedShader(f));
    EXPECT_THAT(text, ::testing::Not(HasSubstr("\n#version")));  // (comments may name it)
  }
  EXPECT_EQ(gl::shaderText("color.frag", gl::GlslDialect::core330, "#define X\n"),
            "#version 330 core\n#define X\n#line 1\n" + std::string(gl::embeddedShader("color.frag")));
  EXPECT_EQ(gl::shaderText("color.frag", gl::GlslDialect::es300),
            "#version 300 es\n#line 1\n" + std::string(gl::embeddedShader("color.frag")));
  // A compile error's line number is the file's: line 3 of the fragment below is the broken one.
  GlContext& ctx = *test::egl().context;
  const std::string message = test::errorOf([&] {
    gl::Program(ctx.gl(), {{GL_VERTEX_SHADER, "good.vert", kGoodVertex},
                           {GL_FRAGMENT_SHADER, "broken.frag", "#version 330 core\n#define X\n#line 1\n"
                                                               "out vec4 fragColor;\n\nvoid main() { fragColor = y; }\n"}});
  });
  EXPECT_THAT(message, HasSubstr("0:3("));  // Mesa's "0:LINE(COLUMN): error: …"
  expectNoGlErrorAndDropCompilerMessages(ctx);
}

// WebGL2 compiles GLSL ES 3.00: every program, in every variant, compiles and links as such on an
// OpenGL ES 3.0 context (Mesa's, through EGL with EGL_OPENGL_ES_API). Mesa's ES compiler rejects
// what ES lacks (geometry stages, noperspective, gl_ClipDistance, missing precision).
TEST(Shaders, EveryProgramCompilesAndLinksAsGlslEs300) {
  const std::unique_ptr<GlContext> es = createEglEsContext(/*debug=*/true);  // Mesa always has one
  ASSERT_THAT(es->description(), HasSubstr("OpenGL ES 3."));
  EXPECT_EQ(gl::dialectOf(es->gl()), gl::GlslDialect::es300);
  expectEveryProgramLinks(*es);
  // and a desktop-only construct is an error there (so the check above means something)
  const std::string message = test::errorOf([&] {
    gl::Program(es->gl(), {{GL_VERTEX_SHADER, "np.vert", "#version 300 es\nnoperspective out float v;\n"
                                                         "void main() { v = 1.0; gl_Position = vec4(0.0); }\n"},
                           {GL_FRAGMENT_SHADER, "np.frag", "#version 300 es\nprecision highp float;\nnoperspective in float v;\n"
                                                           "out vec4 c;\nvoid main() { c = vec4(v); }\n"}});
  });
  EXPECT_THAT(message, HasSubstr("compile failed"));
  expectNoGlErrorAndDropCompilerMessages(*es);
}

}  // namespace
}  // namespace vplab
