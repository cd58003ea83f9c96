// The camera view: what the synthetic camera sees, the scene in WC through the scene camera's own
// matrices (lecture notes 15.2). At the device's W × H its pixels are DC: the overlays the CPU
// pipeline gives in DC (the probe, its clipped polygons, the vanishing points) are drawn in pixels,
// DC scaled to the view's size.
#include "app/text/catalogue.h"
#include "app/views/batches.h"
#include "app/views/number_text.h"
#include "app/views/student_marks.h"
#include "app/views/theme.h"
#include "app/views/views.h"

#include "pipeline/vanishing_points.h"

namespace vplab {

namespace {

using namespace draw;

// DC of the scene's device → the view's pixels (both y down, z kept).
struct PixelsFromDc {
  Vec2 scale;
  Vec3 operator()(const Vec3& dc) const { return {dc.x * scale.x, dc.y * scale.y, dc.z}; }
};

// Wire: every edge. Hidden line (lecture notes figures 16.1 and 16.3): the faces fill the depth
// buffer only, pushed back a little so their own edges pass; the visible edges solid, the hidden
// ones dashed (hidden-line) or not at all (hidden-removed).
void addEdges(const Scene& scene, const theme::Palette& pal, Style style, float scale, DisplayList& list) {
  const bool hidden = style == Style::hiddenLine || style == Style::hiddenRemoved;
  const std::vector<MeshInstance> meshes = sceneMeshes(scene);
  const std::vector<Vec4> planes = userClipPlanes(scene);
  if (hidden) {
    Fill occluder;
    occluder.space = Space::wc;
    occluder.meshes = meshes;
    occluder.depthOnly = true;
    occluder.clipPlanes = planes;
    list.add(std::move(occluder));
  }
  auto edges = [&](Depth depth, float dashPx, float alpha) {
    Lines l;
    l.space = Space::wc;
    l.meshEdges = meshes;
    for (MeshInstance& m : l.meshEdges) m.color.a = alpha;
    l.widthPx = pal.edgeWidthPx * scale;
    l.dashPx = dashPx;
    l.depth = depth;
    l.clipPlanes = planes;
    list.add(std::move(l));
  };
  if (!hidden) edges(Depth::ignore, 0.f, 1.f);
  if (hidden) edges(Depth::test, 0.f, 1.f);
  if (style == Style::hiddenLine) edges(Depth::hiddenOnly, theme::kDashPx, 0.8f);
}

// lecture notes 14.2: the images of an object's edges along each principal axis meet in the axis's
// vanishing point. Each edge is drawn on to it, dashed, in the axis's colour.
void addVanishingPoints(const PipelineRun& run, const theme::Palette& pal, Language lang, int sceneIndex,
                        const PixelsFromDc& pixels, Marks& b, std::vector<TextLabel>& labels, int width, int height) {
  const ObjectRun* o = nullptr;
  for (size_t i = 0; i < run.sceneIndex.size(); ++i)
    if (int(run.sceneIndex[i]) == sceneIndex) o = &run.objects[i];
  if (!o) return;
  const auto vps = vanishingPoints(run, o->wcFromMc);
  const glm::vec4 colors[3] = {pal.u, pal.v, pal.n};
  const char* names[3] = {"x", "y", "z"};
  // The run's edge list when it clipped edges (the viewer's does), not a new one per axis and frame.
  const std::vector<Edge> ownEdges = o->edges.empty() ? uniqueEdges(*o->mesh) : std::vector<Edge>{};
  const std::vector<Edge>& edges = o->edges.empty() ? ownEdges : o->edges;
  for (int axis = 0; axis < 3; ++axis) {
    const VanishingPoint& vp = vps[size_t(axis)];
    if (!vp.finite) continue;
    const Vec3 target = pixels(Vec3(vp.dc, 0.5));
    for (const Edge& e : edges) {
      const Vec3 d = o->wc(e.b) - o->wc(e.a);
      if (glm::length(glm::cross(glm::normalize(d), vp.directionWc)) > 1e-6) continue;  // not along this axis
      for (uint32_t v : {e.a, e.b}) {
        const Vec4 h = o->npcH[v];
        if (h.w <= 0) continue;
        const Vec3 dc = Vec3(run.dcFromNpc * Vec4(Vec3(h) / h.w, 1.0));
        b.line(pixels({dc.x, dc.y, 0.5}), target, glm::vec4(glm::vec3(colors[axis]), 0.7f), 1.2f, 4.f);
      }
    }
    b.point(target, colors[axis], 12.f);
    const Vec2 at(target);
    const bool inside = at.x >= 0 && at.y >= 0 && at.x <= width && at.y <= height;
    const std::string x = formatNumber(std::round(vp.dc.x), {10}), y = formatNumber(std::round(vp.dc.y), {10});
    std::string name = inside ? text::fill(lang, "VP {1} ({2}, {3})", {names[axis], x, y})
                              : text::fill(lang, "VP {1} ({2}, {3}) outside", {names[axis], x, y});
    const Vec2 shown = glm::clamp(at, Vec2(4), Vec2(width - 4, height - 4));
    labels.push_back({shown + Vec2(8, -8), std::move(name), colors[axis], TextSize::label, Anchor::left, true, true, shown,
                      0, text::fill(lang, "VP {1}", {names[axis]})});
  }
}

}  // namespace

DisplayList cameraView(const ViewInput& in) {
  const Scene& scene = in.scene;
  const PipelineRun& run = in.run;
  const DisplaySettings& s = in.settings;
  const int w = in.width, h = in.height;
  const float scale = in.text.scale();
  // The ground is the scene's own background (what the camera sees); the theme colours the marks.
  const theme::Palette& pal = theme::palette(s.theme);

  DisplayList list;
  list.width = w;
  list.height = h;
  list.background = glm::vec3(scene.background);
  list.observer = {Space::wc, viewCameraOf(scene.camera)};
  list.antialiased = false;  // pixel-aligned with DC

  const Style style = s.camera.style;
  if (isFilled(style)) {
    Fill objects;
    objects.space = Space::wc;
    objects.meshes = sceneMeshes(scene);
    objects.lit = style == Style::shaded;
    if (objects.lit) objects.lights = sceneLights(scene);
    objects.ambient = kSceneAmbient;
    objects.clipPlanes = userClipPlanes(scene);
    list.add(std::move(objects));
  } else {
    addEdges(scene, pal, style, scale, list);
  }

  const PixelsFromDc pixels{{double(w) / run.device.width, double(h) / run.device.height}};
  Marks marks;
  if (in.highlights.probeDc) marks.point(pixels(*in.highlights.probeDc), pal.probe, 14.f);
  studentDcMarks(in.highlights.student, pal, pixels, marks);
  if (s.overlays.cpuPolygons) {
    std::vector<Vec3> poly;
    for (const ObjectRun& o : run.objects) {
      for (size_t f = 0; f < o.faceCount(); ++f) {
        poly.clear();
        for (uint32_t ref : o.clippedFace(f)) poly.push_back(pixels(o.clippedDc(ref)));
        marks.polyline(poly, true, pal.cpuPolygon, 1.5f);
      }
    }
  }
  std::vector<TextLabel> labels;
  if (s.overlays.vanishingPoints)
    addVanishingPoints(run, pal, s.language, in.highlights.vanishingObject, pixels, marks, labels, w, h);
  marks.emit(list, Space::pixels, Depth::ignore, scale);
  if (!labels.empty()) list.add(Text{placeLabels(labels, in.text, w, h), pal.labelOutline});
  return list;
}

void cameraView(const ViewInput& in, DisplayList& out) { out = cameraView(in); }

}  // namespace vplab
