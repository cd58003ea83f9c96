// The five stages run over a scene (seed 15.2.6, figure 15.10): every vertex of every polygon goes
// MC → WC → VRC → homogeneous NPC; polygons are clipped against the unit cube; the survivors are
// divided by w and mapped to DC. A run keeps every stage's results for the views, the dump, the
// vertex probe and the tests, plus statistics and operation counts (seed 15.3.3).
//
// Data-oriented: each stage is a batch over arrays (one per space); polygons index the vertex
// arrays, so a vertex is transformed and classified once however many faces use it. Buffers are
// reused from run to run; no heap allocation per polygon in the hot loop.
#pragma once

#include "pipeline/clipping.h"
#include "pipeline/cost_model.h"
#include "pipeline/scene.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

/// Where polygons are clipped (seed 15.3.1–15.3.3). divideFirst is wrong on purpose: it divides by w
/// before clipping, so points behind the eye flip into view (seeds 002, 003).
enum class ClipStrategy { npc, wc, divideFirst };
std::string_view toString(ClipStrategy s);
std::optional<ClipStrategy> clipStrategyFromString(std::string_view s);
inline bool isCorrect(ClipStrategy s) { return s != ClipStrategy::divideFirst; }

struct PipelineOptions {
  ClipStrategy strategy = ClipStrategy::npc;
  bool boundingBoxTest = false;  // decide whole objects by their MC bounding box first (seed 15.3.4)
  bool clipEdges = false;        // also clip every unique edge (wireframe styles and overlays)
};

/// What stage 4 did with a face.
enum class Fate : uint8_t {
  accepted,     // trivially: its outcodes OR to 0 (or its object's box is inside)
  rejected,     // trivially: its outcodes AND to non-zero (or its object's box is outside)
  clipped,      // cut by Sutherland–Hodgman, something visible remains
  clippedAway,  // cut by Sutherland–Hodgman, nothing remains
};
std::string_view toString(Fate f);

/// The bounding-box verdict for an object (seed 15.3.4).
enum class BoxVerdict : uint8_t { notTested, inside, outside, crossing };

/// One object's pass through the pipeline. Vertex refs of clipped polygons below `vertexCount()`
/// name mesh vertices; refs from `vertexCount()` on name vertices created by clipping.
struct ObjectRun {
  std::string name;
  Vec3 color{1};
  std::shared_ptr<const Mesh> mesh;  // MC, stage 0
  Mat4 wcFromMc{1.0};

  // Stages 1–3, per mesh vertex.
  std::vector<Vec3> wc;
  std::vector<Vec3> vrc;
  std::vector<Vec4> npcH;  // homogeneous NPC: not divided yet

  // Stage 4, per mesh vertex: the boundary values the strategy tested (NPC: Blinn's BCs of npcH;
  // WC: the frustum's plane equations at wc, equal in exact arithmetic; divide first: the BCs
  // of npcH / w) and their outcodes. For an object decided by its box the vertices are not
  // classified: their outcodes are 0 (box inside) or the box's common bits (box outside).
  std::vector<Boundary> bc;
  std::vector<Outcode> outcodes;  // bits 6 … 11: the user clip planes
  // The user clip planes' values per vertex (seed 003), in the strategy's space like bc; empty
  // when the scene has none.
  std::vector<std::array<double, kMaxUserPlanes>> userValues;
  int userPlaneCount = 0;
  BoxVerdict box = BoxVerdict::notTested;

  // Stage 4, per face.
  std::vector<Fate> fate;
  std::vector<uint32_t> clippedStart;  // face f: clippedRefs[clippedStart[f] .. clippedStart[f + 1])
  std::vector<uint32_t> clippedRefs;
  std::vector<Vec4> createdNpcH;       // homogeneous NPC of the vertices created by clipping
  std::vector<uint8_t> createdOnPlanes;  // bit i: created on plane i (new edges join such vertices)

  // Stage 5: DC of every vertex the clipped polygons use (mesh vertices with outcode 0).
  std::vector<Vec3> dc;
  std::vector<Vec3> createdDc;

  // Edges (PipelineOptions::clipEdges): the visible parameter range of each unique edge.
  std::vector<Edge> edges;
  std::vector<EdgeRange> edgeRanges;

  size_t vertexCount() const { return npcH.size(); }
  /// All the boundary values of a mesh vertex, the cube's and the user planes', for the clipper.
  ClipValues clipValuesOf(uint32_t v) const {
    return userValues.empty() ? clipValues(bc[v])
                              : clipValues(bc[v], {userValues[v].data(), size_t(userPlaneCount)});
  }
  size_t faceCount() const { return fate.size(); }
  std::span<const uint32_t> clippedFace(size_t f) const {
    return {clippedRefs.data() + clippedStart[f], clippedRefs.data() + clippedStart[f + 1]};
  }
  bool isCreated(uint32_t ref) const { return ref >= vertexCount(); }
  /// A clipped polygon's vertex: homogeneous NPC, NPC after the division, DC.
  Vec4 clippedNpcH(uint32_t ref) const { return isCreated(ref) ? createdNpcH[ref - vertexCount()] : npcH[ref]; }
  Vec3 clippedNpc(uint32_t ref) const;
  Vec3 clippedDc(uint32_t ref) const { return isCreated(ref) ? createdDc[ref - vertexCount()] : dc[ref]; }
  /// Whether the edge of clipped face f from corner i to corner i + 1 was made by clipping
  /// (it lies in a clip plane, so it is not part of the original polygon's boundary).
  bool isNewEdge(size_t f, size_t i) const;
};

struct PipelineRun {
  Camera camera;
  ViewFrame frame{};
  Device device;
  PipelineOptions options;
  Mat4 vrcFromWc{1.0};
  Mat4 npcFromVrc{1.0};
  Mat4 dcFromNpc{1.0};
  Mat4 npcFromWc{1.0};  // npcFromVrc · vrcFromWc
  // The enabled user clip planes (seed 003) as linear forms: in WC on (x, y, z, 1), and pulled back
  // to homogeneous NPC (plane_wc · wcFromNpc), where they clip together with the cube's planes.
  std::vector<Vec4> userPlanesWc, userPlanesNpc;
  std::vector<ObjectRun> objects;  // one per visible scene object, in scene order
  std::vector<size_t> sceneIndex;  // objects[i] is scene.objects[sceneIndex[i]]
  PipelineStats stats;
};

/// Runs the five stages over the scene's visible objects, reusing `run`'s buffers.
/// Throws vplab::Error when the camera is invalid (nothing in `run` is NaN or infinite then either:
/// it keeps the previous results).
void runPipeline(const Scene& scene, const PipelineOptions& options, PipelineRun& run);
PipelineRun runPipeline(const Scene& scene, const PipelineOptions& options = {});

/// The six frustum planes in WC (seed 15.3.1): plane i at a WC point p is BCi(npcFromWc · p).
std::array<Vec4, kPlaneCount> frustumPlanesWc(const Mat4& npcFromWc);

}  // namespace vplab
