// A polygon mesh in MC (lecture notes chapter 16): a vertex list and faces that index it, each face
// counter-clockwise seen from outside. Faces share vertices, so the pipeline transforms each vertex
// and computes its outcode once, whatever the number of faces using it (Hill 7.4).
#pragma once

#include "pipeline/math.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace vplab {

struct Mesh {
  std::vector<Vec3> positions;       // MC
  std::vector<uint32_t> indices;     // every face's vertex indices, concatenated
  std::vector<uint32_t> faceStart{0};  // face f is indices[faceStart[f] .. faceStart[f + 1])
  // Smooth shading's normals, indexed as OBJ's "vn" are: corner c's normal is normals[normalIndices[c]],
  // or, with no normal indices, the vertex's own normals[indices[c]] (a sphere: one normal a vertex,
  // not three doubles a corner, 36 of the 1M-triangle sphere's 76 MiB). No normals: flat shading.
  std::vector<Vec3> normals;            // MC
  std::vector<uint32_t> normalIndices;  // one per entry of `indices`, or none

  size_t faceCount() const { return faceStart.size() - 1; }
  bool smooth() const { return !normals.empty(); }
  /// The normal of corner c (an entry of `indices`) of a smooth mesh.
  const Vec3& cornerNormal(size_t c) const { return normals[normalIndices.empty() ? indices[c] : normalIndices[c]]; }
  size_t vertexCount() const { return positions.size(); }
  std::span<const uint32_t> face(size_t f) const {
    return {indices.data() + faceStart[f], indices.data() + faceStart[f + 1]};
  }
  /// The largest number of vertices of any face (sizes the clipper's scratch buffers).
  size_t maxFaceSize() const;

  /// Appends a face of vertex indices (a smooth mesh with normal indices appends its corners' too).
  void addFace(std::initializer_list<uint32_t> face);
  void addFace(std::span<const uint32_t> face);
};

/// The size of a mesh, known before it is built (to check it against the scene's budget first).
struct MeshSize {
  size_t faces = 0, vertices = 0, corners = 0;
};

/// Newell's normal of face f (unnormalized; robust for non-planar and concave faces).
Vec3 faceNormal(const Mesh& mesh, size_t f);

struct Bounds {
  Vec3 min{0}, max{0};
  std::array<Vec3, 8> corners() const;
};
Bounds bounds(const Mesh& mesh);

/// An undirected edge between two vertices, as drawn by the wireframe styles.
struct Edge {
  uint32_t a, b;  // a < b
};
/// Every edge of the mesh once, in the order of first appearance in the faces.
std::vector<Edge> uniqueEdges(const Mesh& mesh);

/// uniqueEdges in steps: a page lists a million edges (60 ms) across frames. The sides of the faces
/// are bucketed by their smaller vertex (a counting sort), each bucket marks the first side of each
/// edge, and the marked sides in face order are the list. `mesh` must outlive the job.
class UniqueEdgesJob {
 public:
  explicit UniqueEdgesJob(const Mesh& mesh) : mesh_(&mesh) {}
  /// Does about `budget` units (a face's sides or a vertex each); true once the list is complete.
  bool step(uint64_t budget);
  /// The list, once step returned true (moved out).
  std::vector<Edge> take() { return std::move(edges_); }
  /// The units of the whole job: two passes over the vertices, three over the faces' sides.
  static uint64_t units(const Mesh& mesh) { return 2 * mesh.positions.size() + 3 * mesh.indices.size(); }

 private:
  struct Entry {
    uint32_t b, side;  // the side's other vertex, and its first corner
  };
  bool side(size_t f, size_t k, uint32_t& a, uint32_t& b) const;
  const Mesh* mesh_;
  int pass_ = 0;     // count, sum, fill, mark, collect, done
  size_t next_ = 0;  // the pass's next face or vertex
  std::vector<uint32_t> start_, fill_;
  std::vector<Entry> bucket_;
  std::vector<uint8_t> first_;
  std::vector<Edge> edges_;
};

/// Where the vertices of a cluster of faces lie: the faces [c · kFaces, (c + 1) · kFaces) of a mesh (the
/// last cluster may have fewer), and at most kRuns intervals [first, last] of vertex numbers that hold
/// every vertex of those faces (and maybe a few between them, which only make a test of them
/// stricter). No interval (runs 0) when the vertices lie scattered. The face pass decides a cluster's
/// faces at once when the outcodes of its intervals agree (lecture notes 15.3.4: the bounding box test
/// for a group of faces, by its vertices' own outcodes): a mesh made row by row, as a sphere or a
/// grid, has a cluster's vertices in two or three runs.
struct FaceCluster {
  static constexpr uint32_t kFaces = 64, kRuns = 4;
  std::array<uint32_t, kRuns> first{}, last{};
  uint32_t runs = 0;
};
/// The number of clusters of the mesh's faces.
inline size_t clusterCount(const Mesh& mesh) { return (mesh.faceCount() + FaceCluster::kFaces - 1) / FaceCluster::kFaces; }
/// Cluster c of the mesh; `scratch` is any buffer (reused between calls).
FaceCluster faceCluster(const Mesh& mesh, size_t c, std::vector<uint32_t>& scratch);

/// The same mesh with each face split into a fan of triangles (for the GPU and benchmarks).
Mesh triangulated(const Mesh& mesh);

/// Drops a smooth mesh's normal indices when each vertex's corners all name one normal: the normals
/// become one a vertex (a vertex no face uses gets +z). Unchanged otherwise.
void normalPerVertexWherePossible(Mesh& mesh);

}  // namespace vplab
