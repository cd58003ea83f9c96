// SVG export (app/export/svg.h) of whole views: the document is well-formed XML of the PNG's size,
// the hidden-line passes are where the PNG dashes, the camera view's clipped edges end exactly on
// the window border, the labels are where the PNG draws them, and only a document too large to open
// is declined. Whether the SVG shows the PNG's picture, pixel for pixel, in every view and style is
// svg_raster_test.cpp's (which superseded this file's line-sampling comparison).
#include "app/export/svg.h"
#include "app/render/headless.h"
#include "app/export/cpu_raster.h"
#include "base/error.h"
#include "io/scene_io.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vplab {
namespace {

constexpr int kWidth = 640, kHeight = 480;

// ---------------------------------------------------------------- a strict, small XML parser

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<XmlElement> children;
  std::string text;  // character data directly inside, entities resolved

  const std::string* attribute(const std::string& key) const {
    for (const auto& [k, v] : attributes)
      if (k == key) return &v;
    return nullptr;
  }
};

/// Parses a whole document: an optional XML declaration, comments, exactly one root element.
/// Throws std::runtime_error naming the offset of the first violation of well-formedness it checks:
/// names, quoted attribute values without '<', no duplicate attributes, known entity references,
/// matching end tags, nothing but white space and comments outside the root.
class XmlParser {
 public:
  explicit XmlParser(const std::string& s) : s_(s) {}

  XmlElement document() {
    skipMisc();
    if (s_.compare(i_, 5, "<?xml") == 0) {
      const size_t end = s_.find("?>", i_);
      if (end == std::string::npos) fail("unterminated XML declaration");
      i_ = end + 2;
    }
    skipMisc();
    XmlElement root = element();
    skipMisc();
    if (i_ != s_.size()) fail("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("XML: " + what + " at offset " + std::to_string(i_));
  }
  bool at(char c) const { return i_ < s_.size() && s_[i_] == c; }
  void expect(char c) {
    if (!at(c)) fail(std::string("expected '") + c + "'");
    ++i_;
  }
  void skipSpace() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  void skipMisc() {
    for (;;) {
      skipSpace();
      if (s_.compare(i_, 4, "<!--") != 0) return;
      const size_t end = s_.find("-->", i_ + 4);
      if (end == std::string::npos) fail("unterminated comment");
      i_ = end + 3;
    }
  }
  static bool nameStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == ':';
  }
  static bool nameChar(char c) {
    return nameStart(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
  }
  std::string name() {
    if (i_ >= s_.size() || !nameStart(s_[i_])) fail("expected a name");
    const size_t start = i_;
    while (i_ < s_.size() && nameChar(s_[i_])) ++i_;
    return s_.substr(start, i_ - start);
  }
  std::string resolve(const std::string& raw) const {
    std::string out;
    for (size_t k = 0; k < raw.size(); ++k) {
      if (raw[k] != '&') {
        out += raw[k];
        continue;
      }
      const size_t end = raw.find(';', k);
      if (end == std::string::npos) fail("'&' without ';'");
      const std::string ref = raw.substr(k + 1, end - k - 1);
      static const std::map<std::string, char> named{
          {"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
      if (auto it = named.find(ref); it != named.end())
        out += it->second;
      else if (ref.size() > 1 && ref[0] == '#')
        out += '?';  // a character reference: well-formed, not needed here
      else
        fail("unknown entity &" + ref + ";");
      k = end;
    }
    return out;
  }
  XmlElement element() {
    expect('<');
    XmlElement e;
    e.name = name();
    for (;;) {
      const size_t before = i_;
      skipSpace();
      if (at('/')) {
        ++i_;
        expect('>');
        return e;
      }
      if (at('>')) {
        ++i_;
        break;
      }
      if (i_ == before) fail("expected white space before an attribute");
      std::string key = name();
      skipSpace();
      expect('=');
      skipSpace();
      if (!at('"') && !at('\'')) fail("attribute value not quoted");
      const char quote = s_[i_++];
      const size_t end = s_.find(quote, i_);
      if (end == std::string::npos) fail("unterminated attribute value");
      const std::string raw = s_.substr(i_, end - i_);
      if (raw.find('<') != std::string::npos) fail("'<' in an attribute value");
      if (e.attribute(key)) fail("duplicate attribute " + key);
      e.attributes.emplace_back(std::move(key), resolve(raw));
      i_ = end + 1;
    }
    // Content: character data, comments, child elements, then the matching end tag.
    std::string raw;
    for (;;) {
      if (i_ >= s_.size()) fail("unterminated element <" + e.name + ">");
      if (s_.compare(i_, 4, "<!--") == 0) {
        skipMisc();
        continue;
      }
      if (s_.compare(i_, 2, "</") == 0) {
        i_ += 2;
        if (name() != e.name) fail("end tag does not match <" + e.name + ">");
        skipSpace();
        expect('>');
        e.text = resolve(raw);
        return e;
      }
      if (at('<')) {
        e.children.push_back(element());
        continue;
      }
      if (at('>')) fail("'>' in character data");  // allowed by XML, never written by the export
      raw += s_[i_++];
    }
  }

  const std::string& s_;
  size_t i_ = 0;
};

double number(const std::string& s) {
  size_t used = 0;
  const double v = std::stod(s, &used);
  if (used != s.size()) throw std::runtime_error("not a number: \"" + s + "\"");
  return v;
}

// ---------------------------------------------------------------- the SVG's primitives

struct SvgLine {
  Vec2 a, b;
  std::string cls;  // the enclosing group's class
  Rgba color;
  double opacity = 1, width = 0;
  bool dashed = false;
  double dashPx = 0, dashOffset = 0;  // stroke-dasharray "d d", stroke-dashoffset
};
struct SvgCircle {
  Vec2 centre;
  double r;
  std::string cls;
};
struct SvgText {
  Vec2 baseline;  // x, y of the text element (panel offset applied)
  std::string text;
  Rgba color;
  double fontSize;
};
struct SvgPolygon {
  std::vector<Vec2> points;
  Rgba fill;
  double opacity = 1;
};
struct Svg {
  XmlElement root;
  std::vector<SvgLine> lines;
  std::vector<SvgCircle> circles;
  std::vector<SvgText> texts;
  std::vector<SvgPolygon> polygons;

  /// The primitives inside the panel [x0, x0 + w) × [y0, …) moved into the panel's own pixels.
  Svg panel(double x0, double y0, double w) const {
    Svg out;
    const Vec2 o(x0, y0);
    auto inside = [&](const Vec2& p) { return p.y >= y0 && p.x >= x0 && p.x <= x0 + w; };
    for (SvgLine l : lines)
      if (inside(l.a) && inside(l.b)) {
        l.a -= o;
        l.b -= o;
        out.lines.push_back(l);
      }
    for (SvgCircle c : circles)
      if (inside(c.centre)) {
        c.centre -= o;
        out.circles.push_back(c);
      }
    for (SvgPolygon p : polygons)
      if (inside(p.points[0])) {
        for (Vec2& q : p.points) q -= o;
        out.polygons.push_back(p);
      }
    return out;
  }

  std::vector<SvgLine> linesOf(const std::string& cls, std::optional<bool> dashed = {}) const {
    std::vector<SvgLine> out;
    for (const SvgLine& l : lines)
      if (l.cls == cls && (!dashed || l.dashed == *dashed)) out.push_back(l);
    return out;
  }
};

Rgba colorOf(const std::string& hex) {
  if (hex.size() != 7 || hex[0] != '#') throw std::runtime_error("not a #rrggbb colour: " + hex);
  auto byte = [&](int i) { return uint8_t(std::stoi(hex.substr(size_t(1 + 2 * i), 2), nullptr, 16)); };
  return {byte(0), byte(1), byte(2), 255};
}

/// Collects the drawing primitives with the attributes they inherit from their groups and the
/// offsets of nested <svg> panels.
void collect(const XmlElement& e, std::map<std::string, std::string> inherited, Vec2 offset, Svg& out,
             bool isRoot) {
  for (const auto& [k, v] : e.attributes)
    if (k != "x" && k != "y" && k != "width" && k != "height" && k != "viewBox") inherited[k] = v;
  if (e.name == "svg" && !isRoot) offset += Vec2(number(*e.attribute("x")), number(*e.attribute("y")));
  auto get = [&](const std::string& k) -> std::string {
    if (const std::string* v = e.attribute(k)) return *v;
    auto it = inherited.find(k);
    return it == inherited.end() ? std::string() : it->second;
  };
  if (e.name == "line") {
    SvgLine l;
    l.a = offset + Vec2(number(get("x1")), number(get("y1")));
    l.b = offset + Vec2(number(get("x2")), number(get("y2")));
    l.cls = get("class");
    l.color = colorOf(get("stroke"));
    l.opacity = get("stroke-opacity").empty() ? 1.0 : number(get("stroke-opacity"));
    l.width = number(get("stroke-width"));
    l.dashed = !get("stroke-dasharray").empty();
    if (l.dashed) l.dashPx = number(get("stroke-dasharray").substr(0, get("stroke-dasharray").find(' ')));
    l.dashOffset = get("stroke-dashoffset").empty() ? 0.0 : number(get("stroke-dashoffset"));
    out.lines.push_back(l);
  } else if (e.name == "circle") {
    out.circles.push_back(
        {offset + Vec2(number(get("cx")), number(get("cy"))), number(get("r")), get("class")});
  } else if (e.name == "text") {
    out.texts.push_back({offset + Vec2(number(get("x")), number(get("y"))), e.text, colorOf(get("fill")),
                         number(get("font-size"))});
  } else if (e.name == "polygon") {
    SvgPolygon p;
    std::istringstream points(get("points"));
    std::string pair;
    while (points >> pair) {
      const size_t comma = pair.find(',');
      if (comma == std::string::npos) throw std::runtime_error("not a point: " + pair);
      p.points.push_back(offset + Vec2(number(pair.substr(0, comma)), number(pair.substr(comma + 1))));
    }
    if (p.points.size() < 3) throw std::runtime_error("a polygon of fewer than 3 points");
    p.fill = colorOf(get("fill"));
    p.opacity = get("fill-opacity").empty() ? 1.0 : number(get("fill-opacity"));
    out.polygons.push_back(std::move(p));
  }
  for (const XmlElement& c : e.children) collect(c, inherited, offset, out, false);
}

Svg parseSvg(const std::string& text) {
  Svg svg;
  svg.root = XmlParser(text).document();
  collect(svg.root, {}, Vec2(0), svg, true);
  return svg;
}

// ---------------------------------------------------------------- rendering both

struct Both {
  std::string svgText;
  Svg svg;
  Image png;
};

DisplaySettings settingsFor(const Scene& scene, Style style, int w, int h, bool labels) {
  DisplaySettings s = displaySettingsFor(scene, style, double(w) / h);
  s.overlays.labels = labels;
  return s;
}

Both renderBoth(ViewKind view, Style style, bool labels = false, int w = kWidth, int h = kHeight) {
  const Scene scene = defaultScene();
  const PipelineRun run = runPipeline(scene, RenderRequest{}.pipeline);
  const DisplaySettings s = settingsFor(scene, style, w, h, labels);
  Both b;
  b.svgText = svgOfView(view, scene, run, s, {}, w, h);
  b.svg = parseSvg(b.svgText);
  b.png = test::egl().renderer->render(view, scene, run, s, {}, w, h);
  return b;
}

std::string name(ViewKind v, Style s) { return std::string(toString(v)) + "-" + std::string(toString(s)); }

// A preview of the SVG's lines and discs (no text), drawn on the CPU, for looking at a failure next
// to the PNG: a debugging aid, not part of the comparison.
Image preview(const Svg& svg, int w, int h, Rgba background) {
  Image im(w, h, background);
  auto blend = [&](int x, int y, Rgba c, double a) {
    if (x < 0 || y < 0 || x >= w || y >= h) return;
    Rgba& p = im.at(x, y);
    p.r = uint8_t(std::lround(p.r + a * (c.r - p.r)));
    p.g = uint8_t(std::lround(p.g + a * (c.g - p.g)));
    p.b = uint8_t(std::lround(p.b + a * (c.b - p.b)));
  };
  for (const SvgLine& l : svg.lines) {
    const Vec2 d = l.b - l.a;
    const double len = glm::length(d);
    if (len <= 0) continue;
    const int x0 = int(std::floor(std::min(l.a.x, l.b.x) - l.width)),
              x1 = int(std::ceil(std::max(l.a.x, l.b.x) + l.width));
    const int y0 = int(std::floor(std::min(l.a.y, l.b.y) - l.width)),
              y1 = int(std::ceil(std::max(l.a.y, l.b.y) + l.width));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Vec2 p(x + 0.5, y + 0.5);
        const double t = glm::dot(p - l.a, d) / (len * len);
        if (t < 0 || t > 1) continue;
        if (l.dashed && std::fmod(t * len, 10.0) > 5.0) continue;
        if (glm::length(p - (l.a + t * d)) <= 0.5 * l.width) blend(x, y, l.color, l.opacity);
      }
  }
  for (const SvgCircle& c : svg.circles)
    for (int y = int(c.centre.y - c.r - 2); y <= int(c.centre.y + c.r + 2); ++y)
      for (int x = int(c.centre.x - c.r - 2); x <= int(c.centre.x + c.r + 2); ++x)
        if (glm::length(Vec2(x + 0.5, y + 0.5) - c.centre) <= c.r) blend(x, y, {255, 255, 255, 255}, 1);
  for (const SvgText& t : svg.texts)  // a mark at each text's start
    for (int k = 0; k < 4; ++k) blend(int(t.baseline.x) + k, int(t.baseline.y), t.color, 1);
  return im;
}

/// Writes the SVG, its preview and the PNG into the test output directory (on failure, or always
/// with VPLAB_KEEP_TEST_OUTPUT=1) and returns where.
std::string keep(const Both& b, const std::string& what) {
  const std::filesystem::path dir = test::outputDir();
  writeSvg(b.svgText, dir / (what + ".svg"));
  writePng(b.png, dir / (what + ".png"));
  writePng(preview(b.svg, b.png.width, b.png.height, b.png.pixels.empty() ? Rgba{} : b.png.at(0, 0)),
           dir / (what + ".svg-preview.png"));
  return (dir / what).string() + ".{svg,png,svg-preview.png}";
}

bool keepAlways() {
  const char* k = std::getenv("VPLAB_KEEP_TEST_OUTPUT");
  return k && std::string(k) == "1";
}

int contrast(const Rgba& a, const Rgba& b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

struct Share {
  size_t passed = 0, total = 0;
  double value() const { return total ? double(passed) / double(total) : 1.0; }
};

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = glm::dot(d, d);
  const double t = len2 > 0 ? std::clamp(glm::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * d));
}

double totalLength(const std::vector<SvgLine>& lines) {
  double sum = 0;
  for (const SvgLine& l : lines) sum += glm::length(l.b - l.a);
  return sum;
}

// ---------------------------------------------------------------- structure

TEST(SvgExport, IsWellFormedWithThePngsSize) {
  const Scene scene = defaultScene();
  const PipelineRun run = runPipeline(scene, RenderRequest{}.pipeline);
  for (ViewKind view : {ViewKind::camera, ViewKind::world, ViewKind::npc, ViewKind::morph, ViewKind::all})
    for (Style style : {Style::flat, Style::shaded, Style::wire, Style::hiddenLine, Style::hiddenRemoved}) {
      SCOPED_TRACE(name(view, style));
      const int w = 400, h = 300;
      const std::string text =
          svgOfView(view, scene, run, displaySettingsFor(scene, style, double(w) / h), {}, w, h);
      Svg svg;
      ASSERT_NO_THROW(svg = parseSvg(text));
      EXPECT_EQ(text.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n", 0), 0u);
      ASSERT_EQ(svg.root.name, "svg");
      ASSERT_TRUE(svg.root.attribute("xmlns"));
      EXPECT_EQ(*svg.root.attribute("xmlns"), "http://www.w3.org/2000/svg");
      // The PNG's size ("all": three panels and the title strip).
      const Image png =
          test::egl().renderer->render(view, scene, run, displaySettingsFor(scene, style, double(w) / h), {}, w, h);
      const int totalW = png.width, totalH = png.height;
      if (view == ViewKind::all)
        EXPECT_EQ(totalW, 3 * w + 12);
      else
        EXPECT_EQ(std::pair(totalW, totalH), std::pair(w, h));
      EXPECT_EQ(*svg.root.attribute("width"), std::to_string(totalW));
      EXPECT_EQ(*svg.root.attribute("height"), std::to_string(totalH));
      EXPECT_EQ(*svg.root.attribute("viewBox"),
                "0 0 " + std::to_string(totalW) + " " + std::to_string(totalH));
      // The morph view draws every style filled (displaySettingsFor), with its polygons' outlines.
      if (isFilled(style) || view == ViewKind::morph) {
        EXPECT_GT(svg.polygons.size(), 5u);
      } else {  // no faces: the translucent overlays only (the window, the volume's faces, the cube's front)
        for (const SvgPolygon& p : svg.polygons) EXPECT_LT(p.opacity, 1.0);
      }
      if (!isFilled(style) || view != ViewKind::camera) {
        EXPECT_GT(svg.lines.size(), 50u);
      }
      // Every line is clipped to its view: nothing outside the canvas (to the 2 decimals written).
      for (const SvgLine& l : svg.lines)
        for (const Vec2& p : {l.a, l.b}) {
          EXPECT_GE(p.x, -0.005);
          EXPECT_LE(p.x, totalW + 0.005);
          EXPECT_GE(p.y, -0.005);
          EXPECT_LE(p.y, totalH + 0.005);
        }
      // Coordinates have at most two decimals.
      for (const std::string& attr : {std::string("x1=\""), std::string("y2=\"")}) {
        size_t at = 0;
        while ((at = text.find(attr, at)) != std::string::npos) {
          at += attr.size();
          const std::string value = text.substr(at, text.find('"', at) - at);
          const size_t dot = value.find('.');
          EXPECT_TRUE(dot == std::string::npos || value.size() - dot - 1 <= 2) << value;
        }
      }
    }
}

// Filled styles and the morph view are exported now (svg_raster_test.cpp compares them with the
// PNG); what is declined is a document too large to open: the viewer greys its menu entry out by
// svgExportError, svgOfView throws with the count, the limit and the way out.
TEST(SvgExport, OnlyAHugeDocumentIsDeclined) {
  const Scene scene = defaultScene();
  const PipelineRun run = runPipeline(scene, RenderRequest{}.pipeline);
  for (ViewKind view : {ViewKind::camera, ViewKind::world, ViewKind::npc, ViewKind::morph, ViewKind::all})
    for (Style style : {Style::flat, Style::shaded, Style::wire}) {
      const DisplaySettings s = displaySettingsFor(scene, style, 4.0 / 3.0);
      EXPECT_FALSE(svgExportError(view, scene, s)) << *svgExportError(view, scene, s);
    }
  EXPECT_NO_THROW(svgOfView(ViewKind::morph, scene, run, displaySettingsFor(scene, Style::shaded, 4.0 / 3.0), {}, 320, 240));
  EXPECT_THROW(svgOfView(ViewKind::camera, scene, run, displaySettingsFor(scene, Style::wire, 4.0 / 3.0), {}, 0, 240), Error);

  const Scene large = loadScene(VPLAB_ASSETS "/scenes/large-mesh.json");
  const DisplaySettings shaded = displaySettingsFor(large, Style::shaded, 4.0 / 3.0);
  const std::optional<std::string> why = svgExportError(ViewKind::camera, large, shaded);
  ASSERT_TRUE(why);
  EXPECT_NE(why->find(std::to_string(kMaxSvgFaces)), std::string::npos) << *why;
  EXPECT_NE(why->find("PNG"), std::string::npos) << *why;
  // Its wireframe styles draw no filled faces: they are exported.
  EXPECT_FALSE(svgExportError(ViewKind::camera, large, displaySettingsFor(large, Style::hiddenLine, 4.0 / 3.0)));
  const PipelineRun largeRun = runPipeline(large, RenderRequest{}.pipeline);
  try {
    svgOfView(ViewKind::camera, large, largeRun, shaded, {}, 320, 240);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(kMaxSvgFaces)), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("PNG"), std::string::npos) << e.what();
  }
}

TEST(SvgExport, WriteSvgWritesTheTextAndNamesTheFileItCannotWrite) {
  const std::filesystem::path file = test::outputDir() / "write-test.svg";
  const std::string text = svgOfRequest(defaultScene(), RenderRequest{ViewKind::npc, Style::wire, 200, 150});
  writeSvg(text, file);
  std::ifstream in(file, std::ios::binary);
  std::stringstream back;
  back << in.rdbuf();
  EXPECT_EQ(back.str(), text);
  const std::filesystem::path bad = test::outputDir() / "no-such-directory" / "x.svg";
  try {
    writeSvg(text, bad);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
  }
}

// The hidden parts the export found are the ones the GPU dashes, in phase: in the middle of each dash
// of a hidden-line SVG's dashed edge (where SVG's dash pattern, offset by stroke-dashoffset, is
// between 1.5 and 3.5 px into a 5 px dash, and at least 2 px from the piece's ends, where the GPU's
// per-pixel visibility and the line caps blur the boundary), the hidden-line PNG differs from the
// hidden-removed PNG within one pixel: the GPU drew a dash there (samples within 3 px of a visible
// line are left out, see below). A part wrongly called hidden is
// drawn alike in both PNGs and fails; a dash out of phase lands in the PNG's gaps and fails. At least
// 95 % (the GPU's per-pixel depth test flickers along edges that run almost in a face's plane).
TEST(SvgExport, HiddenPartsAreWhereThePngDashes) {
  for (ViewKind view : {ViewKind::camera, ViewKind::world, ViewKind::npc}) {
    SCOPED_TRACE(toString(view));
    const Scene scene = defaultScene();
    const PipelineRun run = runPipeline(scene, RenderRequest{}.pipeline);
    const DisplaySettings line = settingsFor(scene, Style::hiddenLine, kWidth, kHeight, false);
    const DisplaySettings removed = settingsFor(scene, Style::hiddenRemoved, kWidth, kHeight, false);
    const Svg svg = parseSvg(svgOfView(view, scene, run, line, {}, kWidth, kHeight));
    const Image dashes = test::egl().renderer->render(view, scene, run, line, {}, kWidth, kHeight);
    const Image none = test::egl().renderer->render(view, scene, run, removed, {}, kWidth, kHeight);
    // Where a visible line runs within 3 px (dense meshes: the sphere, the cylinder seen small) it
    // may cover the dash in both PNGs alike: such samples tell nothing and are left out.
    auto nearSolid = [&](const Vec2& p) {
      for (const SvgLine& o : svg.lines)
        if (!o.dashed && distanceToSegment(p, o.a, o.b) < 3.0) return true;
      return false;
    };
    Share share;
    for (const SvgLine& l : svg.linesOf("lines hidden-only", true)) {
      ASSERT_EQ(l.dashPx, 5.0);
      const double len = glm::length(l.b - l.a);
      for (double s = 2; s <= len - 2; s += 0.5) {
        const double pattern = std::fmod(l.dashOffset + s, 2 * l.dashPx);
        if (pattern < 1.5 || pattern > 3.5) continue;
        const Vec2 p = l.a + (l.b - l.a) * (s / len);
        if (nearSolid(p)) continue;
        const int cx = int(p.x), cy = int(p.y);
        bool differs = false;
        for (int y = cy - 1; y <= cy + 1; ++y)
          for (int x = cx - 1; x <= cx + 1; ++x)
            if (x >= 0 && y >= 0 && x < kWidth && y < kHeight)
              differs |= contrast(dashes.at(x, y), none.at(x, y)) >= 12;
        ++share.total;
        share.passed += differs;
      }
    }
    std::cout << toString(view) << ": " << share.passed << " of " << share.total
              << " samples in the SVG's hidden dashes fall on the PNG's dashes\n";
    EXPECT_GT(share.total, 80u);
    EXPECT_GE(share.value(), 0.95);
  }
}

// ---------------------------------------------------------------- hidden lines

// The hidden-line passes are the line batches of depth "hidden-only" (dashed) and "depth-test"
// (solid): hidden-removed has the second only, wire neither, and the visible parts are the same
// with hidden lines dashed or removed.
TEST(SvgExport, HiddenRemovedHasNoDashedEdgesAndHiddenLineHasSome) {
  const Scene scene = defaultScene();
  const PipelineRun run = runPipeline(scene, RenderRequest{}.pipeline);
  for (ViewKind view : {ViewKind::camera, ViewKind::world, ViewKind::npc}) {
    SCOPED_TRACE(toString(view));
    auto svgOf = [&](Style style) {
      return parseSvg(
          svgOfView(view, scene, run, displaySettingsFor(scene, style, 4.0 / 3.0), {}, kWidth, kHeight));
    };
    const Svg wire = svgOf(Style::wire), line = svgOf(Style::hiddenLine),
              removed = svgOf(Style::hiddenRemoved);
    EXPECT_TRUE(removed.linesOf("lines hidden-only").empty());
    EXPECT_TRUE(wire.linesOf("lines hidden-only").empty());
    EXPECT_GT(line.linesOf("lines hidden-only", true).size(), 20u);
    const double visible = totalLength(line.linesOf("lines depth-test")),
                 hiddenLen = totalLength(line.linesOf("lines hidden-only"));
    EXPECT_GT(visible, 0);
    EXPECT_NEAR(totalLength(removed.linesOf("lines depth-test")), visible, 1e-6);
    // Camera view: the edges are the only lines, so visible + hidden is every edge's clipped part
    // (wire's), to 0.1 % for the 2-decimal rounding of the pieces' ends.
    if (view == ViewKind::camera) {
      const double all = totalLength(wire.linesOf("lines"));
      EXPECT_LT(visible, 0.9 * all);
      EXPECT_NEAR(visible + hiddenLen, all, 1e-3 * all);
    }
  }
}

// ---------------------------------------------------------------- clipping in the camera view

// The default scene's tetrahedron crosses the window's right and bottom edges: the camera view's
// SVG ends those edges exactly where the CPU clipper cut them, on the window border.
TEST(SvgExport, CameraViewEndsClippedEdgesOnTheWindowBorder) {
  const Scene scene = defaultScene();
  const PipelineRun run = runPipeline(scene, RenderRequest{}.pipeline);
  const ObjectRun* tetra = nullptr;
  for (const ObjectRun& o : run.objects)
    if (o.name == "tetrahedron") tetra = &o;
  ASSERT_TRUE(tetra);
  // The cut points from the run: the clipped end of each edge that was cut, in pixels.
  std::vector<Vec2> cuts;
  const Mat4 dc = dcFromNpc(Device{kWidth, kHeight});
  for (size_t i = 0; i < tetra->edges.size(); ++i) {
    const EdgeRange r = tetra->edgeRange(i);
    if (!r.visible) continue;
    const Vec4 a = tetra->npcH[tetra->edges[i].a], b = tetra->npcH[tetra->edges[i].b];
    for (double t : {r.t0, r.t1}) {
      if (t == 0.0 || t == 1.0) continue;
      const Vec4 h = glm::mix(a, b, t);
      cuts.push_back(Vec2(dc * Vec4(Vec3(h) / h.w, 1.0)));
    }
  }
  int right = 0, bottom = 0;
  for (const Vec2& p : cuts) {
    right += std::abs(p.x - kWidth) < 1e-6;
    bottom += std::abs(p.y - kHeight) < 1e-6;
  }
  EXPECT_GE(right, 1);
  EXPECT_GE(bottom, 1);

  const Rgba blue = rgbaFromColor(tetra->color);
  for (Style style : {Style::wire, Style::hiddenLine}) {
    SCOPED_TRACE(toString(style));
    const Svg svg = parseSvg(
        svgOfView(ViewKind::camera, scene, run, displaySettingsFor(scene, style, 4.0 / 3.0), {}, kWidth, kHeight));
    for (const Vec2& cut : cuts) {
      bool found = false;
      for (const SvgLine& l : svg.lines)
        if (l.color == blue && (glm::length(l.a - cut) <= 0.0071 || glm::length(l.b - cut) <= 0.0071))
          found = true;
      EXPECT_TRUE(found) << "no tetrahedron line ends at the cut (" << cut.x << ", " << cut.y << ")";
    }
  }
}

// ---------------------------------------------------------------- labels

// Each label is written where the PNG draws it: the PNG has pixels of the label's colour inside the
// box from the text's start to its estimated width (0.5 em per character), an em above the baseline
// and 0.3 em below. "Of the colour" allows 40 levels per channel: the glyphs are antialiased, their
// strokes barely more than a pixel wide, and some label colours have alpha 0.9 over the text's dark
// outline; every label colour is more than 100 levels away from the background.
TEST(SvgExport, LabelsAreWhereThePngDrawsThem) {
  for (ViewKind view : {ViewKind::world, ViewKind::npc}) {
    SCOPED_TRACE(toString(view));
    const Both b = renderBoth(view, Style::hiddenLine, /*labels=*/true);
    EXPECT_GE(b.svg.texts.size(), view == ViewKind::world ? 9u : 9u);
    std::set<std::string> texts;
    for (const SvgText& t : b.svg.texts) {
      texts.insert(t.text);
      int hits = 0;
      const int x0 = int(t.baseline.x), x1 = int(t.baseline.x + 0.5 * t.fontSize * double(t.text.size())) + 1;
      const int y0 = int(t.baseline.y - t.fontSize), y1 = int(t.baseline.y + 0.3 * t.fontSize);
      for (int y = std::max(0, y0); y <= std::min(b.png.height - 1, y1); ++y)
        for (int x = std::max(0, x0); x <= std::min(b.png.width - 1, x1); ++x)
          hits += contrast(b.png.at(x, y), t.color) <= 40;
      EXPECT_GE(hits, 3) << "label \"" << t.text << "\" at (" << t.baseline.x << ", " << t.baseline.y << ")";
    }
    if (view == ViewKind::world) {
      for (const char* expected : {"VRP", "PRP", "U", "V", "N", "VUP", "window", "front F", "back B"})
        EXPECT_TRUE(texts.count(expected)) << expected;
    }
    if (HasFailure() || keepAlways())
      std::cout << "pictures: " << keep(b, "svg-labels-" + std::string(toString(view))) << "\n";
  }
}

}  // namespace
}  // namespace vplab
