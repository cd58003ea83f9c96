// pipeline/mesh.h: clusters of faces and where their vertices lie.
#include "pipeline/mesh.h"
#include "pipeline/primitives.h"
#include "tests/support/test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

namespace vplab {
namespace {

// The same mesh with its vertices numbered at random: a cluster's vertices lie scattered.
Mesh renumbered(const Mesh& m, test::Rng& rng) {
  std::vector<uint32_t> to(m.vertexCount());
  std::iota(to.begin(), to.end(), 0u);
  for (size_t i = to.size(); i > 1; --i) std::swap(to[i - 1], to[size_t(rng.integer(0, int(i) - 1))]);
  Mesh r = m;
  for (size_t i = 0; i < m.vertexCount(); ++i) r.positions[to[i]] = m.positions[i];
  if (!m.normals.empty() && m.normalIndices.empty())
    for (size_t i = 0; i < m.vertexCount(); ++i) r.normals[to[i]] = m.normals[i];
  for (uint32_t& v : r.indices) v = to[v];
  return r;
}

// Every vertex of every face of a cluster lies in one of its intervals; the intervals are ordered,
// apart, and no more than the cluster's faces are worth reading.
void expectClustersHoldTheirFaces(const Mesh& m, size_t& withRuns) {
  std::vector<uint32_t> scratch;
  withRuns = 0;
  for (size_t c = 0; c < clusterCount(m); ++c) {
    const FaceCluster k = faceCluster(m, c, scratch);
    ASSERT_LE(k.runs, FaceCluster::kRuns);
    if (k.runs == 0) continue;
    ++withRuns;
    size_t read = 0, corners = 0;
    for (uint32_t r = 0; r < k.runs; ++r) {
      ASSERT_LE(k.first[r], k.last[r]);
      if (r > 0) {
        ASSERT_GT(k.first[r], k.last[r - 1] + 1) << "cluster " << c;
      }
      read += k.last[r] - k.first[r] + 1;
    }
    for (size_t f = c * FaceCluster::kFaces; f < std::min(m.faceCount(), (c + 1) * FaceCluster::kFaces); ++f)
      for (uint32_t v : m.face(f)) {
        ++corners;
        bool in = false;
        for (uint32_t r = 0; r < k.runs; ++r) in |= k.first[r] <= v && v <= k.last[r];
        ASSERT_TRUE(in) << "vertex " << v << " of face " << f << " lies outside cluster " << c << "'s intervals";
      }
    EXPECT_LE(read, 8 * corners);
  }
}

TEST(FaceClusters, HoldEveryVertexOfTheirFaces) {
  test::Rng rng(5);
  for (const Mesh& m : {sphere(64), triangulated(sphere(64)), cube(), triangulated(sphere(6))}) {
    size_t withRuns = 0;
    expectClustersHoldTheirFaces(m, withRuns);
    EXPECT_EQ(clusterCount(m), (m.faceCount() + 63) / 64);
  }
  // A sphere made row by row: every cluster's vertices in a few runs (its two rows).
  const Mesh s = triangulated(sphere(200));
  size_t withRuns = 0;
  expectClustersHoldTheirFaces(s, withRuns);
  EXPECT_EQ(withRuns, clusterCount(s));
  // Numbered at random: scattered, so (nearly) none is worth a test, and those that are still hold.
  const Mesh shuffled = renumbered(s, rng);
  expectClustersHoldTheirFaces(shuffled, withRuns);
  EXPECT_LT(withRuns, clusterCount(shuffled) / 100);
  EXPECT_EQ(clusterCount(Mesh{}), 0u);
}

}  // namespace
}  // namespace vplab
