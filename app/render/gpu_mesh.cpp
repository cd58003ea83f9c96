#include "app/render/gpu_mesh.h"

#include <glm/glm.hpp>

#include <vector>

namespace vplab {

namespace {

GpuMesh upload(const GladGLContext& gl, const Mesh& mesh) {
  // One GPU vertex per face corner: a corner's normal depends on its face for flat polyhedra.
  std::vector<glm::vec3> corners;  // position, normal, position, normal, …
  corners.reserve(mesh.indices.size() * 2);
  std::vector<uint32_t> triangles;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto face = mesh.face(f);
    const glm::vec3 flat(glm::normalize(faceNormal(mesh, f)));
    const uint32_t first = uint32_t(corners.size() / 2);
    for (size_t k = 0; k < face.size(); ++k) {
      corners.emplace_back(mesh.positions[face[k]]);
      const size_t corner = mesh.faceStart[f] + k;
      corners.push_back(mesh.cornerNormals.empty() ? flat : glm::vec3(mesh.cornerNormals[corner]));
    }
    for (uint32_t k = 1; k + 1 < face.size(); ++k) triangles.insert(triangles.end(), {first, first + k, first + k + 1});
  }

  GpuMesh g;
  g.faces = gl::makeVertexArray(gl);
  g.faceVertices = gl::makeBuffer(gl);
  g.faceIndices = gl::makeBuffer(gl);
  gl.BindVertexArray(g.faces.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, g.faceVertices.id());
  gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(corners.size() * sizeof(glm::vec3)), corners.data(), GL_STATIC_DRAW);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec3), nullptr);
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec3), reinterpret_cast<void*>(sizeof(glm::vec3)));
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.faceIndices.id());
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(triangles.size() * sizeof(uint32_t)), triangles.data(), GL_STATIC_DRAW);
  g.faceIndexCount = GLsizei(triangles.size());

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
  return g;
}

}  // namespace

const GpuMesh& GpuMeshCache::get(const std::shared_ptr<const Mesh>& mesh) {
  auto it = entries_.find(mesh.get());
  if (it != entries_.end() && it->second.mesh.lock() == mesh) return it->second.gpu;
  Entry& e = entries_[mesh.get()];
  e.mesh = mesh;
  e.gpu = upload(*gl_, *mesh);
  return e.gpu;
}

void GpuMeshCache::collect() {
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (it->second.mesh.expired()) it = entries_.erase(it);
    else ++it;
  }
}

}  // namespace vplab
