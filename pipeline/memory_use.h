// Where the bytes of a scene and a run go (issue 42: `vplab bench --memory`): each structure's heap
// parts by name, as allocated (a vector's capacity, not its size: what the process holds).
#pragma once

#include "pipeline/pipeline.h"

#include <cstddef>
#include <string>
#include <vector>

namespace vplab {

struct MemoryPart {
  std::string name;  // the member, e.g. "npcH" or "mesh.positions"
  size_t bytes = 0;
};
/// The parts of one structure, largest first once sorted by sortedLargestFirst.
using MemoryUse = std::vector<MemoryPart>;

template <class T>
size_t heapBytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

/// A mesh's arrays: positions, indices, face starts, corner normals.
MemoryUse memoryUse(const Mesh& mesh);
/// Every object's mesh once (objects sharing one mesh count it once), the parts summed over them.
MemoryUse meshMemoryUse(const Scene& scene);
/// A run's per-vertex, per-face and per-edge arrays, each summed over its objects (not the meshes,
/// which the run shares with the scene).
MemoryUse memoryUse(const PipelineRun& run);

size_t totalBytes(const MemoryUse& use);
MemoryUse sortedLargestFirst(MemoryUse use);
/// Adds `more` into `into`, part by part of the same name.
void accumulate(MemoryUse& into, const MemoryUse& more);

}  // namespace vplab
