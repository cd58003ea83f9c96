#include "app/views/render_request.h"

namespace vplab {

DisplaySettings displaySettingsFor(const Scene& scene, Style style, double aspect) {
  DisplaySettings s;
  s.camera.style = style;
  s.world = {style, defaultWorldOrbit(scene, aspect)};
  s.npc = {style, defaultNpcOrbit()};
  s.morph = {style == Style::shaded ? Style::shaded : Style::flat, {}};
  return s;
}

PixelSize pixelSizeOf(const RenderRequest& request, const Scene& scene) {
  return {request.width > 0 ? request.width : scene.device.width,
          request.height > 0 ? request.height : scene.device.height};
}

PipelineOptions pipelineOptionsOf(const RenderRequest& request) {
  PipelineOptions options = request.pipeline;
  if (request.view == ViewKind::divideFirst) options.strategy = ClipStrategy::divideFirst;
  return options;
}

DisplaySettings displaySettingsOf(const RenderRequest& request, const Scene& scene) {
  if (request.display) return *request.display;
  const PixelSize size = pixelSizeOf(request, scene);
  DisplaySettings settings = displaySettingsFor(scene, request.style, double(size.width) / size.height);
  settings.morphing.t = request.morphT;
  settings.theme = request.theme;
  settings.language = request.language;
  return settings;
}

}  // namespace vplab
