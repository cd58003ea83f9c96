#include "pipeline/memory_use.h"

#include <algorithm>
#include <set>

namespace vplab {

MemoryUse memoryUse(const Mesh& mesh) {
  return {{"mesh.positions", heapBytes(mesh.positions)},
          {"mesh.indices", heapBytes(mesh.indices)},
          {"mesh.faceStart", heapBytes(mesh.faceStart)},
          {"mesh.normals", heapBytes(mesh.normals)},
          {"mesh.normalIndices", heapBytes(mesh.normalIndices)}};
}

MemoryUse meshMemoryUse(const Scene& scene) {
  MemoryUse use;
  std::set<const Mesh*> seen;
  for (const SceneObject& o : scene.objects)
    if (o.mesh && seen.insert(o.mesh.get()).second) accumulate(use, memoryUse(*o.mesh));
  return use;
}

MemoryUse memoryUse(const PipelineRun& run) {
  MemoryUse use;
  for (const ObjectRun& o : run.objects)
    accumulate(use, {{"run.npcH", heapBytes(o.npcH)},
                     {"run.outcodes", heapBytes(o.outcodes)},
                     {"run.fate", heapBytes(o.fate)},
                     {"run.clipped (faces, starts, refs)",
                      heapBytes(o.clippedFaces) + heapBytes(o.clippedStart) + heapBytes(o.clippedRefs)},
                     {"run.created (NPC, planes)", heapBytes(o.createdNpcH) + heapBytes(o.createdOnPlanes)},
                     {"run.edges", heapBytes(o.edges)},
                     {"run.edge fates, clipped edges",
                      heapBytes(o.edgeFate) + heapBytes(o.clippedEdges) + heapBytes(o.clippedEdgeRanges)},
                     {"run.clip value cache", heapBytes(o.valueSlots) + heapBytes(o.values)},
                     {"run.face clusters", heapBytes(o.faceClusters)},
                     {"run.userForms", heapBytes(o.userForms)}});
  size_t clipWork = heapBytes(run.clipWork.scratch.a) + heapBytes(run.clipWork.scratch.b) + heapBytes(run.clipWork.chunks);
  for (const detail::ChunkWork& w : run.clipWork.chunks)
    clipWork += heapBytes(w.crossing) + heapBytes(w.scratch.a) + heapBytes(w.scratch.b) + heapBytes(w.clippedFaces) +
                heapBytes(w.clippedStart) + heapBytes(w.clippedRefs) + heapBytes(w.createdNpcH) +
                heapBytes(w.createdOnPlanes) + heapBytes(w.ranges);
  accumulate(use, {{"run.objects", heapBytes(run.objects)}, {"run.stage 4 working lists", clipWork}});
  return use;
}

size_t totalBytes(const MemoryUse& use) {
  size_t sum = 0;
  for (const MemoryPart& p : use) sum += p.bytes;
  return sum;
}

MemoryUse sortedLargestFirst(MemoryUse use) {
  std::stable_sort(use.begin(), use.end(), [](const MemoryPart& a, const MemoryPart& b) { return a.bytes > b.bytes; });
  return use;
}

void accumulate(MemoryUse& into, const MemoryUse& more) {
  for (const MemoryPart& p : more) {
    auto it = std::find_if(into.begin(), into.end(), [&](const MemoryPart& q) { return q.name == p.name; });
    if (it == into.end()) into.push_back(p);
    else it->bytes += p.bytes;
  }
}

}  // namespace vplab
