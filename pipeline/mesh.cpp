#include "pipeline/mesh.h"

#include <limits>

#include "base/error.h"

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
  UniqueEdgesJob job(mesh);
  job.step(UINT64_MAX);
  return job.take();
}

// Side k of face f: from its corner k to the next corner (a, b with a < b); false for a degenerate one.
bool UniqueEdgesJob::side(size_t f, size_t k, uint32_t& a, uint32_t& b) const {
  const auto face = mesh_->face(f);
  a = face[k];
  b = face[(k + 1) % face.size()];
  if (a > b) std::swap(a, b);
  return a != b && a < mesh_->positions.size();
}

bool UniqueEdgesJob::step(uint64_t budget) {
  const Mesh& mesh = *mesh_;
  const size_t vertices = mesh.positions.size(), faces = mesh.faceCount();
  // Runs `body` over each side of the pass's faces from next_ while the budget lasts; true when the
  // pass is through.
  auto overFaces = [&](auto body) {
    for (; next_ < faces && budget > 0; ++next_) {
      const size_t n = mesh.faceStart[next_ + 1] - mesh.faceStart[next_];
      for (size_t k = 0; k < n; ++k) body(next_, k);
      budget -= std::min<uint64_t>(budget, std::max<size_t>(n, 1));
    }
    return next_ == faces;
  };
  for (;;) {
    auto nextPass = [&] {
      ++pass_;
      next_ = 0;
    };
    switch (pass_) {
      case 0:  // count the sides of each bucket
        if (start_.empty()) start_.assign(vertices + 1, 0);
        if (!overFaces([&](size_t f, size_t k) {
              uint32_t a, b;
              if (side(f, k, a, b)) ++start_[a + 1];
            }))
          return false;
        nextPass();
        break;
      case 1: {  // the buckets' starts
        const size_t end = next_ + size_t(std::min<uint64_t>(budget, vertices - next_));
        budget -= end - next_;
        for (; next_ < end; ++next_) start_[next_ + 1] += start_[next_];
        if (next_ < vertices) return false;
        bucket_.resize(start_[vertices]);
        fill_.assign(start_.begin(), start_.end() - 1);
        nextPass();
        break;
      }
      case 2:  // each side into its bucket, in side order
        if (!overFaces([&](size_t f, size_t k) {
              uint32_t a, b;
              if (side(f, k, a, b)) bucket_[fill_[a]++] = {b, uint32_t(mesh.faceStart[f] + k)};
            }))
          return false;
        std::vector<uint32_t>().swap(fill_);
        first_.assign(mesh.indices.size(), 0);
        nextPass();
        break;
      case 3: {  // in each bucket, the first side of each edge
        constexpr uint32_t kSmallBucket = 16;
        const size_t end = next_ + size_t(std::min<uint64_t>(budget, vertices - next_));
        budget -= end - next_;
        for (; next_ < end; ++next_) {
          Entry* begin = bucket_.data() + start_[next_];
          Entry* last = bucket_.data() + start_[next_ + 1];
          if (last - begin <= kSmallBucket) {
            for (Entry* e = begin; e != last; ++e) {  // in side order: the counting sort kept it
              bool seen = false;
              for (Entry* d = begin; d != e && !seen; ++d) seen = d->b == e->b;
              first_[e->side] = !seen;
            }
          } else {
            std::sort(begin, last, [](const Entry& x, const Entry& y) { return x.b != y.b ? x.b < y.b : x.side < y.side; });
            for (Entry* e = begin; e != last; ++e) first_[e->side] = e == begin || e[-1].b != e->b;
          }
        }
        if (next_ < vertices) return false;
        std::vector<Entry>().swap(bucket_);
        std::vector<uint32_t>().swap(start_);
        nextPass();
        break;
      }
      case 4:  // the marked sides in face order
        if (!overFaces([&](size_t f, size_t k) {
              uint32_t a, b;
              if (first_[mesh.faceStart[f] + k] && side(f, k, a, b)) edges_.push_back({a, b});
            }))
          return false;
        std::vector<uint8_t>().swap(first_);
        nextPass();
        break;
      default: return true;
    }
  }
}

FaceCluster faceCluster(const Mesh& mesh, size_t c, std::vector<uint32_t>& v) {
  // Vertices up to kJoin apart are joined into one interval: the few between cost less to read than
  // an interval more. A cluster whose intervals together are over kMostRead times its corners is read
  // face by face instead (reading the intervals would cost more than the faces' own outcodes).
  constexpr uint32_t kJoin = 16, kMostRead = 8;
  const size_t f0 = c * FaceCluster::kFaces, f1 = std::min(mesh.faceCount(), f0 + FaceCluster::kFaces);
  v.assign(mesh.indices.begin() + mesh.faceStart[f0], mesh.indices.begin() + mesh.faceStart[f1]);
  if (v.empty()) return {};
  std::sort(v.begin(), v.end());
  FaceCluster k;
  uint64_t read = 0;
  uint32_t first = v.front(), last = v.front();
  auto close = [&] {
    if (k.runs == FaceCluster::kRuns) return false;
    k.first[k.runs] = first;
    k.last[k.runs] = last;
    ++k.runs;
    read += uint64_t(last - first) + 1;
    return true;
  };
  for (uint32_t x : v) {
    if (x - last <= kJoin) {
      last = x;
      continue;
    }
    if (!close()) return {};
    first = last = x;
  }
  if (!close() || read > uint64_t(kMostRead) * v.size()) return {};
  return k;
}

Mesh triangulated(const Mesh& mesh) {
  Mesh out;
  out.positions = mesh.positions;
  out.normals = mesh.normals;  // one a vertex stays valid: the triangles' corners are the same vertices
  const bool indexed = !mesh.normalIndices.empty();
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto face = mesh.face(f);
    const uint32_t first = mesh.faceStart[f];
    for (size_t i = 1; i + 1 < face.size(); ++i) {
      out.addFace({face[0], face[i], face[i + 1]});
      if (indexed)
        for (size_t k : {size_t(0), i, i + 1}) out.normalIndices.push_back(mesh.normalIndices[first + k]);
    }
  }
  return out;
}

void normalPerVertexWherePossible(Mesh& mesh) {
  if (mesh.normalIndices.empty() || mesh.normalIndices.size() != mesh.indices.size()) return;
  constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> normalOf(mesh.positions.size(), kNone);
  for (size_t c = 0; c < mesh.indices.size(); ++c) {
    uint32_t& n = normalOf[mesh.indices[c]];
    if (n != kNone && n != mesh.normalIndices[c]) return;  // two normals at one vertex: indexed it stays
    n = mesh.normalIndices[c];
  }
  std::vector<Vec3> perVertex(mesh.positions.size(), Vec3(0, 0, 1));
  for (size_t v = 0; v < perVertex.size(); ++v)
    if (normalOf[v] != kNone) perVertex[v] = mesh.normals[normalOf[v]];
  mesh.normals = std::move(perVertex);
  std::vector<uint32_t>().swap(mesh.normalIndices);
}

}  // namespace vplab
