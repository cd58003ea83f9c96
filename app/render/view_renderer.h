// Draws the views (app/views/views.h) into render targets: each view's display list, built by its
// builder with the text renderer's font atlas as the metrics, drawn by the GL backend
// (app/render/gl_backend.h). One instance per GL context.
#pragma once

#include "app/context/context.h"
#include "app/gl/render_target.h"
#include "app/render/gl_backend.h"
#include "app/views/display_list.h"
#include "app/views/image.h"
#include "app/views/views.h"
#include "pipeline/pipeline.h"

#include <array>
#include <optional>
#include <vector>

namespace vplab {

class ViewRenderer {
 public:
  explicit ViewRenderer(GlContext& context, float textScale = 1.f);

  /// Each draws one view into `target` (already sized; the camera view is pixel-aligned with DC when
  /// the target is the device's W × H). `run` is the CPU pipeline's run of `scene` (with clipEdges
  /// for the wireframe overlays).
  void drawCamera(const Scene& scene, const PipelineRun& run, const DisplaySettings& s, const Highlights& h,
                  gl::RenderTarget& target);
  void drawWorld(const Scene& scene, const PipelineRun& run, const DisplaySettings& s, const Highlights& h,
                  gl::RenderTarget& target);
  void drawNpc(const Scene& scene, const PipelineRun& run, const DisplaySettings& s, const Highlights& h,
                  gl::RenderTarget& target);
  void drawMorph(const Scene& scene, const PipelineRun& run, const DisplaySettings& s, const Highlights& h,
                  gl::RenderTarget& target);
  /// The divide-first comparison: `run` must be the divide-first strategy's (views.h, divideFirstView).
  void drawDivideFirst(const Scene& scene, const PipelineRun& run, const DisplaySettings& s, gl::RenderTarget& target);

  /// A view drawn in slices across frames (ViewImages without a render thread): its display list,
  /// built when it starts, and where its drawing stopped. The scene and run it was built from must
  /// live until it is drawn (the list points into them).
  struct Slices {
    draw::DisplayList list;
    GlBackend::Cursor cursor;
    GlBackend::PolygonBuffers polygons;  // its own: other views are drawn between its slices
  };
  /// Builds `kind`'s list (world, camera, NPC or morph) for `target`, already sized, into `slices`.
  void startSlices(ViewKind kind, const Scene& scene, const PipelineRun& run, const DisplaySettings& s,
                   const Highlights& h, const gl::RenderTarget& target, Slices& slices);
  /// Draws the next at most `triangles` triangles of it (GlBackend::drawSlice); true when complete.
  bool drawSlice(Slices& slices, gl::RenderTarget& target, size_t& triangles) {
    return backend_->drawSlice(slices.list, target, slices.cursor, triangles, slices.polygons);
  }

  /// Renders a view headless into an image: camera at width × height, world and NPC likewise,
  /// all as three panels of width × height with a title strip.
  Image render(ViewKind kind, const Scene& scene, const PipelineRun& run, const DisplaySettings& s, const Highlights& h,
               int width, int height);

  /// The metrics its labels are measured with (the text renderer's atlas at its scale): a picture
  /// built with them (a view with a caption under it, app/lessons/) is drawn by render(picture).
  const TextMetrics& textMetrics() const;
  /// Draws a picture built with textMetrics() into an image.
  Image render(const draw::Picture& picture);

  GlContext& context() { return ctx_; }
  /// The context lost every object (a WebGL context lost and restored): the backend's shaders,
  /// buffers and text atlas are made again; its settings (text scale, partitioning, chunks) stay.
  void recreateGlObjects();
  /// Whether the world view draws each of its two passes from the faces that can show in it
  /// (GlBackend::setPartitioned; on by default, used only without multisampling).
  void setPartitionedWorld(bool on) { backend_->setPartitioned(on); }
  /// The triangles the last partitioned world view drew of its i-th visible scene object in its
  /// inside and its outside pass ({0, 0} when it was not partitioned).
  std::array<size_t, 2> partitionedTriangles(size_t i) const { return backend_->partitionedTriangles(i); }
  /// The corners of a mesh's GPU chunks at most (GpuMeshCache::setChunkCorners): tests of chunk
  /// boundaries make them small. Meshes uploaded before keep theirs.
  void setMeshChunkCorners(uint32_t corners) { backend_->setMeshChunkCorners(corners); }
  /// The bytes of the meshes' GPU buffers (GlBackend::gpuMemoryUse).
  MemoryUse gpuMemoryUse() const { return backend_->gpuMemoryUse(); }
  /// Where the last view drawn put its labels (x0, y0, x1, y1, pixels), for the tests.
  const std::vector<glm::vec4>& labelsPlaced() const { return backend_->labelsPlaced(); }
  /// Larger text, lines and points for a projector (lecture mode).
  void setScale(float scale) { backend_->setTextScale(scale); }
  float scale() const { return backend_->text().scale(); }

 private:
  using Builder = void (*)(const ViewInput&, draw::DisplayList&);
  void drawView(Builder build, draw::DisplayList& list, const Scene& scene, const PipelineRun& run,
                const DisplaySettings& s, const Highlights& h, gl::RenderTarget& target);

  GlContext& ctx_;
  std::optional<GlBackend> backend_;  // always engaged (optional: made again by recreateGlObjects)
  // Each view's last list, its storage reused by the view's next (the NPC view's polygons of a
  // large scene are not allocated anew when the views are drawn in turn).
  draw::DisplayList camera_, world_, npc_, morph_, divideFirst_;
  draw::Picture picture_;
};

}  // namespace vplab
