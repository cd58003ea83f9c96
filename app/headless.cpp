#include "app/headless.h"

namespace vplab {

FrameSettings frameSettingsFor(const Scene& scene, Style style, double aspect) {
  FrameSettings s;
  s.camera.style = style;
  s.world = {style, defaultWorldOrbit(scene, aspect)};
  s.npc = {style, defaultNpcOrbit()};
  s.morph = {style == Style::shaded ? Style::shaded : Style::flat, {}};
  return s;
}

Image renderImage(ViewRenderer& renderer, const Scene& scene, const RenderRequest& request) {
  const int w = request.width > 0 ? request.width : scene.device.width;
  const int h = request.height > 0 ? request.height : scene.device.height;
  const PipelineRun run = runPipeline(scene, request.pipeline);
  FrameSettings settings = frameSettingsFor(scene, request.style, double(w) / h);
  settings.morphing.t = request.morphT;
  return renderer.render(request.view, scene, run, settings, w, h);
}

}  // namespace vplab
