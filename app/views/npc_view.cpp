// The NPC view: the unit cube of normalized projection coordinates (front z = 1, back z = 0) with
// the scene after view mapping, clipping in homogeneous coordinates and the division by w, seen by
// an orbiting observer. The filled polygons are the CPU clipper's output; what it cut away is shown
// faded, as far as it lies in front of the eye (w > 0) and not too far outside the cube.
#include "app/views/batches.h"
#include "app/views/student_marks.h"
#include "app/views/theme.h"
#include "app/views/view_geometry.h"
#include "app/views/views.h"

#include "pipeline/clipping.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <tuple>
#include <vector>

namespace vplab {

namespace {

using namespace draw;

bool insideCube(const Vec3& p) {
  constexpr double e = 1e-9;
  return p.x >= -e && p.x <= 1 + e && p.y >= -e && p.y <= 1 + e && p.z >= -e && p.z <= 1 + e;
}

// An edge by its end points in NPC, in either direction.
std::array<double, 6> edgeKey(const Vec3& a, const Vec3& b) {
  const bool swap = std::tie(b.x, b.y, b.z) < std::tie(a.x, a.y, a.z);
  const Vec3 &p = swap ? b : a, &q = swap ? a : b;
  return {p.x, p.y, p.z, q.x, q.y, q.z};
}

// The edges drawn so far, by their end points (edgeKey): a set in flat arrays, open addressing over
// FNV-1a of the coordinates' bits (−0 as +0: they are equal keys). A tree of a million-edge mesh's
// keys took two seconds of the view's build, a node-based hash set one.
class DrawnEdges {
 public:
  explicit DrawnEdges(size_t expected) { grow(expected); }
  /// True when the edge was not drawn before (and is now).
  bool insert(const std::array<double, 6>& key) {
    if (2 * (keys_.size() + 1) > slots_.size()) grow(2 * keys_.size());
    for (size_t i = hash(key) & (slots_.size() - 1);; i = (i + 1) & (slots_.size() - 1)) {
      if (slots_[i] == 0) {
        keys_.push_back(key);
        slots_[i] = uint32_t(keys_.size());
        return true;
      }
      if (keys_[slots_[i] - 1] == key) return false;
    }
  }

 private:
  static uint64_t hash(const std::array<double, 6>& key) {
    uint64_t h = 1469598103934665603ull;
    for (double d : key) {
      const double positive = d + 0.0;
      uint64_t bits;  // std::bit_cast is not in the page's libc++
      std::memcpy(&bits, &positive, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
    return h ^ (h >> 29);
  }
  void grow(size_t keys) {  // slots for twice `keys` at least, a power of two; the keys placed again
    size_t n = 16;
    while (n < 2 * keys) n *= 2;
    slots_.assign(n, 0);
    keys_.reserve(keys);
    for (uint32_t k = 1; k <= keys_.size(); ++k) {
      size_t i = hash(keys_[k - 1]) & (n - 1);
      while (slots_[i] != 0) i = (i + 1) & (n - 1);
      slots_[i] = k;
    }
  }
  std::vector<std::array<double, 6>> keys_;
  std::vector<uint32_t> slots_;  // 0: empty, else 1 + the key's index
};

void addCube(const theme::Palette& pal, Language lang, Marks& b, std::vector<TextLabel>& labels,
             std::vector<LabelObstacle>& axes, const ViewCamera& view, int w, int h, bool withLabels) {
  using geometry::cubeCorner;
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) b.line(cubeCorner(i), cubeCorner(i | bit), pal.cube, 1.5f);
  b.quad(cubeCorner(4), cubeCorner(5), cubeCorner(7), cubeCorner(6), pal.cubeFront);
  const double len = geometry::kNpcAxisLength;
  b.line({0, 0, 0}, {len, 0, 0}, pal.u, theme::kLineWidth);
  b.line({0, 0, 0}, {0, len, 0}, pal.v, theme::kLineWidth);
  b.line({0, 0, 0}, {0, 0, len}, pal.n, theme::kLineWidth);
  if (!withLabels) return;
  // No label crosses an axis ("vorne z = 1" lay across y in every view).
  const Projected origin = projectToPixels(view, {0, 0, 0}, w, h);
  for (const Vec3& end : {Vec3(len, 0, 0), Vec3(0, len, 0), Vec3(0, 0, len)}) {
    const Projected q = projectToPixels(view, end, w, h);
    if (origin.visible && q.visible) axes.push_back({origin.pixel, q.pixel});
  }
  for (const geometry::AnchoredLabel& l : geometry::npcCubeLabels(pal, lang)) {
    const Projected q = projectToPixels(view, l.at, w, h);
    if (q.visible)
      labels.push_back({q.pixel, l.text, l.color, TextSize::label, Anchor::center, true, true, {}, l.priority, l.shortText});
  }
}

}  // namespace

void npcView(const ViewInput& in, DisplayList& list) {
  const PipelineRun& run = in.run;
  const DisplaySettings& s = in.settings;
  const int w = in.width, h = in.height;
  const float scale = in.text.scale();
  const Style style = s.npc.style;
  const OverlaySettings& ov = s.overlays;
  const theme::Palette& pal = theme::palette(s.theme);

  Recycled recycled(list);  // the previous frame's polygon arrays, with their capacity
  list.width = w;
  list.height = h;
  list.background = pal.viewBackground;
  const ViewCamera view = viewCameraOf(observerCamera(s.npc.orbit, double(w) / h));
  list.observer = {Space::npc, view};
  list.antialiased = true;

  // The clipped polygons (drawn filled, or as the hidden-line styles' occluders) and the faded ones
  // (filled styles), one set per object.
  const bool keepInside = style != Style::wire, keepFaded = isFilled(style) && ov.fadeOutside;
  std::vector<PolygonSet> inside = recycled.polygonSets(keepInside ? run.objects.size() : 0);
  // Two faded sets an object: its faces whole inside the grown cube by reference, then those the
  // grown cube cuts, copied (the same colour and alpha: their order among themselves shows nowhere).
  std::vector<PolygonSet> faded = recycled.polygonSets(keepFaded ? 2 * run.objects.size() : 0);
  Marks outlines, dashedOutlines, newEdges, fadedOutlines;
  ClipScratch scratch;
  const bool outlined = !isFilled(style) || style == Style::hiddenLine;
  // The mesh's edges by reference when the run clipped them (the wireframe styles' runs do, issue 42):
  // each once, its visible part (the clipped polygons' boundaries along them); the polygons then add
  // only the edges clipping made. A run without its edges has its polygons' edges copied, each once.
  auto edgesByReference = [&](const ObjectRun& o) {
    return outlined && !o.edges.empty() && o.edgeFate.size() == o.edges.size();
  };
  size_t corners = 0;  // each edge is shared by about two faces
  if (outlined)
    for (const ObjectRun& o : run.objects) corners += (edgesByReference(o) ? o.clippedFaces.size() : o.faceCount()) * 3;
  DrawnEdges drawnEdges(corners / 2);
  std::vector<Vec3> poly;  // reused: no allocation per polygon
  for (size_t k = 0; k < run.objects.size(); ++k) {
    const ObjectRun& o = run.objects[k];
    if (keepInside) {  // the clipped faces by number: their points are read from the run when drawn
      inside[k].npcOf = &o;
      inside[k].faces.reserve(o.faceCount());
      inside[k].color = glm::vec3(o.color);
    }
    if (keepFaded) {
      faded[2 * k].npcOf = &o;
      faded[2 * k].wholeFaces = true;
      faded[2 * k].color = faded[2 * k + 1].color = glm::vec3(o.color);
    }
    const glm::vec4 c = theme::ink(pal, glm::vec4(glm::vec3(o.color), 1.f));
    const bool byReference = edgesByReference(o);
    if (byReference && !isFilled(style)) outlines.runEdges({&o, c, true}, pal.edgeWidthPx);
    if (byReference && style == Style::hiddenLine)
      dashedOutlines.runEdges({&o, glm::vec4(glm::vec3(c), 0.8f), true}, pal.edgeWidthPx, theme::kDashPx);
    // What clipping cut away, outlined: by reference too (each edge once), else each face's copied.
    const glm::vec4 fadedInk(glm::vec3(c), pal.fadedAlpha);
    const bool fadedOutlined = ov.fadeOutside && !isFilled(style), fadedCopied = fadedOutlined && !byReference;
    if (fadedOutlined && byReference) fadedOutlines.runEdges({&o, fadedInk, false, true}, pal.edgeWidthPx);
    for (size_t f = 0; f < o.faceCount(); ++f) {
      const auto face = o.clippedFace(f);
      if (!face.empty()) {
        if (keepInside) inside[k].faces.push_back(uint32_t(f));
        // Only clipped faces have new edges; only the wireframe styles draw the others.
        const bool cut = o.fate[f] == Fate::clipped, clipped = ov.newEdges && cut;
        const bool outlineHere = outlined && (!byReference || cut);
        if (clipped || outlineHere) {
          poly.clear();
          for (uint32_t ref : face) poly.push_back(o.clippedNpc(ref));
        }
        for (size_t i = 0; (clipped || outlineHere) && i < face.size(); ++i) {
          const Vec3 &a = poly[i], &b = poly[(i + 1) % poly.size()];
          const bool made = cut && o.isNewEdge(f, i);
          if (clipped && made) {
            newEdges.line(a, b, pal.newEdge, theme::kLineWidth + 0.5f);
            continue;
          }
          if (!outlineHere || (byReference && !made)) continue;  // a mesh edge: drawn by reference
          // Two faces share each mesh edge: draw it once, or its dashes would overlap out of phase.
          if (!drawnEdges.insert(edgeKey(a, b))) continue;
          if (!isFilled(style)) outlines.line(a, b, c, pal.edgeWidthPx);
          if (style == Style::hiddenLine)
            dashedOutlines.line(a, b, glm::vec4(glm::vec3(c), 0.8f), pal.edgeWidthPx, theme::kDashPx);
        }
      }
      if (ov.fadeOutside && o.fate[f] != Fate::accepted && (keepFaded || fadedCopied)) {
        if (keepFaded && geometry::fadedFaceWhole(o, f)) {
          faded[2 * k].faces.push_back(uint32_t(f));
          continue;
        }
        geometry::fadedNpcPolygon(o, f, scratch, poly);
        if (poly.size() >= 3) {
          if (fadedCopied) fadedOutlines.polyline(poly, true, fadedInk, pal.edgeWidthPx);
          if (keepFaded) faded[2 * k + 1].add(poly);
        }
      }
    }
  }

  const bool shaded = style == Style::shaded;
  auto polygons = [&](std::vector<PolygonSet>&& sets, float alpha, bool lit, bool depthOnly) {
    Fill fill;
    fill.space = Space::npc;
    fill.polygons = std::move(sets);
    fill.lit = lit;
    if (lit) fill.lights = polygonLights(view);
    fill.ambient = kPolygonAmbient;
    fill.alpha = alpha;
    fill.depthOnly = depthOnly;
    list.add(std::move(fill));
  };
  if (isFilled(style)) polygons(std::move(inside), 1.f, shaded, false);
  else if (style != Style::wire) polygons(std::move(inside), 1.f, false, true);
  const Depth depth = style == Style::wire ? Depth::ignore : Depth::test;
  outlines.emit(list, Space::npc, depth, scale);
  dashedOutlines.emit(list, Space::npc, Depth::hiddenOnly, scale);
  if (ov.fadeOutside) {
    if (isFilled(style)) polygons(std::move(faded), pal.fadedAlpha, shaded, false);
    else fadedOutlines.emit(list, Space::npc, depth, scale);
  }

  Marks cube;
  std::vector<TextLabel> labels;
  std::vector<LabelObstacle> axes;
  if (ov.cube) addCube(pal, s.language, cube, labels, axes, view, w, h, ov.labels);
  // The translucent front face lies in z = 1, where clipping puts the scene's cut polygons and
  // edges: pushed back, it loses every depth tie to them instead of z-fighting (the cube's lines
  // are not pushed back).
  cube.emit(list, Space::npc, Depth::test, scale, /*pushedBack=*/true);
  if (in.highlights.probeNpc) newEdges.point(*in.highlights.probeNpc, pal.probe, 14.f);
  studentNpcMarks(in.highlights.student, pal, newEdges);
  // A lesson's highlighted planes of the view volume: faces of the cube, outlined.
  for (int plane : in.highlights.planes) {
    if (plane < 0 || plane >= kPlaneCount) continue;
    const auto ring = geometry::cubeFaceRing(plane);
    using geometry::cubeCorner;
    const std::array<Vec3, 4> face{cubeCorner(ring[0]), cubeCorner(ring[1]), cubeCorner(ring[2]), cubeCorner(ring[3])};
    newEdges.quad(face[0], face[1], face[2], face[3], pal.stepPlane);
    newEdges.polyline(face, true, pal.handleHot, theme::kLineWidth + 1.5f);
  }
  if (const auto& step = in.highlights.step) {
    // The clipping step-through: the plane being applied as a face of the cube, the polygon after
    // the step, its new vertices.
    if (step->plane >= 0 && step->plane < kPlaneCount) {
      const auto ring = geometry::cubeFaceRing(step->plane);
      using geometry::cubeCorner;
      newEdges.quad(cubeCorner(ring[0]), cubeCorner(ring[1]), cubeCorner(ring[2]), cubeCorner(ring[3]), pal.stepPlane);
    }
    newEdges.polyline(step->polygonNpc, true, pal.probe, theme::kLineWidth + 1.f);
    for (size_t i = 0; i < step->polygonNpc.size(); ++i)
      newEdges.point(step->polygonNpc[i], step->created[i] ? pal.newEdge : pal.probe, step->created[i] ? 13.f : 9.f);
  }
  if (ov.vertexNames && ov.labels) {
    // The polygons' vertices P1 … Pn where they lie inside the view volume (the others were clipped
    // away; a vertex behind the eye has no place in NPC).
    for (const geometry::NamedPoint& v : geometry::polygonVertexNames(in.scene)) {
      const Vec4 h4 = run.npcFromWc * Vec4(v.at, 1.0);
      if (!(h4.w > 0) || !insideCube(Vec3(h4) / h4.w)) continue;
      const Vec3 p = Vec3(h4) / h4.w;
      newEdges.point(p, theme::ink(pal, v.color), theme::kPointSize * 0.7f);
      const Projected q = projectToPixels(view, p, w, h);
      if (q.visible)
        labels.push_back({q.pixel + Vec2(7, -9) * double(scale), v.name, theme::ink(pal, v.color), TextSize::label,
                          Anchor::left, true, true, q.pixel, 1});
    }
  }
  newEdges.emit(list, Space::npc, Depth::xray, scale);
  if (!labels.empty()) list.add(Text{placeLabels(labels, in.text, w, h, axes), pal.labelOutline});
}

DisplayList npcView(const ViewInput& in) {
  DisplayList list;
  npcView(in, list);
  return list;
}

}  // namespace vplab
