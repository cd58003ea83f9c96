// The camera view: what the synthetic camera sees, through the GLSL path with the CPU pipeline's
// matrices (docs/conventions.md). At the device's W × H it is pixel-aligned with DC: glViewport(0, 0, W, H).
#include "app/views/number_text.h"
#include "app/views/theme.h"
#include "app/render/view_renderer.h"

#include "pipeline/vanishing_points.h"

#include <cstdio>

namespace vplab {

namespace {

// DC as a space the overlay can be drawn in: DC → NPC (the inverse device mapping), then GL clip.
ViewCamera dcCamera(const Device& device) {
  ViewCamera v;
  v.vrcFromWc = Mat4(1.0);
  v.npcFromVrc = glm::inverse(dcFromNpc(device));
  return v;
}

// lecture notes 14.2: the images of an object's edges along each principal axis meet in the axis's
// vanishing point. Each edge is drawn on to it, dashed, in the axis's colour.
void addVanishingPoints(const PipelineRun& run, int sceneIndex, OverlayBatch& b, std::vector<TextLabel>& labels,
                        int width, int height) {
  const ObjectRun* o = nullptr;
  for (size_t i = 0; i < run.sceneIndex.size(); ++i)
    if (int(run.sceneIndex[i]) == sceneIndex) o = &run.objects[i];
  if (!o) return;
  const auto vps = vanishingPoints(run, o->wcFromMc);
  const glm::vec4 colors[3] = {theme::kU, theme::kV, theme::kN};
  const char* names[3] = {"x", "y", "z"};
  const Vec2 toPixels(double(width) / run.device.width, double(height) / run.device.height);
  // The run's edge list when it clipped edges (the viewer's does), not a new one per axis and frame.
  const std::vector<Edge> ownEdges = o->edges.empty() ? uniqueEdges(*o->mesh) : std::vector<Edge>{};
  const std::vector<Edge>& edges = o->edges.empty() ? ownEdges : o->edges;
  for (int axis = 0; axis < 3; ++axis) {
    const VanishingPoint& vp = vps[size_t(axis)];
    if (!vp.finite) continue;
    const Vec3 target(vp.dc, 0.5);
    for (const Edge& e : edges) {
      const Vec3 d = o->wc(e.b) - o->wc(e.a);
      if (glm::length(glm::cross(glm::normalize(d), vp.directionWc)) > 1e-6) continue;  // not along this axis
      for (uint32_t v : {e.a, e.b}) {
        const Vec4 h = o->npcH[v];
        if (h.w <= 0) continue;
        const Vec3 dc = Vec3(run.dcFromNpc * Vec4(Vec3(h) / h.w, 1.0));
        b.line({dc.x, dc.y, 0.5}, target, glm::vec4(glm::vec3(colors[axis]), 0.7f), 1.2f, 4.f);
      }
    }
    b.point(target, colors[axis], 12.f);
    const Vec2 at = vp.dc * toPixels;
    const bool inside = at.x >= 0 && at.y >= 0 && at.x <= width && at.y <= height;
    char text[96];
    std::snprintf(text, sizeof text, "VP %s (%s, %s)%s", names[axis], formatNumber(std::round(vp.dc.x), {10}).c_str(),
                  formatNumber(std::round(vp.dc.y), {10}).c_str(), inside ? "" : " outside");
    labels.push_back({glm::clamp(at, Vec2(4), Vec2(width - 4, height - 4)) + Vec2(8, -8), text, colors[axis],
                      TextSize::label, Anchor::left});
  }
}

}  // namespace

void ViewRenderer::drawCamera(const Scene& scene, const PipelineRun& run, const FrameSettings& s,
                              gl::RenderTarget& target) {
  beginView(target, scene.background);

  const ViewCamera view = viewCameraOf(scene.camera);
  const Style style = s.camera.style;
  if (isFilled(style)) drawObjects(scene, view, {0, Mat4(1.0), 1.f, style == Style::shaded, true});
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
  std::vector<TextLabel> labels;
  if (s.overlays.vanishingPoints) addVanishingPoints(run, s.highlights.vanishingObject, batch, labels, target.width(),
                                                     target.height());
  if (!batch.empty()) overlay_.draw(batch, dcCamera(run.device), target.width(), target.height(), OverlayDepth::ignore);
  text_->draw(labels, target.width(), target.height());
}

}  // namespace vplab
