// The NPC view: the unit cube of normalized projection coordinates (front z = 1, back z = 0) with
// the scene after view mapping, clipping in homogeneous coordinates and the division by w, seen by
// an orbiting observer. The filled polygons are the CPU clipper's output; what it cut away is shown
// faded, as far as it lies in front of the eye (w > 0) and not too far outside the cube.
#include "app/views/theme.h"
#include "app/views/view_geometry.h"
#include "app/render/view_renderer.h"

#include "pipeline/clipping.h"

#include <array>
#include <set>
#include <tuple>

namespace vplab {

namespace {

// An edge by its end points in NPC, in either direction.
std::array<double, 6> edgeKey(const Vec3& a, const Vec3& b) {
  const bool swap = std::tie(b.x, b.y, b.z) < std::tie(a.x, a.y, a.z);
  const Vec3 &p = swap ? b : a, &q = swap ? a : b;
  return {p.x, p.y, p.z, q.x, q.y, q.z};
}

void addCube(OverlayBatch& b, std::vector<TextLabel>& labels, const ViewCamera& view, int w, int h, bool withLabels) {
  using geometry::cubeCorner;
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) b.line(cubeCorner(i), cubeCorner(i | bit), theme::kCube, 1.5f);
  b.quad(cubeCorner(4), cubeCorner(5), cubeCorner(7), cubeCorner(6), theme::kCubeFront);
  const double len = geometry::kNpcAxisLength;
  b.line({0, 0, 0}, {len, 0, 0}, theme::kU, theme::kLineWidth);
  b.line({0, 0, 0}, {0, len, 0}, theme::kV, theme::kLineWidth);
  b.line({0, 0, 0}, {0, 0, len}, theme::kN, theme::kLineWidth);
  if (!withLabels) return;
  for (const geometry::AnchoredLabel& l : geometry::npcCubeLabels()) {
    const Projected q = projectToPixels(view, l.at, w, h);
    if (q.visible) labels.push_back({q.pixel, l.text, l.color, TextSize::label, Anchor::center});
  }
}

}  // namespace

void ViewRenderer::drawNpc(const Scene& /*scene*/, const PipelineRun& run, const FrameSettings& s,
                           gl::RenderTarget& target) {
  const int w = target.width(), h = target.height();
  beginView(target, Vec3(theme::kViewBackground));

  const ViewCamera view = viewCameraOf(observerCamera(s.npc.orbit, double(w) / h));
  const Style style = s.npc.style;
  const OverlaySettings& ov = s.overlays;

  // The polygons' storage is kept from frame to frame (npcInside_, npcFaded_).
  std::vector<PolygonSet>& inside = npcInside_;
  std::vector<PolygonSet>& faded = npcFaded_;
  inside.resize(run.objects.size());
  faded.resize(run.objects.size());
  OverlayBatch outlines, dashedOutlines, newEdges, fadedOutlines;
  ClipScratch scratch;
  std::set<std::array<double, 6>> drawnEdges;
  const bool outlined = !isFilled(style) || style == Style::hiddenLine;
  std::vector<Vec3> poly;  // reused: no allocation per polygon
  for (size_t k = 0; k < run.objects.size(); ++k) {
    const ObjectRun& o = run.objects[k];
    PolygonSet &in = inside[k], &out = faded[k];
    for (PolygonSet* set : {&in, &out}) {
      set->color = glm::vec3(o.color);
      set->points.clear();
      set->ends.clear();
    }
    const glm::vec4 c(glm::vec3(o.color), 1.f);
    for (size_t f = 0; f < o.faceCount(); ++f) {
      const auto face = o.clippedFace(f);
      if (!face.empty()) {
        poly.clear();
        for (uint32_t ref : face) poly.push_back(o.clippedNpc(ref));
        // Only clipped faces have new edges; only the wireframe styles draw the others.
        const bool clipped = ov.newEdges && o.fate[f] == Fate::clipped;
        for (size_t i = 0; (clipped || outlined) && i < face.size(); ++i) {
          const Vec3 &a = poly[i], &b = poly[(i + 1) % poly.size()];
          if (clipped && o.isNewEdge(f, i)) {
            newEdges.line(a, b, theme::kNewEdge, theme::kLineWidth + 0.5f);
            continue;
          }
          // Two faces share each mesh edge: draw it once, or its dashes would overlap out of phase.
          if (!outlined || !drawnEdges.insert(edgeKey(a, b)).second) continue;
          if (!isFilled(style)) outlines.line(a, b, c, theme::kEdgeWidth);
          if (style == Style::hiddenLine) dashedOutlines.line(a, b, glm::vec4(glm::vec3(c), 0.8f), theme::kEdgeWidth, theme::kDashPx);
        }
        in.add(poly);
      }
      if (ov.fadeOutside && o.fate[f] != Fate::accepted) {
        geometry::fadedNpcPolygon(o, f, scratch, poly);
        if (poly.size() >= 3) {
          if (!isFilled(style)) fadedOutlines.polyline(poly, true, glm::vec4(glm::vec3(c), theme::kFadedAlpha), theme::kEdgeWidth);
          out.add(poly);
        }
      }
    }
  }

  const bool shaded = style == Style::shaded;
  if (isFilled(style)) {
    drawPolygons(inside, view, {0, Mat4(1.0), 1.f, shaded}, kNpcInside);
  } else if (style != Style::wire) {
    depthOnly([&] { drawPolygons(inside, view, {0, Mat4(1.0), 1.f, false}, kNpcInside); });
  }
  const OverlayDepth depth = style == Style::wire ? OverlayDepth::ignore : OverlayDepth::test;
  overlay_.draw(outlines, view, w, h, depth);
  if (style == Style::hiddenLine) {
    gl_.Enable(GL_BLEND);
    gl_.DepthMask(GL_FALSE);
    gl_.DepthFunc(GL_GREATER);
    overlay_.drawLines(dashedOutlines, view, w, h, Mat4(1.0));
    gl_.DepthFunc(GL_LESS);
    gl_.DepthMask(GL_TRUE);
  }
  if (ov.fadeOutside) {
    gl_.Enable(GL_BLEND);
    gl_.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl_.DepthMask(GL_FALSE);
    if (isFilled(style)) drawPolygons(faded, view, {0, Mat4(1.0), theme::kFadedAlpha, shaded}, kNpcFaded);
    else overlay_.draw(fadedOutlines, view, w, h, depth);
    gl_.DepthMask(GL_TRUE);
    gl_.Disable(GL_BLEND);
  }

  OverlayBatch cube;
  std::vector<TextLabel> labels;
  if (ov.cube) addCube(cube, labels, view, w, h, ov.labels);
  // The translucent front face lies in z = 1, where clipping puts the scene's cut polygons and
  // edges: pushed back by glPolygonOffset it loses every depth tie to them instead of z-fighting
  // (the cube's lines are not offset: GL_POLYGON_OFFSET_FILL acts on filled triangles only).
  gl_.Enable(GL_POLYGON_OFFSET_FILL);
  gl_.PolygonOffset(1.f, 2.f);
  overlay_.draw(cube, view, w, h, OverlayDepth::test);
  gl_.Disable(GL_POLYGON_OFFSET_FILL);
  if (s.highlights.probeNpc) newEdges.point(*s.highlights.probeNpc, theme::kProbe, 14.f);
  if (const auto& step = s.highlights.step) {
    // The clipping step-through: the plane being applied as a face of the cube, the polygon after
    // the step, its new vertices.
    if (step->plane >= 0 && step->plane < kPlaneCount) {
      const auto ring = geometry::cubeFaceRing(step->plane);
      using geometry::cubeCorner;
      newEdges.quad(cubeCorner(ring[0]), cubeCorner(ring[1]), cubeCorner(ring[2]), cubeCorner(ring[3]), theme::kStepPlane);
    }
    newEdges.polyline(step->polygonNpc, true, theme::kProbe, theme::kLineWidth + 1.f);
    for (size_t i = 0; i < step->polygonNpc.size(); ++i)
      newEdges.point(step->polygonNpc[i], step->created[i] ? theme::kNewEdge : theme::kProbe, step->created[i] ? 13.f : 9.f);
  }
  overlay_.draw(newEdges, view, w, h, OverlayDepth::xray);
  text_->draw(labels, w, h);
}

}  // namespace vplab
