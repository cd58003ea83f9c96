// The camera view: what the synthetic camera sees, through the GLSL path with the CPU pipeline's
// matrices (domain.md). At the device's W × H it is pixel-aligned with DC: glViewport(0, 0, W, H).
#include "app/views/theme.h"
#include "app/views/view_renderer.h"

namespace vplab {

namespace {

// DC as a space the overlay can be drawn in: DC → NPC (the inverse device mapping), then GL clip.
ViewCamera dcCamera(const Device& device) {
  ViewCamera v;
  v.vrcFromWc = Mat4(1.0);
  v.npcFromVrc = glm::inverse(dcFromNpc(device));
  return v;
}

}  // namespace

void ViewRenderer::drawCamera(const Scene& scene, const PipelineRun& run, const FrameSettings& s,
                              gl::RenderTarget& target) {
  target.bind();
  gl_.ClearColor(float(scene.background.r), float(scene.background.g), float(scene.background.b), 1.f);
  gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LESS);
  gl_.Disable(GL_BLEND);
  gl_.Disable(GL_CULL_FACE);

  const ViewCamera view = viewCameraOf(scene.camera);
  const Style style = s.camera.style;
  if (isFilled(style)) drawObjects(scene, view, {0, Mat4(1.0), 1.f, style == Style::shaded});
  else drawEdges(scene, view, target.width(), target.height(), style);

  OverlayBatch batch;
  if (s.highlights.probeDc) batch.point(*s.highlights.probeDc, theme::kProbe, 14.f);
  if (s.overlays.cpuPolygons) {
    for (const ObjectRun& o : run.objects) {
      for (size_t f = 0; f < o.faceCount(); ++f) {
        std::vector<Vec3> poly;
        for (uint32_t ref : o.clippedFace(f)) poly.push_back(o.clippedDc(ref));
        batch.polyline(poly, true, theme::kCpuPolygon, 1.5f);
      }
    }
  }
  if (!batch.empty()) overlay_.draw(batch, dcCamera(run.device), target.width(), target.height(), OverlayDepth::ignore);
}

}  // namespace vplab
