#include "pipeline/mesh.h"

#include "pipeline/error.h"

#include <algorithm>
#include <string>

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

// Without hashing (a hash set of a million edges took a quarter of a second): each face side goes
// into the bucket of its smaller vertex (a counting sort), a side is new when no earlier side in its
// bucket has the same other end, and the new ones are listed in the order the faces give them. A
// bucket is searched by hand while small (a vertex has few neighbours) and sorted when large (a fan
// of many faces around one vertex, which a hostile file may hold): linear in the corners.
std::vector<Edge> uniqueEdges(const Mesh& mesh) {
  const size_t corners = mesh.indices.size();
  const size_t vertices = mesh.positions.size();
  // Side j of the mesh: from corner j to the next corner of its face (a, b with a < b).
  auto side = [&](size_t f, size_t k, uint32_t& a, uint32_t& b) {
    const auto face = mesh.face(f);
    a = face[k];
    b = face[(k + 1) % face.size()];
    if (a > b) std::swap(a, b);
    return a != b && a < vertices;
  };
  std::vector<uint32_t> start(vertices + 1, 0);
  for (size_t f = 0; f < mesh.faceCount(); ++f)
    for (size_t k = 0; k < mesh.faceStart[f + 1] - mesh.faceStart[f]; ++k) {
      uint32_t a, b;
      if (side(f, k, a, b)) ++start[a + 1];
    }
  for (size_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  struct Entry {
    uint32_t b, side;
  };
  std::vector<Entry> bucket(start[vertices]);
  {
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t f = 0; f < mesh.faceCount(); ++f)
      for (size_t k = 0; k < mesh.faceStart[f + 1] - mesh.faceStart[f]; ++k) {
        uint32_t a, b;
        if (side(f, k, a, b)) bucket[fill[a]++] = {b, uint32_t(mesh.faceStart[f] + k)};
      }
  }
  std::vector<uint8_t> first(corners, 0);
  constexpr uint32_t kSmallBucket = 16;
  for (size_t v = 0; v < vertices; ++v) {
    Entry* begin = bucket.data() + start[v];
    Entry* end = bucket.data() + start[v + 1];
    if (end - begin <= kSmallBucket) {
      for (Entry* e = begin; e != end; ++e) {  // in side order: the counting sort kept it
        bool seen = false;
        for (Entry* d = begin; d != e && !seen; ++d) seen = d->b == e->b;
        first[e->side] = !seen;
      }
    } else {
      std::sort(begin, end, [](const Entry& x, const Entry& y) { return x.b != y.b ? x.b < y.b : x.side < y.side; });
      for (Entry* e = begin; e != end; ++e) first[e->side] = e == begin || e[-1].b != e->b;
    }
  }
  std::vector<Edge> edges;
  for (size_t f = 0; f < mesh.faceCount(); ++f)
    for (size_t k = 0; k < mesh.faceStart[f + 1] - mesh.faceStart[f]; ++k) {
      uint32_t a, b;
      if (first[mesh.faceStart[f] + k] && side(f, k, a, b)) edges.push_back({a, b});
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
