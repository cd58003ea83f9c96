#include "app/render/headless.h"

namespace vplab {

Image renderImage(ViewRenderer& renderer, const Scene& scene, const RenderRequest& request) {
  const PixelSize size = pixelSizeOf(request, scene);
  const PipelineRun run = runPipeline(scene, pipelineOptionsOf(request));
  if (renderer.scale() != request.scale) renderer.setScale(request.scale);
  return renderer.render(request.view, scene, run, displaySettingsOf(request, scene), request.highlights, size.width,
                         size.height);
}

}  // namespace vplab
