#include "app/render/view_renderer.h"

#include "base/error.h"

#include <string>

namespace vplab {

ViewRenderer::ViewRenderer(GlContext& context, float textScale) : ctx_(context) { backend_.emplace(context, textScale); }

void ViewRenderer::recreateGlObjects() {
  const float scale = backend_->text().scale();
  const bool partitioned = backend_->partitioned();
  const uint32_t chunkCorners = backend_->meshChunkCorners();
  backend_.reset();  // deletes names a lost context took with it: errors that say nothing of the new ones
  ctx_.discardErrors();
  backend_.emplace(ctx_, scale);
  backend_->setPartitioned(partitioned);
  backend_->setMeshChunkCorners(chunkCorners);
}

void ViewRenderer::drawView(Builder build, draw::DisplayList& list, const Scene& scene, const PipelineRun& run,
                            const DisplaySettings& s, const Highlights& h, gl::RenderTarget& target) {
  const ViewInput in{scene, run, s, h, target.width(), target.height(), backend_->text().atlas()};
  build(in, list);
  backend_->draw(list, target);
}

void ViewRenderer::drawCamera(const Scene& scene, const PipelineRun& run, const DisplaySettings& s, const Highlights& h,
                              gl::RenderTarget& target) {
  drawView(&cameraView, camera_, scene, run, s, h, target);
}

void ViewRenderer::drawWorld(const Scene& scene, const PipelineRun& run, const DisplaySettings& s, const Highlights& h,
                              gl::RenderTarget& target) {
  drawView(&worldView, world_, scene, run, s, h, target);
}

void ViewRenderer::drawNpc(const Scene& scene, const PipelineRun& run, const DisplaySettings& s, const Highlights& h,
                              gl::RenderTarget& target) {
  drawView(&npcView, npc_, scene, run, s, h, target);
}

void ViewRenderer::drawMorph(const Scene& scene, const PipelineRun& run, const DisplaySettings& s, const Highlights& h,
                              gl::RenderTarget& target) {
  drawView(&morphView, morph_, scene, run, s, h, target);
}

void ViewRenderer::drawDivideFirst(const Scene& scene, const PipelineRun& run, const DisplaySettings& s,
                                   gl::RenderTarget& target) {
  drawView(&divideFirstView, divideFirst_, scene, run, s, Highlights{}, target);  // it marks nothing
}

void ViewRenderer::startSlices(ViewKind kind, const Scene& scene, const PipelineRun& run, const DisplaySettings& s,
                               const Highlights& h, const gl::RenderTarget& target, Slices& slices) {
  const ViewInput in{scene, run, s, h, target.width(), target.height(), backend_->text().atlas()};
  switch (kind) {
    case ViewKind::world: worldView(in, slices.list); break;
    case ViewKind::npc: npcView(in, slices.list); break;
    case ViewKind::morph: morphView(in, slices.list); break;
    case ViewKind::camera:
    case ViewKind::all: cameraView(in, slices.list); break;
    case ViewKind::divideFirst:
    case ViewKind::depth: throw Error("the " + std::string(toString(kind)) + " view is not drawn in slices");
  }
  slices.cursor = {};
}

Image ViewRenderer::render(ViewKind kind, const Scene& scene, const PipelineRun& run, const DisplaySettings& s,
                           const Highlights& h, int width, int height) {
  const ViewInput in{scene, run, s, h, width, height, backend_->text().atlas()};
  buildPicture(kind, in, picture_);
  Image image = backend_->render(picture_);
  ctx_.checkErrors("rendering the " + std::string(toString(kind)) + " view");
  return image;
}

const TextMetrics& ViewRenderer::textMetrics() const { return backend_->text().atlas(); }

Image ViewRenderer::render(const draw::Picture& picture) {
  Image image = backend_->render(picture);
  ctx_.checkErrors("rendering a picture");
  return image;
}

}  // namespace vplab
