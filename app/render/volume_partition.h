// The world view's volume passes (lecture notes 15.3; Hill 7.4 boundary coordinates): which faces of
// a mesh can have a fragment in the inside and in the outside pass, from the CPU run's homogeneous
// NPC. A face whose vertices all lie outside one plane of the volume has no fragment inside it; one
// whose vertices all lie inside every plane has none outside. Both by a margin far above the GPU's
// float rounding, so the fragment shader's own test would discard every fragment of a face left
// out: the picture is the same, and each pass draws about half the faces instead of all.
//
// A partition is made in steps (a page draws a million-triangle view in slices across frames): the
// vertices' sides a block at a time, then the faces of one GPU chunk (GpuMesh) at a time, each
// chunk's lists going to buffers of their own as soon as they are made.
#pragma once

#include "app/gl/objects.h"
#include "app/render/gpu_mesh.h"
#include "app/views/display_list.h"

#include <array>
#include <cstdint>
#include <vector>

namespace vplab {

class VolumePartitions {
 public:
  /// kInsideFaces: inside every plane (the inside pass draws them without its fragment test);
  /// kInsidePass: the other faces the inside pass must draw; kOutsidePass: those the outside pass must.
  enum List { kInsideFaces = 0, kInsidePass, kOutsidePass, kLists };
  /// One GPU chunk's lists: indices into the chunk's vertices, as its own triangles are.
  struct Chunk {
    std::array<gl::Buffer, kLists> indices;
    std::array<GLsizeiptr, kLists> capacity{};
    std::array<GLsizei, kLists> count{};
  };
  struct Part {
    uint64_t serial = 0;  // the draw it was made for (its slices share it)
    size_t instance = 0;  // the mesh instance of that draw's fills
    const ObjectRun* run = nullptr;
    std::vector<Chunk> chunks;  // complete for chunks [0, chunksDone)
    size_t verticesDone = 0, chunksDone = 0;
    double productMargin = 0;
    std::vector<uint8_t> sides;  // per vertex, while under way
    bool ready() const { return run && chunksDone == chunks.size() && verticesDone == sides.size(); }
    GLsizei count(List list) const;
  };

  explicit VolumePartitions(const GladGLContext& gl) : gl_(&gl) {}
  /// The partition of mesh instance `instance` in draw `serial`, continued by as much work as
  /// `triangles` pays for (taken off; none when it is 0); null when the instance is not partitioned
  /// (its run is not this mesh's: drawn whole). Not ready(): the budget ran out, ask again.
  const Part* get(uint64_t serial, size_t instance, const draw::MeshInstance& m, const Mat4& npcFromWc,
                  const GpuMesh& g, size_t& triangles);
  /// The triangles of instance `instance` in draw `serial`'s inside and outside pass ({0, 0}: none).
  std::array<size_t, 2> triangles(uint64_t serial, size_t instance) const;

 private:
  /// The draws kept per instance: slices of the three views' draws interleave, and each must find
  /// its own partition again (a shared one would be remade by every view in turn, for ever).
  static constexpr size_t kKeptPerInstance = 4;
  Part& partFor(uint64_t serial, size_t instance);
  void start(Part& part, const draw::MeshInstance& m, const Mat4& npcFromWc, const GpuMesh& g);
  /// One chunk's lists before their upload, as wide as its indices.
  struct ChunkLists {
    std::array<std::vector<uint16_t>, kLists> narrow;
    std::array<std::vector<uint32_t>, kLists> wide;
    std::array<size_t, kLists> count{};
  };
  /// The sides of vertices [begin, end): only theirs are written (blocks run on every core).
  static void sideVertices(Part& part, const ObjectRun& run, size_t begin, size_t end);
  /// A chunk's faces into its lists: reads only the part's sides (chunks run on every core).
  static void listChunk(const Part& part, const Mesh& mesh, const GpuMeshChunk& chunk, ChunkLists& out);
  void uploadChunk(const GpuMeshChunk& chunk, const ChunkLists& lists, Chunk& out);
  const GladGLContext* gl_;
  std::vector<Part> parts_;
  std::vector<ChunkLists> lists_;  // one a thread
};

}  // namespace vplab
