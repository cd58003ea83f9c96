// Meshes on the GPU, uploaded once per mesh (the scene's objects share their MC meshes): fan-
// triangulated faces with a normal per corner (the mesh's own, or the face normal for flat faces),
// and the unique edges, one pair of end points each (an instance of shaders/line.vert).
#pragma once

#include "app/gl/objects.h"
#include "pipeline/mesh.h"

#include <memory>
#include <unordered_map>

namespace vplab {

struct GpuMesh {
  gl::VertexArray faces;     // location 0: MC position, 1: MC normal
  gl::Buffer faceVertices, faceIndices;
  GLsizei faceIndexCount = 0;
  gl::VertexArray edges;     // per instance: location 0, 2: the MC end points (1, 3, the colours, are set constant)
  gl::Buffer edgeEnds;
  GLsizei edgeCount = 0;
};

class GpuMeshCache {
 public:
  explicit GpuMeshCache(const GladGLContext& gl) : gl_(&gl) {}
  /// The GPU copy of `mesh`, uploaded on first use.
  const GpuMesh& get(const std::shared_ptr<const Mesh>& mesh);
  /// Drops the GPU copies of meshes nobody else holds any more.
  void collect();

 private:
  struct Entry {
    std::weak_ptr<const Mesh> mesh;
    GpuMesh gpu;
  };
  const GladGLContext* gl_;
  std::unordered_map<const Mesh*, Entry> entries_;
};

}  // namespace vplab
