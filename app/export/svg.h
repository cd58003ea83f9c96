// SVG export of the wireframe views (styles wire, hidden-line, hidden-removed): the line drawing the
// PNG of the same view, style and size shows, as vector lines for slides and lecture notes.
//
// What it contains (views.h, view_renderer.h):
//   camera  the CPU edge clipping's visible part of every edge (ObjectRun::edgeRanges, the same cut
//           as GL's clipping of the camera view's lines), mapped to the width × height pixels
//   world   the edges in WC seen by the world observer: the part inside the scene camera's view
//           volume solid, the whole edge faded; the clipping's new edges, the view volume, the
//           user clip planes, the window, VRP, PRP, U, V, N, VUP, labels
//   npc     the clipped polygons' outlines in NPC seen by the NPC observer, faded what clipping cut
//           away, the new edges, the unit cube and its axes, labels
//   all     the three side by side with their title strip, as the PNG of ViewKind::all
// plus the interactive highlights the views draw (probe, step-through, handles, vanishing points).
//
// Hidden lines are found on the CPU, not read back from the GPU: every projected segment is sampled
// every half pixel and each sample is tested against the filled polygons of the view (a list of
// screen-space triangles in a grid, with exact plane depth instead of a pixel z-buffer), with the
// same rule as the views' depth test: a face hides a point only when it lies in front of it by more
// than the glPolygonOffset(1, 2) the views push the faces back by. Where the visibility changes
// between two samples the boundary is found by bisection. Style wire: every part visible; hidden-line:
// the hidden parts dashed (as the PNG, in phase with its dashes); hidden-removed: left out. Overlays
// drawn "x-ray" by the views (hidden parts faint) get the faint opacity on their hidden parts.
//
// The filled styles (flat, shaded) are not exported: a painter's-order polygon list cannot show
// intersecting or cyclically overlapping faces as the depth buffer does, nor the shaded colours; they
// throw vplab::Error. So does the stage-morph view.
//
// Lines keep the PNG's colours (object colours and theme.h) and opacities. Their stroke width is the
// PNG's line width + 1 px: the line shader draws widthPx at full coverage with a one-pixel ramp on
// each side, so that is the PNG's ink across a line. Dashes are 5 px on, 5 px off as in the PNG.
// Coordinates have at most 2 decimals. Labels are <text> in DejaVu Sans, placed where the PNG places
// them (the same font metrics through Dear ImGui's font atlas, the same overlap avoidance).
// Duplicate lines (an edge shared by two NPC polygons is drawn twice by the PNG) are written once.
#pragma once

#include "app/views/views.h"
#include "pipeline/pipeline.h"

#include <filesystem>
#include <optional>
#include <string>

namespace vplab {

struct RenderRequest;

/// Why a view cannot be exported as SVG with these settings (a filled style, the morph view), or
/// nullopt when it can. For greying out a menu entry.
std::optional<std::string> svgExportError(ViewKind view, const FrameSettings& settings);

/// The view as a standalone SVG document of width × height pixels (ViewKind::all: three panels of
/// width × height and a title strip, like the PNG), viewBox in pixels, origin top-left as DC.
/// `run` is the CPU pipeline's run of `scene` (with PipelineOptions::clipEdges; without, the edges
/// are clipped here). `scale`: lecture mode, ViewRenderer::setScale's factor for the text, the line
/// widths and the marker sizes. Throws vplab::Error when svgExportError says why, or for a size
/// below 1 × 1.
std::string svgOfView(ViewKind view, const Scene& scene, const PipelineRun& run,
                      const FrameSettings& settings, int width, int height, float scale = 1.f);

/// The SVG of what renderImage draws for the request (same pipeline run, frame settings and scale;
/// app/views/render_request.h).
std::string svgOfRequest(const Scene& scene, const RenderRequest& request);

/// Writes the SVG text to a file. Throws vplab::Error naming the file when it cannot be written.
void writeSvg(const std::string& svg, const std::filesystem::path& file);

}  // namespace vplab
