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

PipelineOptions pipelineOptionsOf(const RenderRequest& request) {
  PipelineOptions options = request.pipeline;
  if (request.view == ViewKind::divideFirst) options.strategy = ClipStrategy::divideFirst;
  return options;
}

Image renderImage(ViewRenderer& renderer, const Scene& scene, const RenderRequest& request) {
  const int w = request.width > 0 ? request.width : scene.device.width;
  const int h = request.height > 0 ? request.height : scene.device.height;
  const PipelineRun run = runPipeline(scene, pipelineOptionsOf(request));
  FrameSettings settings = frameSettingsFor(scene, request.style, double(w) / h);
  settings.morphing.t = request.morphT;
  return renderer.render(request.view, scene, run, settings, w, h);
}

}  // namespace vplab
