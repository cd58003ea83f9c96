// The SVG backend: draws a display list (app/views/display_list.h) as an SVG document, as the GL
// backend draws it into pixels. It decides nothing about what is drawn; where GL has a depth buffer
// it has the CPU's: app/views/projection.h (the observer's camera and the pipeline's own clipper),
// app/views/hidden_lines.h (what the depth-writing faces drawn before a batch hide of its lines,
// points and translucent polygons, with the views' polygon-offset rule) and app/views/painted_fill.h
// (filled faces in painter's order, coloured as the shaders colour them, once per face).
//
// The document: a <svg> of the picture's pixels (viewBox in pixels, origin top-left as DC) on its
// background, each panel a nested <svg> at its offset with its list's background, then the batches
// in order. Lines keep their colours and opacities; their stroke is widthPx + 1 px wide (the line
// shader covers widthPx fully with a one-pixel ramp on each side: that is the PNG's ink across a
// line), solid lines with square caps (they end half their width beyond their end points), dashes
// dashPx on, dashPx off in phase with GL's. Markers are discs with the point shader's dark rim.
// Labels are <text> in the font atlas's family and size at the places the views gave them, with
// the PNG's dark shadow as a stroke painted under the glyphs. Opaque faces get a 0.5 px stroke of
// their own colour, which closes the hairline seams an anti-aliased renderer leaves between
// neighbouring faces. Coordinates have at most 2 decimals.
#pragma once

#include "app/views/display_list.h"
#include "app/views/views.h"
#include "pipeline/pipeline.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace vplab {

struct RenderRequest;
class FontAtlas;

/// The most filled faces an SVG export draws: a document of more opens too slowly to be of use.
inline constexpr size_t kMaxSvgFaces = 200000;

/// The faces the picture's visible fills draw (depth-only fills not counted).
size_t svgFaceCount(const draw::Picture& picture);

/// The picture as a standalone SVG document titled `title`, its labels in `fonts` (the atlas that
/// measured them). Throws vplab::Error, before building anything, when it has more than kMaxSvgFaces
/// filled faces.
std::string svgOfPicture(const draw::Picture& picture, const FontAtlas& fonts, std::string_view title);

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

/// The SVG of what renderImage draws for the request (same pipeline run, same frame settings).
std::string svgOfRequest(const Scene& scene, const RenderRequest& request);

/// Writes the SVG text to a file. Throws vplab::Error naming the file when it cannot be written.
void writeSvg(const std::string& svg, const std::filesystem::path& file);

}  // namespace vplab
