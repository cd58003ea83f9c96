#include "app/export/cpu_raster.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace vplab {

namespace {

/// The colour image and a depth buffer of z_dc values (larger = nearer). Depth starts at 0, the back
/// plane: GL's depth buffer cleared to 1 holds window depth 1 − z_npc = 1 there.
struct Target {
  Image image;
  std::vector<double> depth;

  Target(int width, int height, Rgba background)
      : image(width, height, background), depth(size_t(width) * size_t(height), 0.0) {}
};

/// The edge function of the directed edge a → b at p: (b − a) × (p − a). In DC's axes (x right,
/// y down) it is positive on the screen's clockwise side: below an edge that points right.
///
/// Two triangles sharing an edge traverse it in opposite directions. Computing (b − a) × (p − a)
/// and (a − b) × (p − b) rounds differently, so a centre very close to the edge could land inside
/// both triangles or neither. Evaluating the edge always from its lexicographically smaller
/// endpoint and negating (exact) gives both triangles the same magnitude with opposite signs, as
/// the integer edge functions of a GPU do.
double edgeFunction(const Vec3& a, const Vec3& b, double px, double py) {
  const bool canonical = a.y < b.y || (a.y == b.y && a.x <= b.x);
  const Vec3& u = canonical ? a : b;
  const Vec3& v = canonical ? b : a;
  const double e = (v.x - u.x) * (py - u.y) - (v.y - u.y) * (px - u.x);
  return canonical ? e : -e;
}

/// Whether centres exactly on the directed edge a → b belong to the triangle, for a triangle whose
/// interior lies on the positive side of its edges. GL's top-left rule is measured from the window
/// origin at the bottom left with y up (see cpu_raster.h); mirrored into DC (y_dc = H − y_w) it
/// keeps left edges and bottom edges:
/// - left edge: the interior lies at larger x, i.e. the edge's gradient (−dy, dx) has −dy > 0;
/// - bottom edge: horizontal (dy = 0) with the interior at smaller y_dc (above it on screen),
///   i.e. the gradient's y component dx is negative.
bool ownsCentresOnEdge(const Vec3& a, const Vec3& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  return dy < 0 || (dy == 0 && dx < 0);
}

/// One triangle ready for the pixel loop: vertices ordered so the interior is on the positive side
/// of every edge, and each edge's tie-breaking decision.
struct Triangle {
  Vec3 v[3];
  bool owns[3];  // edge i runs from v[i] to v[(i + 1) % 3]
};

/// Orients a, b, c so that the interior lies on the positive side; false when the triangle has no
/// area (or a non-finite vertex), which covers no pixel centre in GL either and would give the depth
/// interpolation a zero denominator.
bool setUpTriangle(const Vec3& a, const Vec3& b, const Vec3& c, Triangle& t) {
  if (!isFinite(a) || !isFinite(b) || !isFinite(c)) return false;
  const double area2 = edgeFunction(a, b, c.x, c.y);  // twice the signed area
  if (area2 == 0 || !std::isfinite(area2)) return false;
  // No culling: a triangle seen from behind is reversed instead of dropped.
  t.v[0] = a;
  t.v[1] = area2 > 0 ? b : c;
  t.v[2] = area2 > 0 ? c : b;
  for (int i = 0; i < 3; ++i) t.owns[i] = ownsCentresOnEdge(t.v[i], t.v[(i + 1) % 3]);
  return true;
}

/// The pixels [first, last] whose centres x + 0.5 lie in [lo, hi], cut to [0, size − 1]. Computed in
/// double before converting, so huge coordinates (divide-first strategy) cannot overflow an int.
bool pixelRange(double lo, double hi, int size, int& first, int& last) {
  const double f = std::max(0.0, std::ceil(lo - 0.5));
  const double l = std::min(double(size) - 1, std::floor(hi - 0.5));
  if (!(f <= l)) return false;
  first = int(f);
  last = int(l);
  return true;
}

/// The interpolated z_dc at a covered centre, or a negative value when it is not covered. The three
/// edge functions are the centre's barycentric weights times twice the area: z_dc is affine in
/// screen space (like GL's window depth), so these weights interpolate it exactly.
double coveredDepth(const Triangle& t, double px, double py) {
  double e[3];
  for (int i = 0; i < 3; ++i) {
    e[i] = edgeFunction(t.v[i], t.v[(i + 1) % 3], px, py);
    if (e[i] < 0 || (e[i] == 0 && !t.owns[i])) return -1;
  }
  const double sum = e[0] + e[1] + e[2];
  if (!(sum > 0)) return -1;
  // Edge i is opposite vertex (i + 2) % 3, so its function weighs that vertex.
  const double z = (e[1] * t.v[0].z + e[2] * t.v[1].z + e[0] * t.v[2].z) / sum;
  return std::clamp(z, 0.0, 1.0);  // GL clamps window depth to the depth range
}

/// Fills one triangle into the target with the depth test "strictly nearer than stored" (GL_LESS on
/// window depth 1 − z_dc).
void fillTriangle(const Triangle& t, Rgba color, Target& target) {
  int x0, x1, y0, y1;
  const auto [minX, maxX] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
  const auto [minY, maxY] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
  if (!pixelRange(minX, maxX, target.image.width, x0, x1) ||
      !pixelRange(minY, maxY, target.image.height, y0, y1))
    return;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double z = coveredDepth(t, x + 0.5, y + 0.5);
      double& stored = target.depth[size_t(y) * size_t(target.image.width) + size_t(x)];
      if (z > stored) {
        stored = z;
        target.image.at(x, y) = color;
      }
    }
  }
}

/// Rounds x and y to multiples of 1 / 2^bits (none for bits ≤ 0), ties to even as llvmpipe's
/// lrintf. Snapping y_dc is the same as snapping GL's y_w = H − y_dc: H · 2^bits is an even integer
/// and rounding half to even is symmetric.
Vec3 snapToSubpixels(Vec3 p, int subpixelBits) {
  if (subpixelBits <= 0) return p;
  const double scale = std::ldexp(1.0, subpixelBits);
  p.x = std::nearbyint(p.x * scale) / scale;
  p.y = std::nearbyint(p.y * scale) / scale;
  return p;
}

/// A clipped convex polygon as the fan (0, i, i + 1), the order mesh.h's triangulated() uses.
void fillPolygon(const ObjectRun& object, std::span<const uint32_t> refs, Rgba color, int subpixelBits,
                 Target& target) {
  if (refs.size() < 3) return;
  const auto vertex = [&](size_t i) { return snapToSubpixels(object.clippedDc(refs[i]), subpixelBits); };
  const Vec3 first = vertex(0);
  for (size_t i = 1; i + 1 < refs.size(); ++i) {
    Triangle t;
    if (setUpTriangle(first, vertex(i), vertex(i + 1), t)) fillTriangle(t, color, target);
  }
}

}  // namespace

uint8_t unorm8(double c) {
  if (!(c > 0)) return 0;                   // also NaN, which GL converts to 0
  const float f = float(std::min(c, 1.0));  // GL receives the colour as a 32-bit float
  // llvmpipe: f · (255/256) as a float multiply (exact in double, then one rounding to float), then
  // + 2^15 in float, whose ulp is 1/256, keeping the low 8 mantissa bits: round-half-even of
  // 256 · that product. nearbyint in the default rounding mode is that rounding.
  const float scaled = float(double(f) * (255.0 / 256.0));
  return uint8_t(std::nearbyint(double(scaled) * 256.0));
}

Rgba rgbaFromColor(const Vec3& color) { return {unorm8(color.x), unorm8(color.y), unorm8(color.z), 255}; }

Image rasterizeClippedPolygons(const PipelineRun& run, const Vec3& background, int width, int height,
                               int subpixelBits) {
  Target target(std::max(width, 0), std::max(height, 0), rgbaFromColor(background));
  // Scene order, then face order: the order the GLSL path draws in, which decides depth ties.
  for (const ObjectRun& object : run.objects) {
    const Rgba color = rgbaFromColor(object.color);
    for (size_t f = 0; f < object.faceCount(); ++f)
      fillPolygon(object, object.clippedFace(f), color, subpixelBits, target);
  }
  return std::move(target.image);
}

}  // namespace vplab
