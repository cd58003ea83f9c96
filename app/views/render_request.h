// One picture of a view, however it is asked for: `vplab render` (app/commands/cli.cpp), the viewer's export
// menu (app/ui/viewer.cpp) and the tests all describe it with a RenderRequest, and two backends draw
// it: renderImage (app/render/headless.h, a PNG through GL) and svgOfRequest (app/export/svg.h, an SVG).
// GL-free: the request names what to draw, not how.
#pragma once

#include "app/views/views.h"
#include "pipeline/pipeline.h"

#include <optional>

namespace vplab {

struct RenderRequest {
  ViewKind view = ViewKind::camera;
  Style style = Style::flat;  // of every view (without `display`)
  int width = 0, height = 0;  // pixels of the view (ViewKind::all: of each of its panels); 0: the scene's device
  double morphT = 0;          // the stage morph's t, 0 (MC) to 4 (DC) (ViewKind::morph; without `display`)
  /// The CPU pipeline's run the view shows (with clipEdges: the wireframe styles and overlays draw
  /// the clipped edges).
  PipelineOptions pipeline{ClipStrategy::npc, false, true};
  Theme theme = Theme::dark;  // without `display`: the theme of every view (app/views/theme.h)
  Language language = Language::en;  // without `display`: the labels' language
  float scale = 1.f;  // text, line widths and markers (lecture mode on a projector, the viewer's UI scale)
  /// Every view setting as the viewer shows it (each view's style and observer, the overlays, the
  /// morph); nullopt: `vplab render`'s, from `style` and `morphT` (displaySettingsFor).
  std::optional<DisplaySettings> display = std::nullopt;
  /// The viewer's marks of the frame (the probe, the handles, the step-through); none for `vplab render`.
  Highlights highlights{};
};

/// The display settings `vplab render` uses: the style for every view, the default observers framed for
/// views of the given aspect ratio (width / height).
DisplaySettings displaySettingsFor(const Scene& scene, Style style, double aspect);

/// The view's size in pixels: the request's, the scene's device W × H where the request says 0.
struct PixelSize {
  int width = 0, height = 0;
};
PixelSize pixelSizeOf(const RenderRequest& request, const Scene& scene);

/// The pipeline options the request's view is drawn from: the request's, except that the
/// divide-first comparison is always the divide-first strategy's run (what the viewer shows it from).
PipelineOptions pipelineOptionsOf(const RenderRequest& request);

/// The display settings the request is drawn with: its `display`, or displaySettingsFor its style at its
/// size's aspect ratio with its morph t.
DisplaySettings displaySettingsOf(const RenderRequest& request, const Scene& scene);

}  // namespace vplab
