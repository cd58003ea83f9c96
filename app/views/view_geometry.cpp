#include "app/views/view_geometry.h"

#include "app/text/catalogue.h"
#include "app/views/theme.h"

namespace vplab::geometry {

Vec3 wcOfNpc(const Mat4& wcFromNpc, const Vec3& npc) {
  const Vec4 p = wcFromNpc * Vec4(npc, 1.0);
  return Vec3(p) / p.w;
}

std::array<Vec3, 8> viewVolumeCorners(const Mat4& wcFromNpc) {
  std::array<Vec3, 8> c;
  for (int i = 0; i < 8; ++i) c[size_t(i)] = wcOfNpc(wcFromNpc, cubeCorner(i));
  return c;
}

std::array<int, 4> cubeFaceRing(int plane) {
  const int axisBit = 1 << (plane / 2), side = plane % 2 ? axisBit : 0;
  std::array<int, 4> ring{};
  size_t k = 0;
  for (int i = 0; i < 8; ++i)
    if ((i & axisBit) == side) ring[k++] = i;
  std::swap(ring[2], ring[3]);  // (0, 1, 2, 3) in index order → around the face
  return ring;
}

std::array<Vec3, 4> clipPlaneSquare(const UserClipPlane& plane, double halfSize) {
  const Vec3 n = glm::normalize(plane.normal);
  const Vec3 a = glm::normalize(glm::cross(n, std::abs(n.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0)));
  const Vec3 b = glm::cross(n, a);
  const Vec3& p = plane.point;
  return {p + (a + b) * halfSize, p + (a - b) * halfSize, p - (a + b) * halfSize, p + (b - a) * halfSize};
}

double clipPlaneSquareSize(const Camera& camera) {
  return 0.6 * std::max(camera.window.width(), camera.window.height());
}

std::vector<Vec3> fadedNpcPolygon(const ObjectRun& o, size_t f, ClipScratch& scratch) {
  std::vector<Vec3> out;
  fadedNpcPolygon(o, f, scratch, out);
  return out;
}

Boundary grownBoundary(const Vec4& p, double m) {
  return {p.x + m * p.w, (1 + m) * p.w - p.x, p.y + m * p.w, (1 + m) * p.w - p.y, p.z + m * p.w, (1 + m) * p.w - p.z};
}

bool fadedFaceWhole(const ObjectRun& o, size_t f) {
  // Sutherland–Hodgman would keep every vertex of such a face as it is, so its faded polygon is the
  // face divided by w, without the clipper's copies.
  const auto face = o.mesh->face(f);
  bool inside = face.size() >= 3;
  for (size_t k = 0; inside && k < face.size(); ++k) {
    const Vec4& p = o.npcH[face[k]];
    inside = p.w > 1e-12;
    for (double bc : grownBoundary(p, kFadedMargin)) inside = inside && bc >= 0;
  }
  return inside;
}

void fadedNpcPolygon(const ObjectRun& o, size_t f, ClipScratch& scratch, std::vector<Vec3>& out) {
  const auto face = o.mesh->face(f);
  out.clear();
  if (fadedFaceWhole(o, f)) {  // most of them
    for (uint32_t v : face) out.push_back(o.clippedNpc(v));
    return;
  }
  constexpr double m = kFadedMargin;
  scratch.a.clear();
  for (uint32_t v : face) scratch.a.push_back({o.npcH[v], clipValues(grownBoundary(o.npcH[v], m)), v});
  for (const ClipVertex& c : clipPolygon(0x3f /* the six grown cube planes */, scratch))
    if (c.p.w > 1e-12) out.push_back(Vec3(c.p) / c.p.w);
}

std::vector<NamedPoint> polygonVertexNames(const Scene& scene) {
  std::vector<const SceneObject*> polygons;
  for (const SceneObject& o : scene.objects)
    if (o.visible && o.shape == Shape::polygon) polygons.push_back(&o);
  std::vector<NamedPoint> out;
  for (const SceneObject* o : polygons) {
    const Mat4 m = wcFromMc(o->transform);
    const std::string prefix = polygons.size() > 1 ? o->name + "." : "";
    for (size_t i = 0; i < o->vertices.size(); ++i)
      out.push_back({transformAffine(m, o->vertices[i]), prefix + "P" + std::to_string(i + 1),
                     glm::vec4(glm::vec3(o->color), 1.f)});
  }
  return out;
}

std::vector<AnchoredLabel> npcCubeLabels(const theme::Palette& pal, Language lang) {
  const double len = kNpcAxisLength;
  // The axes' names first, the faces' next, the ticks last (they give way when the view is small).
  return {{{len + 0.07, 0, 0}, "x", pal.u, {}, 2},
          {{0, len + 0.07, 0}, "y", pal.v, {}, 2},
          {{0, 0, len + 0.07}, "z", pal.n, {}, 2},
          {{-0.06, -0.06, -0.06}, "0", pal.text},
          {{1, -0.07, 0}, "1", pal.u},
          {{-0.07, 1, 0}, "1", pal.v},
          {{-0.07, -0.07, 1}, "1", pal.n},
          {{0.5, 1.08, 1}, text::Text("front z = 1").in(lang), pal.frustum, "z = 1", 1},
          {{0.5, 1.08, 0}, text::Text("back z = 0").in(lang), pal.frustum, "z = 0", 1}};
}

}  // namespace vplab::geometry
