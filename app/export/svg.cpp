// The SVG backend (svg.h; svg_view.cpp makes the views' pictures). 1 SVG text  2 a display list  3 pictures
#include "app/export/svg.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>

#include "app/export/cpu_raster.h"
#include "app/fonts/font_atlas.h"
#include "app/views/hidden_lines.h"
#include "app/views/painted_fill.h"
#include "app/views/projection.h"
#include "base/error.h"

namespace vplab {

namespace {

using namespace draw;

constexpr double kInkPx = 1.0;  // the line shader: full coverage over widthPx, then a 1 px ramp per side

// ---------------------------------------------------------------- 1 SVG text

/// At most `decimals` decimals, trailing zeros dropped: 12.5, 640, -0.25 (appended: a large mesh
/// writes millions of coordinates).
void appendNum(std::string& out, double v, int decimals = 2) {
  if (!std::isfinite(v) || std::abs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0;  // no "-0"
#if defined(__cpp_lib_to_chars)
  char buf[64];
  char* end = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals).ptr;
#else  // the browser build's libc++ (LLVM 14) has no to_chars with a precision; printf rounds the same
  char buf[512];
  const int n = std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  char* end = buf + std::clamp(n, 0, int(sizeof buf) - 1);
#endif
  if (std::find(buf, end, '.') != end) {
    while (end[-1] == '0') --end;
    if (end[-1] == '.') --end;
  }
  out.append(buf, end);
}
std::string num(double v, int decimals = 2) {
  std::string s;
  appendNum(s, v, decimals);
  return s;
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
    const char* entity = ch == '&'   ? "&amp;"
                         : ch == '<' ? "&lt;"
                         : ch == '>' ? "&gt;"
                         : ch == '"' ? "&quot;"
                                     : nullptr;
    entity ? out += entity : out += ch;
  }
  return out;
}

std::string opacity(const char* attribute, double alpha) {
  if (alpha >= 0.9995) return "";
  return std::string(" ") + attribute + "=\"" + num(std::clamp(alpha, 0.0, 1.0), 3) + '"';
}

// ---------------------------------------------------------------- 2 a display list

/// Whether a part that is `hidden` is drawn under `depth`, and its alpha factor.
std::optional<float> depthAlpha(Depth depth, bool hidden) {
  if ((depth == Depth::test && hidden) || (depth == Depth::hiddenOnly && !hidden)) return std::nullopt;
  return depth == Depth::xray && hidden ? kXrayAlpha : 1.f;
}

class ListWriter {
 public:
  ListWriter(const DisplayList& list, const FontAtlas& fonts, std::string& out)
      : list_(list), fonts_(fonts), out_(out), depth_(list.width, list.height) {}

  void write() {
    out_ += "<rect class=\"background\" width=\"" + std::to_string(list_.width) + "\" height=\"" +
            std::to_string(list_.height) + "\" fill=\"" + hex(list_.background) + "\"/>\n";
    // A run of x-ray batches is drawn as GL draws it, in two passes: every hidden part (faint), then
    // every visible part, so visible lines lie over the hidden lines of the whole run.
    const std::vector<Batch>& b = list_.batches;
    auto xray = [](const Batch& x) {  // a Lines, Points or Triangles with Depth::xray
      return std::visit(
          [](const auto& y) {
            if constexpr (requires { y.depth; })
              return y.depth == Depth::xray;
            else
              return false;
          },
          x);
    };
    for (size_t i = 0; i < b.size();) {
      size_t j = i;
      while (j < b.size() && xray(b[j])) ++j;
      if (j == i) j = i + 1;  // not x-ray: drawn once
      for (bool hidden : {true, false}) {
        if (xray(b[i])) pass_ = hidden;
        if (xray(b[i]) || hidden)
          for (size_t k = i; k < j; ++k) std::visit([this](const auto& batch) { draw(batch); }, b[k]);
      }
      pass_.reset();
      i = j;
    }
  }

 private:
  // Faces back to front; those that write depth (opaque, depth-only) join the depth field first: each is
  // drawn where no face of this batch or an earlier one is in front (faces that intersect, enclose).
  void draw(const Fill& fill) {
    const std::vector<PaintedPolygon> faces = paintedPolygons(fill, list_);
    if (fill.depthOnly || fill.alpha >= 1.f)
      for (const PaintedPolygon& face : faces) depth_.addFan(face.points, fill.depthOnly);
    if (fill.depthOnly) return;
    out_ += std::string("<g class=\"fill\"") + crisp() + ">\n";
    for (const PaintedPolygon& face : faces)
      for (const DepthField::Part& part : depth_.parts(face.points))
        if (!part.hidden) polygon(part.polygon, face.color, list_.antialiased && face.color.a >= 1.f);
    out_ += "</g>\n";
  }

  void draw(const Triangles& t) {
    const ViewProjection proj(list_, t.space);
    out_ += std::string("<g class=\"triangles\"") + crisp() + ">\n";
    for (size_t i = 0; i + 2 < t.vertices.size(); i += 3) {
      const std::vector<Vec4> h = {proj.npcH(t.vertices[i].position), proj.npcH(t.vertices[i + 1].position),
                                   proj.npcH(t.vertices[i + 2].position)};
      const std::vector<PixelPoint> p = proj.polygon(h);
      if (p.empty()) continue;
      const glm::vec4& c = t.vertices[i].color;
      const double push = t.pushedBack ? DepthField::polygonOffset(p[0], p[1], p[2]) : 0.0;
      for (const DepthField::Part& part :
           t.depth == Depth::ignore ? std::vector<DepthField::Part>{{p, false}} : depth_.parts(p, push))
        if (const auto a = alphaFor(t.depth, part.hidden))
          polygon(part.polygon, c * glm::vec4(1, 1, 1, *a), false);
    }
    out_ += "</g>\n";
  }

  void draw(const Lines& l) {
    // The class names the depth mode (readers and tests find the hidden-line passes by it).
    const char* depth[] = {"", " depth-test", " hidden-only", " x-ray"};
    const std::string cap =
        l.dashPx > 0 ? "butt\" stroke-dasharray=\"" + num(l.dashPx) + ' ' + num(l.dashPx) : "square";
    out_ += std::string("<g class=\"lines") + depth[int(l.depth)] + "\" stroke-width=\"" +
            num(l.widthPx + kInkPx) + "\" stroke-linecap=\"" + cap + "\">\n";
    const ViewProjection proj(list_, l.space), clipped(list_, l.space, l.clipPlanes);
    std::vector<Vertex> segments;  // its own and its runs' edges (Lines::segmentsInto)
    l.segmentsInto(0, l.segmentCount(), segments);
    for (size_t i = 0; i + 1 < segments.size(); i += 2)
      segment(l, proj.segment(segments[i].position, segments[i + 1].position), segments[i].color);
    for (const MeshInstance& m : l.meshEdges) {
      if (!m.mesh) continue;
      auto at = [&](uint32_t v) { return clipped.npcH(m.spaceFromMc * Vec4(m.mesh->positions[v], 1.0)); };
      for (const Edge& e : uniqueEdges(*m.mesh)) segment(l, clipped.segment(at(e.a), at(e.b)), m.color);
    }
    closeStroke();
    out_ += "</g>\n";
  }

  void draw(const Points& p) {
    const ViewProjection proj(list_, p.space);
    const double radius = 0.5 * p.sizePx;
    for (const Vertex& v : p.points) {
      const std::optional<PixelPoint> at = proj.point(v.position);
      if (!at) continue;  // behind the eye, before the front or beyond the back plane
      const auto a = alphaFor(p.depth, p.depth != Depth::ignore && depth_.hides(*at));
      if (!a) continue;
      // The point shader: a disc sizePx across, its outer 1.5 px darkened to 35 %.
      out_ += "<circle cx=\"" + num(at->x) + "\" cy=\"" + num(at->y) + "\" r=\"" + num(radius - 0.75) +
              "\" fill=\"" + hex(glm::vec3(v.color)) + "\" stroke=\"" + hex(glm::vec3(v.color) * 0.35f) +
              "\" stroke-width=\"1.5\"" + opacity("opacity", v.color.a * *a) + "/>\n";
    }
  }

  void draw(const Text& t) {
    // The PNG's shadow (the glyphs drawn in the outline's colour one pixel off in four directions) as a
    // stroke under them.
    out_ += std::string("<g class=\"labels\" font-family=\"") + fonts_.cssFamily() +
            "\" stroke=\"" + hex(t.outline) + "\" stroke-width=\"2\" stroke-linejoin=\"round\" paint-order=\"stroke\">\n";
    for (const PlacedLabel& p : t.labels)
      out_ += "<text x=\"" + num(p.topLeft.x) + "\" y=\"" + num(p.topLeft.y + fonts_.baselinePx(p.size)) +
              "\" font-size=\"" + num(fonts_.emPx(p.size)) + "\" fill=\"" + hex(glm::vec3(p.color)) + '"' +
              opacity("fill-opacity", p.color.a) +
              (p.shadow ? opacity("stroke-opacity", 0.75 * p.color.a) : std::string(" stroke=\"none\"")) +
              '>' + escaped(p.text) + "</text>\n";
    out_ += "</g>\n";
  }

  std::optional<float> alphaFor(Depth depth, bool hidden) const {
    if (pass_ && hidden != *pass_) return std::nullopt;
    return depthAlpha(depth, hidden);
  }

  // A list GL draws without multisampling (the camera view, pixel-aligned with DC) has aliased
  // faces: so have the SVG's (the lines keep their own smooth edge, as the line shader's).
  const char* crisp() const { return list_.antialiased ? "" : " shape-rendering=\"crispEdges\""; }

  // A segment's parts as depth decides, consecutive lines of one colour in one group.
  void segment(const Lines& l, const std::optional<PixelSegment>& s, const glm::vec4& color) {
    if (!s) return;
    if (l.depth == Depth::ignore || depth_.empty()) {
      if (const auto a = alphaFor(l.depth, false)) line(l, s->a, s->b, s->dashOrigin, color.a * *a, color);
      return;
    }
    const double len = distancePx(s->a, s->b);
    for (const DepthField::Piece& piece : depth_.pieces(s->a, s->b))
      if (const auto a = alphaFor(l.depth, piece.hidden))
        line(l, mix(s->a, s->b, piece.t0), mix(s->a, s->b, piece.t1), s->dashOrigin + piece.t0 * len,
             color.a * *a, color);
  }

  void line(const Lines& l, const PixelPoint& a, const PixelPoint& b, double along, double alpha,
            const glm::vec4& color) {
    if (!(distancePx(a, b) > 1e-6)) return;
    const glm::vec4 stroke{glm::vec3(color), float(alpha)};
    if (stroke_ != stroke) {
      closeStroke();
      out_ += "<g stroke=\"" + hex(glm::vec3(color)) + '"' + opacity("stroke-opacity", alpha) + ">\n";
      stroke_ = stroke;
    }
    out_ += "<line";
    for (const auto& [name, v] :
         {std::pair(" x1=\"", a.x), {" y1=\"", a.y}, {" x2=\"", b.x}, {" y2=\"", b.y}}) {
      out_ += name;
      appendNum(out_, v);
      out_ += '"';
    }
    if (const double phase = std::fmod(along, 2.0 * l.dashPx); l.dashPx > 0 && phase > 0.005)
      out_ += " stroke-dashoffset=\"" + num(phase) + '"';
    out_ += "/>\n";
  }
  void closeStroke() {
    if (stroke_) out_ += "</g>\n";
    stroke_.reset();
  }

  void polygon(const std::vector<PixelPoint>& points, const glm::vec4& color, bool sealed) {
    out_ += "<polygon points=\"";
    for (size_t i = 0; i < points.size(); ++i) {
      if (i) out_ += ' ';
      appendNum(out_, points[i].x);
      out_ += ',';
      appendNum(out_, points[i].y);
    }
    out_ += "\" fill=\"" + hex(glm::vec3(color)) + '"' + opacity("fill-opacity", color.a);
    if (sealed)
      out_ += " stroke=\"" + hex(glm::vec3(color)) + "\" stroke-width=\"0.5\" stroke-linejoin=\"round\"";
    out_ += "/>\n";
  }

  const DisplayList& list_;
  const FontAtlas& fonts_;
  std::string& out_;
  DepthField depth_;
  std::optional<glm::vec4> stroke_;
  std::optional<bool> pass_;  // the x-ray pass: hidden parts (true) or visible parts (false)
};

}  // namespace

// ---------------------------------------------------------------- 3 pictures

size_t svgFaceCount(const draw::Picture& picture) {
  size_t n = 0;
  for (const Panel& p : picture.panels)
    for (const Batch& b : p.list.batches)
      if (const Fill* f = std::get_if<Fill>(&b); f && !f->depthOnly) n += faceCount(*f);
  return n;
}

std::string svgOfPicture(const draw::Picture& picture, const FontAtlas& fonts, std::string_view title) {
  const std::string w = std::to_string(picture.width), h = std::to_string(picture.height);
  if (picture.width < 1 || picture.height < 1)
    throw Error("SVG export: the picture is " + w + " x " + h + " pixels, not at least 1 x 1");
  if (const size_t faces = svgFaceCount(picture); faces > kMaxSvgFaces)
    throw Error("SVG export: " + std::to_string(faces) + " filled faces, more than the " +
                std::to_string(kMaxSvgFaces) + " a document can hold and still open; export a PNG instead");
  std::string out =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
      "version=\"1.1\" width=\"" +
      w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + ' ' + h + "\">\n<title>" + escaped(title) +
      "</title>\n<rect class=\"background\" width=\"" + w + "\" height=\"" + h + "\" fill=\"" +
      hex(picture.background) + "\"/>\n";
  for (const Panel& p : picture.panels) {
    const std::string pw = std::to_string(p.list.width), ph = std::to_string(p.list.height);
    out += "<svg class=\"panel\" x=\"" + std::to_string(p.x) + "\" y=\"" + std::to_string(p.y) +
           "\" width=\"" + pw + "\" height=\"" + ph + "\" viewBox=\"0 0 " + pw + ' ' + ph + "\">\n";
    ListWriter(p.list, fonts, out).write();
    out += "</svg>\n";
  }
  return out + "</svg>\n";
}

}  // namespace vplab
