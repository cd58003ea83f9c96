// Where the bytes go (pipeline/memory_use.h): each part against what the structure's own sizes say,
// worked out here from the element counts (an allocation holds at least its elements).
#include "pipeline/memory_use.h"
#include "pipeline/primitives.h"
#include "tests/support/memory_use_support.h"

#include <gtest/gtest.h>

#include <memory>

namespace vplab {
namespace {

using test::bytesOf;

// A sphere's arrays, shrunk to their sizes: each part is exactly its element count × element size.
TEST(MemoryUse, AMeshsPartsAreItsArrays) {
  Mesh m = sphere(16);
  m.positions.shrink_to_fit();
  m.indices.shrink_to_fit();
  m.faceStart.shrink_to_fit();
  m.normals.shrink_to_fit();
  const MemoryUse use = memoryUse(m);
  EXPECT_EQ(bytesOf(use, "mesh.positions"), m.vertexCount() * 3 * sizeof(double));
  EXPECT_EQ(bytesOf(use, "mesh.indices"), m.indices.size() * 4);
  EXPECT_EQ(bytesOf(use, "mesh.faceStart"), (m.faceCount() + 1) * 4);
  EXPECT_EQ(bytesOf(use, "mesh.normals"), m.vertexCount() * 3 * sizeof(double));  // one a vertex
  EXPECT_EQ(bytesOf(use, "mesh.normalIndices"), 0u);
  EXPECT_EQ(totalBytes(use), 2 * m.vertexCount() * 24 + m.indices.size() * 4 + (m.faceCount() + 1) * 4);
}

// Two objects sharing one mesh hold it once; a second mesh adds its own.
TEST(MemoryUse, AMeshSharedByObjectsCountsOnce) {
  Scene scene = defaultScene();
  scene.objects.resize(1);
  const size_t one = totalBytes(meshMemoryUse(scene));
  ASSERT_GT(one, 0u);
  scene.objects.push_back(scene.objects[0]);  // the same shared_ptr<const Mesh>
  EXPECT_EQ(totalBytes(meshMemoryUse(scene)), one);
  const auto copy = std::make_shared<const Mesh>(*scene.objects[0].mesh);  // its own arrays
  scene.objects[1].mesh = copy;
  EXPECT_EQ(totalBytes(meshMemoryUse(scene)), one + totalBytes(memoryUse(*copy)));
}

// A run's per-vertex and per-face arrays hold at least one entry a vertex and a face of every object,
// and the edges' arrays one an edge when the edges are clipped.
TEST(MemoryUse, ARunHoldsItsPerVertexPerFaceAndPerEdgeArrays) {
  const Scene scene = defaultScene();
  PipelineRun run;
  runPipeline(scene, {ClipStrategy::npc, false, true}, run);
  size_t vertices = 0, faces = 0, edges = 0;
  for (const ObjectRun& o : run.objects) {
    vertices += o.vertexCount();
    faces += o.faceCount();
    edges += o.edges.size();
  }
  ASSERT_GT(edges, 0u);
  const MemoryUse use = memoryUse(run);
  EXPECT_GE(bytesOf(use, "run.npcH"), vertices * 4 * sizeof(double));
  EXPECT_GE(bytesOf(use, "run.outcodes"), vertices * sizeof(Outcode));
  EXPECT_GE(bytesOf(use, "run.fate"), faces);
  EXPECT_GE(bytesOf(use, "run.edges"), edges * 2 * sizeof(uint32_t));
  // one fate an edge, and a range only for each edge cut with something left (issue 42)
  size_t cut = 0;
  for (const ObjectRun& o : run.objects) cut += o.clippedEdges.size();
  EXPECT_GE(bytesOf(use, "run.edge fates, clipped edges"), edges * sizeof(Fate) + cut * (sizeof(uint32_t) + sizeof(EdgeRange)));
  EXPECT_EQ(totalBytes(use), [&] {
    size_t sum = 0;
    for (const MemoryPart& p : use) sum += p.bytes;
    return sum;
  }());

  PipelineRun noEdges;
  runPipeline(scene, {ClipStrategy::npc, false, false}, noEdges);
  EXPECT_EQ(bytesOf(memoryUse(noEdges), "run.edge fates, clipped edges"), 0u);
}

TEST(MemoryUse, PartsOfOneNameAddUpAndSortLargestFirst) {
  MemoryUse use{{"a", 1}, {"b", 5}};
  accumulate(use, {{"b", 2}, {"c", 4}});
  ASSERT_EQ(use.size(), 3u);
  EXPECT_EQ(bytesOf(use, "b"), 7u);
  EXPECT_EQ(totalBytes(use), 12u);
  const MemoryUse sorted = sortedLargestFirst(use);
  EXPECT_EQ(sorted[0].name, "b");
  EXPECT_EQ(sorted[1].name, "c");
  EXPECT_EQ(sorted[2].name, "a");
}

}  // namespace
}  // namespace vplab
