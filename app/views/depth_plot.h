// The depth plot (lecture notes 15.2.4): NPC z and GL's window depth 1 − z against VRC z between the
// back plane B (left) and the front plane F (right); equal VRC steps and where they land in NPC
// (they crowd near the back plane); below the axis, each object's depth range (the VRC z of its
// vertices) as a named bar along the same axis. Drawn in the inspector's Depth tab (through the
// ImDrawList backend, app/ui/imdrawlist_backend.h) and by `vplab render --view depth-plot`.
//
// All in the chart's pixels (origin top-left, y down): one display list of Space::pixels batches
// (lines, triangles for the bars, placed labels), no depth test.
#pragma once

#include "app/views/views.h"

#include <string>
#include <vector>

namespace vplab {

struct DepthPlotOptions {
  bool legend = false;      // the curves' legend above the plot (the panel shows its own, in ImGui)
  bool background = true;   // the list's background is theme::kViewBackground (the panel: its window's)
  Language language = Language::en;  // the legend's
};

/// The chart and where its parts went, for the panel's hover boxes and the tests.
struct DepthPlot {
  draw::DisplayList list;  // width × height pixels
  struct Box {
    glm::vec2 min{0}, max{0};
  };
  Box legend;  // empty (min == max) without DepthPlotOptions::legend
  Box plot;    // the frame of the curves: x from B to F, y from depth 1 (top) to 0 (bottom)
  Box axis;    // the row under the plot naming B and F
  struct Bar {
    std::string name;
    Box row;       // the object's row under the axis (its hover box)
    Box bar;       // the bar: its VRC z range, cut to [B, F], in whole pixels, at least 2 px wide
    double lo = 0, hi = 0;  // VRC z of its nearest-to-B and nearest-to-F vertex, uncut
  };
  std::vector<Bar> bars;  // one per object with vertices, in the run's order
  /// The pixel of (VRC z, depth), depth 0 … 1 upwards; x from B (left) to F (right).
  glm::vec2 at(double vrcZ, double depth) const;
  double back = 0, front = 0;  // B and F
};

/// The rows the chart `width` wide adds to a plot `plotHeight` high (legend, axis and bars), in pixels.
float depthPlotExtraHeight(const PipelineRun& run, int width, const TextMetrics& text,
                           const DepthPlotOptions& options = {});

/// The chart `width` wide with a plot frame ending `plotHeight` below its top (legend included when
/// asked): text measured with `text`, lines and bars ×text.scale(). Its height is
/// plotHeight + depthPlotExtraHeight(…). Throws vplab::Error, naming both, for a width or plot
/// height below 8 px.
DepthPlot depthPlot(const PipelineRun& run, int width, int plotHeight, const TextMetrics& text,
                    const DepthPlotOptions& options = {});

/// ViewKind::depth: the chart filling in.width × in.height (legend and background included; the
/// plot takes the height the rows below it leave, at least four lines).
draw::DisplayList depthPlotView(const ViewInput& in);

}  // namespace vplab
