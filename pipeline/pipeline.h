// The five stages run over a scene (lecture notes 15.2.6, figure 15.10): every vertex of every polygon goes
// MC → WC → VRC → homogeneous NPC; polygons are clipped against the unit cube; the survivors are
// divided by w and mapped to DC. A run keeps every stage's results for the views, the dump, the
// vertex probe and the tests, plus statistics and operation counts (lecture notes 15.3.3).
//
// Data-oriented, in two passes: one over the vertices (stages 1–3 as the one composite matrix
// npcFromMc and the classification) and one over the faces (trivial
// accept and reject by the outcodes; Sutherland–Hodgman for the few faces that cross a plane).
// Polygons index the vertex arrays, so a vertex is transformed and classified once however many
// faces use it. Per vertex only what later stages read is stored (homogeneous NPC, outcode); WC,
// VRC and DC are recomputed on demand, bit for bit as the stage matrices give them. Per face
// only its fate is stored: an accepted face is drawn from the mesh's own indices. Buffers are
// reused from run to run; no heap allocation per polygon in the hot loop.
#pragma once

#include "pipeline/clipping.h"
#include "pipeline/cost_model.h"
#include "base/enum_table.h"
#include "pipeline/scene.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

/// Where polygons are clipped (lecture notes 15.3.1–15.3.3). divideFirst is wrong on purpose: it divides by w
/// before clipping, so points behind the eye flip into view (Hill 7.4 and the DGL wiki).
enum class ClipStrategy { npc, wc, divideFirst };
inline constexpr EnumTable<ClipStrategy, 3> kClipStrategyNames = {{
    {ClipStrategy::npc, "npc"}, {ClipStrategy::wc, "wc"}, {ClipStrategy::divideFirst, "divide-first"}}};
constexpr const auto& namesOf(ClipStrategy) { return kClipStrategyNames; }
inline bool isCorrect(ClipStrategy s) { return s != ClipStrategy::divideFirst; }

struct PipelineOptions {
  ClipStrategy strategy = ClipStrategy::npc;
  bool boundingBoxTest = false;  // decide whole objects by their MC bounding box first (lecture notes 15.3.4)
  bool clipEdges = false;        // also clip every unique edge (wireframe styles and overlays)
  /// The vertices, and the faces and edges the outcodes decide, on every core (pipeline/parallel.h;
  /// natively only): the result is the serial run's bit for bit.
  bool parallel = true;
};

/// What stage 4 did with a face.
enum class Fate : uint8_t {
  accepted,     // trivially: its outcodes OR to 0 (or its object's box is inside)
  rejected,     // trivially: its outcodes AND to non-zero (or its object's box is outside)
  clipped,      // cut by Sutherland–Hodgman, something visible remains
  clippedAway,  // cut by Sutherland–Hodgman, nothing remains
};
/// The names of the dump's "fate".
inline constexpr EnumTable<Fate, 4> kFateNames = {{
    {Fate::accepted, "accepted"}, {Fate::rejected, "rejected"}, {Fate::clipped, "clipped"}, {Fate::clippedAway, "clipped_away"}}};
constexpr const auto& namesOf(Fate) { return kFateNames; }

/// The bounding-box verdict for an object (lecture notes 15.3.4).
enum class BoxVerdict : uint8_t { notTested, inside, outside, crossing };

/// One object's pass through the pipeline. Vertex refs of clipped polygons below `vertexCount()`
/// name mesh vertices; refs from `vertexCount()` on name vertices created by clipping.
struct ObjectRun {
  std::string name, nameDe;  // the scene object's (SceneObject::name, nameDe)
  Vec3 color{1};
  std::shared_ptr<const Mesh> mesh;  // MC, stage 0
  Mat4 wcFromMc{1.0};
  Mat4 vrcFromWc{1.0};  // the run's, kept here so wc() and vrc() need nothing else
  Mat4 npcFromMc{1.0};  // npcFromVrc · vrcFromWc · wcFromMc: stages 1–3 in one matrix
  ClipStrategy strategy = ClipStrategy::npc;
  std::array<Vec4, kPlaneCount> planesWc{};  // the frustum's planes in WC (the WC strategy's tests)
  // The enabled user clip planes (DGL wiki) as linear forms in the space the strategy clips in:
  // homogeneous NPC (npc), WC on (x, y, z, 1) (wc), NPC after the division (divide first).
  std::vector<Vec4> userForms;

  // Stages 1–3, per mesh vertex: homogeneous NPC, not divided yet (npcFromMc · MC: one 4 × 4
  // product per vertex, the lecture notes' cost model). WC and VRC on demand, the very affine products the
  // stage matrices define (storing them would double the vertex pass's memory traffic).
  std::vector<Vec4> npcH;
  Vec3 wc(uint32_t v) const { return transformAffine(wcFromMc, mesh->positions[v]); }
  Vec3 vrc(uint32_t v) const { return transformAffine(vrcFromWc, wc(v)); }

  // Stage 4, per mesh vertex: the outcode (bits 0–5 the cube's planes, 6–11 the user planes). For
  // an object decided by its box the vertices are not classified: their outcodes are 0 (box inside)
  // or the box's common bits (box outside).
  std::vector<Outcode> outcodes;
  BoxVerdict box = BoxVerdict::notTested;
  Outcode boxCode = 0;  // the outcode every vertex gets when the box decides (0 inside, common bits outside)
  bool classified() const { return box == BoxVerdict::notTested || box == BoxVerdict::crossing; }
  /// The boundary values the strategy tests for vertex v (NPC: Blinn's BCs of npcH; WC: the
  /// frustum's plane equations at wc, equal in exact arithmetic; divide first: the BCs of npcH / w;
  /// then the user planes'), computed as the vertex pass computed them for the outcode.
  ClipValues clipValuesOf(uint32_t v) const;
  /// The same, written into `out` (the clipper's vertices are built in place).
  void clipValuesInto(uint32_t v, ClipValues& out) const;
  /// The same, computed once per vertex when a polygon or edge crossing a plane first needs them
  /// and kept for every other one using the vertex (Hill 7.4), in a cache reused from run to run
  /// (the WC strategy's clipping on one thread; the others work the values out anew, as cheap).
  const ClipValues& sharedClipValues(uint32_t v);

  // Stage 4, per face: its fate. The faces cut with something left (fate clipped), ascending, and
  // their polygons: clipped face i is clippedRefs[clippedStart[i] .. clippedStart[i + 1]).
  std::vector<Fate> fate;
  std::vector<uint32_t> clippedFaces;
  std::vector<uint32_t> clippedStart{0};
  std::vector<uint32_t> clippedRefs;
  std::vector<Vec4> createdNpcH;          // homogeneous NPC of the vertices created by clipping
  std::vector<uint16_t> createdOnPlanes;  // bit i: created on plane i (new edges join such vertices)

  // Stage 5: DC of every vertex the clipped polygons use, worked out where it is read from its
  // homogeneous NPC, the same arithmetic every time (bit for bit): a mesh vertex's (outcode 0: inside)
  // and a created one's. (Stored, a mesh vertex's DC was 24 B the GPU path never reads, and the
  // created vertices' a serial step at the end of every run.)
  Mat4 dcFromNpc{1.0};  // the run's
  Vec3 dc(uint32_t v) const;
  /// A created vertex's (i counts from 0): divided as divideByW divides, so that one on the plane
  /// x = w lands exactly on the window's edge (x / w is 1, x · (1 / w) need not be).
  Vec3 createdDc(size_t i) const { return Vec3(dcFromNpc * Vec4(divideByW(createdNpcH[i]), 1.0)); }

  // Edges (PipelineOptions::clipEdges), kept as the faces are: each unique edge's fate, and only for
  // the edges cut with something left (fate clipped), ascending, their visible parameter range
  // [t0, t1] from a to b. An accepted edge is visible whole, [0, 1]; a rejected or clipped-away one not
  // at all. (A range for every edge was 24 B an edge: 24 MiB for the large scene, whose few edges
  // crossing a plane now take 24 B each and the rest 1 B.)
  std::vector<Edge> edges;
  std::vector<Fate> edgeFate;
  std::vector<uint32_t> clippedEdges;
  std::vector<EdgeRange> clippedEdgeRanges;
  /// The visible part of edge e: {0, 1, true} when accepted, the stored range when clipped, not
  /// visible when rejected or clipped away.
  EdgeRange edgeRange(size_t e) const;
  bool edgeVisible(size_t e) const { return edgeFate[e] == Fate::accepted || edgeFate[e] == Fate::clipped; }

  // Cached per mesh (like `edges`): the number of vertices of every face, 0 when they differ; the
  // clusters of faces the face pass decides at once when it can (listed in the run's steps).
  uint32_t uniformFaceSize = 0;
  std::vector<FaceCluster> faceClusters;
  // sharedClipValues' cache: per vertex the run that filled its slot (high 32 bits) and the slot.
  std::vector<uint64_t> valueSlots;
  std::vector<ClipValues> values;
  uint32_t generation = 0;

  size_t vertexCount() const { return npcH.size(); }
  size_t faceCount() const { return fate.size(); }
  /// The visible polygon of face f: the mesh face when accepted, the clipped polygon when clipped,
  /// empty when rejected or clipped away.
  std::span<const uint32_t> clippedFace(size_t f) const;
  bool isCreated(uint32_t ref) const { return ref >= vertexCount(); }
  /// A clipped polygon's vertex: homogeneous NPC, NPC after the division, DC.
  Vec4 clippedNpcH(uint32_t ref) const { return isCreated(ref) ? createdNpcH[ref - vertexCount()] : npcH[ref]; }
  Vec3 clippedNpc(uint32_t ref) const;
  Vec3 clippedDc(uint32_t ref) const { return isCreated(ref) ? createdDc(ref - vertexCount()) : dc(ref); }
  /// Whether the edge of clipped face f from corner i to corner i + 1 was made by clipping
  /// (it lies in a clip plane, so it is not part of the original polygon's boundary).
  bool isNewEdge(size_t f, size_t i) const;
};

/// A face or an edge its outcodes could not decide (stage 4): clipped after its chunk's trivial
/// decisions, in order, by the thread that decided them.
struct ClipCandidate {
  uint32_t index;  // the face's or edge's
  Outcode planes;  // the planes its vertices' outcodes name (OR)
};

namespace detail {
/// What a chunk of faces or edges leaves for the run: the ones its outcodes could not decide, and
/// (clipped on every core) what clipping made of them, in ascending order, as the run keeps it
/// (the faces' ends in clippedStart, without the run's leading 0; created vertices numbered from the
/// mesh's vertex count within the chunk). pipeline.cpp's joinChunk appends it to the run, renumbered.
struct ChunkWork {
  std::vector<ClipCandidate> crossing;
  ClipScratch scratch;
  std::vector<uint32_t> clippedFaces, clippedStart, clippedRefs;
  std::vector<Vec4> createdNpcH;
  std::vector<uint16_t> createdOnPlanes;
  std::vector<EdgeRange> ranges;  // edges: crossing[i]'s

  void clear() {
    crossing.clear();
    clippedFaces.clear();
    clippedStart.clear();
    clippedRefs.clear();
    createdNpcH.clear();
    createdOnPlanes.clear();
    ranges.clear();
  }
};

/// Stage 4's working lists, kept by the run from one run to the next so that they keep their memory
/// (made anew by every run they were 4 % of the large scene's run on one core: allocations and their
/// growth). Not a result: what a run leaves in them means nothing.
struct ClipWork {
  ClipScratch scratch;
  std::vector<ChunkWork> chunks;  // one a chunk of the faces or edges
};
}  // namespace detail

struct PipelineRun {
  Camera camera;
  VrcAxes vrc{};  // U, V, N, VPD, dmin, dmax (stage 2)
  Device device;
  PipelineOptions options;
  Mat4 vrcFromWc{1.0};
  Mat4 npcFromVrc{1.0};
  Mat4 dcFromNpc{1.0};
  Mat4 npcFromWc{1.0};  // npcFromVrc · vrcFromWc
  // The inverses, computed once per run (glm::inverse of the two above) for everything that maps
  // back: NPC points to WC (the world view's clipped polygons, the front and back plane handles),
  // VRC points to WC (the window, the camera's axes). A homogeneous result needs its division by w.
  Mat4 wcFromVrc{1.0};  // vrcFromWc⁻¹: the rotation's transpose after translating back by VRP
  Mat4 wcFromNpc{1.0};  // npcFromWc⁻¹ = wcFromVrc · npcFromVrc⁻¹
  /// WC of a point given in NPC after the division (z = 1 front, 0 back): back through wcFromNpc,
  /// then divided by the w that comes out (1 for parallel projections).
  Vec3 wcOfNpc(const Vec3& npc) const {
    const Vec4 p = wcFromNpc * Vec4(npc, 1.0);
    return Vec3(p) / p.w;
  }
  // The enabled user clip planes (DGL wiki) as linear forms: in WC on (x, y, z, 1), and pulled back
  // to homogeneous NPC (plane_wc · wcFromNpc), where they clip together with the cube's planes.
  std::vector<Vec4> userPlanesWc, userPlanesNpc;
  std::vector<ObjectRun> objects;  // one per visible scene object, in scene order
  std::vector<size_t> sceneIndex;  // objects[i] is scene.objects[sceneIndex[i]]
  PipelineStats stats;
  detail::ClipWork clipWork;
};

/// The five stages run in steps, so that a page with no threads can run a large scene across frames
/// (docs/measured.md "Large scenes in the page"): each step does about `budget` units of work (a vertex, a
/// face or an edge each), and the run's results equal runPipeline's bit for bit however it was cut.
/// `run` must outlive the job (the scene need not: the run holds its meshes); `run` is complete only when step returns true (until then
/// it is half old, half new: not to be shown). A job dropped before it is done leaves `run` fit to be
/// run into again.
class PipelineJob {
 public:
  /// Computes every matrix: throws vplab::Error when the camera or a transform is invalid, before
  /// `run` changes.
  PipelineJob(const Scene& scene, const PipelineOptions& options, PipelineRun& run);
  PipelineJob(const PipelineJob&) = delete;
  PipelineJob& operator=(const PipelineJob&) = delete;
  ~PipelineJob();

  /// Does at most about `budget` units; returns whether the run is complete.
  bool step(uint64_t budget);
  bool done() const { return object_ == run_.objects.size(); }
  /// The share of the work done, from 0 to 1 (1 only once complete).
  double progress() const;

 private:
  enum class Phase : uint8_t;
  PipelineRun& run_;
  std::optional<UniqueEdgesJob> edgeJob_;  // Phase::listEdges
  size_t object_ = 0;
  Phase phase_{};
  size_t next_ = 0;  // the phase's next vertex, face or edge
  uint64_t done_ = 0, total_ = 0;
  bool finished_ = false;
};

/// The object's name as a viewer in `lang` shows it (nameIn of its scene object).
inline const std::string& nameIn(const ObjectRun& o, Language lang) {
  return lang == Language::de && !o.nameDe.empty() ? o.nameDe : o.name;
}

/// Runs the five stages over the scene's visible objects, reusing `run`'s buffers.
/// Throws vplab::Error when the camera is invalid (nothing in `run` is NaN or infinite then either:
/// it keeps the previous results).
void runPipeline(const Scene& scene, const PipelineOptions& options, PipelineRun& run);
PipelineRun runPipeline(const Scene& scene, const PipelineOptions& options = {});

/// The six frustum planes in WC (lecture notes 15.3.1): plane i at a WC point p is BCi(npcFromWc · p).
std::array<Vec4, kPlaneCount> frustumPlanesWc(const Mat4& npcFromWc);

}  // namespace vplab
