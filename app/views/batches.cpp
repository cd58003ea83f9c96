#include "app/views/batches.h"

#include "pipeline/clipping.h"

#include <algorithm>

namespace vplab::draw {

Recycled::Recycled(DisplayList& old) {
  for (Batch& b : old.batches)
    if (Fill* f = std::get_if<Fill>(&b); f && !f->polygons.empty()) sets_.push_back(std::move(f->polygons));
  old.batches.clear();
}

std::vector<PolygonSet> Recycled::polygonSets(size_t count) {
  std::vector<PolygonSet> sets;
  if (next_ < sets_.size()) sets = std::move(sets_[next_++]);
  sets.resize(count);
  for (PolygonSet& s : sets) s.clear();
  return sets;
}

void Marks::line(const Vec3& a, const Vec3& b, const glm::vec4& color, float widthPx, float dashPx) {
  std::vector<Vertex>& v = lines_[{widthPx, dashPx}].segments;
  v.push_back({a, color});
  v.push_back({b, color});
}

void Marks::polyline(std::span<const Vec3> points, bool closed, const glm::vec4& color, float widthPx,
                     float dashPx) {
  if (points.size() < 2) return;
  for (size_t i = 0; i + 1 < points.size(); ++i) line(points[i], points[i + 1], color, widthPx, dashPx);
  if (closed && points.size() > 2) line(points.back(), points.front(), color, widthPx, dashPx);
}

void Marks::runEdges(const RunEdges& edges, float widthPx, float dashPx) {
  lines_[{widthPx, dashPx}].runEdges.push_back(edges);
}

void Marks::point(const Vec3& p, const glm::vec4& color, float sizePx) { points_[sizePx].push_back({p, color}); }

void Marks::triangle(const Vec3& a, const Vec3& b, const Vec3& c, const glm::vec4& color) {
  triangles_.insert(triangles_.end(), {{a, color}, {b, color}, {c, color}});
}

void Marks::quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const glm::vec4& color) {
  triangle(a, b, c, color);
  triangle(a, c, d, color);
}

void Marks::emit(DisplayList& list, Space space, Depth depth, float scale, bool pushedBack) {
  if (!triangles_.empty()) {
    Triangles t{space, std::move(triangles_), depth, pushedBack};
    list.add(std::move(t));
  }
  for (auto& [style, group] : lines_) {
    Lines l;
    l.space = space;
    l.segments = std::move(group.segments);
    l.runEdges = std::move(group.runEdges);
    l.widthPx = style.first * scale;
    l.dashPx = style.second;
    l.depth = depth;
    list.add(std::move(l));
  }
  for (auto& [size, points] : points_) list.add(Points{space, std::move(points), size * scale, depth});
  triangles_.clear();
  lines_.clear();
  points_.clear();
}

std::vector<MeshInstance> sceneMeshes(const Scene& scene, const PipelineRun* run) {
  std::vector<const ObjectRun*> runs(scene.objects.size(), nullptr);
  if (run)
    for (size_t k = 0; k < run->objects.size() && k < run->sceneIndex.size(); ++k)
      if (run->sceneIndex[k] < runs.size()) runs[run->sceneIndex[k]] = &run->objects[k];
  std::vector<MeshInstance> meshes;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (!o.visible || !o.mesh) continue;
    MeshInstance m{o.mesh, wcFromMc(o.transform), glm::vec4(glm::vec3(o.color), 1.f), nullptr};
    // A stale run (kept after an invalid camera, or of an edited object) is not this object's.
    if (const ObjectRun* r = runs[i]; r && r->mesh == o.mesh && r->npcH.size() == o.mesh->vertexCount() &&
                                      r->fate.size() == o.mesh->faceCount() && r->wcFromMc == m.spaceFromMc)
      m.run = r;
    meshes.push_back(std::move(m));
  }
  return meshes;
}

std::vector<Light> sceneLights(const Scene& scene) {
  std::vector<Light> lights = scene.lights;
  if (lights.empty()) lights.push_back({scene.camera.prp, {1, 1, 1}});  // a light at the eye
  if (lights.size() > kMaxSceneLights) lights.resize(kMaxSceneLights);
  return lights;
}

std::vector<Light> polygonLights(const ViewCamera& observer) {
  return {{Vec3(observer.eyeWc) + Vec3(0.6, 1.2, 0.4), {1, 1, 1}}};
}

std::vector<Vec4> userClipPlanes(const Scene& scene) {
  std::vector<Vec4> planes;
  for (const UserClipPlane& p : scene.clipPlanes)
    if (p.enabled && planes.size() < size_t(kMaxUserPlanes)) planes.push_back(p.coefficients());
  return planes;
}

}  // namespace vplab::draw
