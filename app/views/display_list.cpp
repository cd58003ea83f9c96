#include "app/views/display_list.h"

#include "app/views/view_geometry.h"
#include "pipeline/pipeline.h"

#include <algorithm>

namespace vplab::draw {

std::span<const uint32_t> PolygonSet::refs(size_t i) const {
  return wholeFaces ? npcOf->mesh->face(faces[i]) : npcOf->clippedFace(faces[i]);
}

std::span<const Vec3> PolygonSet::polygon(size_t i, std::vector<Vec3>& scratch) const {
  if (!npcOf) {
    const uint32_t begin = i ? ends[i - 1] : 0;
    return {points.data() + begin, ends[i] - begin};
  }
  scratch.clear();
  for (uint32_t ref : refs(i)) scratch.push_back(npcOf->clippedNpc(ref));
  return scratch;
}

void Lines::polyline(std::span<const Vec3> points, bool closed, const glm::vec4& color) {
  if (points.size() < 2) return;
  for (size_t i = 0; i + 1 < points.size(); ++i) line(points[i], points[i + 1], color);
  if (closed && points.size() > 2) line(points.back(), points.front(), color);
}

size_t RunEdges::count() const { return run ? std::min(run->edges.size(), run->edgeFate.size()) : 0; }

namespace {

// Edges [first, end) of a run in NPC: the visible part [t0, t1] of each, taken where the strategy
// clipped it (homogeneous NPC, linear in WC too, for the NPC and WC strategies; the divided points for
// divide first), then divided by w: the same segments as the clipped polygons' boundaries along the
// mesh's edges (lecture notes 15.3.2), which the NPC view once copied from them.
void npcEdgesInto(const ObjectRun& o, const RunEdges& r, size_t first, size_t end, std::vector<Vertex>& out) {
  const bool divided = o.strategy == ClipStrategy::divideFirst;
  for (size_t i = first; i < end; ++i) {
    const Edge& e = o.edges[i];
    if (r.fadedPart) {
      if (!(o.outcodes[e.a] | o.outcodes[e.b])) continue;
      const Vec4 &a = o.npcH[e.a], &b = o.npcH[e.b];
      const Boundary ga = geometry::grownBoundary(a, geometry::kFadedMargin), gb = geometry::grownBoundary(b, geometry::kFadedMargin);
      Outcode planes = 0;
      for (int k = 0; k < kPlaneCount; ++k)
        if (ga[size_t(k)] < 0 || gb[size_t(k)] < 0) planes |= Outcode(1u << k);
      const EdgeRange range = planes ? clipEdge(ga, gb, planes) : EdgeRange{0, 1, true};
      if (!range.visible) continue;
      const Vec4 p = a + range.t0 * (b - a), q = a + range.t1 * (b - a);
      if (p.w <= 1e-12 || q.w <= 1e-12) continue;  // a point of the eye plane (the grown cube's apex)
      out.insert(out.end(), {{Vec3(p) / p.w, r.color}, {Vec3(q) / q.w, r.color}});
      continue;
    }
    if (!r.visiblePart) {
      out.insert(out.end(), {{divideByW(o.npcH[e.a]), r.color}, {divideByW(o.npcH[e.b]), r.color}});
      continue;
    }
    if (!o.edgeVisible(i)) continue;
    const EdgeRange range = o.edgeRange(i);
    if (divided) {
      const Vec3 a = divideByW(o.npcH[e.a]), b = divideByW(o.npcH[e.b]);
      out.insert(out.end(), {{a + range.t0 * (b - a), r.color}, {a + range.t1 * (b - a), r.color}});
    } else {
      const Vec4 &a = o.npcH[e.a], &b = o.npcH[e.b];
      out.insert(out.end(), {{divideByW(a + range.t0 * (b - a)), r.color}, {divideByW(a + range.t1 * (b - a)), r.color}});
    }
  }
}

}  // namespace

size_t Lines::segmentCount() const {
  size_t n = segments.size() / 2;
  for (const RunEdges& r : runEdges) n += r.count();
  return n;
}

void Lines::segmentsInto(size_t first, size_t end, std::vector<Vertex>& out) const {
  const size_t own = segments.size() / 2;
  for (size_t i = first; i < std::min(end, own); ++i) out.insert(out.end(), {segments[2 * i], segments[2 * i + 1]});
  size_t base = own;  // the first segment of the next run
  for (const RunEdges& r : runEdges) {
    const size_t n = r.count();
    const size_t from = std::max(first, base), to = std::min(end, base + n);
    if (space == Space::npc) {
      if (from < to) npcEdgesInto(*r.run, r, from - base, to - base, out);  // [first, end) may lie before or after these
      base += n;
      continue;
    }
    for (size_t i = from; i < to; ++i) {
      const ObjectRun& o = *r.run;
      const Edge& e = o.edges[i - base];
      const Vec3 a = o.wc(e.a), b = o.wc(e.b);
      if (!r.visiblePart) {
        out.insert(out.end(), {{a, r.color}, {b, r.color}});
        continue;
      }
      if (!o.edgeVisible(i - base)) continue;
      const EdgeRange range = o.edgeRange(i - base);
      // Boundary coordinates are linear along the WC segment, so t carries over from NPC.
      out.insert(out.end(), {{a + range.t0 * (b - a), r.color}, {a + range.t1 * (b - a), r.color}});
    }
    base += n;
  }
}

std::vector<PlacedLabel> DisplayList::labels() const {
  std::vector<PlacedLabel> out;
  for (const Batch& b : batches)
    if (const Text* t = std::get_if<Text>(&b)) out.insert(out.end(), t->labels.begin(), t->labels.end());
  return out;
}

MemoryUse memoryUse(const DisplayList& list) {
  size_t meshes = 0, polygons = 0, lines = 0, points = 0, triangles = 0, text = 0;
  for (const Batch& b : list.batches) {
    if (const Fill* f = std::get_if<Fill>(&b)) {
      meshes += heapBytes(f->meshes) + heapBytes(f->lights) + heapBytes(f->clipPlanes);
      polygons += heapBytes(f->polygons);
      for (const PolygonSet& p : f->polygons) polygons += heapBytes(p.points) + heapBytes(p.ends) + heapBytes(p.faces);
    } else if (const Lines* l = std::get_if<Lines>(&b)) {
      lines += heapBytes(l->segments) + heapBytes(l->runEdges) + heapBytes(l->meshEdges) + heapBytes(l->clipPlanes);
    } else if (const Points* p = std::get_if<Points>(&b)) {
      points += heapBytes(p->points);
    } else if (const Triangles* t = std::get_if<Triangles>(&b)) {
      triangles += heapBytes(t->vertices);
    } else if (const Text* x = std::get_if<Text>(&b)) {
      text += heapBytes(x->labels);
      for (const PlacedLabel& label : x->labels) text += label.text.capacity() > 15 ? label.text.capacity() + 1 : 0;
    }
  }
  return {{"batches", heapBytes(list.batches)}, {"fill meshes", meshes}, {"polygons", polygons}, {"lines", lines},
          {"points", points}, {"triangles", triangles}, {"labels", text}};
}

}  // namespace vplab::draw
