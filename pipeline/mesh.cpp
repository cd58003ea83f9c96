#include "pipeline/mesh.h"

#include "pipeline/error.h"

#include <algorithm>
#include <string>
#include <unordered_set>

namespace vplab {

size_t Mesh::maxFaceSize() const {
  size_t m = 0;
  for (size_t f = 0; f < faceCount(); ++f) m = std::max<size_t>(m, faceStart[f + 1] - faceStart[f]);
  return m;
}

void Mesh::addFace(std::initializer_list<uint32_t> face) {
  addFace(std::span<const uint32_t>(face.begin(), face.size()));
}

void Mesh::addFace(std::span<const uint32_t> face) {
  indices.insert(indices.end(), face.begin(), face.end());
  faceStart.push_back(uint32_t(indices.size()));
}

Vec3 faceNormal(const Mesh& mesh, size_t f) {
  const auto face = mesh.face(f);
  Vec3 n{0};
  for (size_t i = 0; i < face.size(); ++i) {
    const Vec3& p = mesh.positions[face[i]];
    const Vec3& q = mesh.positions[face[(i + 1) % face.size()]];
    n += Vec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
  }
  return n;
}

std::array<Vec3, 8> Bounds::corners() const {
  std::array<Vec3, 8> c;
  for (int i = 0; i < 8; ++i)
    c[i] = Vec3(i & 1 ? max.x : min.x, i & 2 ? max.y : min.y, i & 4 ? max.z : min.z);
  return c;
}

Bounds bounds(const Mesh& mesh) {
  if (mesh.positions.empty()) return {};
  Bounds b{mesh.positions[0], mesh.positions[0]};
  for (const Vec3& p : mesh.positions) {
    b.min = glm::min(b.min, p);
    b.max = glm::max(b.max, p);
  }
  return b;
}

std::vector<Edge> uniqueEdges(const Mesh& mesh) {
  std::vector<Edge> edges;
  std::unordered_set<uint64_t> seen;
  seen.reserve(mesh.indices.size());
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto face = mesh.face(f);
    for (size_t i = 0; i < face.size(); ++i) {
      uint32_t a = face[i], b = face[(i + 1) % face.size()];
      if (a == b) continue;
      if (a > b) std::swap(a, b);
      if (seen.insert(uint64_t(a) << 32 | b).second) edges.push_back({a, b});
    }
  }
  return edges;
}

Mesh triangulated(const Mesh& mesh) {
  Mesh out;
  out.positions = mesh.positions;
  const bool smooth = !mesh.cornerNormals.empty();
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto face = mesh.face(f);
    const uint32_t first = mesh.faceStart[f];
    for (size_t i = 1; i + 1 < face.size(); ++i) {
      out.addFace({face[0], face[i], face[i + 1]});
      if (smooth)
        for (size_t k : {size_t(0), i, i + 1}) out.cornerNormals.push_back(mesh.cornerNormals[first + k]);
    }
  }
  return out;
}

}  // namespace vplab
