// Headless rendering of a scene to an image: the core of `vplab render`, also used by the tests.
#pragma once

#include "app/context/context.h"
#include "app/views/image.h"
#include "app/render/view_renderer.h"

namespace vplab {

struct RenderRequest {
  ViewKind view = ViewKind::camera;
  Style style = Style::flat;
  int width = 0, height = 0;  // 0: the scene's device
  double morphT = 0;          // the stage morph's t (ViewKind::morph)
  PipelineOptions pipeline{ClipStrategy::npc, false, true};
};

/// The frame settings `vplab render` uses: the style for every view, the default observers framed for
/// views of the given aspect ratio.
FrameSettings frameSettingsFor(const Scene& scene, Style style, double aspect);

/// The pipeline options a request's view is drawn from: the request's, except that the divide-first
/// comparison is always the divide-first strategy's run (what the viewer shows it from).
PipelineOptions pipelineOptionsOf(const RenderRequest& request);

/// Runs the CPU pipeline and draws the requested view with `renderer`. Throws vplab::Error.
Image renderImage(ViewRenderer& renderer, const Scene& scene, const RenderRequest& request);

}  // namespace vplab
