#include "app/views/hidden_lines.h"

#include <algorithm>
#include <cmath>

namespace vplab::draw {

namespace {
constexpr double kSampleStepPx = 0.5;  // visibility samples along a segment, at most this far apart
constexpr int kBisections = 16;        // where visibility changes: to 0.5 / 2^16 px
constexpr double kMinPiecePx = 0.05;   // shorter visible/hidden pieces are numerical noise: merged
constexpr double kSmallestPartPx = 2;  // polygons are split no finer than this
constexpr int kMaxSplits = 8;          // … and at most this many times (2^16 parts of a triangle)
}  // namespace

double DepthField::polygonOffset(const PixelPoint& a, const PixelPoint& b, const PixelPoint& c) {
  const double area2 = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  const double r2 = 2.0 * std::ldexp(1.0, -24);
  if (!(std::abs(area2) > 1e-9)) return r2;
  const double zx = ((b.z - a.z) * (c.y - a.y) - (c.z - a.z) * (b.y - a.y)) / area2;
  const double zy = ((c.z - a.z) * (b.x - a.x) - (b.z - a.z) * (c.x - a.x)) / area2;
  return std::max(std::abs(zx), std::abs(zy)) + r2;
}

void DepthField::addFan(std::span<const PixelPoint> polygon, bool pushedBack) {
  for (size_t i = 1; i + 1 < polygon.size(); ++i)
    addTriangle(polygon[0], polygon[i], polygon[i + 1], pushedBack);
}

void DepthField::addTriangle(const PixelPoint& a, const PixelPoint& b, const PixelPoint& c, bool pushedBack) {
  const double area2 = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  if (!(std::abs(area2) > 1e-9)) return;  // degenerate (or not finite): GL draws nothing either
  Triangle t;
  t.v[0] = {a.x, a.y};
  t.v[1] = {b.x, b.y};
  t.v[2] = {c.x, c.y};
  t.min = glm::min(t.v[0], glm::min(t.v[1], t.v[2]));
  t.max = glm::max(t.v[0], glm::max(t.v[1], t.v[2]));
  t.sign = area2 > 0 ? 1.0 : -1.0;
  t.zx = ((b.z - a.z) * (c.y - a.y) - (c.z - a.z) * (b.y - a.y)) / area2;
  t.zy = ((c.z - a.z) * (b.x - a.x) - (b.z - a.z) * (c.x - a.x)) / area2;
  t.z0 = a.z - t.zx * a.x - t.zy * a.y;
  t.offset = pushedBack ? polygonOffset(a, b, c) : 2.0 * std::ldexp(1.0, -24);
  triangles_.push_back(t);
  indexed_ = false;
}

// Cells about twice the size of an average triangle's box: 1 px for a million-polygon sphere, 16 px
// at most.
void DepthField::index() const {
  if (indexed_) return;
  double area = 0;
  for (const Triangle& t : triangles_) area += (t.max.x - t.min.x) * (t.max.y - t.min.y);
  const double typical = triangles_.empty() ? 16.0 : 2.0 * std::sqrt(area / double(triangles_.size()));
  cell_ = std::clamp(std::round(typical), 1.0, 16.0);
  cols_ = std::max(1, int(std::ceil(width_ / cell_)));
  rows_ = std::max(1, int(std::ceil(height_ / cell_)));
  cells_.assign(size_t(cols_) * size_t(rows_), {});
  for (uint32_t i = 0; i < triangles_.size(); ++i) {
    const Triangle& t = triangles_[i];
    const int x0 = std::clamp(int(std::floor(t.min.x / cell_)), 0, cols_ - 1);
    const int x1 = std::clamp(int(std::floor(t.max.x / cell_)), 0, cols_ - 1);
    const int y0 = std::clamp(int(std::floor(t.min.y / cell_)), 0, rows_ - 1);
    const int y1 = std::clamp(int(std::floor(t.max.y / cell_)), 0, rows_ - 1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) cells_[size_t(y) * size_t(cols_) + size_t(x)].push_back(i);
  }
  indexed_ = true;
}

bool DepthField::hides(const PixelPoint& p, double pushBack) const {
  if (triangles_.empty() || !std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  index();
  const int cx = std::clamp(int(std::floor(p.x / cell_)), 0, cols_ - 1);
  const int cy = std::clamp(int(std::floor(p.y / cell_)), 0, rows_ - 1);
  for (uint32_t i : cells_[size_t(cy) * size_t(cols_) + size_t(cx)]) {
    const Triangle& t = triangles_[i];
    if (p.x < t.min.x || p.x > t.max.x || p.y < t.min.y || p.y > t.max.y) continue;
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      const Vec2 &a = t.v[k], &b = t.v[(k + 1) % 3];
      inside = t.sign * ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) >= 0;
    }
    if (inside && p.z - pushBack < t.zx * p.x + t.zy * p.y + t.z0 - t.offset) return true;
  }
  return false;
}

std::vector<DepthField::Piece> DepthField::pieces(const PixelPoint& a, const PixelPoint& b) const {
  const double len = distancePx(a, b);
  if (triangles_.empty()) return {{0.0, 1.0, false}};
  const int n = std::max(1, int(std::ceil(len / kSampleStepPx)));
  std::vector<Piece> out;
  bool prev = hides(a);
  double start = 0;
  for (int i = 1; i <= n; ++i) {
    const double t = double(i) / n;
    const bool cur = hides(mix(a, b, t));
    if (cur == prev) continue;
    double lo = double(i - 1) / n, hi = t;
    for (int k = 0; k < kBisections; ++k) {
      const double mid = 0.5 * (lo + hi);
      (hides(mix(a, b, mid)) == prev ? lo : hi) = mid;
    }
    const double cut = 0.5 * (lo + hi);
    out.push_back({start, cut, prev});
    start = cut;
    prev = cur;
  }
  out.push_back({start, 1.0, prev});
  // Slivers (a sample grazing a face's border) take their neighbour's side, then equal neighbours merge.
  for (size_t i = 0; i < out.size() && out.size() > 1; ++i)
    if ((out[i].t1 - out[i].t0) * len < kMinPiecePx) out[i].hidden = out[i > 0 ? i - 1 : i + 1].hidden;
  std::vector<Piece> merged;
  for (const Piece& p : out) {
    if (!merged.empty() && merged.back().hidden == p.hidden)
      merged.back().t1 = p.t1;
    else
      merged.push_back(p);
  }
  return merged;
}

std::vector<DepthField::Part> DepthField::parts(std::span<const PixelPoint> polygon, double pushBack) const {
  std::vector<Part> out;
  if (polygon.size() < 3) return out;
  const std::vector<PixelPoint> whole(polygon.begin(), polygon.end());
  if (triangles_.empty()) return {{whole, false}};
  PixelPoint centre{0, 0, 0};
  for (const PixelPoint& p : polygon) centre = {centre.x + p.x, centre.y + p.y, centre.z + p.z};
  const double n = double(polygon.size());
  centre = {centre.x / n, centre.y / n, centre.z / n};
  const bool hidden = hides(centre, pushBack);
  bool uniform = true;
  for (size_t i = 0; i < polygon.size() && uniform; ++i) {
    const PixelPoint& p = polygon[i];
    const double d = distancePx(p, centre);
    const PixelPoint inner = d > 0.25 ? mix(p, centre, 0.25 / d) : centre;
    uniform = hides(inner, pushBack) == hidden &&
              hides(mix(p, polygon[(i + 1) % polygon.size()], 0.5), pushBack) == hidden;
  }
  if (uniform) return {{whole, hidden}};
  for (size_t i = 1; i + 1 < polygon.size(); ++i)
    split(polygon[0], polygon[i], polygon[i + 1], pushBack, 0, out);
  return out;
}

void DepthField::split(const PixelPoint& a, const PixelPoint& b, const PixelPoint& c, double pushBack,
                       int depth, std::vector<Part>& out) const {
  const PixelPoint centre{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3};
  const double longest = std::max({distancePx(a, b), distancePx(b, c), distancePx(c, a)});
  const bool ha = hides(a, pushBack), hb = hides(b, pushBack), hc = hides(c, pushBack);
  const bool hm = hides(centre, pushBack);
  if (depth >= kMaxSplits || longest <= kSmallestPartPx || (ha == hb && hb == hc && hc == hm)) {
    out.push_back({{a, b, c}, hm});
    return;
  }
  const PixelPoint ab = mix(a, b, 0.5), bc = mix(b, c, 0.5), ca = mix(c, a, 0.5);
  split(a, ab, ca, pushBack, depth + 1, out);
  split(ab, b, bc, pushBack, depth + 1, out);
  split(ca, bc, c, pushBack, depth + 1, out);
  split(ab, bc, ca, pushBack, depth + 1, out);
}

}  // namespace vplab::draw
