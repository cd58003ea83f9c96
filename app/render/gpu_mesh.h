// Meshes on the GPU, uploaded once per mesh (the scene's objects share their MC meshes): fan-
// triangulated faces with a normal per corner (the mesh's own, or the face normal for flat faces),
// and the unique edges, one pair of end points each (an instance of shaders/line.vert). The edges
// are uploaded only when a view first draws them (a shaded view never does): listing a million
// edges takes a tenth of the first upload of a large mesh.
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
  /// The GPU copy of `mesh`'s faces, uploaded on first use (the rest of it, when begun by upload).
  const GpuMesh& get(const std::shared_ptr<const Mesh>& mesh);
  /// Uploads about `triangles` more of `mesh`'s triangles (at least one face), taking them off
  /// `triangles`: a view drawn in slices (the page) uploads a large mesh across frames. The mesh
  /// once it is complete, else null.
  const GpuMesh* upload(const std::shared_ptr<const Mesh>& mesh, size_t& triangles);
  /// The same with its edges uploaded too.
  const GpuMesh& withEdges(const std::shared_ptr<const Mesh>& mesh);
  /// Drops the GPU copies of meshes nobody else holds any more.
  void collect();

 private:
  struct Entry {
    std::weak_ptr<const Mesh> mesh;
    GpuMesh gpu;
    bool edges = false;  // gpu.edges uploaded
    size_t faces = 0;      // the faces uploaded so far, in order
    size_t triangles = 0;  // ... and their triangles
  };
  Entry& entry(const std::shared_ptr<const Mesh>& mesh);
  const GladGLContext* gl_;
  std::unordered_map<const Mesh*, Entry> entries_;
};

}  // namespace vplab
