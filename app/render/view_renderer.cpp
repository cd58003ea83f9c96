#include "app/render/view_renderer.h"

#include <string>

namespace vplab {

ViewRenderer::ViewRenderer(GlContext& context, float textScale) : ctx_(context), backend_(context, textScale) {}

void ViewRenderer::drawView(Builder build, const Scene& scene, const PipelineRun& run, const FrameSettings& s,
                            gl::RenderTarget& target) {
  const ViewInput in{scene, run, s, target.width(), target.height(), backend_.text().atlas()};
  build(in, list_);
  backend_.draw(list_, target);
}

void ViewRenderer::drawCamera(const Scene& scene, const PipelineRun& run, const FrameSettings& s,
                              gl::RenderTarget& target) {
  drawView(&cameraView, scene, run, s, target);
}

void ViewRenderer::drawWorld(const Scene& scene, const PipelineRun& run, const FrameSettings& s,
                             gl::RenderTarget& target) {
  drawView(&worldView, scene, run, s, target);
}

void ViewRenderer::drawNpc(const Scene& scene, const PipelineRun& run, const FrameSettings& s, gl::RenderTarget& target) {
  drawView(&npcView, scene, run, s, target);
}

void ViewRenderer::drawMorph(const Scene& scene, const PipelineRun& run, const FrameSettings& s,
                             gl::RenderTarget& target) {
  drawView(&morphView, scene, run, s, target);
}

void ViewRenderer::drawDivideFirst(const Scene& scene, const PipelineRun& run, const FrameSettings& s,
                                   gl::RenderTarget& target) {
  drawView(&divideFirstView, scene, run, s, target);
}

Image ViewRenderer::render(ViewKind kind, const Scene& scene, const PipelineRun& run, const FrameSettings& s,
                           int width, int height) {
  const ViewInput in{scene, run, s, width, height, backend_.text().atlas()};
  buildPicture(kind, in, picture_);
  Image image = backend_.render(picture_);
  ctx_.checkErrors("rendering the " + std::string(toString(kind)) + " view");
  return image;
}

}  // namespace vplab
