#include "app/render/gpu_mesh.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <limits>
#include <vector>

namespace vplab {

namespace {

size_t trianglesOf(const Mesh& mesh, size_t f) {
  const size_t n = mesh.faceStart[f + 1] - mesh.faceStart[f];
  return n >= 3 ? n - 2 : 0;
}

// Faces [first, end) as a chunk of their own: one GPU vertex per distinct (mesh vertex, normal) pair
// of its corners, fan triangles. A smooth mesh's corners of one vertex share its normal (a sphere's
// 2.1 M corners are 0.52 M vertices: 50 → 12.6 MB of floats); a flat polyhedron's corners have their
// face's normal, so its corners stay apart. A corner whose vertex last got another normal gets a GPU
// vertex of its own (`slotOf` keeps one per mesh vertex): exact, at most one vertex per corner.
GpuMeshChunk makeChunk(const GladGLContext& gl, const Mesh& mesh, size_t first, size_t end,
                       std::vector<uint32_t>& slotOf) {
  constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  GpuMeshChunk chunk;
  chunk.firstFace = first;
  chunk.endFace = end;
  chunk.firstCorner = mesh.faceStart[first];
  const size_t cornerCount = mesh.faceStart[end] - chunk.firstCorner;
  if (slotOf.size() < mesh.positions.size()) slotOf.assign(mesh.positions.size(), kNone);  // all kNone between chunks
  std::vector<uint32_t> cornerVertex(cornerCount);
  std::vector<glm::vec3> vertices;  // position, normal, position, normal, …
  vertices.reserve(cornerCount * 2);
  std::vector<uint32_t> triangles;
  for (size_t f = first; f < end; ++f) {
    const auto face = mesh.face(f);
    const glm::vec3 flat(glm::normalize(faceNormal(mesh, f)));
    const uint32_t corner0 = mesh.faceStart[f];
    const uint32_t local = corner0 - chunk.firstCorner;
    for (size_t k = 0; k < face.size(); ++k) {
      const glm::vec3 normal = mesh.smooth() ? glm::vec3(mesh.cornerNormal(corner0 + k)) : flat;
      uint32_t& slot = slotOf[face[k]];
      if (slot == kNone || vertices[2 * size_t(slot) + 1] != normal) {
        slot = uint32_t(vertices.size() / 2);
        vertices.emplace_back(mesh.positions[face[k]]);
        vertices.push_back(normal);
      }
      cornerVertex[local + k] = slot;
    }
    for (uint32_t k = 1; k + 1 < face.size(); ++k)
      triangles.insert(triangles.end(), {cornerVertex[local], cornerVertex[local + k], cornerVertex[local + k + 1]});
  }
  for (size_t c = chunk.firstCorner; c < mesh.faceStart[end]; ++c) slotOf[mesh.indices[c]] = kNone;
  chunk.vao = gl::makeVertexArray(gl);
  chunk.vertices = gl::makeBuffer(gl);
  chunk.indices = gl::makeBuffer(gl);
  gl.BindVertexArray(chunk.vao.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, chunk.vertices.id());
  gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(glm::vec3)), vertices.data(), GL_STATIC_DRAW);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec3), nullptr);
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec3), reinterpret_cast<void*>(sizeof(glm::vec3)));
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, chunk.indices.id());
  chunk.vertexCount = uint32_t(vertices.size() / 2);
  if (chunk.vertexCount <= 65536) {
    chunk.indexType = GL_UNSIGNED_SHORT;
    const std::vector<uint16_t> shorter(triangles.begin(), triangles.end());
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(shorter.size() * sizeof(uint16_t)), shorter.data(), GL_STATIC_DRAW);
    chunk.cornerVertex16.assign(cornerVertex.begin(), cornerVertex.end());
  } else {
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(triangles.size() * sizeof(uint32_t)), triangles.data(), GL_STATIC_DRAW);
    chunk.cornerVertex32 = std::move(cornerVertex);
  }
  chunk.bytes = vertices.size() * sizeof(glm::vec3) + triangles.size() * chunk.indexSize();
  gl.BindVertexArray(0);
  gl.BindBuffer(GL_ARRAY_BUFFER, 0);
  return chunk;
}

GpuEdgeChunk makeEdgeChunk(const GladGLContext& gl, const Mesh& mesh, const std::vector<Edge>& edges, size_t first,
                           size_t end) {
  // The end points of each edge side by side: instanced attributes cannot go through an index buffer.
  std::vector<glm::vec3> ends;
  ends.reserve(2 * (end - first));
  for (size_t i = first; i < end; ++i)
    ends.insert(ends.end(), {glm::vec3(mesh.positions[edges[i].a]), glm::vec3(mesh.positions[edges[i].b])});
  GpuEdgeChunk chunk;
  chunk.first = GLsizei(first);
  chunk.count = GLsizei(end - first);
  chunk.vao = gl::makeVertexArray(gl);
  chunk.ends = gl::makeBuffer(gl);
  gl.BindVertexArray(chunk.vao.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, chunk.ends.id());
  gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(ends.size() * sizeof(glm::vec3)), ends.data(), GL_STATIC_DRAW);
  chunk.bytes = ends.size() * sizeof(glm::vec3);
  gl.BindVertexArray(0);
  pointEdgesAt(gl, chunk, 0);
  return chunk;
}

}  // namespace

void pointEdgesAt(const GladGLContext& gl, const GpuEdgeChunk& chunk, GLsizei first) {
  gl.BindVertexArray(chunk.vao.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, chunk.ends.id());
  for (GLuint end = 0; end < 2; ++end) {
    const size_t offset = (2 * size_t(first) + end) * sizeof(glm::vec3);
    gl.EnableVertexAttribArray(2 * end);
    gl.VertexAttribPointer(2 * end, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec3), reinterpret_cast<void*>(offset));
    gl.VertexAttribDivisor(2 * end, 1);
  }
  gl.BindVertexArray(0);
  gl.BindBuffer(GL_ARRAY_BUFFER, 0);
}

GpuMeshCache::Entry& GpuMeshCache::entry(const std::shared_ptr<const Mesh>& mesh) {
  auto it = entries_.find(mesh.get());
  if (it != entries_.end() && it->second.mesh.lock() == mesh) return it->second;
  Entry& e = entries_[mesh.get()];
  e = Entry{};
  e.mesh = mesh;
  return e;
}

const GpuMesh* GpuMeshCache::upload(const std::shared_ptr<const Mesh>& mesh, size_t& triangles) {
  GpuMesh& g = entry(mesh).gpu;
  const size_t faces = mesh->faceCount();
  size_t next = g.chunks.empty() ? 0 : g.chunks.back().endFace;
  for (bool first = true; next < faces; first = false) {
    // The chunk's faces: at least one, then while the corners fit.
    size_t end = next, now = 0;
    const uint32_t corner0 = mesh->faceStart[next];
    do now += trianglesOf(*mesh, end++);
    while (end < faces && mesh->faceStart[end + 1] - corner0 <= chunkCorners_);
    if (!first && now > triangles) break;
    g.chunks.push_back(makeChunk(*gl_, *mesh, next, end, slotOf_));
    g.indexStart.push_back(g.indexStart.back() + GLsizei(3 * now));
    triangles -= std::min(triangles, now);
    next = end;
  }
  if (next < faces) return nullptr;
  std::vector<uint32_t>().swap(slotOf_);
  return &g;
}

const GpuMesh& GpuMeshCache::get(const std::shared_ptr<const Mesh>& mesh) {
  size_t all = std::numeric_limits<size_t>::max();
  return *upload(mesh, all);
}

const GpuMesh* GpuMeshCache::uploadEdges(const std::shared_ptr<const Mesh>& mesh, size_t& triangles) {
  Entry& e = entry(mesh);
  GpuMesh& g = e.gpu;
  if (!e.edgesListed) {
    e.edges = uniqueEdges(*mesh);
    e.edgesListed = true;
    g.edgeCount = GLsizei(e.edges.size());
  }
  const size_t all = size_t(g.edgeCount), per = chunkEdges();
  size_t next = g.edgeChunks.empty() ? 0 : size_t(g.edgeChunks.back().first + g.edgeChunks.back().count);
  for (bool first = true; next < all; first = false) {
    const size_t end = std::min(all, next + per);
    if (!first && 2 * (end - next) > triangles) break;
    g.edgeChunks.push_back(makeEdgeChunk(*gl_, *mesh, e.edges, next, end));
    triangles -= std::min(triangles, 2 * (end - next));
    next = end;
  }
  if (next < all) return nullptr;
  std::vector<Edge>().swap(e.edges);
  return &g;
}

const GpuMesh& GpuMeshCache::withEdges(const std::shared_ptr<const Mesh>& mesh) {
  size_t all = std::numeric_limits<size_t>::max();
  return *uploadEdges(mesh, all);
}

void GpuMeshCache::collect() {
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (it->second.mesh.expired()) it = entries_.erase(it);
    else ++it;
  }
}

size_t GpuMeshCache::faceBytes() const {
  size_t sum = 0;
  for (const auto& [mesh, e] : entries_)
    for (const GpuMeshChunk& c : e.gpu.chunks) sum += c.bytes;
  return sum;
}

size_t GpuMeshCache::cornerMapBytes() const {
  size_t sum = 0;
  for (const auto& [mesh, e] : entries_)
    for (const GpuMeshChunk& c : e.gpu.chunks) sum += c.cornerMapBytes();
  return sum;
}

size_t GpuMeshCache::edgeBytes() const {
  size_t sum = 0;
  for (const auto& [mesh, e] : entries_)
    for (const GpuEdgeChunk& c : e.gpu.edgeChunks) sum += c.bytes;
  return sum;
}

}  // namespace vplab
