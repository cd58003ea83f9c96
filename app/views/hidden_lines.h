// Hidden lines on the CPU (lecture notes 16.1 and 16.3): what the GL backend's depth buffer decides
// for a depth-tested line, point or translucent polygon (draw::Depth), decided here for the SVG
// backend with the views' own rule. The depth-writing faces drawn before a batch are kept as
// screen-space triangles with their exact plane depth (not a pixel z-buffer, so the answer does not
// depend on pixel centres and where it changes along a segment is found to a fraction of a pixel),
// sorted into a grid of cells. A face hides a point only when it lies in front of it by more than
// the glPolygonOffset(1, 2) the views push the depth-only faces back by: GL_LEQUAL fails when
// 1 − z_point > 1 − z_face + m + 2r, m the face's largest depth slope per pixel (factor 1), r the
// depth buffer's resolution 2^−24 (units 2). Faces drawn in colour are not pushed back: they hide
// what lies more than 2r behind them.
//
// No GL.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "app/views/projection.h"

namespace vplab::draw {

class DepthField {
 public:
  DepthField(int width, int height) : width_(width), height_(height) {}

  /// A polygon as GL fans it, from its first vertex; every triangle writes depth. `pushedBack`: drawn
  /// with glPolygonOffset(1, 2) (the hidden-line styles' depth-only faces); else it hides what lies
  /// behind it by more than the two depth-buffer steps of rounding only.
  void addFan(std::span<const PixelPoint> polygon, bool pushedBack = true);
  bool empty() const { return triangles_.empty(); }

  /// Whether a face hides the point. `pushBack`: the point's own polygon offset (a pushed-back
  /// translucent face loses the ties it would otherwise win).
  bool hides(const PixelPoint& p, double pushBack = 0) const;

  /// The segment a → b cut into pieces [t0, t1] that are all hidden or all visible: sampled every
  /// half pixel, each change of visibility found by bisection to 2^−16 of that, slivers under
  /// 0.05 px merged into their neighbours.
  struct Piece {
    double t0, t1;
    bool hidden;
  };
  std::vector<Piece> pieces(const PixelPoint& a, const PixelPoint& b) const;

  /// A convex polygon cut into parts that are all hidden or all visible: whole when its corners
  /// (pulled a quarter pixel inwards), edge midpoints and centre agree, else its fan's triangles
  /// split in four, recursively, down to about 2 px, each small triangle by its centre.
  struct Part {
    std::vector<PixelPoint> polygon;
    bool hidden;
  };
  std::vector<Part> parts(std::span<const PixelPoint> polygon, double pushBack = 0) const;

  /// The polygon offset of a face with these vertices: its largest depth slope per pixel plus two
  /// steps of a 24-bit depth buffer (glPolygonOffset(1, 2)).
  static double polygonOffset(const PixelPoint& a, const PixelPoint& b, const PixelPoint& c);

 private:
  struct Triangle {
    Vec2 v[3];
    Vec2 min, max;
    double sign;        // of the area: the inside of every edge function
    double zx, zy, z0;  // z = zx·x + zy·y + z0
    double offset;      // the polygon offset in z
  };
  void addTriangle(const PixelPoint& a, const PixelPoint& b, const PixelPoint& c, bool pushedBack);
  void index() const;  // sorts the triangles into the grid when some were added since the last query
  void split(const PixelPoint& a, const PixelPoint& b, const PixelPoint& c, double pushBack, int depth,
             std::vector<Part>& out) const;

  int width_, height_;
  std::vector<Triangle> triangles_;
  // The grid, rebuilt lazily by the first query after a face was added.
  mutable bool indexed_ = true;
  mutable double cell_ = 16;
  mutable int cols_ = 1, rows_ = 1;
  mutable std::vector<std::vector<uint32_t>> cells_ = std::vector<std::vector<uint32_t>>(1);
};

}  // namespace vplab::draw
