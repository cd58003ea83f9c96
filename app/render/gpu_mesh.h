// Meshes on the GPU, uploaded once per mesh (the scene's objects share their MC meshes): fan-
// triangulated faces with a normal per corner (the mesh's own, or the face normal for flat faces),
// and the unique edges, one pair of end points each (an instance of shaders/line.vert). The edges
// are uploaded only when a view first draws them (a shaded view never does): listing a million
// edges takes a tenth of the first upload of a large mesh. They go in chunks as the faces do.
//
// The faces go to the GPU in chunks of consecutive faces, each with buffers of its own of at most
// about chunkCorners() corners (corners of one vertex with one normal share a GPU vertex): a chunk is made at once with its data, so no frame makes (and
// WebGL clears) the 60 MB of a million triangles at once, and a page uploads a mesh a chunk at a time.
#pragma once

#include "app/gl/objects.h"
#include "pipeline/mesh.h"

#include <algorithm>
#include <memory>
#include <unordered_map>
#include <vector>

namespace vplab {

/// Faces [firstFace, endFace) of a mesh: the mesh's face corner firstCorner + i is GPU vertex
/// cornerVertex16 or 32[i]; corners of one mesh vertex with the same normal share theirs.
struct GpuMeshChunk {
  gl::VertexArray vao;  // location 0: MC position, 1: MC normal; its element buffer is `indices`
  gl::Buffer vertices, indices;
  size_t firstFace = 0, endFace = 0;
  uint32_t firstCorner = 0;
  uint32_t vertexCount = 0;            // GPU vertices (distinct position and normal pairs)
  /// 16-bit indices when its vertices allow (every chunk of at most 65 536 corners): half the bytes
  /// of its own index buffer and of the volume partition's lists; 32-bit for a larger face.
  GLenum indexType = GL_UNSIGNED_INT;
  size_t indexSize() const { return indexType == GL_UNSIGNED_SHORT ? 2 : 4; }
  // CPU: each corner's GPU vertex (the volume partition's lists), as wide as the indices: one of the
  // two is filled.
  std::vector<uint16_t> cornerVertex16;
  std::vector<uint32_t> cornerVertex32;
  size_t cornerMapBytes() const { return cornerVertex16.capacity() * 2 + cornerVertex32.capacity() * 4; }
  size_t bytes = 0;  // of its two buffers (on llvmpipe and SwiftShader, the process's memory)
};

/// Edges [first, first + count) of the mesh's unique edges (uniqueEdges), one instance each.
struct GpuEdgeChunk {
  gl::VertexArray vao;  // per instance: location 0, 2: the MC end points (1, 3, the colours, are set constant)
  gl::Buffer ends;
  GLsizei first = 0, count = 0;
  size_t bytes = 0;  // of its buffer
};
/// Points the chunk's instanced attributes at its edge `first` (0: its start). WebGL2 has no base
/// instance, so a draw of a part of a chunk moves the attributes' offsets instead.
void pointEdgesAt(const GladGLContext& gl, const GpuEdgeChunk& chunk, GLsizei first);

struct GpuMesh {
  std::vector<GpuMeshChunk> chunks;
  /// Chunk k's triangles are elements [indexStart[k], indexStart[k + 1]) of the mesh's triangle
  /// list (3 per triangle), at 0 in its own index buffer. One more entry than chunks.
  std::vector<GLsizei> indexStart{0};
  std::vector<GpuEdgeChunk> edgeChunks;  // consecutive, from edge 0 on
  GLsizei edgeCount = 0;                  // the mesh's unique edges (all chunks' once complete)
};

class GpuMeshCache {
 public:
  /// Chunks of about 65 536 corners: 1.5 MB of vertices, a few milliseconds to make in the page.
  static constexpr uint32_t kChunkCorners = 1u << 16;
  explicit GpuMeshCache(const GladGLContext& gl) : gl_(&gl) {}
  /// The GPU copy of `mesh`'s faces, uploaded on first use (the rest of it, when begun by upload).
  const GpuMesh& get(const std::shared_ptr<const Mesh>& mesh);
  /// Uploads chunks of `mesh` while their triangles fit in `triangles` (at least one), taking them
  /// off: a view drawn in slices (the page) uploads a large mesh across frames. The mesh once it is
  /// complete, else null.
  const GpuMesh* upload(const std::shared_ptr<const Mesh>& mesh, size_t& triangles);
  /// Uploads chunks of `mesh`'s edges (kChunkCorners / 2 edges each, charged two triangles an
  /// edge) while they fit in `triangles` (at least one): the mesh with all its edges, else null.
  /// Only the edges: the faces are uploaded by get or upload.
  const GpuMesh* uploadEdges(const std::shared_ptr<const Mesh>& mesh, size_t& triangles);
  /// The mesh with all its edges uploaded.
  const GpuMesh& withEdges(const std::shared_ptr<const Mesh>& mesh);
  /// Drops the GPU copies of meshes nobody else holds any more.
  void collect();
  /// The bytes of the buffers uploaded (faces; edges), over every mesh held.
  size_t faceBytes() const;
  size_t edgeBytes() const;
  /// The CPU bytes of the chunks' corner maps (GpuMeshChunk::cornerVertex16 or 32).
  size_t cornerMapBytes() const;
  /// The corners a chunk holds at most (unless one face has more); for tests of chunk boundaries.
  /// Meshes uploaded before keep their chunks.
  void setChunkCorners(uint32_t corners) { chunkCorners_ = std::max<uint32_t>(corners, 3); }
  uint32_t chunkCorners() const { return chunkCorners_; }
  /// The edges an edge chunk holds: the corners of a face chunk, two per edge.
  uint32_t chunkEdges() const { return std::max<uint32_t>(chunkCorners_ / 2, 1); }

 private:
  struct Entry {
    std::weak_ptr<const Mesh> mesh;
    GpuMesh gpu;
    bool edgesListed = false;  // gpu.edgeCount is known
    std::vector<Edge> edges;   // while its edges are uploaded: all of them (freed when complete)
  };
  Entry& entry(const std::shared_ptr<const Mesh>& mesh);
  const GladGLContext* gl_;
  uint32_t chunkCorners_ = kChunkCorners;
  std::vector<uint32_t> slotOf_;  // while a mesh is uploaded: makeChunk's GPU vertex of each mesh vertex
  std::unordered_map<const Mesh*, Entry> entries_;
};

}  // namespace vplab
