#include "app/render/volume_partition.h"

#include "pipeline/clipping.h"
#include "pipeline/parallel.h"
#include "pipeline/pipeline.h"

#include <algorithm>
#include <cmath>

namespace vplab {

namespace {

// Bits 0–5: the vertex lies outside plane i by the margin; bit 6: inside every plane by it.
constexpr uint8_t kInside = 1u << 6;
// The GPU's value of a boundary coordinate (float matrices, float MC positions, interpolated)
// differs from the CPU's double by far less than these margins: 1e-3 of the vertex's own
// coordinates, and 1e-5 of the largest value the float products can reach for this object.
constexpr double kRelativeMargin = 1e-3, kProductMargin = 1e-5;
// What a triangle of the slice budget pays for: sorting a vertex or a face costs about an eighth
// of drawing a triangle in the page's software WebGL (1M of each took 0.33 s; the page's slices
// draw about 20 000 triangles in 50 ms). The budget adapts to the frame times anyway.
constexpr size_t kItemsPerTriangle = 8;
constexpr size_t kVertexBlock = 8192;  // the vertices' sides are found this many at a time

}  // namespace

GLsizei VolumePartitions::Part::count(List list) const {
  GLsizei n = 0;
  for (const Chunk& c : chunks) n += c.count[list];
  return n;
}

VolumePartitions::Part& VolumePartitions::partFor(uint64_t serial, size_t instance) {
  Part* oldest = nullptr;
  size_t kept = 0;
  for (Part& p : parts_) {
    if (p.instance != instance) continue;
    if (p.serial == serial) return p;
    ++kept;
    if (!oldest || p.serial < oldest->serial) oldest = &p;
  }
  Part& p = kept < kKeptPerInstance ? parts_.emplace_back() : *oldest;  // its buffers are reused
  p.serial = serial;
  p.instance = instance;
  p.run = nullptr;
  return p;
}

void VolumePartitions::start(Part& part, const draw::MeshInstance& m, const Mat4& npcFromWc, const GpuMesh& g) {
  const ObjectRun& o = *m.run;
  double wcMax = 0;
  for (const Vec3& c : bounds(*o.mesh).corners()) {
    const Vec3 wc = transformAffine(o.wcFromMc, c);
    wcMax = std::max({wcMax, std::abs(wc.x), std::abs(wc.y), std::abs(wc.z)});
  }
  double rowMax = 0;
  for (int r = 0; r < 4; ++r) {
    double sum = 0;
    for (int c = 0; c < 4; ++c) sum += std::abs(npcFromWc[c][r]);
    rowMax = std::max(rowMax, sum);
  }
  part.productMargin = kProductMargin * rowMax * (wcMax + 1);
  part.run = m.run;
  part.sides.resize(o.npcH.size());
  part.verticesDone = 0;
  part.chunks.resize(g.chunks.size());
  part.chunksDone = 0;
}

void VolumePartitions::sideVertices(Part& part, const ObjectRun& o, size_t begin, size_t end) {
  for (size_t v = begin; v < end; ++v) {
    const Vec4& p = o.npcH[v];
    const double margin =
        std::max(kRelativeMargin * (std::abs(p.x) + std::abs(p.y) + std::abs(p.z) + std::abs(p.w)), part.productMargin);
    const Boundary bc = boundaryCoordinates(p);
    uint8_t sides = kInside;
    for (int b = 0; b < kPlaneCount; ++b) {
      if (bc[size_t(b)] < -margin) sides |= uint8_t(1u << b);
      if (!(bc[size_t(b)] > margin)) sides &= uint8_t(~kInside);  // NaN: not inside either
    }
    part.sides[v] = sides;
  }
}

namespace {

// Face f's corners are the chunk's corners faceStart[f] − firstCorner …, fanned from the first,
// each its GPU vertex through the chunk's corner map (the chunk's own triangles, in its order),
// written as wide as the chunk's own indices. kTriangles: every face is a triangle, whose corners
// start at 3 f without faceStart (a 4 MiB array a million faces, read twice: about a quarter of the
// lists' time).
template <bool kTriangles, class Index>
void listFaces(const uint8_t* sides, const Mesh& mesh, const GpuMeshChunk& chunk, const Index* cornerVertex,
               std::array<std::vector<Index>, VolumePartitions::kLists>& lists, std::array<size_t, VolumePartitions::kLists>& count) {
  auto firstCorner = [&](size_t f) { return kTriangles ? uint32_t(3 * f) : mesh.faceStart[f]; };
  auto cornerCount = [&](size_t f) { return kTriangles ? 3u : mesh.faceStart[f + 1] - mesh.faceStart[f]; };
  size_t capacity = 0;
  for (size_t f = chunk.firstFace; f < chunk.endFace; ++f) capacity += 3 * (std::max<uint32_t>(cornerCount(f), 2) - 2);
  std::array<Index*, VolumePartitions::kLists> end{};
  for (size_t list = 0; list < VolumePartitions::kLists; ++list) {
    lists[list].resize(capacity);  // only what the loop writes is read
    end[list] = lists[list].data();
  }
  for (size_t f = chunk.firstFace; f < chunk.endFace; ++f) {
    const uint32_t first = firstCorner(f), n = cornerCount(f);
    const uint32_t* corner = mesh.indices.data() + first;
    uint8_t all = 0xff;
    for (uint32_t c = 0; c < n; ++c) all &= sides[corner[c]];
    const bool outsideOnePlane = all & 0x3f, insideAll = all & kInside;
    const Index* vertex = cornerVertex + (first - chunk.firstCorner);
    auto add = [&](size_t list) {
      for (uint32_t c = 1; c + 1 < n; ++c) {
        end[list][0] = vertex[0];
        end[list][1] = vertex[c];
        end[list][2] = vertex[c + 1];
        end[list] += 3;
      }
    };
    if (insideAll) add(VolumePartitions::kInsideFaces);
    else if (!outsideOnePlane) add(VolumePartitions::kInsidePass);
    if (!insideAll) add(VolumePartitions::kOutsidePass);
  }
  for (size_t list = 0; list < VolumePartitions::kLists; ++list) count[list] = size_t(end[list] - lists[list].data());
}

template <class Index>
void listFaces(bool triangles, const uint8_t* sides, const Mesh& mesh, const GpuMeshChunk& chunk, const Index* cornerVertex,
               std::array<std::vector<Index>, VolumePartitions::kLists>& lists, std::array<size_t, VolumePartitions::kLists>& count) {
  if (triangles) listFaces<true>(sides, mesh, chunk, cornerVertex, lists, count);
  else listFaces<false>(sides, mesh, chunk, cornerVertex, lists, count);
}

}  // namespace

void VolumePartitions::listChunk(const Part& part, const Mesh& mesh, const GpuMeshChunk& chunk, ChunkLists& out) {
  const bool triangles = part.run->uniformFaceSize == 3;
  if (chunk.indexType == GL_UNSIGNED_SHORT)
    listFaces(triangles, part.sides.data(), mesh, chunk, chunk.cornerVertex16.data(), out.narrow, out.count);
  else listFaces(triangles, part.sides.data(), mesh, chunk, chunk.cornerVertex32.data(), out.wide, out.count);
}

void VolumePartitions::uploadChunk(const GpuMeshChunk& chunk, const ChunkLists& lists, Chunk& out) {
  const GladGLContext& gl = *gl_;
  const bool narrow = chunk.indexType == GL_UNSIGNED_SHORT;
  for (size_t l = 0; l < kLists; ++l) {
    out.count[l] = GLsizei(lists.count[l]);
    if (out.count[l] == 0) continue;
    if (!out.indices[l]) out.indices[l] = gl::makeBuffer(gl);
    // Bound as an array buffer: the element binding belongs to whichever VAO is bound.
    gl.BindBuffer(GL_ARRAY_BUFFER, out.indices[l].id());
    const GLsizeiptr bytes = GLsizeiptr(out.count[l]) * GLsizeiptr(chunk.indexSize());
    if (bytes > out.capacity[l] || bytes < out.capacity[l] / 4) {
      out.capacity[l] = bytes + bytes / 4;
      gl.BufferData(GL_ARRAY_BUFFER, out.capacity[l], nullptr, GL_STREAM_DRAW);
    }
    gl.BufferSubData(GL_ARRAY_BUFFER, 0, bytes,
                     narrow ? static_cast<const void*>(lists.narrow[l].data()) : static_cast<const void*>(lists.wide[l].data()));
  }
  gl.BindBuffer(GL_ARRAY_BUFFER, 0);
}

const VolumePartitions::Part* VolumePartitions::get(uint64_t serial, size_t instance, const draw::MeshInstance& m,
                                                    const Mat4& npcFromWc, const GpuMesh& g, size_t& triangles) {
  const ObjectRun& o = *m.run;
  if (!o.mesh || o.mesh != m.mesh || o.npcH.size() != o.mesh->vertexCount() || o.fate.size() != o.mesh->faceCount() ||
      m.spaceFromMc != o.wcFromMc || (!g.chunks.empty() && g.chunks.back().endFace != o.mesh->faceCount()))
    return nullptr;  // not this mesh's run: drawn whole
  Part& part = partFor(serial, instance);
  if (part.run != m.run) start(part, m, npcFromWc, g);
  // Work while the budget lasts; a block or chunk begun is finished (at most one past the budget).
  size_t items = triangles > SIZE_MAX / kItemsPerTriangle ? SIZE_MAX : triangles * kItemsPerTriangle;
  auto spend = [&](size_t n) {
    items -= std::min(items, n);
    triangles -= std::min(triangles, (n + kItemsPerTriangle - 1) / kItemsPerTriangle);
  };
  // The blocks of vertices and the chunks the budget pays for, on every core (natively; each block
  // and chunk writes only its own sides or lists, so the partition is the serial one), a chunk's
  // lists uploaded here (GL has one thread). A world frame of the million triangles spent 7.5 ms
  // on the partition on one thread; about 2.6 ms so on two cores (docs/measured.md).
  if (items > 0 && part.verticesDone < part.sides.size()) {
    const size_t begin = part.verticesDone;
    const size_t end = std::min(part.sides.size(), begin + chunkCount(items, kVertexBlock) * kVertexBlock);
    forEachChunk(chunkCount(end - begin, kVertexBlock), true, [&](size_t k) {
      const size_t from = begin + k * kVertexBlock;
      sideVertices(part, o, from, std::min(end, from + kVertexBlock));
    });
    part.verticesDone = end;
    spend(end - begin);
  }
  lists_.resize(std::max<size_t>(1, parallelThreads()));
  while (items > 0 && part.verticesDone == part.sides.size() && part.chunksDone < part.chunks.size()) {
    size_t wave = 0;  // the chunks listed together, one a thread
    for (size_t left = items; left > 0 && wave < lists_.size() && part.chunksDone + wave < part.chunks.size(); ++wave) {
      const GpuMeshChunk& chunk = g.chunks[part.chunksDone + wave];
      left -= std::min(left, chunk.endFace - chunk.firstFace);
    }
    forEachChunk(wave, true, [&](size_t k) { listChunk(part, *o.mesh, g.chunks[part.chunksDone + k], lists_[k]); });
    for (size_t k = 0; k < wave; ++k) {
      const GpuMeshChunk& chunk = g.chunks[part.chunksDone];
      uploadChunk(chunk, lists_[k], part.chunks[part.chunksDone++]);
      spend(chunk.endFace - chunk.firstFace);
    }
  }
  if (part.ready()) {  // the sides are needed again only by the next draw's partition
    std::vector<uint8_t>().swap(part.sides);
    part.verticesDone = 0;
  }
  return &part;
}

std::array<size_t, 2> VolumePartitions::triangles(uint64_t serial, size_t instance) const {
  for (const Part& p : parts_)
    if (p.serial == serial && p.instance == instance && p.ready())
      return {size_t(p.count(kInsideFaces) + p.count(kInsidePass)) / 3, size_t(p.count(kOutsidePass)) / 3};
  return {0, 0};
}

}  // namespace vplab
