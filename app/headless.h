// Headless rendering of a scene to an image: the core of `vplab render`, also used by the tests.
// What to draw is a RenderRequest (app/views/render_request.h), shared with the SVG export.
#pragma once

#include "app/context/context.h"
#include "app/render/view_renderer.h"
#include "app/views/image.h"
#include "app/views/render_request.h"

namespace vplab {

/// Runs the CPU pipeline and draws the requested view with `renderer`, at the request's scale
/// (the renderer keeps it for the next request). Throws vplab::Error.
Image renderImage(ViewRenderer& renderer, const Scene& scene, const RenderRequest& request);

}  // namespace vplab
