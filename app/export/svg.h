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
// the PNG's dark shadow as a stroke painted under the glyphs. Faces of a list GL multisamples get,
// when opaque, a 0.5 px stroke of their own colour, which closes the hairline seams an anti-aliased
// renderer leaves between neighbouring faces; a list GL draws aliased (the camera view) has its
// faces drawn with shape-rendering="crispEdges", aliased as well. Coordinates have at most 2 decimals.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "app/views/display_list.h"
#include "app/views/views.h"
#include "pipeline/pipeline.h"

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

/// Why a view of the scene cannot be exported as SVG with these settings (its filled panels would
/// draw more than kMaxSvgFaces faces, estimated from the scene's faces), or nullopt when it can.
/// For greying out a menu entry.
std::optional<std::string> svgExportError(ViewKind view, const Scene& scene, const DisplaySettings& settings);

/// The view as a standalone SVG document: the picture buildPicture makes of it (ViewKind::all:
/// three panels of width × height and a title strip, like the PNG), with labels measured by a font
/// atlas of `scale` (lecture mode: text, line widths and marker sizes grow with it). `run` is the
/// CPU pipeline's run of `scene`. Throws vplab::Error for a size below 1 × 1 or too many faces.
std::string svgOfView(ViewKind view, const Scene& scene, const PipelineRun& run, const DisplaySettings& settings,
                      const Highlights& highlights, int width, int height, float scale = 1.f);

/// The SVG of what renderImage draws for the request (same pipeline run, frame settings and scale;
/// app/views/render_request.h).
std::string svgOfRequest(const Scene& scene, const RenderRequest& request);

/// Writes the SVG text to a file. Throws vplab::Error naming the file when it cannot be written.
void writeSvg(const std::string& svg, const std::filesystem::path& file);

}  // namespace vplab
