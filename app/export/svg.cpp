// Index: 1 SVG text  2 fonts and labels  3 projection and clipping  4 visibility  5 the drawing
//        6 camera view  7 world view  8 NPC view  9 documents and files
//
// Each view is rebuilt here from the same inputs its GPU drawing uses (views/*_view.cpp), step by
// step in the same order, but into SVG elements instead of GL draw calls; the comments name the
// GPU code each part mirrors.
#include "app/views/number_text.h"
#include "app/export/svg.h"

#include "app/views/render_request.h"
#include "app/export/cpu_raster.h"
#include "app/render/text.h"
#include "app/views/view_camera.h"
#include "app/views/theme.h"
#include "app/views/view_geometry.h"
#include "pipeline/error.h"
#include "pipeline/vanishing_points.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <unordered_set>
#include <variant>
#include <vector>

namespace vplab {

namespace {

constexpr double kSampleStepPx = 0.5;  // visibility samples along a segment, at most this far apart
constexpr int kBisections = 16;        // where visibility changes: to 0.5 / 2^16 px
constexpr double kMinPiecePx = 0.05;   // shorter visible/hidden pieces are numerical noise: merged
constexpr double kXrayAlpha = 0.3;     // OverlayRenderer::draw's x-ray pass (overlay.cpp)
constexpr double kInkPx = 1.0;         // line.frag: full coverage over widthPx, then a 1 px ramp per side
constexpr double kGap = 6;             // ViewRenderer::compose: between the panels of "all"

// ---------------------------------------------------------------- 1 SVG text

/// At most `decimals` decimals, trailing zeros dropped: 12.5, 640, -0.25.
std::string num(double v, int decimals = 2) {
  if (!std::isfinite(v)) v = 0;
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  std::string s(buf, r.ptr);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

/// num() appended without a temporary string (a large mesh writes millions of coordinates).
void appendNum(std::string& out, double v) {
  if (!std::isfinite(v)) v = 0;
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 2);
  char* end = r.ptr;
  if (std::find(buf, end, '.') != end) {
    while (end[-1] == '0') --end;
    if (end[-1] == '.') --end;
  }
  if (end - buf == 2 && buf[0] == '-' && buf[1] == '0') {
    out += '0';
    return;
  }
  out.append(buf, size_t(end - buf));
}

/// #rrggbb, each channel converted to 8 bits as GL converts a float colour (cpu_raster.h).
std::string hex(const glm::vec3& c) {
  const Rgba p = rgbaFromColor(Vec3(c));
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", p.r, p.g, p.b);
  return buf;
}

std::string escaped(std::string_view text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

// ---------------------------------------------------------------- 2 fonts and labels

// The text renderer's fonts (render/text.cpp): DejaVu Sans at 15 px (labels) and 20 px (titles)
// times the text scale with its glyph ranges, else Dear ImGui's built-in font. Built here on the CPU
// only, to measure and place labels exactly as the PNG does.
constexpr const char* kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x206F, 0x2070,
                                    0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};
// Dear ImGui sizes a font by its line height, ascent − descent (stbtt_ScaleForPixelHeight); SVG by
// its em. DejaVu Sans: 2048 units per em, hhea ascent 1901, descent −483.
constexpr double kDejaVuEmPerLine = 2048.0 / (1901.0 + 483.0);

struct Fonts {
  std::unique_ptr<ImFontAtlas> atlas = std::make_unique<ImFontAtlas>();
  ImFont* label = nullptr;
  ImFont* title = nullptr;
  bool dejaVu = false;
  float scale = 1.f;  // the text scale (TextRenderer's)

  ImFont* font(TextSize size) const { return size == TextSize::title ? title : label; }
  Vec2 measure(const std::string& text, TextSize size) const {
    ImFont* f = font(size);
    const ImVec2 s = f->CalcTextSizeA(f->FontSize, 1e6f, 0.f, text.c_str());
    return {s.x, s.y};
  }
  double emPx(TextSize size) const { return font(size)->FontSize * (dejaVu ? kDejaVuEmPerLine : 1.0); }
  /// Baseline below the top of the line: Dear ImGui puts glyphs at round(Ascent).
  double baseline(TextSize size) const { return std::round(font(size)->Ascent); }
  const char* family() const { return dejaVu ? "DejaVu Sans, Verdana, sans-serif" : "monospace"; }
};

// Built for each export (a few milliseconds), so no font cache outlives it.
std::unique_ptr<Fonts> makeFonts(float scale) {
  auto f = std::make_unique<Fonts>();
  f->scale = scale;
  if (std::filesystem::exists(kFontFile)) {
    f->label = f->atlas->AddFontFromFileTTF(kFontFile, 15.f * scale, nullptr, kGlyphRanges);
    f->title = f->atlas->AddFontFromFileTTF(kFontFile, 20.f * scale, nullptr, kGlyphRanges);
    f->dejaVu = f->label && f->title;
  }
  if (!f->label || !f->title) {
    ImFontConfig config;
    config.SizePixels = 13.f * std::max(1.f, std::round(scale));
    f->label = f->title = f->atlas->AddFontDefault(&config);
  }
  if (!f->atlas->Build()) throw Error("SVG export: cannot build the label font atlas");
  f->atlas->ClearTexData();  // the glyph metrics stay
  return f;
}

/// A label where the PNG puts it (app/views/labels.h).
struct SvgLabel {
  Vec2 topLeft;
  std::string text;
  glm::vec4 color;
  TextSize size;
  bool shadow;
};

struct FontsMetrics final : TextMetrics {
  const Fonts& fonts;
  explicit FontsMetrics(const Fonts& f) : fonts(f) {}
  Vec2 measure(std::string_view text, TextSize size) const override { return fonts.measure(std::string(text), size); }
  float scale() const override { return fonts.scale; }
};

std::vector<SvgLabel> placeSvgLabels(const std::vector<TextLabel>& labels, const Fonts& fonts, int width,
                                     int height) {
  std::vector<SvgLabel> out;
  for (const PlacedLabel& p : vplab::placeLabels(labels, FontsMetrics(fonts), width, height))
    out.push_back({Vec2(p.topLeft), p.text, p.color, p.size, p.shadow});
  return out;
}

// ---------------------------------------------------------------- 3 projection and clipping

/// A point of a view's pixel space (x right, y down) with the NPC z of the view's camera (1 at its
/// front plane, 0 at its back plane: larger is nearer, GL's window depth is 1 − z).
struct Px {
  double x, y, z;
};

Px mix(const Px& a, const Px& b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
}
double distance2d(const Px& a, const Px& b) { return std::hypot(b.x - a.x, b.y - a.y); }

class DepthField;

/// The space a view draws in ("S": WC for the world view, NPC for the NPC view, the scene camera's
/// homogeneous NPC or the device's DC for the camera view) seen through the view's camera.
struct Canvas {
  Mat4 npcFromS{1.0};  // homogeneous NPC of the view's camera
  int width = 0, height = 0;
  const DepthField* depth = nullptr;  // the faces that hide lines (hidden-line styles); none: nothing hides

  Vec4 hom(const Vec3& p) const { return npcFromS * Vec4(p, 1.0); }
  /// DC of the view (docs/conventions.md stage 5 at width × height) after the division by w > 0.
  Px pixel(const Vec4& h) const { return {width * (h.x / h.w), height * (1.0 - h.y / h.w), h.z / h.w}; }
};

// Clipping against the view camera's volume in homogeneous coordinates (docs/conventions.md stage 4), written
// out here over linear forms so the same code also clips to the NPC view's grown cube. Plane i's
// boundary value at p is dot(form_i, p); inside is ≥ 0.
using Planes = std::array<Vec4, 6>;
Planes grownCube(double m) {  // x + m·w ≥ 0, (1 + m)·w − x ≥ 0, … (m = 0: Blinn's BC0..BC5)
  return {Vec4(1, 0, 0, m),      Vec4(-1, 0, 0, 1 + m), Vec4(0, 1, 0, m),
          Vec4(0, -1, 0, 1 + m), Vec4(0, 0, 1, m),      Vec4(0, 0, -1, 1 + m)};
}
const Planes kCube = grownCube(0);
constexpr int kFrontPlane = 5;  // BC5 = w − z: the front plane, GL's near plane

/// The parameter range [t0, t1] of a → b inside every plane: pipeline/clipping.h's parametric
/// clipping, for these forms.
std::optional<EdgeRange> clipRange(const Vec4& a, const Vec4& b, const Planes& planes = kCube) {
  const EdgeRange r = clipEdgeByForms(a, b, planes);
  if (!r.visible) return std::nullopt;
  return r;
}

/// Sutherland–Hodgman against every plane with the pipeline's kernel (pipeline/clipping.h).
std::vector<Vec4> clipPolygonHom(std::vector<Vec4> polygon, const Planes& planes = kCube) {
  ClipScratch scratch;
  return clipPolygonByForms(polygon, planes, scratch);
}

/// A segment's part inside the view's volume, in pixels, with the dash phase the line shader gives
/// its start: line.geom measures dashes from the segment's start after cutting it at GL's near
/// plane (the view camera's front plane); GL then clips the rest.
struct ClippedSegment {
  Px a, b;
  double along;  // px from the dash origin to a
};

std::optional<ClippedSegment> clipSegment(const Canvas& c, const Vec4& a, const Vec4& b,
                                          std::optional<EdgeRange> known = std::nullopt) {
  const std::optional<EdgeRange> r = known ? known : clipRange(a, b);
  if (!r || !r->visible || !(r->t1 > r->t0)) return std::nullopt;
  const double fa = glm::dot(kCube[kFrontPlane], a), fb = glm::dot(kCube[kFrontPlane], b);
  const double tNear = fa < 0 ? fa / (fa - fb) : 0.0;
  const Px origin = c.pixel(glm::mix(a, b, tNear));
  const Px p0 = c.pixel(glm::mix(a, b, r->t0)), p1 = c.pixel(glm::mix(a, b, r->t1));
  return ClippedSegment{p0, p1, distance2d(origin, p0)};
}

/// A polygon given in homogeneous NPC of the view's camera, clipped to its volume (as GL clips a
/// triangle) and taken to pixels. Empty when nothing remains.
std::vector<Px> clipPolygonToView(const Canvas& c, std::span<const Vec4> polygon) {
  std::vector<Px> out;
  for (const Vec4& h : clipPolygonHom({polygon.begin(), polygon.end()}))
    if (h.w > 0) out.push_back(c.pixel(h));
  return out;
}

// ---------------------------------------------------------------- 4 visibility

/// The filled faces of a view as screen-space triangles, for "is this point hidden?" (the depth test
/// the views make against faces drawn with glPolygonOffset(1, 2)). Exact plane depth at any point
/// instead of a pixel z-buffer: the answer does not depend on pixel centres, and where it changes
/// along a segment can be found to a fraction of a pixel.
class DepthField {
 public:
  DepthField(int width, int height) : width_(width), height_(height) {}

  /// A convex polygon (or any polygon GL would fan the same way) as a fan from its first vertex.
  void addFan(std::span<const Px> polygon) {
    for (size_t i = 1; i + 1 < polygon.size(); ++i) addTriangle(polygon[0], polygon[i], polygon[i + 1]);
  }

  /// Whether a face lies in front of the point by more than the face's polygon offset: GL_LEQUAL
  /// fails when 1 − z_point > 1 − z_face + m + 2r, with m the face's largest depth slope per pixel
  /// (glPolygonOffset factor 1) and r the depth buffer's resolution (units 2; 2^−24).
  bool hides(const Px& p) const {
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
      if (!inside) continue;
      if (p.z < t.zx * p.x + t.zy * p.y + t.z0 - t.offset) return true;
    }
    return false;
  }

  /// Sorts the triangles into a grid of square cells (after the last addFan, before the first
  /// query), the cells about twice the size of an average triangle's box: 1 px for a million-
  /// polygon sphere, 16 px at most.
  void finish() {
    double area = 0;
    for (const Triangle& t : triangles_) area += (t.max.x - t.min.x) * (t.max.y - t.min.y);
    const double typical = triangles_.empty() ? 16.0 : 2.0 * std::sqrt(area / double(triangles_.size()));
    cell_ = std::clamp(std::round(typical), 1.0, 16.0);
    cols_ = std::max(1, int(std::ceil(width_ / cell_)));
    rows_ = std::max(1, int(std::ceil(height_ / cell_)));
    cells_.assign(size_t(cols_) * size_t(rows_), {});
    for (uint32_t index = 0; index < triangles_.size(); ++index) {
      const Triangle& t = triangles_[index];
      const int x0 = std::clamp(int(std::floor(t.min.x / cell_)), 0, cols_ - 1);
      const int x1 = std::clamp(int(std::floor(t.max.x / cell_)), 0, cols_ - 1);
      const int y0 = std::clamp(int(std::floor(t.min.y / cell_)), 0, rows_ - 1);
      const int y1 = std::clamp(int(std::floor(t.max.y / cell_)), 0, rows_ - 1);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) cells_[size_t(y) * size_t(cols_) + size_t(x)].push_back(index);
    }
  }

  /// The segment a → b cut into pieces [t0, t1] that are all hidden or all visible.
  struct Piece {
    double t0, t1;
    bool hidden;
  };
  std::vector<Piece> pieces(const Px& a, const Px& b) const {
    const double len = distance2d(a, b);
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
    // Slivers (a sample grazing a face's border) take their neighbour's side, then equal
    // neighbours merge.
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

 private:
  struct Triangle {
    Vec2 v[3];
    Vec2 min, max;
    double sign;        // of the area: the inside of every edge function
    double zx, zy, z0;  // z = zx·x + zy·y + z0
    double offset;      // the polygon offset in z
  };

  void addTriangle(const Px& a, const Px& b, const Px& c) {
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
    t.offset = std::max(std::abs(t.zx), std::abs(t.zy)) + 2.0 * std::ldexp(1.0, -24);
    triangles_.push_back(t);
  }

  int width_, height_;
  double cell_ = 16;
  int cols_ = 1, rows_ = 1;
  std::vector<std::vector<uint32_t>> cells_ = std::vector<std::vector<uint32_t>>(1);  // empty until finish()
  std::vector<Triangle> triangles_;
};

/// A polygon given in the canvas's space S: fanned from its first vertex (as GL and the views fan
/// faces), each triangle clipped to the view's volume and added to the field.
void addFaceToDepth(DepthField& depth, const Canvas& c, std::span<const Vec4> polygonHom) {
  for (size_t i = 1; i + 1 < polygonHom.size(); ++i) {
    const Vec4 triangle[3] = {polygonHom[0], polygonHom[i], polygonHom[i + 1]};
    const std::vector<Px> clipped = clipPolygonToView(c, triangle);
    depth.addFan(clipped);
  }
}

// ---------------------------------------------------------------- 5 the drawing

/// How a line or point meets the faces (OverlayDepth and the hidden-line passes of the views):
/// ignore: all of it; test: the visible parts (GL_LEQUAL); hiddenOnly: the hidden parts (GL_GREATER,
/// the dashed pass); xray: the hidden parts faint, the rest as usual.
enum class DepthMode { ignore, test, hiddenOnly, xray };

struct Stroke {
  std::string cls;
  glm::vec3 rgb;
  double alpha;
  double widthPx;  // the PNG's line width
  double dashPx;   // 0: solid
  bool operator==(const Stroke&) const = default;
};

Stroke stroke(std::string cls, const glm::vec4& color, double widthPx, double dashPx = 0) {
  return {std::move(cls), glm::vec3(color), color.a, widthPx, dashPx};
}

struct LineElement {
  size_t stroke;
  Px a, b;
  double along;  // dash phase at a
};
struct CircleElement {
  std::string cls;
  Px centre;
  double sizePx;
  glm::vec3 rgb;
  double alpha;
};
struct PolygonElement {
  std::string cls;
  std::vector<Px> points;
  glm::vec3 rgb;
  double alpha;
};
struct TextElement {
  SvgLabel label;
};
using Element = std::variant<LineElement, CircleElement, PolygonElement, TextElement>;

/// One view's SVG elements in drawing order (later ones on top, as the GL passes).
class Drawing {
 public:
  Drawing(int width, int height, const glm::vec3& background, const Fonts& fonts, double scale)
      : width_(width), height_(height), background_(background), fonts_(&fonts), scale_(scale) {}
  double scale() const { return scale_; }

  void line(const Stroke& s, const Px& a, const Px& b, double along) {
    if (!(distance2d(a, b) > 1e-6)) return;
    size_t id = 0;
    while (id < strokes_.size() && !(strokes_[id] == s)) ++id;
    if (id == strokes_.size()) strokes_.push_back(s);
    // The same line twice (an edge of two polygons) once: keyed by its style and its end points in
    // hundredths of a pixel (as written), in either order.
    std::array<int64_t, 5> key{int64_t(id), std::llround(a.x * 100), std::llround(a.y * 100),
                               std::llround(b.x * 100), std::llround(b.y * 100)};
    if (std::pair(key[3], key[4]) < std::pair(key[1], key[2])) {
      std::swap(key[1], key[3]);
      std::swap(key[2], key[4]);
    }
    if (!lineKeys_.insert(key).second) return;
    elements_.push_back(LineElement{id, a, b, along});
  }

  /// A segment given in homogeneous NPC of the view's camera, in the parts `mode` draws.
  void segment(const Canvas& c, const Vec4& a, const Vec4& b, const Stroke& s, DepthMode mode,
               std::optional<EdgeRange> known = std::nullopt) {
    const std::optional<ClippedSegment> seg = clipSegment(c, a, b, known);
    if (!seg) return;
    if (!c.depth || mode == DepthMode::ignore) {
      if (mode != DepthMode::hiddenOnly) line(s, seg->a, seg->b, seg->along);
      return;
    }
    const double len = distance2d(seg->a, seg->b);
    for (const DepthField::Piece& piece : c.depth->pieces(seg->a, seg->b)) {
      const Px p0 = mix(seg->a, seg->b, piece.t0), p1 = mix(seg->a, seg->b, piece.t1);
      const double along = seg->along + piece.t0 * len;
      if (mode == DepthMode::test && !piece.hidden) line(s, p0, p1, along);
      if (mode == DepthMode::hiddenOnly && piece.hidden) line(s, p0, p1, along);
      if (mode == DepthMode::xray) line(piece.hidden ? faint(s) : s, p0, p1, along);
    }
  }
  void segment(const Canvas& c, const Vec3& a, const Vec3& b, const Stroke& s, DepthMode mode) {
    segment(c, c.hom(a), c.hom(b), s, mode);
  }
  void polyline(const Canvas& c, const std::vector<Vec3>& points, bool closed, const Stroke& s,
                DepthMode mode) {
    if (points.size() < 2) return;
    for (size_t i = 0; i + 1 < points.size(); ++i) segment(c, points[i], points[i + 1], s, mode);
    if (closed && points.size() > 2) segment(c, points.back(), points.front(), s, mode);
  }

  /// A marker disc (point.geom, point.frag): dropped behind the view camera's front or back plane.
  void point(const Canvas& c, const Vec3& p, const glm::vec4& color, double sizePx, DepthMode mode,
             std::string cls) {
    const Vec4 h = c.hom(p);
    if (!(h.w > 0) || h.z > h.w || h.z < 0) return;
    const Px at = c.pixel(h);
    sizePx *= scale_;
    const double r = 0.5 * sizePx + 1;
    if (at.x < -r || at.y < -r || at.x > c.width + r || at.y > c.height + r) return;
    double alpha = color.a;
    if (c.depth && mode != DepthMode::ignore && c.depth->hides(at)) {
      if (mode == DepthMode::test) return;
      alpha *= kXrayAlpha;
      cls += " behind";
    }
    if (mode == DepthMode::hiddenOnly) return;
    elements_.push_back(CircleElement{std::move(cls), at, sizePx, glm::vec3(color), alpha});
  }

  /// A translucent polygon (OverlayBatch::quad), clipped to the view; not split by depth.
  void fill(const Canvas& c, const std::vector<Vec3>& polygon, const glm::vec4& color, std::string cls) {
    std::vector<Vec4> hom;
    for (const Vec3& p : polygon) hom.push_back(c.hom(p));
    std::vector<Px> points = clipPolygonToView(c, hom);
    if (points.size() >= 3)
      elements_.push_back(PolygonElement{std::move(cls), std::move(points), glm::vec3(color), color.a});
  }

  void labels(const std::vector<TextLabel>& labels) {
    for (SvgLabel& l : placeSvgLabels(labels, *fonts_, width_, height_))
      elements_.push_back(TextElement{std::move(l)});
  }

  /// The elements, background first.
  std::string body() const;

 private:
  static Stroke faint(Stroke s) {
    s.alpha *= kXrayAlpha;
    s.cls += " behind";
    return s;
  }

  int width_, height_;
  glm::vec3 background_;
  const Fonts* fonts_;
  double scale_;  // lecture mode: line widths and marker sizes (OverlayRenderer::setScale)
  std::vector<Stroke> strokes_;
  struct KeyHash {
    size_t operator()(const std::array<int64_t, 5>& k) const {
      uint64_t h = 1469598103934665603ull;
      for (int64_t v : k) h = (h ^ uint64_t(v)) * 1099511628211ull;
      return size_t(h);
    }
  };
  std::unordered_set<std::array<int64_t, 5>, KeyHash> lineKeys_;
  std::vector<Element> elements_;
};

std::string opacity(const char* attribute, double alpha) {
  if (alpha >= 0.9995) return "";
  return std::string(" ") + attribute + "=\"" + num(std::clamp(alpha, 0.0, 1.0), 3) + '"';
}

std::string Drawing::body() const {
  std::string out = "<rect class=\"background\" width=\"" + std::to_string(width_) + "\" height=\"" +
                    std::to_string(height_) + "\" fill=\"" + hex(background_) + "\"/>\n";
  // Consecutive lines of one stroke share a group; so do consecutive labels of one size.
  std::optional<size_t> openStroke;
  std::optional<TextSize> openText;
  auto close = [&] {
    if (openStroke || openText) out += "</g>\n";
    openStroke.reset();
    openText.reset();
  };
  for (const Element& e : elements_) {
    if (const auto* l = std::get_if<LineElement>(&e)) {
      const Stroke& s = strokes_[l->stroke];
      if (openStroke != l->stroke) {
        close();
        out += "<g class=\"" + s.cls + "\" stroke=\"" + hex(s.rgb) + '"' +
               opacity("stroke-opacity", s.alpha) + " stroke-width=\"" + num(s.widthPx * scale_ + kInkPx) +
               '"';
        // Solid lines end half their width beyond their end points (line.geom); dashes do not.
        if (s.dashPx > 0)
          out += " stroke-linecap=\"butt\" stroke-dasharray=\"" + num(s.dashPx) + ' ' + num(s.dashPx) + '"';
        else
          out += " stroke-linecap=\"square\"";
        out += ">\n";
        openStroke = l->stroke;
      }
      out += "<line x1=\"";
      appendNum(out, l->a.x);
      out += "\" y1=\"";
      appendNum(out, l->a.y);
      out += "\" x2=\"";
      appendNum(out, l->b.x);
      out += "\" y2=\"";
      appendNum(out, l->b.y);
      out += '"';
      if (s.dashPx > 0) {
        const double phase = std::fmod(l->along, 2 * s.dashPx);
        if (phase > 0.005) out += " stroke-dashoffset=\"" + num(phase) + '"';
      }
      out += "/>\n";
    } else if (const auto* t = std::get_if<TextElement>(&e)) {
      const SvgLabel& p = t->label;
      if (openText != p.size) {
        close();
        out += std::string("<g class=\"") + (p.size == TextSize::title ? "title" : "label") +
               "\" font-family=\"" + fonts_->family() + "\" font-size=\"" + num(fonts_->emPx(p.size)) +
               // the PNG's text shadow: the glyphs drawn dark one pixel off in four directions
               "\" stroke=\"#000000\" stroke-width=\"2\" stroke-linejoin=\"round\" paint-order=\"stroke\">\n";
        openText = p.size;
      }
      out += "<text x=\"" + num(p.topLeft.x) + "\" y=\"" + num(p.topLeft.y + fonts_->baseline(p.size)) +
             "\" fill=\"" + hex(glm::vec3(p.color)) + '"' + opacity("fill-opacity", p.color.a) +
             (p.shadow ? opacity("stroke-opacity", 0.75 * p.color.a) : std::string(" stroke=\"none\"")) +
             '>' + escaped(p.text) + "</text>\n";
    } else if (const auto* c = std::get_if<CircleElement>(&e)) {
      close();
      // point.frag: a disc sizePx across, its outer 1.5 px darkened to 35 %.
      const double radius = 0.5 * c->sizePx;
      out += "<circle class=\"" + c->cls + "\" cx=\"" + num(c->centre.x) + "\" cy=\"" + num(c->centre.y) +
             "\" r=\"" + num(radius - 0.75) + "\" fill=\"" + hex(c->rgb) + "\" stroke=\"" +
             hex(c->rgb * 0.35f) + "\" stroke-width=\"1.5\"" + opacity("opacity", c->alpha) + "/>\n";
    } else if (const auto* p = std::get_if<PolygonElement>(&e)) {
      close();
      out += "<polygon class=\"" + p->cls + "\" points=\"";
      for (size_t i = 0; i < p->points.size(); ++i)
        out += (i ? " " : "") + num(p->points[i].x) + ',' + num(p->points[i].y);
      out += "\" fill=\"" + hex(p->rgb) + '"' + opacity("fill-opacity", p->alpha) + "/>\n";
    }
  }
  close();
  return out;
}

/// A mesh vertex in WC (stage 1, as the pipeline computes it).
Vec3 wcOf(const ObjectRun& o, uint32_t v) { return transformAffine(o.wcFromMc, o.mesh->positions[v]); }

bool hiddenStyle(Style s) { return s == Style::hiddenLine || s == Style::hiddenRemoved; }

/// The object's edges and their visible parts for the scene camera: the run's when it clipped them
/// (PipelineOptions::clipEdges), else clipped here with the same function.
std::vector<std::pair<Edge, EdgeRange>> clippedEdges(const ObjectRun& o) {
  std::vector<std::pair<Edge, EdgeRange>> out;
  if (!o.edges.empty() && o.edgeRanges.size() == o.edges.size()) {
    for (size_t i = 0; i < o.edges.size(); ++i) out.emplace_back(o.edges[i], o.edgeRanges[i]);
    return out;
  }
  if (!o.mesh) return out;
  for (const Edge& e : uniqueEdges(*o.mesh))
    out.emplace_back(e, clipRange(o.npcH[e.a], o.npcH[e.b]).value_or(EdgeRange{0, 0, false}));
  return out;
}

// ---------------------------------------------------------------- 6 camera view (camera_view.cpp)

// lecture notes 14.2's vanishing points as camera_view.cpp's addVanishingPoints draws them (in device DC).
void vanishingPointOverlay(Drawing& d, const Canvas& dc, const PipelineRun& run, int sceneIndex,
                           std::vector<TextLabel>& labels, std::vector<std::function<void()>>& points) {
  const ObjectRun* o = nullptr;
  for (size_t i = 0; i < run.sceneIndex.size(); ++i)
    if (int(run.sceneIndex[i]) == sceneIndex) o = &run.objects[i];
  if (!o || !o->mesh) return;
  const auto vps = vanishingPoints(run, o->wcFromMc);
  const glm::vec4 colors[3] = {theme::kU, theme::kV, theme::kN};
  const char* names[3] = {"x", "y", "z"};
  const Vec2 toPixels(double(dc.width) / run.device.width, double(dc.height) / run.device.height);
  for (int axis = 0; axis < 3; ++axis) {
    const VanishingPoint& vp = vps[size_t(axis)];
    if (!vp.finite) continue;
    const Vec3 target(vp.dc, 0.5);
    const Stroke s = stroke("vanishing-line", glm::vec4(glm::vec3(colors[axis]), 0.7f), 1.2, 4);
    for (const Edge& e : uniqueEdges(*o->mesh)) {
      const Vec3 dir = wcOf(*o, e.b) - wcOf(*o, e.a);
      if (glm::length(glm::cross(glm::normalize(dir), vp.directionWc)) > 1e-6) continue;
      for (uint32_t v : {e.a, e.b}) {
        const Vec4 h = o->npcH[v];
        if (h.w <= 0) continue;
        const Vec3 p = Vec3(run.dcFromNpc * Vec4(Vec3(h) / h.w, 1.0));
        d.segment(dc, Vec3(p.x, p.y, 0.5), target, s, DepthMode::ignore);
      }
    }
    const glm::vec4 color = colors[axis];
    points.push_back(
        [&d, &dc, target, color] { d.point(dc, target, color, 12, DepthMode::ignore, "vanishing-point"); });
    const Vec2 at = vp.dc * toPixels;
    const bool inside = at.x >= 0 && at.y >= 0 && at.x <= dc.width && at.y <= dc.height;
    char text[96];
    std::snprintf(text, sizeof text, "VP %s (%s, %s)%s", names[axis], formatNumber(std::round(vp.dc.x), {10}).c_str(),
                  formatNumber(std::round(vp.dc.y), {10}).c_str(),
                  inside ? "" : " outside");
    labels.push_back({glm::clamp(at, Vec2(4), Vec2(dc.width - 4, dc.height - 4)) + Vec2(8, -8), text,
                      colors[axis], TextSize::label, Anchor::left});
  }
}

void cameraView(Drawing& d, const PipelineRun& run, const FrameSettings& s, int w, int h) {
  const Style style = s.camera.style;
  // The scene camera's homogeneous NPC is the space: its volume is the view's.
  Canvas c{Mat4(1.0), w, h};
  DepthField depth(w, h);
  if (hiddenStyle(style)) {
    // drawEdges: the faces fill the depth buffer. GL fans each mesh face and clips the triangles;
    // the CPU clipper's polygons cover the same points (up to the fan of a concave face) and
    // carry whatever else the pipeline clipped.
    std::vector<Vec4> face;
    for (const ObjectRun& o : run.objects)
      for (size_t f = 0; f < o.faceCount(); ++f) {
        face.clear();
        for (uint32_t ref : o.clippedFace(f)) face.push_back(Vec4(o.clippedNpc(ref), 1.0));
        addFaceToDepth(depth, c, face);
      }
    depth.finish();
    c.depth = &depth;
  }
  // drawEdges: wire every edge (GL_ALWAYS); hidden styles the visible parts (GL_LEQUAL), hidden-line
  // also the hidden parts dashed (GL_GREATER). The GPU draws each whole mesh edge and GL clips it;
  // the CPU's edge ranges are that cut.
  for (const ObjectRun& o : run.objects) {
    const Stroke solid = stroke("edge", glm::vec4(glm::vec3(o.color), 1.f), theme::kEdgeWidth);
    for (const auto& [e, r] : clippedEdges(o))
      d.segment(c, o.npcH[e.a], o.npcH[e.b], solid, c.depth ? DepthMode::test : DepthMode::ignore, r);
  }
  if (style == Style::hiddenLine)
    for (const ObjectRun& o : run.objects) {
      const Stroke dashed =
          stroke("edge hidden", glm::vec4(glm::vec3(o.color), 0.8f), theme::kEdgeWidth, theme::kDashPx);
      for (const auto& [e, r] : clippedEdges(o))
        d.segment(c, o.npcH[e.a], o.npcH[e.b], dashed, DepthMode::hiddenOnly, r);
    }

  // The overlay batch, in the device's DC (dcCamera), drawn without depth: lines, then points.
  const Canvas dc{glm::inverse(dcFromNpc(run.device)), w, h};
  std::vector<TextLabel> labels;
  std::vector<std::function<void()>> points;
  if (s.highlights.probeDc)
    points.push_back(
        [&] { d.point(dc, *s.highlights.probeDc, theme::kProbe, 14, DepthMode::ignore, "probe"); });
  if (s.overlays.cpuPolygons) {
    const Stroke cpu = stroke("cpu-polygon", theme::kCpuPolygon, 1.5);
    for (const ObjectRun& o : run.objects)
      for (size_t f = 0; f < o.faceCount(); ++f) {
        std::vector<Vec3> poly;
        for (uint32_t ref : o.clippedFace(f)) poly.push_back(o.clippedDc(ref));
        d.polyline(dc, poly, true, cpu, DepthMode::ignore);
      }
  }
  if (s.overlays.vanishingPoints)
    vanishingPointOverlay(d, dc, run, s.highlights.vanishingObject, labels, points);
  for (const auto& p : points) p();
  d.labels(labels);
}

// ---------------------------------------------------------------- 7 world view (world_view.cpp)

struct WorldFrame {
  Mat4 wcFromNpc;
  Mat4 wcFromVrc;
  Vec3 wcOfNpc(const Vec3& npc) const {
    const Vec4 p = wcFromNpc * Vec4(npc, 1.0);
    return Vec3(p) / p.w;
  }
  std::array<Vec3, 8> volumeCorners() const { return geometry::viewVolumeCorners(wcFromNpc); }
};

void addArrow(Drawing& d, const Canvas& c, const Vec3& from, const Vec3& to, const Vec3& eye,
              const glm::vec4& color, const std::string& cls, double dash = 0) {
  d.segment(c, from, to, stroke(cls, color, theme::kLineWidth + 0.5, dash), DepthMode::xray);
  const Vec3 dir = to - from;
  const double len = glm::length(dir);
  if (len <= 0) return;
  Vec3 side = glm::cross(dir / len, eye - to);
  if (glm::length(side) < 1e-12) return;
  side = glm::normalize(side) * (0.07 * len);
  const Vec3 base = to - dir * 0.16;
  const Stroke head = stroke(cls, color, theme::kLineWidth + 0.5);
  d.segment(c, to, base + side, head, DepthMode::xray);
  d.segment(c, to, base - side, head, DepthMode::xray);
}

/// The clipping step-through's marks (world and NPC views): the plane's face of the volume, the
/// polygon after the step, its vertices. `corner` gives a corner of the volume, `place` takes an
/// NPC point into the canvas's space.
void stepOverlay(Drawing& d, const Canvas& c, const Highlights::Step& step,
                 const std::function<Vec3(int)>& corner, const std::function<Vec3(const Vec3&)>& place,
                 std::vector<std::function<void()>>& points) {
  if (step.plane >= 0 && step.plane < kPlaneCount) {
    const auto ring = geometry::cubeFaceRing(step.plane);
    d.fill(c, {corner(ring[0]), corner(ring[1]), corner(ring[2]), corner(ring[3])}, theme::kStepPlane,
           "step-plane");
  }
  std::vector<Vec3> poly;
  for (const Vec3& p : step.polygonNpc) poly.push_back(place(p));
  d.polyline(c, poly, true, stroke("step-polygon", theme::kProbe, theme::kLineWidth + 1.0), DepthMode::xray);
  for (size_t i = 0; i < poly.size(); ++i) {
    const bool created = i < step.created.size() && step.created[i];
    const Vec3 p = poly[i];
    points.push_back([&d, &c, p, created] {
      d.point(c, p, created ? theme::kNewEdge : theme::kProbe, created ? 13 : 9, DepthMode::xray,
              "step-vertex");
    });
  }
}

void worldView(Drawing& d, const Scene& scene, const PipelineRun& run, const FrameSettings& s, int w, int h) {
  const ViewCamera view = viewCameraOf(observerCamera(s.world.orbit, double(w) / h));
  Canvas c{view.npcFromWc(), w, h};
  const WorldFrame f{glm::inverse(run.npcFromWc), glm::inverse(run.vrcFromWc)};
  const Style style = s.world.style;
  const OverlaySettings& ov = s.overlays;
  const bool hidden = hiddenStyle(style);

  DepthField depth(w, h);
  if (hidden) {
    // The objects' faces in WC fill the depth buffer (all of them, inside the volume or not).
    std::vector<Vec4> face;
    for (const ObjectRun& o : run.objects) {
      if (!o.mesh) continue;
      for (size_t fi = 0; fi < o.mesh->faceCount(); ++fi) {
        face.clear();
        for (uint32_t v : o.mesh->face(fi)) face.push_back(c.hom(wcOf(o, v)));
        addFaceToDepth(depth, c, face);
      }
    }
    depth.finish();
    c.depth = &depth;
  }
  // The wireframe from the CPU's edge clipping: the whole edge faded, the part inside the scene
  // camera's volume solid; hidden-line: that part dashed where hidden.
  const DepthMode mode = hidden ? DepthMode::test : DepthMode::ignore;
  if (ov.fadeOutside)
    for (const ObjectRun& o : run.objects) {
      const Stroke faded =
          stroke("edge faded", glm::vec4(glm::vec3(o.color), theme::kFadedAlpha), theme::kEdgeWidth);
      for (const auto& [e, r] : clippedEdges(o)) d.segment(c, wcOf(o, e.a), wcOf(o, e.b), faded, mode);
    }
  for (int pass = 0; pass < (style == Style::hiddenLine ? 2 : 1); ++pass)
    for (const ObjectRun& o : run.objects) {
      const Stroke st = pass == 0 ? stroke("edge", glm::vec4(glm::vec3(o.color), 1.f), theme::kEdgeWidth)
                                  : stroke("edge hidden", glm::vec4(glm::vec3(o.color), 0.8f),
                                           theme::kEdgeWidth, theme::kDashPx);
      for (const auto& [e, r] : clippedEdges(o)) {
        if (!r.visible) continue;
        const Vec3 a = wcOf(o, e.a), b = wcOf(o, e.b);
        // Boundary coordinates are linear along the WC segment, so t carries over from NPC.
        d.segment(c, a + r.t0 * (b - a), a + r.t1 * (b - a), st, pass == 0 ? mode : DepthMode::hiddenOnly);
      }
    }

  // The overlay batch, drawn x-ray: translucent polygons, lines, then points; then the labels.
  std::vector<TextLabel> labels;
  std::vector<std::function<void()>> points;
  auto label = [&](const Vec3& p, const std::string& text, const glm::vec4& color, Vec2 offset = {8, 0}) {
    if (!ov.labels) return;
    const Projected q = projectToPixels(view, p, w, h);
    if (q.visible)  // as world_view.cpp: the offset grows with the text, the label names its point
      labels.push_back({q.pixel + offset * d.scale(), text, color, TextSize::label, Anchor::left, true, true,
                        q.pixel});
  };
  if (ov.newEdges) {
    const Stroke st = stroke("new-edge", theme::kNewEdge, theme::kLineWidth + 0.5);
    for (const ObjectRun& o : run.objects)
      for (size_t fi = 0; fi < o.faceCount(); ++fi) {
        if (o.fate[fi] != Fate::clipped) continue;
        const auto face = o.clippedFace(fi);
        for (size_t i = 0; i < face.size(); ++i)
          if (o.isNewEdge(fi, i))
            d.segment(c, f.wcOfNpc(o.clippedNpc(face[i])),
                      f.wcOfNpc(o.clippedNpc(face[(i + 1) % face.size()])), st, DepthMode::xray);
      }
  }
  if (ov.frustum) {
    const auto k = f.volumeCorners();
    const int front[4] = {4, 5, 7, 6}, back[4] = {0, 1, 3, 2};
    d.fill(c, {k[4], k[5], k[7], k[6]}, theme::kFrontPlane, "front-plane");
    d.fill(c, {k[0], k[1], k[3], k[2]}, theme::kBackPlane, "back-plane");
    const Stroke edge = stroke("frustum", theme::kFrustum, theme::kLineWidth);
    const Stroke ray =
        stroke("frustum-ray", glm::vec4(glm::vec3(theme::kFrustum), 0.6f), 1.5, theme::kDashPx);
    for (int i = 0; i < 4; ++i) {
      d.segment(c, k[size_t(front[i])], k[size_t(front[(i + 1) % 4])], edge, DepthMode::xray);
      d.segment(c, k[size_t(back[i])], k[size_t(back[(i + 1) % 4])], edge, DepthMode::xray);
      d.segment(c, k[size_t(front[i])], k[size_t(back[i])], edge, DepthMode::xray);
      if (run.camera.projection == Projection::perspective)
        d.segment(c, run.camera.prp, k[size_t(front[i])], ray, DepthMode::xray);
    }
    label(k[7], "front F", theme::kFrustum, {6, -10});
    label(k[3], "back B", theme::kFrustum, {6, -10});
  }
  // User clip planes (DGL wiki): a translucent square on each, around its point, with its normal.
  const double planeSize = geometry::clipPlaneSquareSize(run.camera);
  for (const UserClipPlane& p : scene.clipPlanes) {
    if (!p.enabled) continue;
    const Vec3 n = glm::normalize(p.normal);
    const auto square = geometry::clipPlaneSquare(p, planeSize);
    const std::vector<Vec3> q(square.begin(), square.end());
    d.fill(c, q, theme::kClipPlane, "clip-plane-fill");
    d.polyline(c, q, true, stroke("clip-plane", glm::vec4(glm::vec3(theme::kClipPlane), 0.8f), 1.5),
               DepthMode::xray);
    addArrow(d, c, p.point, p.point + n * (0.3 * planeSize), view.camera.prp,
             glm::vec4(glm::vec3(theme::kClipPlane), 1.f), "clip-plane-normal");
    label(p.point + n * (0.3 * planeSize), "clip plane", glm::vec4(glm::vec3(theme::kClipPlane), 1.f));
  }
  if (ov.viewPlane) {
    const ViewWindow& win = run.camera.window;
    const std::vector<Vec3> corners = {transformAffine(f.wcFromVrc, {win.xmin, win.ymin, 0}),
                                       transformAffine(f.wcFromVrc, {win.xmax, win.ymin, 0}),
                                       transformAffine(f.wcFromVrc, {win.xmax, win.ymax, 0}),
                                       transformAffine(f.wcFromVrc, {win.xmin, win.ymax, 0})};
    d.fill(c, corners, theme::kWindowFill, "window-fill");
    d.polyline(c, corners, true, stroke("window", theme::kWindow, theme::kLineWidth), DepthMode::xray);
    label(corners[3], "window", theme::kWindow, {6, -10});
  }
  if (ov.cameraAxes) {
    const Camera& cam = run.camera;
    const double len = 0.3 * std::max(cam.window.width(), cam.window.height());
    const Vec3 eye = view.camera.prp;
    addArrow(d, c, cam.vrp, cam.vrp + len * run.frame.u, eye, theme::kU, "axis u");
    addArrow(d, c, cam.vrp, cam.vrp + len * run.frame.v, eye, theme::kV, "axis v");
    addArrow(d, c, cam.vrp, cam.vrp + len * run.frame.n, eye, theme::kN, "axis n");
    addArrow(d, c, cam.vrp, cam.vrp + len * glm::normalize(cam.vup), eye, theme::kVup, "axis vup",
             theme::kDashPx);
    points.push_back(
        [&d, &c, &cam] { d.point(c, cam.vrp, theme::kVrp, theme::kPointSize, DepthMode::xray, "vrp"); });
    points.push_back(
        [&d, &c, &cam] { d.point(c, cam.prp, theme::kPrp, theme::kPointSize, DepthMode::xray, "prp"); });
    if (cam.projection == Projection::perspective)
      d.segment(c, cam.vrp, cam.prp,
                stroke("view-axis", glm::vec4(glm::vec3(theme::kN), 0.5f), 1.5, theme::kDashPx),
                DepthMode::xray);
    label(cam.vrp + len * run.frame.u, "U", theme::kU);
    label(cam.vrp + len * run.frame.v, "V", theme::kV);
    label(cam.vrp + len * run.frame.n, "N", theme::kN);
    label(cam.vrp + len * glm::normalize(cam.vup), "VUP", theme::kVup);
    label(cam.vrp, "VRP", theme::kVrp, {8, 12});
    label(cam.prp, "PRP", theme::kPrp);
  }
  const Highlights& hl = s.highlights;
  for (const Highlights::HandleMark& m : hl.handles) {
    const Vec3 p = m.wc;
    const bool hot = m.hot;
    points.push_back([&d, &c, p, hot] {
      d.point(c, p, hot ? theme::kHandleHot : theme::kHandle, hot ? 15 : 9, DepthMode::xray, "handle");
    });
    if (m.hot) label(m.wc, m.name, theme::kHandleHot, {10, -12});
  }
  if (hl.probeWc)
    points.push_back([&] { d.point(c, *hl.probeWc, theme::kProbe, 14, DepthMode::xray, "probe"); });
  if (hl.step) {
    const auto k = f.volumeCorners();
    stepOverlay(
        d, c, *hl.step, [&](int i) { return k[size_t(i)]; }, [&](const Vec3& p) { return f.wcOfNpc(p); },
        points);
  }
  for (const auto& p : points) p();
  d.labels(labels);
}

// ---------------------------------------------------------------- 8 NPC view (npc_view.cpp)

// The NPC view's faded polygon (view_geometry.h).
std::vector<Vec3> fadedPolygon(const ObjectRun& o, size_t f) {
  ClipScratch scratch;
  return geometry::fadedNpcPolygon(o, f, scratch);
}

void npcView(Drawing& d, const PipelineRun& run, const FrameSettings& s, int w, int h) {
  const ViewCamera view = viewCameraOf(observerCamera(s.npc.orbit, double(w) / h));
  Canvas c{view.npcFromWc(), w, h};
  const Style style = s.npc.style;
  const OverlaySettings& ov = s.overlays;

  DepthField depth(w, h);
  if (hiddenStyle(style)) {
    // The clipped polygons (drawPolygons fans them from their first vertex) fill the depth buffer.
    std::vector<Vec4> face;
    for (const ObjectRun& o : run.objects)
      for (size_t f = 0; f < o.faceCount(); ++f) {
        face.clear();
        for (uint32_t ref : o.clippedFace(f)) face.push_back(c.hom(o.clippedNpc(ref)));
        addFaceToDepth(depth, c, face);
      }
    depth.finish();
    c.depth = &depth;
  }
  const DepthMode mode = c.depth ? DepthMode::test : DepthMode::ignore;

  // Outlines, then (hidden-line) the same outlines dashed where hidden, then the faded parts.
  for (int pass = 0; pass < (style == Style::hiddenLine ? 2 : 1); ++pass)
    for (const ObjectRun& o : run.objects) {
      const Stroke st = pass == 0 ? stroke("edge", glm::vec4(glm::vec3(o.color), 1.f), theme::kEdgeWidth)
                                  : stroke("edge hidden", glm::vec4(glm::vec3(o.color), 0.8f),
                                           theme::kEdgeWidth, theme::kDashPx);
      for (size_t f = 0; f < o.faceCount(); ++f) {
        const auto face = o.clippedFace(f);
        for (size_t i = 0; i < face.size(); ++i) {
          if (pass == 0 && ov.newEdges && o.isNewEdge(f, i)) continue;  // drawn below as a new edge
          d.segment(c, o.clippedNpc(face[i]), o.clippedNpc(face[(i + 1) % face.size()]), st,
                    pass == 0 ? mode : DepthMode::hiddenOnly);
        }
      }
    }
  if (ov.fadeOutside) {
    for (const ObjectRun& o : run.objects) {
      if (!o.mesh) continue;
      const Stroke faded =
          stroke("edge faded", glm::vec4(glm::vec3(o.color), theme::kFadedAlpha), theme::kEdgeWidth);
      for (size_t f = 0; f < o.faceCount(); ++f)
        if (o.fate[f] != Fate::accepted) d.polyline(c, fadedPolygon(o, f), true, faded, mode);
    }
  }

  // The cube (depth tested): its front face, edges and axes, and labels.
  std::vector<TextLabel> labels;
  if (ov.cube) {
    auto corner = [](int i) { return Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1); };
    d.fill(c, {corner(4), corner(5), corner(7), corner(6)}, theme::kCubeFront, "cube-front");
    const Stroke edge = stroke("cube", theme::kCube, 1.5);
    for (int i = 0; i < 8; ++i)
      for (int bit : {1, 2, 4})
        if (!(i & bit)) d.segment(c, corner(i), corner(i | bit), edge, DepthMode::test);
    const double len = 1.18;
    d.segment(c, Vec3(0), Vec3(len, 0, 0), stroke("axis x", theme::kU, theme::kLineWidth), DepthMode::test);
    d.segment(c, Vec3(0), Vec3(0, len, 0), stroke("axis y", theme::kV, theme::kLineWidth), DepthMode::test);
    d.segment(c, Vec3(0), Vec3(0, 0, len), stroke("axis z", theme::kN, theme::kLineWidth), DepthMode::test);
    if (ov.labels) {
      auto label = [&](const Vec3& p, const std::string& text, const glm::vec4& color) {
        const Projected q = projectToPixels(view, p, w, h);
        if (q.visible) labels.push_back({q.pixel, text, color, TextSize::label, Anchor::center});
      };
      for (const geometry::AnchoredLabel& l : geometry::npcCubeLabels()) label(l.at, l.text, l.color);
    }
  }

  // The new edges and highlights, x-ray.
  std::vector<std::function<void()>> points;
  if (ov.newEdges) {
    const Stroke st = stroke("new-edge", theme::kNewEdge, theme::kLineWidth + 0.5);
    for (const ObjectRun& o : run.objects)
      for (size_t f = 0; f < o.faceCount(); ++f) {
        const auto face = o.clippedFace(f);
        for (size_t i = 0; i < face.size(); ++i)
          if (o.isNewEdge(f, i))
            d.segment(c, o.clippedNpc(face[i]), o.clippedNpc(face[(i + 1) % face.size()]), st,
                      DepthMode::xray);
      }
  }
  if (s.highlights.probeNpc)
    points.push_back(
        [&] { d.point(c, *s.highlights.probeNpc, theme::kProbe, 14, DepthMode::xray, "probe"); });
  if (s.highlights.step)
    stepOverlay(
        d, c, *s.highlights.step, [](int i) { return Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1); },
        [](const Vec3& p) { return p; }, points);
  for (const auto& p : points) p();
  d.labels(labels);
}

// ---------------------------------------------------------------- 9 documents and files

std::string panel(ViewKind kind, const PipelineRun& run, const FrameSettings& s, const Scene& scene, int w,
                  int h, const Fonts& fonts, double scale) {
  const bool camera = kind == ViewKind::camera;
  Drawing d(w, h, camera ? glm::vec3(scene.background) : theme::kViewBackground, fonts, scale);
  if (camera)
    cameraView(d, run, s, w, h);
  else if (kind == ViewKind::world)
    worldView(d, scene, run, s, w, h);
  else
    npcView(d, run, s, w, h);
  return d.body();
}

std::string header(int width, int height, const std::string& title) {
  const std::string w = std::to_string(width), h = std::to_string(height);
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "version=\"1.1\" width=\"" +
         w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + ' ' + h + "\">\n<title>" + escaped(title) +
         "</title>\n";
}

}  // namespace

std::optional<std::string> svgExportError(ViewKind view, const FrameSettings& settings) {
  auto check = [](ViewKind k, Style style) -> std::optional<std::string> {
    if (!isFilled(style)) return std::nullopt;
    return "SVG export is for the wireframe styles: wire, hidden-line, hidden-removed (the " +
           std::string(toString(k)) + " view's style is " + std::string(toString(style)) + ")";
  };
  if (view == ViewKind::camera) return check(view, settings.camera.style);
  if (view == ViewKind::world) return check(view, settings.world.style);
  if (view == ViewKind::npc) return check(view, settings.npc.style);
  if (view == ViewKind::all) {
    if (auto e = check(ViewKind::camera, settings.camera.style)) return e;
    if (auto e = check(ViewKind::world, settings.world.style)) return e;
    return check(ViewKind::npc, settings.npc.style);
  }
  return "SVG export covers the camera, world, npc and all views, not the " + std::string(toString(view)) +
         " view";
}

std::string svgOfView(ViewKind view, const Scene& scene, const PipelineRun& run,
                      const FrameSettings& settings, int width, int height, float scale) {
  if (auto e = svgExportError(view, settings)) throw Error(*e);
  if (width < 1 || height < 1)
    throw Error("SVG export: the size " + std::to_string(width) + " x " + std::to_string(height) +
                " is not at least 1 x 1 pixels");
  const std::unique_ptr<Fonts> fontsOwned = makeFonts(scale);
  const Fonts& fonts = *fontsOwned;
  const std::string title =
      "vplab " + std::string(toString(view)) + " view" + (scene.title.empty() ? "" : ": " + scene.title);
  if (view != ViewKind::all)
    return header(width, height, title) + panel(view, run, settings, scene, width, height, fonts, scale) +
           "</svg>\n";

  // ViewRenderer::compose: a title strip, then the three panels side by side.
  const int titleHeight = int(fonts.measure("Ag", TextSize::title).y) + 14;
  const int total = 3 * width + 2 * int(kGap);
  std::string out = header(total, titleHeight + height, title);
  out += "<rect class=\"background\" width=\"" + std::to_string(total) + "\" height=\"" +
         std::to_string(titleHeight + height) + "\" fill=\"" + hex(glm::vec3(20, 21, 26) / 255.f) + "\"/>\n";
  Drawing strip(total, titleHeight, theme::kViewBackground * 0.7f, fonts, scale);
  const char* titles[][2] = {{"camera: what the synthetic camera sees (DC)", "camera (DC)"},
                             {"world: scene, camera and view volume (WC)", "world (WC)"},
                             {"npc: after view mapping, clipping and division (NPC)", "NPC"}};
  std::vector<TextLabel> labels;
  for (int i = 0; i < 3; ++i) {
    const bool fits = fonts.measure(titles[i][0], TextSize::title).x <= width - 12;
    TextLabel t{{i * (width + kGap) + width * 0.5, titleHeight * 0.5},
                titles[i][fits ? 0 : 1],
                theme::kText,
                TextSize::title,
                Anchor::center,
                false};
    t.avoid = false;
    labels.push_back(t);
  }
  strip.labels(labels);
  out += "<g class=\"titles\">\n" + strip.body() + "</g>\n";
  const ViewKind kinds[3] = {ViewKind::camera, ViewKind::world, ViewKind::npc};
  for (int i = 0; i < 3; ++i)
    out += "<svg class=\"" + std::string(toString(kinds[i])) + "\" x=\"" + num(i * (width + kGap)) +
           "\" y=\"" + std::to_string(titleHeight) + "\" width=\"" + std::to_string(width) + "\" height=\"" +
           std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) + ' ' +
           std::to_string(height) + "\">\n" +
           panel(kinds[i], run, settings, scene, width, height, fonts, scale) + "</svg>\n";
  return out + "</svg>\n";
}

std::string svgOfRequest(const Scene& scene, const RenderRequest& request) {
  const PixelSize size = pixelSizeOf(request, scene);
  const PipelineRun run = runPipeline(scene, request.pipeline);
  return svgOfView(request.view, scene, run, frameSettingsOf(request, scene), size.width, size.height, request.scale);
}

void writeSvg(const std::string& svg, const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw Error(file.string() + ": cannot open the SVG file for writing");
  out.write(svg.data(), std::streamsize(svg.size()));
  out.close();
  if (!out) throw Error(file.string() + ": cannot write the SVG file");
}

}  // namespace vplab
