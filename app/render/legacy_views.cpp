// The views' GL drawing as it was before the display lists (app/views/views.h): ViewRenderer's
// drawCamera, drawWorld, drawNpc and drawMorph. Kept, unchanged, until the GL backend
// (app/render/gl_backend.h) draws the builders' display lists instead; then this file goes.
// Index: 1 camera  2 world  3 NPC  4 morph
#include "app/render/view_renderer.h"
#include "app/views/number_text.h"
#include "app/views/theme.h"
#include "app/views/view_geometry.h"

#include "pipeline/clipping.h"
#include "pipeline/stage_morph.h"
#include "pipeline/vanishing_points.h"

#include <array>
#include <cstdio>
#include <set>
#include <tuple>

// ---------------------------------------------------------------- 1 camera

// The camera view: what the synthetic camera sees, through the GLSL path with the CPU pipeline's
// matrices (docs/conventions.md). At the device's W × H it is pixel-aligned with DC: glViewport(0, 0, W, H).

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

// ---------------------------------------------------------------- 2 world

// The world view: an orbiting observer (itself a synthetic camera of the pipeline) sees the scene in
// WC together with the scene camera: VRP, PRP, VUP, the U, V, N axes, the window in the view plane
// and the view volume. What lies inside the view volume is drawn solid, the rest faded; the edges
// the CPU clipper created are highlighted (lecture notes 15.1, figures 15.1–15.5).

namespace vplab {

namespace {

struct Frame {
  const PipelineRun& run;
  Mat4 wcFromNpc;  // the inverse of the scene camera's npcFromVrc · vrcFromWc
  Mat4 wcFromVrc;
};

Vec3 wcOfNpc(const Frame& f, const Vec3& npc) {
  const Vec4 p = f.wcFromNpc * Vec4(npc, 1.0);
  return Vec3(p) / p.w;
}

std::array<Vec3, 8> volumeCorners(const Frame& f) { return geometry::viewVolumeCorners(f.wcFromNpc); }

void addArrow(OverlayBatch& b, const Vec3& from, const Vec3& to, const Vec3& eye, const glm::vec4& color,
              float dash = 0.f) {
  b.line(from, to, color, theme::kLineWidth + 0.5f, dash);
  const Vec3 dir = to - from;
  const double len = glm::length(dir);
  if (len <= 0) return;
  Vec3 side = glm::cross(dir / len, eye - to);
  if (glm::length(side) < 1e-12) return;
  side = glm::normalize(side) * (0.07 * len);
  const Vec3 base = to - dir * 0.16;
  b.line(to, base + side, color, theme::kLineWidth + 0.5f);
  b.line(to, base - side, color, theme::kLineWidth + 0.5f);
}

}  // namespace

void ViewRenderer::drawWorld(const Scene& scene, const PipelineRun& run, const FrameSettings& s,
                             gl::RenderTarget& target) {
  const int w = target.width(), h = target.height();
  beginView(target, Vec3(theme::kViewBackground));

  const ViewCamera view = viewCameraOf(observerCamera(s.world.orbit, double(w) / h));
  const Frame f{run, glm::inverse(run.npcFromWc), glm::inverse(run.vrcFromWc)};
  const Style style = s.world.style;
  const bool shaded = style == Style::shaded;
  const OverlaySettings& ov = s.overlays;

  // The objects: inside the view volume solid, outside faded. The fragment shader splits them by
  // the scene camera's boundary coordinates (Hill 7.4), exactly where the CPU clipper cuts.
  if (isFilled(style)) {
    const bool partitioned = partitionedWorld_ && target.samples() == 1;
    if (partitioned) partitionByVolume(scene, run);
    drawObjects(scene, view, {1, run.npcFromWc, 1.f, shaded, true, partitioned});
    if (ov.fadeOutside) {
      gl_.Enable(GL_BLEND);
      gl_.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      gl_.DepthMask(GL_FALSE);
      drawObjects(scene, view, {2, run.npcFromWc, theme::kFadedAlpha, shaded, false, partitioned});
      gl_.DepthMask(GL_TRUE);
      gl_.Disable(GL_BLEND);
    }
  } else {
    // Wireframes from the CPU's edge clipping: the visible part of each edge solid, all of it faded.
    const bool hidden = style != Style::wire;
    if (hidden) {
      depthOnly([&] { drawObjects(scene, view, {0, Mat4(1.0), 1.f, false}); });
    }
    OverlayBatch solid, dashed, faded;
    for (const ObjectRun& o : run.objects) {
      const glm::vec4 c(glm::vec3(o.color), 1.f);
      for (size_t i = 0; i < o.edges.size() && i < o.edgeRanges.size(); ++i) {
        const Vec3 a = o.wc(o.edges[i].a), b = o.wc(o.edges[i].b);
        if (ov.fadeOutside) faded.line(a, b, glm::vec4(glm::vec3(c), theme::kFadedAlpha), theme::kEdgeWidth);
        const EdgeRange& r = o.edgeRanges[i];
        if (!r.visible) continue;
        // Boundary coordinates are linear along the WC segment, so t carries over from NPC.
        const Vec3 p0 = a + r.t0 * (b - a), p1 = a + r.t1 * (b - a);
        solid.line(p0, p1, c, theme::kEdgeWidth);
        if (style == Style::hiddenLine) dashed.line(p0, p1, glm::vec4(glm::vec3(c), 0.8f), theme::kEdgeWidth, theme::kDashPx);
      }
    }
    overlay_.draw(faded, view, w, h, hidden ? OverlayDepth::test : OverlayDepth::ignore);
    overlay_.draw(solid, view, w, h, hidden ? OverlayDepth::test : OverlayDepth::ignore);
    if (style == Style::hiddenLine) {
      gl_.Enable(GL_BLEND);
      gl_.DepthMask(GL_FALSE);
      gl_.DepthFunc(GL_GREATER);
      overlay_.drawLines(dashed, view, w, h, Mat4(1.0));
      gl_.DepthFunc(GL_LESS);
      gl_.DepthMask(GL_TRUE);
    }
  }

  OverlayBatch b;
  std::vector<TextLabel> labels;
  auto label = [&](const Vec3& p, const std::string& text, const glm::vec4& color, Vec2 offset = {8, 0}) {
    if (!ov.labels) return;
    const Projected q = projectToPixels(view, p, w, h);
    // The offset from the point grows with the text (and the markers) at a large UI scale.
    if (q.visible)
      labels.push_back({q.pixel + offset * double(text_->scale()), text, color, TextSize::label, Anchor::left, true, true,
                        q.pixel});
  };

  if (ov.newEdges) {
    for (const ObjectRun& o : run.objects)
      for (size_t fi = 0; fi < o.faceCount(); ++fi) {
        if (o.fate[fi] != Fate::clipped) continue;
        const auto face = o.clippedFace(fi);
        for (size_t i = 0; i < face.size(); ++i)
          if (o.isNewEdge(fi, i))
            b.line(wcOfNpc(f, o.clippedNpc(face[i])), wcOfNpc(f, o.clippedNpc(face[(i + 1) % face.size()])),
                   theme::kNewEdge, theme::kLineWidth + 0.5f);
      }
  }
  if (ov.frustum) {
    const auto c = volumeCorners(f);
    // Corner i has x = bit 0, y = bit 1, z = bit 2 (z = 1 front, 0 back).
    const int front[4] = {4, 5, 7, 6}, back[4] = {0, 1, 3, 2};
    b.quad(c[4], c[5], c[7], c[6], theme::kFrontPlane);
    b.quad(c[0], c[1], c[3], c[2], theme::kBackPlane);
    for (int i = 0; i < 4; ++i) {
      b.line(c[front[i]], c[front[(i + 1) % 4]], theme::kFrustum, theme::kLineWidth);
      b.line(c[back[i]], c[back[(i + 1) % 4]], theme::kFrustum, theme::kLineWidth);
      b.line(c[front[i]], c[back[i]], theme::kFrustum, theme::kLineWidth);
      if (run.camera.projection == Projection::perspective)
        b.line(run.camera.prp, c[front[i]], glm::vec4(glm::vec3(theme::kFrustum), 0.6f), 1.5f, theme::kDashPx);
    }
    label(c[7], "front F", theme::kFrustum, {6, -10});
    label(c[3], "back B", theme::kFrustum, {6, -10});
  }
  // User clip planes (DGL wiki): a translucent square on each, around its point, with its normal.
  const double planeSize = geometry::clipPlaneSquareSize(run.camera);
  for (const UserClipPlane& p : scene.clipPlanes) {
    if (!p.enabled) continue;
    const Vec3 n = glm::normalize(p.normal);
    const auto q = geometry::clipPlaneSquare(p, planeSize);
    b.quad(q[0], q[1], q[2], q[3], theme::kClipPlane);
    b.polyline({q[0], q[1], q[2], q[3]}, true, glm::vec4(glm::vec3(theme::kClipPlane), 0.8f), 1.5f);
    addArrow(b, p.point, p.point + n * (0.3 * planeSize), view.camera.prp, glm::vec4(glm::vec3(theme::kClipPlane), 1.f));
    label(p.point + n * (0.3 * planeSize), "clip plane", glm::vec4(glm::vec3(theme::kClipPlane), 1.f));
  }
  if (ov.viewPlane) {
    const ViewWindow& win = run.camera.window;
    const Vec3 corners[4] = {transformAffine(f.wcFromVrc, {win.xmin, win.ymin, 0}),
                             transformAffine(f.wcFromVrc, {win.xmax, win.ymin, 0}),
                             transformAffine(f.wcFromVrc, {win.xmax, win.ymax, 0}),
                             transformAffine(f.wcFromVrc, {win.xmin, win.ymax, 0})};
    b.quad(corners[0], corners[1], corners[2], corners[3], theme::kWindowFill);
    b.polyline({corners[0], corners[1], corners[2], corners[3]}, true, theme::kWindow, theme::kLineWidth);
    label(corners[3], "window", theme::kWindow, {6, -10});
  }
  if (ov.cameraAxes) {
    const Camera& cam = run.camera;
    const double len = 0.3 * std::max(cam.window.width(), cam.window.height());
    addArrow(b, cam.vrp, cam.vrp + len * run.frame.u, view.camera.prp, theme::kU);
    addArrow(b, cam.vrp, cam.vrp + len * run.frame.v, view.camera.prp, theme::kV);
    addArrow(b, cam.vrp, cam.vrp + len * run.frame.n, view.camera.prp, theme::kN);
    addArrow(b, cam.vrp, cam.vrp + len * glm::normalize(cam.vup), view.camera.prp, theme::kVup, theme::kDashPx);
    b.point(cam.vrp, theme::kVrp, theme::kPointSize);
    b.point(cam.prp, theme::kPrp, theme::kPointSize);
    if (cam.projection == Projection::perspective)
      b.line(cam.vrp, cam.prp, glm::vec4(glm::vec3(theme::kN), 0.5f), 1.5f, theme::kDashPx);
    label(cam.vrp + len * run.frame.u, "U", theme::kU);
    label(cam.vrp + len * run.frame.v, "V", theme::kV);
    label(cam.vrp + len * run.frame.n, "N", theme::kN);
    label(cam.vrp + len * glm::normalize(cam.vup), "VUP", theme::kVup);
    label(cam.vrp, "VRP", theme::kVrp, {8, 12});
    label(cam.prp, "PRP", theme::kPrp);
  }
  const Highlights& hl = s.highlights;
  for (const Highlights::HandleMark& m : hl.handles) {
    b.point(m.wc, m.hot ? theme::kHandleHot : theme::kHandle, m.hot ? 15.f : 9.f);
    if (m.hot) label(m.wc, m.name, theme::kHandleHot, {10, -12});
  }
  if (hl.probeWc) b.point(*hl.probeWc, theme::kProbe, 14.f);
  if (const auto& step = hl.step) {
    // The clipping step-through in WC: the frustum's face of the plane being applied, the polygon.
    if (step->plane >= 0 && step->plane < kPlaneCount) {
      const auto c = volumeCorners(f);
      const auto ring = geometry::cubeFaceRing(step->plane);
      b.quad(c[size_t(ring[0])], c[size_t(ring[1])], c[size_t(ring[2])], c[size_t(ring[3])], theme::kStepPlane);
    }
    std::vector<Vec3> poly;
    for (const Vec3& p : step->polygonNpc) poly.push_back(wcOfNpc(f, p));
    b.polyline(poly, true, theme::kProbe, theme::kLineWidth + 1.f);
    for (size_t i = 0; i < poly.size(); ++i)
      b.point(poly[i], step->created[i] ? theme::kNewEdge : theme::kProbe, step->created[i] ? 13.f : 9.f);
  }
  overlay_.draw(b, view, w, h, OverlayDepth::xray);
  text_->draw(labels, w, h);
}

}  // namespace vplab

// ---------------------------------------------------------------- 3 npc

// The NPC view: the unit cube of normalized projection coordinates (front z = 1, back z = 0) with
// the scene after view mapping, clipping in homogeneous coordinates and the division by w, seen by
// an orbiting observer. The filled polygons are the CPU clipper's output; what it cut away is shown
// faded, as far as it lies in front of the eye (w > 0) and not too far outside the cube.

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

// ---------------------------------------------------------------- 4 morph

// The stage morph view (pipeline/stage_morph.h): the visible part of the scene (the CPU clipper's
// polygons) and the view volume move together from MC (t = 0) through WC, VRC, homogeneous NPC and
// NPC to DC (t = 4). The observer keeps its angles and follows the morphing scene to keep it framed.

namespace vplab {

namespace {

// Every stage of a vertex of a clipped polygon. Created vertices exist only in homogeneous NPC;
// the inverse matrices give their other stages exactly.
struct Inverses {
  Mat4 vrcFromNpc, wcFromVrc;
};

StageValues stagesOf(const ObjectRun& o, uint32_t ref, const Inverses& inv, const Mat4& mcFromWc) {
  if (!o.isCreated(ref)) return {o.mesh->positions[ref], o.wc(ref), o.vrc(ref), o.npcH[ref], o.dc[ref]};
  const Vec4 npcH = o.clippedNpcH(ref);
  const Vec4 vrcH = inv.vrcFromNpc * npcH;
  const Vec3 vrc = Vec3(vrcH) / vrcH.w;
  const Vec3 wc = transformAffine(inv.wcFromVrc, vrc);
  return {transformAffine(mcFromWc, wc), wc, vrc, npcH, o.clippedDc(ref)};
}

// The view volume's corners: the unit cube's corners in every stage (no MC: shown at WC for t < 1).
StageValues cornerStages(const PipelineRun& run, const Inverses& inv, int i) {
  const Vec3 npc(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const Vec4 vrcH = inv.vrcFromNpc * Vec4(npc, 1.0);
  const Vec3 vrc = Vec3(vrcH) / vrcH.w;
  const Vec3 wc = transformAffine(inv.wcFromVrc, vrc);
  return {wc, wc, vrc, run.npcFromVrc * Vec4(vrc, 1.0), Vec3(run.dcFromNpc * Vec4(npc, 1.0))};
}

}  // namespace

void ViewRenderer::drawMorph(const Scene& /*scene*/, const PipelineRun& run, const FrameSettings& s,
                             gl::RenderTarget& target) {
  const int w = target.width(), h = target.height();
  beginView(target, Vec3(theme::kViewBackground));

  const double t = s.morphing.t;
  const Inverses inv{glm::inverse(run.npcFromVrc), glm::inverse(run.vrcFromWc)};
  std::vector<PolygonSet> sets;
  std::vector<Vec3> all;
  OverlayBatch lines;
  for (const ObjectRun& o : run.objects) {
    const Mat4 mcFromWc = glm::inverse(o.wcFromMc);
    PolygonSet set{glm::vec3(o.color), {}, {}};
    std::vector<Vec3> poly;
    for (size_t f = 0; f < o.faceCount(); ++f) {
      poly.clear();
      for (uint32_t ref : o.clippedFace(f)) poly.push_back(morphPosition(stagesOf(o, ref, inv, mcFromWc), t, run.device));
      if (poly.size() < 3) continue;
      lines.polyline(poly, true, glm::vec4(glm::vec3(o.color) * 0.45f, 1.f), 1.f);
      all.insert(all.end(), poly.begin(), poly.end());
      set.add(poly);
    }
    sets.push_back(std::move(set));
  }
  std::array<Vec3, 8> c;
  for (int i = 0; i < 8; ++i) c[size_t(i)] = morphPosition(cornerStages(run, inv, i), std::max(t, 1.0), run.device);
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) lines.line(c[size_t(i)], c[size_t(i | bit)], theme::kFrustum, theme::kLineWidth);
  all.insert(all.end(), c.begin(), c.end());

  // The axes of the space the scene is in at t (of the nearest stage), from its origin.
  Vec3 lo = all.empty() ? Vec3(0) : all[0], hi = lo;
  for (const Vec3& p : all) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double axis = 0.25 * std::max(1e-6, glm::length(hi - lo));
  lines.line({0, 0, 0}, {axis, 0, 0}, theme::kU, theme::kLineWidth);
  lines.line({0, 0, 0}, {0, t > 3.5 ? -axis : axis, 0}, theme::kV, theme::kLineWidth);  // DC's y points down
  lines.line({0, 0, 0}, {0, 0, axis}, theme::kN, theme::kLineWidth);
  all.push_back({0, 0, 0});

  const Orbit o = framed(s.morphing.orbit, all, double(w) / h);
  const ViewCamera view = viewCameraOf(observerCamera(o, double(w) / h));
  drawPolygons(sets, view, {0, Mat4(1.0), 1.f, s.morph.style == Style::shaded}, kMorph);
  overlay_.draw(lines, view, w, h, OverlayDepth::xray);

  std::vector<TextLabel> labels;
  char title[160];
  std::snprintf(title, sizeof title, "t = %.2f   %s", t, std::string(morphStageName(t)).c_str());
  labels.push_back({{10, 10}, title, theme::kText, TextSize::title, Anchor::topLeft});
  labels.push_back({{10, 38}, "step: " + std::string(morphStepName(std::min(t, 3.999))), theme::kFrustum,
                    TextSize::label, Anchor::topLeft});
  auto axisLabel = [&](const Vec3& p, const char* text, const glm::vec4& color) {
    const Projected q = projectToPixels(view, p, w, h);
    if (q.visible) labels.push_back({q.pixel + Vec2(6, 0), text, color, TextSize::label, Anchor::left});
  };
  axisLabel({axis, 0, 0}, "x", theme::kU);
  axisLabel({0, t > 3.5 ? -axis : axis, 0}, "y", theme::kV);
  axisLabel({0, 0, axis}, "z", theme::kN);
  text_->draw(labels, w, h);
}

}  // namespace vplab

