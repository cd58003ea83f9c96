// The shaders' OpenGL ES 3.00 path draws the pixels of the desktop path (app/gl/shader.h): the same
// wide lines (dashes, smooth edges, a segment cut at the near plane, end colours) and the same flat
// polygon, cut by a user clip plane, drawn with the same calls on a desktop OpenGL 3.3 core context
// (noperspective, gl_ClipDistance) and on an OpenGL ES 3.0 context (the values times w divided per
// fragment; a clip distance varying and discard). Both are Mesa's llvmpipe, without multisampling.
//
// Tolerance: a pixel's centre is inside the clipped primitive exactly when the perspective-correct
// clip distance there is ≥ 0, and v·w / w is v, so the two paths agree up to float rounding: a
// channel may round to the neighbouring level (1), and a pixel whose centre lies within rounding
// of a cut, a dash end or the edge of the quad may flip (kMaxFlips, a handful at 96 × 96). A
// missing or misplaced line, dash or cut is tens of pixels and fails. Measured on Mesa 22.3.6: the
// lines differ in 33 to 126 pixels by 1 level (the smooth edge's alpha) and in none by more; the
// polygon is byte-identical. VPLAB_KEEP_IMAGES=1 leaves both pictures in the test output folder.
#include "app/gl/objects.h"
#include "app/gl/shader.h"
#include "app/views/image.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>

#include <glm/gtc/type_ptr.hpp>

#include <array>
#include <iostream>
#include <string>
#include <vector>

namespace vplab {
namespace {

constexpr int kSize = 96;
constexpr int kChannelThreshold = 1;
constexpr size_t kMaxFlips = 6;
const Rgba kBackground{40, 40, 40, 255};

struct LineEnd {
  glm::vec3 position;  // in the space the matrices below take to clip space
  glm::vec4 color;
};

// A perspective-like map (w = 1.5 + 0.5 z, between 1 and 2 for z in [−1, 1]), so that screen-linear
// and perspective-correct interpolation differ and the ES path's emulation of noperspective counts.
Mat4 clipFromPosition() {
  Mat4 m(1.0);
  m[2][3] = 0.5;  // column 2 (z), row 3 (w)
  m[3][3] = 1.5;
  return m;
}

// The plane x ≥ 0 (in the same space), kept side on the right half of the picture.
const Vec4 kPlane(1.0, 0.0, 0.0, 0.0);

struct Target {
  gl::Framebuffer fbo;
  gl::Renderbuffer color;
};

Target makeTarget(const GladGLContext& gl) {
  Target t{gl::makeFramebuffer(gl), gl::makeRenderbuffer(gl)};
  gl.BindRenderbuffer(GL_RENDERBUFFER, t.color.id());
  gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kSize, kSize);
  gl.BindFramebuffer(GL_FRAMEBUFFER, t.fbo.id());
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.color.id());
  EXPECT_EQ(gl.CheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  gl.Viewport(0, 0, kSize, kSize);
  gl.ClearColor(kBackground.r / 255.f, kBackground.g / 255.f, kBackground.b / 255.f, 1.f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  gl.Enable(GL_BLEND);
  gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  return t;
}

Image readBack(const GladGLContext& gl) {
  Image image(kSize, kSize);
  gl.ReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  return image;
}

void setMatrices(const gl::Program& p) {
  p.set("wcFromMc", Mat4(1.0));
  p.set("vrcFromWc", Mat4(1.0));
  p.set("npcFromVrc", clipFromPosition());
  p.set("glClipFromNpc", Mat4(1.0));
  p.set("userPlaneCount", 1);
  p.set("userPlanesWc[0]", glm::vec4(kPlane));
}

/// The user plane on: gl_ClipDistance needs its enable on desktop GL; GLSL ES has neither.
void enablePlane(GlContext& ctx, bool on) {
  if (gl::dialectOf(ctx.gl()) == gl::GlslDialect::core330) (on ? ctx.gl().Enable : ctx.gl().Disable)(GL_CLIP_DISTANCE0);
}

Image drawLines(GlContext& ctx, float widthPx, float dashPx) {
  ctx.makeCurrent();
  const GladGLContext& gl = ctx.gl();
  Target target = makeTarget(gl);
  const std::vector<LineEnd> segments = {
      {{-0.9f, -0.7f, 0.0f}, {1.f, 0.8f, 0.2f, 1.f}},  {{0.9f, -0.5f, 0.0f}, {1.f, 0.8f, 0.2f, 1.f}},
      {{-0.8f, 0.1f, -0.9f}, {0.2f, 0.6f, 1.f, 1.f}},  {{0.85f, 0.6f, 0.9f}, {1.f, 0.2f, 0.4f, 0.8f}},
      {{-0.6f, 0.8f, 0.5f}, {0.3f, 1.f, 0.3f, 1.f}},   {{0.7f, -0.1f, -0.4f}, {0.3f, 1.f, 0.3f, 1.f}},
      // from behind GL's near plane (z < −w) to inside: cut before the divide
      {{0.2f, -0.9f, -4.0f}, {1.f, 1.f, 1.f, 1.f}},    {{0.6f, 0.9f, 0.0f}, {1.f, 1.f, 1.f, 1.f}},
      // wholly behind it: nothing
      {{-0.5f, 0.0f, -5.0f}, {1.f, 0.f, 0.f, 1.f}},    {{0.5f, 0.0f, -6.0f}, {1.f, 0.f, 0.f, 1.f}},
  };
  gl::Program program = gl::Program::fromFiles(gl, {"line.vert", "line.frag"}, "#define USER_PLANES\n");
  program.use();
  setMatrices(program);
  program.set("viewportSize", glm::vec2(kSize, kSize));
  program.set("widthPx", widthPx);
  program.set("dashPx", dashPx);
  program.set("alphaScale", 1.f);
  gl::VertexArray vao = gl::makeVertexArray(gl);
  gl::Buffer vbo = gl::makeBuffer(gl);
  gl.BindVertexArray(vao.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo.id());
  gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(segments.size() * sizeof(LineEnd)), segments.data(), GL_STATIC_DRAW);
  for (GLuint end = 0; end < 2; ++end) {
    const size_t first = end * sizeof(LineEnd);
    gl.EnableVertexAttribArray(2 * end);
    gl.VertexAttribPointer(2 * end, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(LineEnd), reinterpret_cast<void*>(first));
    gl.VertexAttribDivisor(2 * end, 1);
    gl.EnableVertexAttribArray(2 * end + 1);
    gl.VertexAttribPointer(2 * end + 1, 4, GL_FLOAT, GL_FALSE, 2 * sizeof(LineEnd),
                           reinterpret_cast<void*>(first + offsetof(LineEnd, color)));
    gl.VertexAttribDivisor(2 * end + 1, 1);
  }
  enablePlane(ctx, true);
  gl.DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(segments.size() / 2));
  enablePlane(ctx, false);
  Image image = readBack(gl);
  ctx.checkErrors("drawing the lines");
  return image;
}

Image drawPolygon(GlContext& ctx) {
  ctx.makeCurrent();
  const GladGLContext& gl = ctx.gl();
  Target target = makeTarget(gl);
  const std::array<glm::vec3, 6> corners = {glm::vec3{-0.8f, -0.8f, -0.6f}, {0.8f, -0.7f, 0.7f}, {0.1f, 0.85f, 0.1f},
                                            glm::vec3{-0.9f, 0.2f, 0.9f},   {0.3f, -0.9f, -0.9f}, {0.9f, 0.9f, 0.0f}};
  gl::Program program = gl::Program::fromFiles(gl, {"scene.vert", "scene.frag"}, "#define USER_PLANES\n");
  program.use();
  setMatrices(program);
  program.set("wcNormalFromMc", Mat3(1.0));
  program.set("volumeNpcFromWc", Mat4(1.0));
  program.set("color", glm::vec3(0.3f, 0.7f, 0.9f));
  program.set("alpha", 0.75f);
  gl::VertexArray vao = gl::makeVertexArray(gl);
  gl::Buffer vbo = gl::makeBuffer(gl);
  gl.BindVertexArray(vao.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo.id());
  gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(sizeof corners), corners.data(), GL_STATIC_DRAW);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  gl.VertexAttrib3f(1, 0.f, 0.f, 1.f);
  enablePlane(ctx, true);
  gl.DrawArrays(GL_TRIANGLES, 0, GLsizei(corners.size()));
  enablePlane(ctx, false);
  Image image = readBack(gl);
  ctx.checkErrors("drawing the polygon");
  return image;
}

/// Pixels whose largest channel difference exceeds the threshold.
size_t flips(const Image& a, const Image& b) {
  size_t n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const Rgba &p = a.pixels[i], &q = b.pixels[i];
    const int d = std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)});
    n += d > kChannelThreshold;
  }
  return n;
}

/// Drawn pixels in columns [x0, x1) (rows: all).
size_t drawnIn(const Image& image, int x0, int x1) {
  size_t n = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = x0; x < x1; ++x) n += image.at(x, y) != kBackground;
  return n;
}

struct Contexts {
  GlContext& desktop = *test::egl().context;
  std::unique_ptr<GlContext> es = createEglEsContext(/*debug=*/true);
};

void expectSamePicture(const Image& desktop, const Image& es, const std::string& name) {
  // The plane x ≥ 0 keeps the right half: the left half (minus the widest quad's reach) is empty.
  EXPECT_EQ(drawnIn(desktop, 0, kSize / 2 - 5), 0u) << name << ": drawn where the user plane cuts";
  EXPECT_EQ(drawnIn(es, 0, kSize / 2 - 5), 0u) << name << " (GLSL ES): drawn where the user plane cuts";
  EXPECT_GT(drawnIn(desktop, kSize / 2, kSize), 200u) << name << ": too little drawn";
  const size_t n = flips(desktop, es);
  std::cout << name << ": " << n << " pixels differ by more than " << kChannelThreshold << " level\n";
  EXPECT_LE(n, kMaxFlips) << name << ": the GLSL ES path differs from the desktop one";
  if (n > kMaxFlips || ::testing::Test::HasFailure() || std::getenv("VPLAB_KEEP_IMAGES")) {
    writePng(desktop, test::outputDir() / (name + ".desktop.png"));
    writePng(es, test::outputDir() / (name + ".es.png"));
  }
}

TEST(GlesShaders, WideLinesCutByAUserPlaneMatchTheDesktopPath) {
  Contexts c;
  for (const auto& [width, dash] : {std::pair{3.f, 0.f}, std::pair{6.f, 0.f}, std::pair{4.f, 5.f}}) {
    const std::string name = "gles-lines-w" + std::to_string(int(width)) + "-d" + std::to_string(int(dash));
    expectSamePicture(drawLines(c.desktop, width, dash), drawLines(*c.es, width, dash), name);
  }
}

TEST(GlesShaders, PolygonsCutByAUserPlaneMatchTheDesktopPath) {
  Contexts c;
  expectSamePicture(drawPolygon(c.desktop), drawPolygon(*c.es), "gles-polygon");
}

}  // namespace
}  // namespace vplab
