#include "app/render/overlay.h"

#include "app/views/display_list.h"

#include <algorithm>
#include <string>

namespace vplab {

void OverlayBatch::line(const Vec3& a, const Vec3& b, const glm::vec4& color, float widthPx, float dashPx) {
  auto& v = lines_[{widthPx, dashPx}];
  v.push_back({glm::vec3(a), color});
  v.push_back({glm::vec3(b), color});
}

void OverlayBatch::polyline(const std::vector<Vec3>& points, bool closed, const glm::vec4& color, float widthPx,
                            float dashPx) {
  if (points.size() < 2) return;
  for (size_t i = 0; i + 1 < points.size(); ++i) line(points[i], points[i + 1], color, widthPx, dashPx);
  if (closed && points.size() > 2) line(points.back(), points.front(), color, widthPx, dashPx);
}

void OverlayBatch::point(const Vec3& p, const glm::vec4& color, float sizePx) {
  points_[sizePx].push_back({glm::vec3(p), color});
}

void OverlayBatch::triangle(const Vec3& a, const Vec3& b, const Vec3& c, const glm::vec4& color) {
  triangles_.insert(triangles_.end(), {{glm::vec3(a), color}, {glm::vec3(b), color}, {glm::vec3(c), color}});
}

void OverlayBatch::quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const glm::vec4& color) {
  triangle(a, b, c, color);
  triangle(a, c, d, color);
}

void OverlayBatch::clear() {
  lines_.clear();
  points_.clear();
  triangles_.clear();
}

OverlayRenderer::OverlayRenderer(const GladGLContext& gl)
    : gl_(&gl),
      es_(gl::dialectOf(gl) == gl::GlslDialect::es300),
      lines_(gl::Program::fromFiles(gl, {"line.vert", "line.frag"})),
      points_(gl::Program::fromFiles(gl, {"point.vert", "point.frag"})),
      triangles_(gl::Program::fromFiles(gl, {"overlay.vert", "color.frag"})),
      clippedLines_(gl::Program::fromFiles(gl, {"line.vert", "line.frag"}, "#define USER_PLANES\n")),
      vao_(gl::makeVertexArray(gl)),
      segmentVao_(gl::makeVertexArray(gl)),
      vbo_(gl::makeBuffer(gl)) {
  // Vertices (triangles) and, with divisor 1, points: position and colour of one OverlayVertex.
  gl.BindVertexArray(vao_.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo_.id());
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(OverlayVertex), nullptr);
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(OverlayVertex),
                         reinterpret_cast<void*>(offsetof(OverlayVertex, color)));
  // Segments (line.vert): a pair of OverlayVertex per instance, the same buffer read two at a time.
  gl.BindVertexArray(segmentVao_.id());
  for (GLuint end = 0; end < 2; ++end) {
    const size_t first = end * sizeof(OverlayVertex);
    gl.EnableVertexAttribArray(2 * end);
    gl.VertexAttribPointer(2 * end, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(OverlayVertex), reinterpret_cast<void*>(first));
    gl.VertexAttribDivisor(2 * end, 1);
    gl.EnableVertexAttribArray(2 * end + 1);
    gl.VertexAttribPointer(2 * end + 1, 4, GL_FLOAT, GL_FALSE, 2 * sizeof(OverlayVertex),
                           reinterpret_cast<void*>(first + offsetof(OverlayVertex, color)));
    gl.VertexAttribDivisor(2 * end + 1, 1);
  }
  gl.BindVertexArray(0);
}

void OverlayRenderer::setCamera(const gl::Program& p, const ViewCamera& view, const Mat4& wcFromMc) const {
  p.set("wcFromMc", wcFromMc);
  p.set("vrcFromWc", view.vrcFromWc);
  p.set("npcFromVrc", view.npcFromVrc);
  p.set("glClipFromNpc", glClipFromNpc());
}

void OverlayRenderer::upload(const std::vector<OverlayVertex>& vertices) {
  gl_->BindVertexArray(vao_.id());
  gl_->BindBuffer(GL_ARRAY_BUFFER, vbo_.id());
  gl_->BufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(OverlayVertex)), vertices.data(),
                  GL_STREAM_DRAW);
}

void OverlayRenderer::drawLines(const OverlayBatch& batch, const ViewCamera& view, int width, int height,
                                const Mat4& wcFromMc, float alphaScale) {
  const GladGLContext& gl = *gl_;
  lines_.use();
  lines_.set("alphaScale", alphaScale);
  setCamera(lines_, view, wcFromMc);
  lines_.set("viewportSize", glm::vec2(width, height));
  for (const auto& [style, vertices] : batch.lines()) {
    lines_.set("widthPx", style.first * scale_);
    lines_.set("dashPx", style.second);
    upload(vertices);
    gl.BindVertexArray(segmentVao_.id());
    gl.DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(vertices.size() / 2));
  }
}

void OverlayRenderer::draw(const OverlayBatch& batch, const ViewCamera& view, int width, int height,
                           OverlayDepth depth, const Mat4& wcFromMc) {
  const GladGLContext& gl = *gl_;
  gl.DepthMask(GL_FALSE);
  gl.Enable(GL_BLEND);
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.Disable(GL_CULL_FACE);
  switch (depth) {
    case OverlayDepth::ignore:
      gl.Disable(GL_DEPTH_TEST);
      drawPass(batch, view, width, height, wcFromMc, 1.f);
      break;
    case OverlayDepth::xray:
      gl.Enable(GL_DEPTH_TEST);
      gl.DepthFunc(GL_GREATER);
      drawPass(batch, view, width, height, wcFromMc, draw::kXrayAlpha);
      [[fallthrough]];
    case OverlayDepth::test:
      gl.Enable(GL_DEPTH_TEST);
      gl.DepthFunc(GL_LEQUAL);
      drawPass(batch, view, width, height, wcFromMc, 1.f);
      break;
    case OverlayDepth::hiddenOnly:
      gl.Enable(GL_DEPTH_TEST);
      gl.DepthFunc(GL_GREATER);
      drawPass(batch, view, width, height, wcFromMc, 1.f);
      break;
  }
  gl.BindVertexArray(0);
  gl.DepthMask(GL_TRUE);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
}

void OverlayRenderer::drawPass(const OverlayBatch& batch, const ViewCamera& view, int width, int height,
                               const Mat4& wcFromMc, float alphaScale) {
  const GladGLContext& gl = *gl_;
  if (!batch.triangles().empty()) {
    triangles_.use();
    setCamera(triangles_, view, wcFromMc);
    triangles_.set("alphaScale", alphaScale);
    upload(batch.triangles());
    gl.DrawArrays(GL_TRIANGLES, 0, GLsizei(batch.triangles().size()));
  }
  drawLines(batch, view, width, height, wcFromMc, alphaScale);
  points_.use();
  setCamera(points_, view, wcFromMc);
  points_.set("viewportSize", glm::vec2(width, height));
  points_.set("alphaScale", alphaScale);
  gl.BindVertexArray(vao_.id());
  gl.VertexAttribDivisor(0, 1);  // one instance (a quad) per point
  gl.VertexAttribDivisor(1, 1);
  for (const auto& [size, vertices] : batch.points()) {
    points_.set("sizePx", size * scale_);
    upload(vertices);
    gl.DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(vertices.size()));
  }
  gl.BindVertexArray(vao_.id());
  gl.VertexAttribDivisor(0, 0);
  gl.VertexAttribDivisor(1, 0);
}

void OverlayRenderer::drawMeshEdges(GLuint edgeVao, GLsizei edgeCount, const ViewCamera& view,
                                    const Mat4& wcFromMc, int width, int height, const glm::vec4& color,
                                    float widthPx, float dashPx) {
  const GladGLContext& gl = *gl_;
  const int planes = int(std::min<size_t>(userPlanes_.size(), 6));
  const gl::Program& p = planes > 0 ? clippedLines_ : lines_;
  p.use();
  setCamera(p, view, wcFromMc);
  p.set("viewportSize", glm::vec2(width, height));
  p.set("widthPx", widthPx * scale_);
  p.set("dashPx", dashPx);
  p.set("alphaScale", 1.f);
  for (int i = 0; i < planes; ++i) {
    p.set(("userPlanesWc[" + std::to_string(i) + "]").c_str(), glm::vec4(userPlanes_[size_t(i)]));
    if (!es_) gl.Enable(GL_CLIP_DISTANCE0 + GLenum(i));
  }
  p.set("userPlaneCount", planes);
  gl.BindVertexArray(edgeVao);
  gl.VertexAttrib4f(1, color.r, color.g, color.b, color.a);  // the colours are not arrays here
  gl.VertexAttrib4f(3, color.r, color.g, color.b, color.a);
  gl.DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, edgeCount);
  gl.BindVertexArray(0);
  if (!es_)
    for (int i = 0; i < planes; ++i) gl.Disable(GL_CLIP_DISTANCE0 + GLenum(i));
}

}  // namespace vplab
