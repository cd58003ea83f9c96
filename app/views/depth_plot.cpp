// The depth plot (lecture notes 15.2.4): how the view mapping's perspective part bends VRC z into
// NPC z, z_npc = npcDepthOfVrcZ (pipeline/view_mapping.h), 0 at the back plane B and 1 at the front
// plane F; equal VRC steps crowd at B, which is where a depth buffer resolves least.
#include "app/views/depth_plot.h"

#include "app/text/catalogue.h"
#include "app/views/number_text.h"
#include "app/views/theme.h"
#include "pipeline/device_mapping.h"
#include "base/error.h"
#include "pipeline/view_mapping.h"

#include <algorithm>
#include <cmath>

namespace vplab {

namespace {

using namespace draw;

glm::vec4 rgba(int r, int g, int b, int a = 255) { return glm::vec4(r, g, b, a) / 255.f; }

// The colours the inspector has always drawn the chart in.
const glm::vec4 kGrid = rgba(90, 95, 110), kTick = rgba(90, 95, 110, 120), kTickNpc = rgba(120, 200, 230, 110);
const glm::vec4 kNpcCurve = rgba(140, 220, 255), kGlCurve = rgba(255, 200, 90), kLabel = rgba(200, 205, 215);
const glm::vec4 kLegendNpc = rgba(140, 220, 255), kLegendGl = rgba(255, 200, 90);
constexpr int kMinSidePx = 8;  // the chart's width and its plot's height, at least
constexpr int kTicks = 10;     // equal VRC steps from B to F
constexpr int kSegments = 120; // the curves' segments; GL's window depth is dashed by leaving out every other one
// The chart is flat: every mark at the depth half way (z = 0.5, inside the GL backend's depth range,
// as the views' other pixel overlays; z = 0 would lie on its far plane and be cut).
constexpr double kFlat = 0.5;

std::string number(double v) { return formatNumber(v, {4, 0}); }

// The sizes every part of the chart is laid out with, from the text's line height.
struct Metrics {
  float line, gap, scale;
  explicit Metrics(const TextMetrics& text)
      : line(float(text.measure("Ag", TextSize::label).y)), gap(std::round(4.f * text.scale())), scale(text.scale()) {}
  float legendHeight(int rows) const { return rows ? float(rows) * line + 2 * gap : 0.f; }
  float rowHeight() const { return line + gap; }
};

size_t barCount(const PipelineRun& run) {
  return size_t(std::count_if(run.objects.begin(), run.objects.end(),
                              [](const ObjectRun& o) { return o.vertexCount() > 0; }));
}

// The legend, "— NPC z" then GL's window depth, the longest wording that fits: on one row when
// both fit beside each other, else on two.
struct Legend {
  std::string npc = "— NPC z", gl;
  int rows = 0;
};
Legend legendFor(int width, const TextMetrics& text, const DepthPlotOptions& options) {
  Legend l;
  if (!options.legend) return l;
  const float pad = float(text.measure("0.5", TextSize::label).x) + 8, line = float(text.measure("Ag", TextSize::label).y);
  const float room = float(width) - 8 - pad, npcWidth = float(text.measure(l.npc, TextSize::label).x);
  const Language lang = options.language;
  for (const char* gl :
       {text::Text("- - GL window depth = 1 − z").in(lang), text::Text("- - GL depth = 1 − z").in(lang), "- - 1 − z"}) {
    l.gl = gl;
    const float glWidth = float(text.measure(l.gl, TextSize::label).x);
    l.rows = npcWidth + line + glWidth <= room ? 1 : 2;
    if (glWidth <= room) break;
  }
  return l;
}

TextLabel fixedLabel(Vec2 at, std::string text, glm::vec4 color, Anchor anchor = Anchor::topLeft) {
  TextLabel l{at, std::move(text), color, TextSize::label, anchor, false};
  l.avoid = false;
  return l;
}

}  // namespace

glm::vec2 DepthPlot::at(double vrcZ, double depth) const {
  const float x = plot.min.x + float((vrcZ - back) / (front - back)) * (plot.max.x - plot.min.x);
  return {x, plot.max.y - float(depth) * (plot.max.y - plot.min.y)};
}

float depthPlotExtraHeight(const PipelineRun& run, int width, const TextMetrics& text, const DepthPlotOptions& options) {
  const Metrics m(text);
  // The legend above; under the plot: 2 px, the axis row, then one row per bar.
  return m.legendHeight(legendFor(width, text, options).rows) + 2 + m.gap +
         m.rowHeight() * float(1 + barCount(run));
}

DepthPlot depthPlot(const PipelineRun& run, int width, int plotHeight, const TextMetrics& text,
                    const DepthPlotOptions& options) {
  if (width < kMinSidePx || plotHeight < kMinSidePx)
    throw Error("the depth plot needs at least " + std::to_string(kMinSidePx) + " pixels for its width and its plot's "
                "height, not " + std::to_string(width) + " × " + std::to_string(plotHeight) + " (a larger --size)");
  const Camera& c = run.camera;
  const VrcAxes& f = run.vrc;
  const Metrics m(text);
  DepthPlot out;
  out.back = c.back;
  out.front = c.front;
  DisplayList& list = out.list;
  list.width = width;
  list.height = int(std::ceil(float(plotHeight) + depthPlotExtraHeight(run, width, text, options)));
  // The chart keeps the dark theme in every theme: its bars' and scales' colours are chosen for it.
  list.background = theme::kDark.viewBackground;
  // The chart looks at its own pixels: the device mapping of a width × height device undone
  // (a backend that draws observer-space batches through the observer then needs no special case).
  list.observer.space = Space::pixels;
  list.observer.camera.npcFromVrc = glm::inverse(dcFromNpc(Device{width, list.height}));
  // No multisampling: the lines bring their own smooth edges, the bars are whole-pixel rectangles.
  list.antialiased = false;

  std::vector<TextLabel> labels;
  const Legend legend = legendFor(width, text, options);
  const float top = m.legendHeight(legend.rows);
  if (legend.rows) {
    const float pad = float(text.measure("0.5", TextSize::label).x) + 8;
    const float npcWidth = float(text.measure(legend.npc, TextSize::label).x);
    const float glWidth = float(text.measure(legend.gl, TextSize::label).x);
    labels.push_back(fixedLabel({pad, m.gap}, legend.npc, kLegendNpc));
    const Vec2 gl = legend.rows == 1 ? Vec2(pad + npcWidth + m.line, m.gap) : Vec2(pad, m.gap + m.line);
    labels.push_back(fixedLabel(gl, legend.gl, kLegendGl));
    out.legend = {{pad, m.gap}, {std::max(pad + npcWidth, float(gl.x) + glWidth), float(gl.y) + m.line}};
  }

  // The frame: x from B to F, y from 0 (bottom) to 1 (top), room on the left for "0" and "1".
  const float pad = float(text.measure("0.5", TextSize::label).x) + 8;
  out.plot = {{pad, top + m.line * 0.5f}, {float(width) - 8, top + float(plotHeight)}};
  const glm::vec2 p0 = out.plot.min, p1 = out.plot.max;
  auto pixel = [&](double z, double d) { return Vec3(Vec2(out.at(z, d)), kFlat); };
  Lines thin;  // the frame and the ticks
  thin.space = Space::pixels;
  thin.widthPx = 1.f * m.scale;
  const Vec3 corners[4] = {{p0.x, p0.y, kFlat}, {p1.x, p0.y, kFlat}, {p1.x, p1.y, kFlat}, {p0.x, p1.y, kFlat}};
  thin.polyline(corners, true, kGrid);
  // Equal VRC steps and their NPC depth: the ticks crowd at the back plane.
  for (int i = 0; i <= kTicks; ++i) {
    const double z = c.back + (c.front - c.back) * i / double(kTicks);
    const double d = npcDepthOfVrcZ(c, f, z);
    thin.line({pixel(z, 0).x, p1.y, kFlat}, pixel(z, d), kTick);
    thin.line({p0.x, pixel(z, d).y, kFlat}, pixel(z, d), kTickNpc);
  }
  list.add(std::move(thin));
  // GL's window depth 1 − z (dashed: every other segment) under NPC z (solid).
  Lines glDepth, npcDepth;
  glDepth.space = npcDepth.space = Space::pixels;
  glDepth.widthPx = 1.5f * m.scale;
  npcDepth.widthPx = 2.f * m.scale;
  Vec3 prev = pixel(c.back, npcDepthOfVrcZ(c, f, c.back)), prevGl = pixel(c.back, 1 - npcDepthOfVrcZ(c, f, c.back));
  for (int i = 1; i <= kSegments; ++i) {
    const double z = c.back + (c.front - c.back) * i / double(kSegments);
    const double d = npcDepthOfVrcZ(c, f, z);
    const Vec3 p = pixel(z, d), q = pixel(z, 1 - d);
    npcDepth.line(prev, p, kNpcCurve);
    if (i % 2) glDepth.line(prevGl, q, kGlCurve);
    prev = p;
    prevGl = q;
  }
  list.add(std::move(glDepth));
  list.add(std::move(npcDepth));
  labels.push_back(fixedLabel({0, p0.y}, "1", kLabel, Anchor::left));
  labels.push_back(fixedLabel({0, p1.y}, "0", kLabel, Anchor::left));

  // The axis: B under the left end, F under the right end, "VRC z" between them where it fits.
  const float axisTop = p1.y + 2 + m.gap;
  out.axis = {{0, axisTop}, {float(width), axisTop + m.line}};
  const std::string b = "B = " + number(c.back), fr = "F = " + number(c.front), vrc = "VRC z";
  const float bWidth = float(text.measure(b, TextSize::label).x), frWidth = float(text.measure(fr, TextSize::label).x);
  // Under the ends of the axis; in a narrow chart B moves left (as far as the chart's edge) to make room.
  const float bX = std::max(0.f, std::min(p0.x, p1.x - frWidth - m.line - bWidth));
  const float bEnd = bX + bWidth;
  const float frX = std::max(bEnd + m.line, p1.x - frWidth);
  labels.push_back(fixedLabel({bX, axisTop}, b, kLabel));
  labels.push_back(fixedLabel({frX, axisTop}, fr, kLabel));
  const float vrcWidth = float(text.measure(vrc, TextSize::label).x);
  if (frX - bEnd >= vrcWidth + 2 * m.line)
    labels.push_back(fixedLabel({std::round((bEnd + frX - vrcWidth) / 2), axisTop}, vrc, kLabel));

  // The objects' depth ranges (VRC z of their vertices), one named bar each along the same axis.
  Triangles bars;
  bars.space = Space::pixels;
  float rowTop = axisTop + m.rowHeight();
  for (const ObjectRun& o : run.objects) {
    if (o.vertexCount() == 0) continue;
    double lo = 1e300, hi = -1e300;
    for (uint32_t v = 0; v < o.vertexCount(); ++v) {
      const double z = o.vrc(v).z;
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
    const double shownLo = std::clamp(lo, c.back, c.front), shownHi = std::clamp(hi, c.back, c.front);
    const float x0 = std::round(out.at(shownLo, 0).x), x1 = std::max(std::round(out.at(shownHi, 0).x), x0 + 2);
    DepthPlot::Bar bar{nameIn(o, options.language), {{0, rowTop}, {float(width), rowTop + m.line}},
                       {{x0, std::round(rowTop + m.line * 0.25f)}, {x1, std::round(rowTop + m.line * 0.75f)}}, lo, hi};
    const glm::vec4 color(glm::vec3(o.color), 0.9f);
    bars.quad({x0, bar.bar.min.y, kFlat}, {x1, bar.bar.min.y, kFlat}, {x1, bar.bar.max.y, kFlat}, {x0, bar.bar.max.y, kFlat},
              color);
    // The name beside the bar, on whichever side has room.
    const float nameWidth = float(text.measure(bar.name, TextSize::label).x);
    const float nameX = x1 + 6 + nameWidth <= p1.x ? x1 + 6 : std::max(0.f, x0 - 6 - nameWidth);
    labels.push_back(fixedLabel({nameX, rowTop}, bar.name, kLabel));
    out.bars.push_back(std::move(bar));
    rowTop += m.rowHeight();
  }
  if (!bars.vertices.empty()) list.add(std::move(bars));
  list.add(Text{placeLabels(labels, text, list.width, list.height)});
  return out;
}

DisplayList depthPlotView(const ViewInput& in) {
  DepthPlotOptions options;
  options.legend = true;
  options.language = in.settings.language;
  const float extra = depthPlotExtraHeight(in.run, in.width, in.text, options);
  const float line = float(in.text.measure("Ag", TextSize::label).y);
  const int plotHeight = std::max(int(std::floor(float(in.height) - extra)), int(std::ceil(4 * line)));
  DisplayList list = std::move(depthPlot(in.run, in.width, plotHeight, in.text, options).list);
  list.height = in.height;  // what does not fit a small view is cut off at its bottom
  list.observer.camera.npcFromVrc = glm::inverse(dcFromNpc(Device{in.width, in.height}));
  return list;
}

}  // namespace vplab
