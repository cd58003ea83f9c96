#include "app/views/render_request.h"

namespace vplab {

FrameSettings frameSettingsFor(const Scene& scene, Style style, double aspect) {
  FrameSettings s;
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

FrameSettings frameSettingsOf(const RenderRequest& request, const Scene& scene) {
  if (request.frame) return *request.frame;
  const PixelSize size = pixelSizeOf(request, scene);
  FrameSettings settings = frameSettingsFor(scene, request.style, double(size.width) / size.height);
  settings.morphing.t = request.morphT;
  return settings;
}

}  // namespace vplab
