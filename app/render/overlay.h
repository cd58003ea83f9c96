// Wireframe overlays from the CPU pipeline: thick (optionally dashed) lines, marker discs and
// translucent triangles, all in one space (WC for the world view, NPC for the NPC view, DC for the
// camera view), drawn through a ViewCamera with the pipeline's own matrices.
#pragma once

#include "app/gl/objects.h"
#include "app/gl/shader.h"
#include "app/views/view_camera.h"

#include <glm/glm.hpp>

#include <map>
#include <utility>
#include <vector>

namespace vplab {

struct OverlayVertex {
  glm::vec3 position;
  glm::vec4 color;
};

/// Line, point and triangle lists, grouped by style so each group is one draw call.
class OverlayBatch {
 public:
  void line(const Vec3& a, const Vec3& b, const glm::vec4& color, float widthPx = 2.f, float dashPx = 0.f);
  void polyline(const std::vector<Vec3>& points, bool closed, const glm::vec4& color, float widthPx = 2.f,
                float dashPx = 0.f);
  void point(const Vec3& p, const glm::vec4& color, float sizePx = 10.f);
  void triangle(const Vec3& a, const Vec3& b, const Vec3& c, const glm::vec4& color);
  void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const glm::vec4& color);
  void clear();
  bool empty() const { return lines_.empty() && points_.empty() && triangles_.empty(); }

  // (width, dash) → segment end points; size → points; triangles.
  const std::map<std::pair<float, float>, std::vector<OverlayVertex>>& lines() const { return lines_; }
  const std::map<float, std::vector<OverlayVertex>>& points() const { return points_; }
  const std::vector<OverlayVertex>& triangles() const { return triangles_; }

 private:
  std::map<std::pair<float, float>, std::vector<OverlayVertex>> lines_;
  std::map<float, std::vector<OverlayVertex>> points_;
  std::vector<OverlayVertex> triangles_;
};

/// test: hidden by objects in front; ignore: always on top; xray: the hidden part faint, the rest
/// as usual (camera markers inside objects stay visible); hiddenOnly: only the hidden part.
enum class OverlayDepth { test, ignore, xray, hiddenOnly };

class OverlayRenderer {
 public:
  explicit OverlayRenderer(const GladGLContext& gl);
  /// Multiplies every line width and point size (lecture mode on a projector).
  void setScale(float scale) { scale_ = scale; }
  /// User clip planes in WC (DGL wiki) for drawMeshEdges; empty: none.
  void setUserPlanes(std::vector<Vec4> planesWc) { userPlanes_ = std::move(planesWc); }
  /// Draws the batch seen through `view` into the current viewport of `width` × `height` pixels:
  /// triangles first, then lines, then points.
  void draw(const OverlayBatch& batch, const ViewCamera& view, int width, int height, OverlayDepth depth,
            const Mat4& wcFromMc = Mat4(1.0));
  /// Only the lines of a batch, with the depth function given (hidden-line passes).
  void drawLines(const OverlayBatch& batch, const ViewCamera& view, int width, int height, const Mat4& wcFromMc,
                 float alphaScale = 1.f);
  /// The edges of a GPU mesh (see GpuMesh) as thick lines of one colour, optionally dashed.
  void drawMeshEdges(GLuint edgeVao, GLsizei edgeCount, const ViewCamera& view, const Mat4& wcFromMc, int width,
                     int height, const glm::vec4& color, float widthPx, float dashPx);

 private:
  void setCamera(const gl::Program& p, const ViewCamera& view, const Mat4& wcFromMc) const;
  void drawPass(const OverlayBatch& batch, const ViewCamera& view, int width, int height, const Mat4& wcFromMc,
                float alphaScale);
  void upload(const std::vector<OverlayVertex>& vertices);

  const GladGLContext* gl_;
  bool es_ = false;  // OpenGL ES: the clip distances are the shaders' own (no GL_CLIP_DISTANCEi)
  float scale_ = 1.f;
  std::vector<Vec4> userPlanes_;
  gl::Program lines_, points_, triangles_;
  gl::Program clippedLines_;  // lines_ with the user clip planes (USER_PLANES), for objects' edges
  gl::VertexArray vao_;         // vbo_ as OverlayVertex: locations 0, 1
  gl::VertexArray segmentVao_;  // vbo_ as pairs of OverlayVertex per instance: locations 0 … 3
  gl::Buffer vbo_;
};

}  // namespace vplab
