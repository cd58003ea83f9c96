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

// The buffers at their full size, empty, with the attributes: uploadFaces fills them.
GpuMesh makeBuffers(const GladGLContext& gl, const Mesh& mesh) {
  size_t triangles = 0;
  for (size_t f = 0; f < mesh.faceCount(); ++f) triangles += trianglesOf(mesh, f);
  GpuMesh g;
  g.faces = gl::makeVertexArray(gl);
  g.faceVertices = gl::makeBuffer(gl);
  g.faceIndices = gl::makeBuffer(gl);
  gl.BindVertexArray(g.faces.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, g.faceVertices.id());
  gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * 2 * sizeof(glm::vec3)), nullptr, GL_STATIC_DRAW);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec3), nullptr);
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec3), reinterpret_cast<void*>(sizeof(glm::vec3)));
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.faceIndices.id());
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(3 * triangles * sizeof(uint32_t)), nullptr, GL_STATIC_DRAW);
  g.faceIndexCount = GLsizei(3 * triangles);
  gl.BindVertexArray(0);
  return g;
}

// Faces [first, end) into the buffers: one GPU vertex per face corner (a corner's normal depends on
// its face for flat polyhedra), fan triangles. `triangle` is the first face's first triangle.
void uploadFaces(const GladGLContext& gl, const Mesh& mesh, const GpuMesh& g, size_t first, size_t end, size_t triangle) {
  std::vector<glm::vec3> corners;  // position, normal, position, normal, …
  corners.reserve(size_t(mesh.faceStart[end] - mesh.faceStart[first]) * 2);
  std::vector<uint32_t> triangles;
  for (size_t f = first; f < end; ++f) {
    const auto face = mesh.face(f);
    const glm::vec3 flat(glm::normalize(faceNormal(mesh, f)));
    const uint32_t corner0 = mesh.faceStart[f];
    for (size_t k = 0; k < face.size(); ++k) {
      corners.emplace_back(mesh.positions[face[k]]);
      corners.push_back(mesh.cornerNormals.empty() ? flat : glm::vec3(mesh.cornerNormals[corner0 + k]));
    }
    for (uint32_t k = 1; k + 1 < face.size(); ++k) triangles.insert(triangles.end(), {corner0, corner0 + k, corner0 + k + 1});
  }
  gl.BindVertexArray(g.faces.id());  // WebGL binds an index buffer to no other target than its VAO's
  gl.BindBuffer(GL_ARRAY_BUFFER, g.faceVertices.id());
  gl.BufferSubData(GL_ARRAY_BUFFER, GLintptr(size_t(mesh.faceStart[first]) * 2 * sizeof(glm::vec3)),
                   GLsizeiptr(corners.size() * sizeof(glm::vec3)), corners.data());
  gl.BufferSubData(GL_ELEMENT_ARRAY_BUFFER, GLintptr(3 * triangle * sizeof(uint32_t)),
                   GLsizeiptr(triangles.size() * sizeof(uint32_t)), triangles.data());
  gl.BindVertexArray(0);
}

void uploadEdges(const GladGLContext& gl, const Mesh& mesh, GpuMesh& g) {
  // The end points of each edge side by side: instanced attributes cannot go through an index buffer.
  std::vector<glm::vec3> ends;
  for (const Edge& e : uniqueEdges(mesh)) ends.insert(ends.end(), {glm::vec3(mesh.positions[e.a]), glm::vec3(mesh.positions[e.b])});
  g.edges = gl::makeVertexArray(gl);
  g.edgeEnds = gl::makeBuffer(gl);
  gl.BindVertexArray(g.edges.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, g.edgeEnds.id());
  gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(ends.size() * sizeof(glm::vec3)), ends.data(), GL_STATIC_DRAW);
  for (GLuint end = 0; end < 2; ++end) {
    gl.EnableVertexAttribArray(2 * end);
    gl.VertexAttribPointer(2 * end, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec3), reinterpret_cast<void*>(end * sizeof(glm::vec3)));
    gl.VertexAttribDivisor(2 * end, 1);
  }
  g.edgeCount = GLsizei(ends.size() / 2);
  gl.BindVertexArray(0);
}

}  // namespace

GpuMeshCache::Entry& GpuMeshCache::entry(const std::shared_ptr<const Mesh>& mesh) {
  auto it = entries_.find(mesh.get());
  if (it != entries_.end() && it->second.mesh.lock() == mesh) return it->second;
  Entry& e = entries_[mesh.get()];
  e = Entry{};
  e.mesh = mesh;
  e.gpu = makeBuffers(*gl_, *mesh);
  return e;
}

const GpuMesh* GpuMeshCache::upload(const std::shared_ptr<const Mesh>& mesh, size_t& triangles) {
  Entry& e = entry(mesh);
  const size_t faces = mesh->faceCount();
  if (e.faces < faces) {
    // At least one face, so that every call makes progress; then as many as the budget holds.
    size_t end = e.faces, now = 0;
    do now += trianglesOf(*mesh, end++);
    while (end < faces && now + trianglesOf(*mesh, end) <= triangles);
    uploadFaces(*gl_, *mesh, e.gpu, e.faces, end, e.triangles);
    e.faces = end;
    e.triangles += now;
    triangles -= std::min(triangles, now);
  }
  return e.faces == faces ? &e.gpu : nullptr;
}

const GpuMesh& GpuMeshCache::get(const std::shared_ptr<const Mesh>& mesh) {
  size_t all = std::numeric_limits<size_t>::max();
  return *upload(mesh, all);
}

const GpuMesh& GpuMeshCache::withEdges(const std::shared_ptr<const Mesh>& mesh) {
  Entry& e = entry(mesh);
  if (!e.edges) {
    uploadEdges(*gl_, *mesh, e.gpu);
    e.edges = true;
  }
  return e.gpu;
}

void GpuMeshCache::collect() {
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (it->second.mesh.expired()) it = entries_.erase(it);
    else ++it;
  }
}

}  // namespace vplab
