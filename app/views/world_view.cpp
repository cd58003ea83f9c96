// The world view: an orbiting observer (itself a synthetic camera of the pipeline) sees the scene in
// WC together with the scene camera: VRP, PRP, VUP, the U, V, N axes, the window in the view plane
// and the view volume. What lies inside the view volume is drawn solid, the rest faded; the edges
// the CPU clipper created are highlighted (lecture notes 15.1, figures 15.1–15.5).
#include "app/text/catalogue.h"
#include "app/views/batches.h"
#include "app/views/student_marks.h"
#include "app/views/theme.h"
#include "app/views/view_geometry.h"
#include "app/views/views.h"

#include <algorithm>
#include <span>

namespace vplab {

namespace {

using namespace draw;

// A handle's name: app/inspect/picking.h names them in English (their ids); the frustum's planes are
// labelled in the language, as the frustum's own labels.
std::string handleLabel(const std::string& name, Language lang) {
  for (const text::Text t : {text::Text("front F"), text::Text("back B")})
    if (t.english() == name) return t.in(lang);
  return name;  // VRP, PRP, xmin, …: the same in both languages
}

void addArrow(Marks& b, const Vec3& from, const Vec3& to, const Vec3& eye, const glm::vec4& color, float dash = 0.f) {
  // The arrows are the camera's axes: solid, but for VUP's dashes, in every theme.
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

// The objects: inside the view volume solid, outside faded. The backend splits them by the scene
// camera's boundary coordinates (Hill 7.4), exactly where the CPU clipper cuts.
void addFilledObjects(const ViewInput& in, DisplayList& list) {
  const Style style = in.settings.world.style;
  Fill inside;
  inside.space = Space::wc;
  inside.meshes = sceneMeshes(in.scene, &in.run);
  inside.lit = style == Style::shaded;
  if (inside.lit) inside.lights = sceneLights(in.scene);
  inside.ambient = kSceneAmbient;
  inside.volume = {VolumeTest::Keep::inside, in.run.npcFromWc};
  inside.clipPlanes = userClipPlanes(in.scene);
  if (!in.settings.overlays.fadeOutside) {
    list.add(std::move(inside));
    return;
  }
  Fill outside = inside;
  outside.alpha = theme::palette(in.settings.theme).fadedAlpha;
  outside.volume.keep = VolumeTest::Keep::outside;
  outside.clipPlanes.clear();  // the faded rest, outside the volume, is not cut by the user planes
  list.add(std::move(inside));
  list.add(std::move(outside));
}

// Wireframes from the CPU's edge clipping: the visible part of each edge solid, all of it faded.
// Hidden line: the faces fill the depth buffer first; the hidden parts dashed or not drawn.
void addEdges(const ViewInput& in, float scale, DisplayList& list) {
  const Style style = in.settings.world.style;
  const bool hidden = style != Style::wire;
  if (hidden) {
    Fill occluder;
    occluder.space = Space::wc;
    occluder.meshes = sceneMeshes(in.scene);
    occluder.depthOnly = true;
    list.add(std::move(occluder));
  }
  const theme::Palette& pal = theme::palette(in.settings.theme);
  // The run's edges by reference (Lines::runEdges): each edge whole and faded, then its visible part
  // solid (and dashed where hidden), in the order the backends draw batches.
  const Depth depth = hidden ? Depth::test : Depth::ignore;
  Lines faded{Space::wc, {}, {}, {}, pal.edgeWidthPx * scale, 0.f, depth, {}};
  Lines solid = faded;
  Lines dashed{Space::wc, {}, {}, {}, pal.edgeWidthPx * scale, theme::kDashPx, Depth::hiddenOnly, {}};
  for (const ObjectRun& o : in.run.objects) {
    const glm::vec4 c = theme::ink(pal, glm::vec4(glm::vec3(o.color), 1.f));
    const RunEdges edges{&o, c, true};
    if (edges.count() == 0) continue;
    if (in.settings.overlays.fadeOutside) faded.runEdges.push_back({&o, glm::vec4(glm::vec3(c), pal.fadedAlpha), false});
    size_t e = 0;
    while (e < edges.count() && !o.edgeVisible(e)) ++e;
    if (e == edges.count()) continue;  // no edge visible
    solid.runEdges.push_back(edges);
    if (style == Style::hiddenLine) dashed.runEdges.push_back({&o, glm::vec4(glm::vec3(c), 0.8f), true});
  }
  for (Lines* l : {&faded, &solid, &dashed})
    if (!l->runEdges.empty()) list.add(std::move(*l));
}

}  // namespace

DisplayList worldView(const ViewInput& in) {
  const Scene& scene = in.scene;
  const PipelineRun& run = in.run;
  const OverlaySettings& ov = in.settings.overlays;
  const int w = in.width, h = in.height;
  const float scale = in.text.scale();
  const theme::Palette& pal = theme::palette(in.settings.theme);
  const Language lang = in.settings.language;

  DisplayList list;
  list.width = w;
  list.height = h;
  list.background = pal.viewBackground;
  const ViewCamera view = viewCameraOf(observerCamera(in.settings.world.orbit, double(w) / h));
  list.observer = {Space::wc, view};
  list.antialiased = true;

  if (isFilled(in.settings.world.style)) addFilledObjects(in, list);
  else addEdges(in, scale, list);

  const Mat4 &wcFromNpc = run.wcFromNpc, &wcFromVrc = run.wcFromVrc;
  Marks b;
  std::vector<TextLabel> labels;
  // Priorities when labels compete for room (labels.h): a lesson's highlighted handle, then the
  // camera's points and axes, then planes, the window and vertex names.
  enum Priority { kPlane = 0, kCamera = 1, kHot = 2 };
  auto label = [&](const Vec3& p, const std::string& text, const glm::vec4& color, Vec2 offset = {8, 0},
                   int priority = kPlane, std::string shortText = {}) {
    if (!ov.labels) return;
    const Projected q = projectToPixels(view, p, w, h);
    // The offset from the point grows with the text (and the markers) at a large UI scale.
    if (q.visible)
      labels.push_back({q.pixel + offset * double(scale), text, color, TextSize::label, Anchor::left, true, true, q.pixel,
                        priority, std::move(shortText)});
  };

  if (ov.newEdges) {
    for (const ObjectRun& o : run.objects)
      for (size_t fi = 0; fi < o.faceCount(); ++fi) {
        if (o.fate[fi] != Fate::clipped) continue;
        const auto face = o.clippedFace(fi);
        for (size_t i = 0; i < face.size(); ++i)
          if (o.isNewEdge(fi, i))
            b.line(geometry::wcOfNpc(wcFromNpc, o.clippedNpc(face[i])),
                   geometry::wcOfNpc(wcFromNpc, o.clippedNpc(face[(i + 1) % face.size()])), pal.newEdge,
                   theme::kLineWidth + 0.5f);
      }
  }
  if (ov.frustum) {
    const auto c = geometry::viewVolumeCorners(wcFromNpc);
    // Corner i has x = bit 0, y = bit 1, z = bit 2 (z = 1 front, 0 back).
    const int front[4] = {4, 5, 7, 6}, back[4] = {0, 1, 3, 2};
    b.quad(c[4], c[5], c[7], c[6], pal.frontPlane);
    b.quad(c[0], c[1], c[3], c[2], pal.backPlane);
    for (int i = 0; i < 4; ++i) {
      b.line(c[front[i]], c[front[(i + 1) % 4]], pal.frustum, pal.frustumWidthPx);
      b.line(c[back[i]], c[back[(i + 1) % 4]], pal.frustum, pal.frustumWidthPx);
      b.line(c[front[i]], c[back[i]], pal.frustum, pal.frustumWidthPx);
      if (run.camera.projection == Projection::perspective)  // the projectors from PRP
        b.line(run.camera.prp, c[front[i]], glm::vec4(glm::vec3(pal.frustum), 0.6f), 1.5f, pal.projectorDashPx);
    }
    // The lecture's names: vordere/hintere Clippingebene (front and back plane).
    label(c[7], text::Text("front F").in(lang), pal.frustum, {6, -10}, kPlane, "F");
    label(c[3], text::Text("back B").in(lang), pal.frustum, {6, -10}, kPlane, "B");
  }
  // User clip planes (DGL wiki): a translucent square on each, around its point, with its normal.
  const double planeSize = geometry::clipPlaneSquareSize(run.camera);
  for (const UserClipPlane& p : scene.clipPlanes) {
    if (!p.enabled) continue;
    const Vec3 n = glm::normalize(p.normal);
    const auto q = geometry::clipPlaneSquare(p, planeSize);
    b.quad(q[0], q[1], q[2], q[3], pal.clipPlane);
    b.polyline(q, true, glm::vec4(glm::vec3(pal.clipPlane), 0.8f), 1.5f);
    addArrow(b, p.point, p.point + n * (0.3 * planeSize), view.camera.prp, glm::vec4(glm::vec3(pal.clipPlane), 1.f));
    label(p.point + n * (0.3 * planeSize), text::Text("clip plane").in(lang), glm::vec4(glm::vec3(pal.clipPlane), 1.f));
  }
  if (ov.viewPlane) {
    const ViewWindow& win = run.camera.window;
    const std::array<Vec3, 4> corners{transformAffine(wcFromVrc, {win.xmin, win.ymin, 0}),
                                      transformAffine(wcFromVrc, {win.xmax, win.ymin, 0}),
                                      transformAffine(wcFromVrc, {win.xmax, win.ymax, 0}),
                                      transformAffine(wcFromVrc, {win.xmin, win.ymax, 0})};
    b.quad(corners[0], corners[1], corners[2], corners[3], pal.windowFill);
    b.polyline(corners, true, pal.window, pal.windowWidthPx, pal.windowDashPx);
    label(corners[3], text::Text("window").in(lang), pal.window, {6, -10});
  }
  if (ov.cameraAxes) {
    const Camera& cam = run.camera;
    const double len = 0.3 * std::max(cam.window.width(), cam.window.height());
    addArrow(b, cam.vrp, cam.vrp + len * run.vrc.u, view.camera.prp, pal.u);
    addArrow(b, cam.vrp, cam.vrp + len * run.vrc.v, view.camera.prp, pal.v);
    addArrow(b, cam.vrp, cam.vrp + len * run.vrc.n, view.camera.prp, pal.n);
    addArrow(b, cam.vrp, cam.vrp + len * glm::normalize(cam.vup), view.camera.prp, pal.vup, theme::kDashPx);
    b.point(cam.vrp, pal.vrp, theme::kPointSize);
    b.point(cam.prp, pal.prp, theme::kPointSize);
    if (cam.projection == Projection::perspective)
      b.line(cam.vrp, cam.prp, glm::vec4(glm::vec3(pal.n), 0.5f), 1.5f, theme::kDashPx);
    label(cam.vrp + len * run.vrc.u, "U", pal.u, {8, 0}, kCamera);
    label(cam.vrp + len * run.vrc.v, "V", pal.v, {8, 0}, kCamera);
    label(cam.vrp + len * run.vrc.n, "N", pal.n, {8, 0}, kCamera);
    label(cam.vrp + len * glm::normalize(cam.vup), "VUP", pal.vup, {8, 0}, kCamera);
    label(cam.vrp, "VRP", pal.vrp, {8, 12}, kCamera);
    label(cam.prp, "PRP", pal.prp, {8, 0}, kCamera);
  }
  if (ov.vertexNames) {
    // The polygons' vertices as the exercise sheets name them: P1 … Pn in the given order.
    for (const geometry::NamedPoint& v : geometry::polygonVertexNames(scene)) {
      b.point(v.at, theme::ink(pal, v.color), theme::kPointSize * 0.7f);
      label(v.at, v.name, theme::ink(pal, v.color), {7, -9});
    }
  }
  const Highlights& hl = in.highlights;
  for (const Highlights::HandleMark& m : hl.handles) {
    b.point(m.wc, m.hot ? pal.handleHot : pal.handle, m.hot ? 15.f : 9.f);
    if (m.hot) label(m.wc, handleLabel(m.name, lang), pal.handleHot, {10, -12}, kHot);
  }
  if (hl.probeWc) b.point(*hl.probeWc, pal.probe, 14.f);
  studentWorldMarks(hl.student, pal, b);
  // A lesson's highlighted planes: a face of the view volume as the step-through shows its plane,
  // outlined; a user clip plane's square outlined thick. Its highlighted axis: drawn over, thicker.
  for (int plane : hl.planes) {
    if (plane >= 0 && plane < kPlaneCount) {
      const auto c = geometry::viewVolumeCorners(wcFromNpc);
      const auto ring = geometry::cubeFaceRing(plane);
      const std::array<Vec3, 4> face{c[size_t(ring[0])], c[size_t(ring[1])], c[size_t(ring[2])], c[size_t(ring[3])]};
      b.quad(face[0], face[1], face[2], face[3], pal.stepPlane);
      b.polyline(face, true, pal.handleHot, theme::kLineWidth + 1.5f);
    } else if (plane >= kPlaneCount && size_t(plane - kPlaneCount) < scene.clipPlanes.size()) {
      const auto q = geometry::clipPlaneSquare(scene.clipPlanes[size_t(plane - kPlaneCount)], planeSize);
      b.polyline(q, true, pal.handleHot, theme::kLineWidth + 1.5f);
    }
  }
  for (int a : hl.axes) {
    if (a < 0 || a > 2) continue;
    const Camera& cam = run.camera;
    const double len = 0.3 * std::max(cam.window.width(), cam.window.height());
    const Vec3 axis = a == 0 ? run.vrc.u : a == 1 ? run.vrc.v : run.vrc.n;
    b.line(cam.vrp, cam.vrp + len * axis, pal.handleHot, theme::kLineWidth + 3.f);
    b.point(cam.vrp + len * axis, pal.handleHot, 13.f);
  }
  if (const auto& step = hl.step) {
    // The clipping step-through in WC: the frustum's face of the plane being applied, the polygon.
    if (step->plane >= 0 && step->plane < kPlaneCount) {
      const auto c = geometry::viewVolumeCorners(wcFromNpc);
      const auto ring = geometry::cubeFaceRing(step->plane);
      b.quad(c[size_t(ring[0])], c[size_t(ring[1])], c[size_t(ring[2])], c[size_t(ring[3])], pal.stepPlane);
    }
    std::vector<Vec3> poly;
    for (const Vec3& p : step->polygonNpc) poly.push_back(geometry::wcOfNpc(wcFromNpc, p));
    b.polyline(poly, true, pal.probe, theme::kLineWidth + 1.f);
    for (size_t i = 0; i < poly.size(); ++i)
      b.point(poly[i], step->created[i] ? pal.newEdge : pal.probe, step->created[i] ? 13.f : 9.f);
  }
  b.emit(list, Space::wc, Depth::xray, scale);
  if (!labels.empty()) list.add(Text{placeLabels(labels, in.text, w, h), pal.labelOutline});
  return list;
}

void worldView(const ViewInput& in, DisplayList& out) { out = worldView(in); }

}  // namespace vplab
