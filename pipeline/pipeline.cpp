// Index: 1 names and accessors (stage 5, where read)  2 the vertex pass (stages 1–3,
//        classification)  3 the face pass (stage 4: trivial accept and reject, per-face clipping),
//        edges, bounding box  4 the run, in steps (PipelineJob)
//
// Every core (PipelineOptions::parallel, pipeline/parallel.h): the vertex pass and the trivial
// decisions of faces and edges run over chunks of their range on every core, each chunk writing only
// its own vertices', faces' and edges' entries; the faces and edges the outcodes cannot decide are
// clipped by their chunk's thread into the chunk's own lists, which join the run in ascending order
// with their created vertices renumbered (ChunkWork, joinChunk). So the run on every core is the
// serial run bit for bit.
#include "pipeline/pipeline.h"

#include "base/error.h"
#include "pipeline/parallel.h"
#include "pipeline/view_mapping.h"

#include <algorithm>
#include <atomic>
#include <limits>

namespace vplab {

// ---------------------------------------------------------------- 1 names and accessors

// dcFromNpc scales x and y and moves y (docs/conventions.md stage 5): its diagonal and last column are all
// there is to it, so a vertex inside costs two multiplications more than the division (one division
// and three multiplications instead of three divisions; safe: inside, w ≥ dmin > 0 or w = 1).
Vec3 ObjectRun::dc(uint32_t v) const {
  const Vec4& h = npcH[v];
  const double inv = 1.0 / h.w;
  const Mat4& m = dcFromNpc;
  return {m[0][0] * (h.x * inv) + m[3][0], m[1][1] * (h.y * inv) + m[3][1], m[2][2] * (h.z * inv) + m[3][2]};
}

EdgeRange ObjectRun::edgeRange(size_t e) const {
  switch (edgeFate[e]) {
    case Fate::accepted: return {0, 1, true};
    case Fate::clipped: {
      const auto it = std::lower_bound(clippedEdges.begin(), clippedEdges.end(), uint32_t(e));
      return clippedEdgeRanges[size_t(it - clippedEdges.begin())];
    }
    case Fate::rejected:
    case Fate::clippedAway: break;
  }
  return {0, 0, false};
}

std::span<const uint32_t> ObjectRun::clippedFace(size_t f) const {
  switch (fate[f]) {
    case Fate::accepted: return mesh->face(f);
    case Fate::clipped: {
      const auto it = std::lower_bound(clippedFaces.begin(), clippedFaces.end(), uint32_t(f));
      const size_t i = size_t(it - clippedFaces.begin());
      return {clippedRefs.data() + clippedStart[i], clippedRefs.data() + clippedStart[i + 1]};
    }
    case Fate::rejected:
    case Fate::clippedAway: break;
  }
  return {};
}

namespace {

constexpr Outcode kAllPlanes = (1u << kMaxClipPlanes) - 1;

// The cube's boundary values each strategy tests, shared by the vertex pass and clipValuesOf so the
// two agree bit for bit.
Boundary wcBoundary(const std::array<Vec4, kPlaneCount>& planes, const Vec3& wc) {
  const Vec4 p(wc, 1.0);
  Boundary bc;
  for (int k = 0; k < kPlaneCount; ++k) bc[size_t(k)] = glm::dot(planes[size_t(k)], p);
  return bc;
}

Vec4 dividedFirst(const Vec4& npcH) { return Vec4(divideByW(npcH), 1.0); }

// Where the strategy evaluates the user planes' forms for a vertex.
Vec4 userPoint(ClipStrategy s, const Vec4& npcH, const Vec3& wc) {
  switch (s) {
    case ClipStrategy::npc: return npcH;
    case ClipStrategy::wc: return Vec4(wc, 1.0);
    case ClipStrategy::divideFirst: return dividedFirst(npcH);
  }
  return npcH;
}

}  // namespace

ClipValues ObjectRun::clipValuesOf(uint32_t v) const {
  ClipValues out;
  clipValuesInto(v, out);
  return out;
}

// Written where they are kept: the clipper builds its vertices in place (clipFace).
void ObjectRun::clipValuesInto(uint32_t v, ClipValues& out) const {
  Boundary cube;
  switch (strategy) {
    case ClipStrategy::npc: cube = boundaryCoordinates(npcH[v]); break;
    case ClipStrategy::wc: cube = wcBoundary(planesWc, wc(v)); break;
    case ClipStrategy::divideFirst: cube = boundaryCoordinates(dividedFirst(npcH[v])); break;
  }
  std::copy(cube.begin(), cube.end(), out.begin());
  const Vec4 p = userForms.empty() ? Vec4(0) : userPoint(strategy, npcH[v], strategy == ClipStrategy::wc ? wc(v) : Vec3(0));
  for (size_t k = 0; k < size_t(kMaxUserPlanes); ++k)
    out[kPlaneCount + k] = k < userForms.size() ? glm::dot(userForms[k], p) : 1.0;  // no plane: inside
}

const ClipValues& ObjectRun::sharedClipValues(uint32_t v) {
  if (valueSlots.size() != vertexCount()) valueSlots.assign(vertexCount(), 0);  // the first run that uses it
  uint64_t& slot = valueSlots[v];
  if (slot >> 32 == generation) return values[uint32_t(slot)];
  slot = uint64_t(generation) << 32 | uint32_t(values.size());
  values.push_back(clipValuesOf(v));
  return values.back();
}

Vec3 ObjectRun::clippedNpc(uint32_t ref) const { return divideByW(clippedNpcH(ref)); }

bool ObjectRun::isNewEdge(size_t f, size_t i) const {
  const auto face = clippedFace(f);
  const uint32_t a = face[i], b = face[(i + 1) % face.size()];
  if (!isCreated(a) && !isCreated(b)) {
    // Two mesh vertices: an original edge when b follows a in the mesh face. Otherwise clipping
    // dropped the vertices between them, which it does only when both lie exactly on that plane.
    const auto original = mesh->face(f);
    for (size_t k = 0; k < original.size(); ++k)
      if (original[k] == a && original[(k + 1) % original.size()] == b) return false;
    return true;
  }
  // A mesh vertex kept exactly on a plane (boundary value 0, counted inside) is on it just as a
  // created vertex is; the clipper creates no vertex for it.
  auto planes = [&](uint32_t ref) -> unsigned {
    if (isCreated(ref)) return createdOnPlanes[ref - vertexCount()];
    unsigned on = 0;
    if (classified()) {
      const ClipValues v = clipValuesOf(ref);
      for (int p = 0; p < kMaxClipPlanes; ++p) on |= unsigned(v[size_t(p)] == 0) << p;
    }
    return on;
  };
  return (planes(a) & planes(b)) != 0;
}

std::array<Vec4, kPlaneCount> frustumPlanesWc(const Mat4& npcFromWc) {
  // BC0 = x, BC1 = w − x, … as linear forms of homogeneous NPC, pulled back to WC.
  const Vec4 x = row(npcFromWc, 0), y = row(npcFromWc, 1), z = row(npcFromWc, 2), w = row(npcFromWc, 3);
  return {x, w - x, y, w - y, z, w - z};
}

namespace {

// ---------------------------------------------------------------- 2 the vertex pass

// Stages 1–3 and the classification in one pass over the vertices: each MC vertex is read once, and
// only what later stages read is written (npcH, outcode). `classify(i, h)` gives the outcode of
// vertex i with homogeneous NPC h. Stage 5 of the mesh vertices is counted here (those with outcode
// 0: inside, w > 0, the only mesh vertices the clipped polygons use) and worked out where it is read
// (ObjectRun::dc): a stored DC was 24 B a vertex that the GPU path never reads.
// [[gnu::flatten]]: GCC otherwise leaves GLM's vector operators out of line in this file (they are
// used too often), which costs a call per operation in the one loop that must run at the speed of
// a plain transform.
// Over the vertices [begin, end): a run in steps (PipelineJob) passes over them a range at a time;
// the arrays are sized by the object's start (startObject).
// Returns the number of vertices inside (mapped to DC).
template <class Classify>
[[gnu::flatten]] uint64_t vertexPass(ObjectRun& o, Classify classify, size_t begin, size_t end) {
  const Mesh& mesh = *o.mesh;
  const Vec4 c0(o.npcFromMc[0]), c1(o.npcFromMc[1]), c2(o.npcFromMc[2]), c3(o.npcFromMc[3]);
  const Vec3* mc = mesh.positions.data();
  Vec4* npcH = o.npcH.data();
  Outcode* oc = o.outcodes.data();
  uint64_t mapped = 0;
  for (size_t i = begin; i < end; ++i) {
    const Vec4 h = c0 * mc[i].x + c1 * mc[i].y + c2 * mc[i].z + c3;
    npcH[i] = h;
    const Outcode code = classify(i, h);
    oc[i] = code;
    mapped += code == 0;
  }
  return mapped;
}

// The user planes' outcode bits (6 … 11) of a vertex.
Outcode userBits(const ObjectRun& o, const Vec4& p) {
  Outcode bits = 0;
  for (size_t k = 0; k < o.userForms.size(); ++k)
    if (glm::dot(o.userForms[k], p) < 0) bits |= Outcode(1u << (kPlaneCount + k));
  return bits;
}

// The strategy's classification. `kUser`: whether the user planes' bits are needed (decided once
// per object, so the common case without user planes carries no test per vertex).
template <bool kUser>
uint64_t classifyVerticesWith(ObjectRun& o, size_t begin, size_t end) {
  switch (o.strategy) {
    case ClipStrategy::npc:
      return vertexPass(
          o, [&](size_t, const Vec4& h) { return Outcode(outcodeOf(h) | (kUser ? userBits(o, h) : 0)); }, begin, end);
    case ClipStrategy::wc:
      return vertexPass(
          o,
          [&](size_t i, const Vec4&) {
            const Vec3 wc = o.wc(uint32_t(i));
            return Outcode(outcodeOf(wcBoundary(o.planesWc, wc)) | (kUser ? userBits(o, Vec4(wc, 1.0)) : 0));
          },
          begin, end);
    case ClipStrategy::divideFirst:
      return vertexPass(
          o,
          [&](size_t, const Vec4& h) {
            const Vec4 d = dividedFirst(h);
            return Outcode(outcodeOf(boundaryCoordinates(d)) | (kUser ? userBits(o, d) : 0));
          },
          begin, end);
  }
  return 0;
}

uint64_t classifyVertices(ObjectRun& o, size_t begin, size_t end) {
  return o.userForms.empty() ? classifyVerticesWith<false>(o, begin, end) : classifyVerticesWith<true>(o, begin, end);
}

// The chunks a range is shared out in (pipeline/parallel.h): large enough that a chunk's work
// (about 0.1 ms) outweighs handing it to a core, small enough that two cores finish together.
constexpr size_t kChunk = size_t(1) << 15;

// Calls body(chunkBegin, chunkEnd, k) for the chunks k of [begin, end), `grain` units each.
template <class Body>
void forChunks(size_t begin, size_t end, bool parallel, Body body, size_t grain = kChunk) {
  forEachChunk(chunkCount(end - begin, grain), parallel, [&](size_t k) {
    const size_t b = begin + k * grain;
    body(b, std::min(end, b + grain), k);
  });
}

// ---------------------------------------------------------------- 3 the face pass (stage 4)

// How each strategy presents a mesh vertex to the clipper, and what a created vertex becomes.
// A vertex's clip values are worked out anew where they are a few subtractions (NPC, divide first:
// cheaper than looking them up); the WC strategy's plane equations (a WC vertex and six dot products)
// come from the run's cache when `shared` (one thread clips), else anew too (clipping on every core).
// The same values bit for bit either way (ObjectRun::clipValuesOf).
struct NpcSource {
  ObjectRun& o;
  void vertexInto(uint32_t v, ClipVertex& c) const {
    c.p = o.npcH[v];
    o.clipValuesInto(v, c.bc);
  }
  Vec4 npcH(const ClipVertex& c) const {
    Vec4 p = c.p;
    snapToPlanes(p, c.onPlanes);
    return p;
  }
};

struct WcSource {
  ObjectRun& o;
  bool shared;
  const Mat4& npcFromWc;
  void vertexInto(uint32_t v, ClipVertex& c) const {
    c.p = Vec4(o.wc(v), 1.0);
    if (shared) c.bc = o.sharedClipValues(v);
    else o.clipValuesInto(v, c.bc);
  }
  Vec4 npcH(const ClipVertex& c) const {
    Vec4 p = npcFromWc * c.p;  // the plane equations were exact in WC; snap away the rounding
    snapToPlanes(p, c.onPlanes);
    return p;
  }
};

struct DivideFirstSource {
  ObjectRun& o;
  void vertexInto(uint32_t v, ClipVertex& c) const {
    c.p = dividedFirst(o.npcH[v]);
    o.clipValuesInto(v, c.bc);
  }
  Vec4 npcH(const ClipVertex& c) const {
    Vec4 p = c.p;
    snapToPlanes(p, c.onPlanes);
    return p;
  }
};

using detail::ChunkWork;

// Face f's corners. A triangle mesh's are found without faceStart: a 4 MiB array a million faces
// that the face pass otherwise never reads, so each clipped face waited for it from memory.
std::span<const uint32_t> corners(const ObjectRun& o, uint32_t f) {
  if (o.uniformFaceSize == 3) return {o.mesh->indices.data() + 3 * size_t(f), 3};
  return o.mesh->face(f);
}

// A face the outcodes cannot decide: Sutherland–Hodgman. Rare (the faces crossing a plane), so it
// stays out of the face loop. Appended to `out`: the run itself (one thread) or a chunk's ChunkWork.
template <class Source, class Out>
[[gnu::noinline]] Fate clipFace(const ObjectRun& o, const Source& source, ClipScratch& scratch, uint32_t f,
                                Outcode planes, Out& out) {
  const uint32_t nv = uint32_t(o.vertexCount());
  // Built in place (ObjectRun::clipValuesInto); sized without clearing: a vector's new elements are
  // zeroed first (a `rep stos` that cost a third of this function), and faces are mostly of one size.
  const std::span<const uint32_t> face = corners(o, f);
  scratch.a.resize(face.size());
  for (size_t i = 0; i < face.size(); ++i) {
    ClipVertex& c = scratch.a[i];
    source.vertexInto(face[i], c);
    c.source = face[i];
    c.onPlanes = 0;
  }
  const auto clipped = clipPolygon(planes, scratch);
  if (clipped.empty()) return Fate::clippedAway;
  for (const ClipVertex& c : clipped) {
    if (c.source != ClipVertex::kCreated) {
      out.clippedRefs.push_back(c.source);
      continue;
    }
    out.clippedRefs.push_back(nv + uint32_t(out.createdNpcH.size()));
    out.createdNpcH.push_back(source.npcH(c));
    out.createdOnPlanes.push_back(c.onPlanes);
  }
  out.clippedFaces.push_back(f);
  out.clippedStart.push_back(uint32_t(out.clippedRefs.size()));
  return Fate::clipped;
}

// The crossing faces clipped in order into `out`. (Fetching a face's vertices a few faces ahead
// was measured too: under 1 %, not kept.)
template <class Source, class Out>
void clipCrossing(ObjectRun& o, const Source& source, ClipScratch& scratch, std::span<const ClipCandidate> crossing,
                  Out& out) {
  for (const ClipCandidate& c : crossing) o.fate[c.index] = clipFace(o, source, scratch, c.index, c.planes, out);
}

// A chunk's clipped faces appended to the run: its created vertices renumbered after the run's.
void joinChunk(ObjectRun& o, const ChunkWork& w) {
  const uint32_t nv = uint32_t(o.vertexCount());
  const uint32_t created = uint32_t(o.createdNpcH.size()), refs = uint32_t(o.clippedRefs.size());
  o.clippedFaces.insert(o.clippedFaces.end(), w.clippedFaces.begin(), w.clippedFaces.end());
  for (uint32_t end : w.clippedStart) o.clippedStart.push_back(refs + end);
  for (uint32_t ref : w.clippedRefs) o.clippedRefs.push_back(ref >= nv ? ref + created : ref);
  o.createdNpcH.insert(o.createdNpcH.end(), w.createdNpcH.begin(), w.createdNpcH.end());
  o.createdOnPlanes.insert(o.createdOnPlanes.end(), w.createdOnPlanes.begin(), w.createdOnPlanes.end());
}

struct TrivialCounts {
  uint64_t accepted = 0, rejected = 0;
};

// Trivial accept and reject by the outcodes (lecture notes 15.2.4) over the faces [begin, end), face by
// face: only their fates are written; the faces that cross a plane are listed in `crossing`.
void decideEach(ObjectRun& o, uint32_t begin, uint32_t end, std::vector<ClipCandidate>& crossing, TrivialCounts& n) {
  const Mesh& mesh = *o.mesh;
  const uint32_t* idx = mesh.indices.data();
  const uint32_t* start = mesh.faceStart.data();
  const Outcode* oc = o.outcodes.data();
  Fate* fate = o.fate.data();
  // Counted in locals, not in an array indexed by the fate: that would chain every face to the
  // previous one through memory.
  uint64_t accepted = 0, rejected = 0;
  auto decide = [&](uint32_t f, Outcode all, Outcode any) {
    if (all) {
      fate[f] = Fate::rejected;
      ++rejected;
    } else if (!any) {
      fate[f] = Fate::accepted;
      ++accepted;
    } else {
      crossing.push_back({f, any});
    }
  };
  if (o.uniformFaceSize == 3) {  // triangles (the GPU's and the benchmark's meshes): no faceStart
    for (uint32_t f = begin; f < end; ++f) {
      const Outcode a = oc[idx[3 * f]], b = oc[idx[3 * f + 1]], c = oc[idx[3 * f + 2]];
      decide(f, Outcode(a & b & c), Outcode(a | b | c));
    }
  } else {
    for (uint32_t f = begin; f < end; ++f) {
      Outcode all = kAllPlanes, any = 0;
      for (uint32_t k = start[f]; k < start[f + 1]; ++k) {
        all &= oc[idx[k]];
        any |= oc[idx[k]];
      }
      decide(f, all, any);
    }
  }
  n.accepted += accepted;
  n.rejected += rejected;
}

// A cluster's faces decided at once (mesh.h FaceCluster; lecture notes 15.3.4): all accepted when no
// vertex of its intervals is outside a plane, all rejected when every one is outside the same plane.
enum class ClusterVerdict : uint8_t { inside, outside, mixed };
ClusterVerdict clusterVerdict(const ObjectRun& o, const FaceCluster& k) {
  if (k.runs == 0) return ClusterVerdict::mixed;
  const Outcode* oc = o.outcodes.data();
  Outcode all = kAllPlanes, any = 0;
  for (uint32_t r = 0; r < k.runs; ++r) {
    // Consecutive outcodes: the compiler's vector loop, given a count that cannot wrap (a 32-bit
    // `v <= last` could, for last = 2³² − 1, and kept the loop scalar: half the face pass's time).
    const Outcode* run = oc + k.first[r];
    const size_t n = size_t(k.last[r]) - k.first[r] + 1;
    for (size_t i = 0; i < n; ++i) {
      all &= run[i];
      any |= run[i];
    }
  }
  return all ? ClusterVerdict::outside : any ? ClusterVerdict::mixed : ClusterVerdict::inside;
}

// The faces [begin, end): a cluster at a time when its verdict decides its faces (the cluster's
// intervals read once instead of three outcodes a face), else face by face. A cluster's verdict holds
// for any of its faces, so a range that cuts a cluster (a run in steps) uses it too.
TrivialCounts decideFaces(ObjectRun& o, uint32_t begin, uint32_t end, std::vector<ClipCandidate>& crossing) {
  TrivialCounts n;
  for (uint32_t f = begin; f < end;) {
    const size_t c = f / FaceCluster::kFaces;
    const uint32_t stop = std::min(end, uint32_t((c + 1) * FaceCluster::kFaces));
    switch (c < o.faceClusters.size() ? clusterVerdict(o, o.faceClusters[c]) : ClusterVerdict::mixed) {
      case ClusterVerdict::inside:
        std::fill(o.fate.begin() + f, o.fate.begin() + stop, Fate::accepted);
        n.accepted += stop - f;
        break;
      case ClusterVerdict::outside:
        std::fill(o.fate.begin() + f, o.fate.begin() + stop, Fate::rejected);
        n.rejected += stop - f;
        break;
      case ClusterVerdict::mixed: decideEach(o, f, stop, crossing, n); break;
    }
    f = stop;
  }
  return n;
}

// Whether a pass over [begin, end) is shared between cores: then the faces and edges that cross a
// plane are clipped by their chunk's thread too, with clip values worked out anew (no shared cache).
bool onEveryCore(size_t begin, size_t end, bool parallel) {
  return parallel && parallelAvailable() && chunkCount(end - begin, kChunk) > 1;
}

// The faces [begin, end): decided by their outcodes in chunks, the crossing ones clipped, all in the
// faces' order (clippedFaces stays sorted however the run is cut). On every core each chunk clips its
// own crossing faces and the chunks join the run in order; on one, they are clipped into the run.
// finishFaces adds what is counted once per object.
template <class Source>
void clipFaces(ObjectRun& o, const Source& source, ClipScratch& scratch, std::vector<ChunkWork>& work,
               PipelineStats& stats, uint32_t begin, uint32_t end, bool everyCore) {
  const size_t chunks = chunkCount(end - begin, kChunk);
  if (work.size() < chunks) work.resize(chunks);
  std::atomic<uint64_t> accepted = 0, rejected = 0;
  forChunks(begin, end, everyCore, [&](size_t b, size_t e, size_t k) {
    ChunkWork& w = work[k];
    w.clear();
    const TrivialCounts n = decideFaces(o, uint32_t(b), uint32_t(e), w.crossing);
    accepted += n.accepted;
    rejected += n.rejected;
    // One core runs the chunks in order, so it clips into the run while the chunk's indices are near.
    if (everyCore) clipCrossing(o, source, w.scratch, w.crossing, w);
    else clipCrossing(o, source, scratch, w.crossing, o);
  });
  uint64_t clipped = 0;
  for (size_t k = 0; k < chunks; ++k) {
    clipped += work[k].crossing.size();
    if (everyCore) joinChunk(o, work[k]);
  }
  stats.polygonsTriviallyAccepted += accepted;
  stats.polygonsTriviallyRejected += rejected;
  stats.polygonsClippedAway += clipped;  // finishFaces moves those with something left to polygonsClipped
}

void finishFaces(const ObjectRun& o, PipelineStats& stats) {
  const uint64_t kept = o.clippedFaces.size();  // clipped with something left
  stats.polygonsClipped += kept;
  stats.polygonsClippedAway -= kept;
  stats.verticesCreated += o.createdNpcH.size();
}

void clipFaces(ObjectRun& o, const PipelineRun& run, ClipScratch& scratch, std::vector<ChunkWork>& work,
               PipelineStats& stats, uint32_t begin, uint32_t end) {
  const bool every = onEveryCore(begin, end, run.options.parallel), shared = !every;
  switch (o.strategy) {
    case ClipStrategy::npc: clipFaces(o, NpcSource{o}, scratch, work, stats, begin, end, every); break;
    case ClipStrategy::wc:
      clipFaces(o, WcSource{o, shared, run.npcFromWc}, scratch, work, stats, begin, end, every);
      break;
    case ClipStrategy::divideFirst:
      clipFaces(o, DivideFirstSource{o}, scratch, work, stats, begin, end, every);
      break;
  }
}

// The trivial decisions of the edges [begin, end) (as decideFaces'); the crossing ones listed.
TrivialCounts decideEdges(ObjectRun& o, size_t begin, size_t end, std::vector<ClipCandidate>& crossing) {
  const Edge* edges = o.edges.data();
  const Outcode* oc = o.outcodes.data();
  Fate* fate = o.edgeFate.data();
  uint64_t accepted = 0, rejected = 0;
  for (size_t i = begin; i < end; ++i) {
    const Outcode a = oc[edges[i].a], b = oc[edges[i].b];
    if (a & b) {
      fate[i] = Fate::rejected;
      ++rejected;
    } else if (!(a | b)) {
      fate[i] = Fate::accepted;
      ++accepted;
    } else {
      crossing.push_back({uint32_t(i), Outcode(a | b)});
    }
  }
  return {accepted, rejected};
}

// Over the edges [begin, end); edgeFate is sized by the object's start (startEdges). Decided and the
// crossing ones clipped as clipFaces does its faces, so that the clipped edges stay ascending however
// the run is cut.
void clipEdges(ObjectRun& o, std::vector<ChunkWork>& work, PipelineStats& stats, size_t begin, size_t end,
               bool parallel) {
  const size_t chunks = chunkCount(end - begin, kChunk);
  if (work.size() < chunks) work.resize(chunks);
  const bool everyCore = onEveryCore(begin, end, parallel);
  const bool shared = !everyCore && o.strategy == ClipStrategy::wc;  // as the faces' sources
  auto clip = [&o, shared](const ClipCandidate& c) {
    const Edge& e = o.edges[c.index];
    if (shared) return clipEdge(o.sharedClipValues(e.a), o.sharedClipValues(e.b), c.planes);
    return clipEdge(o.clipValuesOf(e.a), o.clipValuesOf(e.b), c.planes);
  };
  std::atomic<uint64_t> accepted = 0, rejected = 0;
  forChunks(begin, end, everyCore, [&](size_t b, size_t e, size_t k) {
    ChunkWork& w = work[k];
    w.clear();
    const TrivialCounts n = decideEdges(o, b, e, w.crossing);
    accepted += n.accepted;
    rejected += n.rejected;
    if (everyCore)
      for (const ClipCandidate& c : w.crossing) w.ranges.push_back(clip(c));
  });
  stats.edgesAccepted += accepted;
  stats.edgesRejected += rejected;
  for (size_t k = 0; k < chunks; ++k)
    for (size_t i = 0; i < work[k].crossing.size(); ++i) {
      const ClipCandidate& c = work[k].crossing[i];
      const EdgeRange r = everyCore ? work[k].ranges[i] : clip(c);
      o.edgeFate[c.index] = r.visible ? Fate::clipped : Fate::clippedAway;
      ++(r.visible ? stats.edgesClipped : stats.edgesRejected);
      if (!r.visible) continue;
      o.clippedEdges.push_back(c.index);
      o.clippedEdgeRanges.push_back(r);
    }
}

// lecture notes 15.3.4: one test of the object's bounding box can decide all its polygons at once.
BoxVerdict boxVerdict(const Mesh& mesh, const Mat4& npcFromMc, const std::vector<Vec4>& userPlanesNpc,
                      Outcode& common) {
  Outcode all = kAllPlanes, any = 0;
  for (const Vec3& corner : bounds(mesh).corners()) {
    const Vec4 h = npcFromMc * Vec4(corner, 1.0);
    Outcode c = outcodeOf(h);
    for (size_t k = 0; k < userPlanesNpc.size(); ++k)
      if (glm::dot(userPlanesNpc[k], h) < 0) c |= Outcode(1u << (kPlaneCount + k));
    all &= c;
    any |= c;
  }
  common = all;
  return all ? BoxVerdict::outside : any ? BoxVerdict::crossing : BoxVerdict::inside;
}

void decideByBox(ObjectRun& o, PipelineStats& stats) {
  const Mesh& mesh = *o.mesh;
  const bool inside = o.box == BoxVerdict::inside;
  std::fill(o.fate.begin(), o.fate.end(), inside ? Fate::accepted : Fate::rejected);
  ++(inside ? stats.objectsAcceptedByBox : stats.objectsRejectedByBox);
  stats.polygonsDecidedByBox += mesh.faceCount();
  if (!o.edges.empty()) {
    o.edgeFate.assign(o.edges.size(), inside ? Fate::accepted : Fate::rejected);
    (inside ? stats.edgesAccepted : stats.edgesRejected) += o.edges.size();
  }
}

// ---------------------------------------------------------------- 4 the run, in steps

// An object's start: its matrices, its arrays sized, its per-run state cleared, the box test.
void startObject(ObjectRun& o, const PipelineRun& run, PipelineStats& stats) {
  const Mesh& mesh = *o.mesh;
  o.vrcFromWc = run.vrcFromWc;
  o.npcFromMc = run.npcFromWc * o.wcFromMc;
  o.dcFromNpc = run.dcFromNpc;
  o.strategy = run.options.strategy;
  o.planesWc = frustumPlanesWc(run.npcFromWc);
  o.userForms = run.options.strategy == ClipStrategy::wc ? run.userPlanesWc : run.userPlanesNpc;
  stats.vertices += mesh.vertexCount();
  stats.verticesTransformed += mesh.vertexCount();
  stats.polygons += mesh.faceCount();

  // The per-vertex arrays grow with the vertex pass (passVertices): sizing a million vertices' at
  // once held the page's frame for a tenth of a second. The memory is taken here, untouched. Arrays
  // of the mesh's size already (the run before was of the same mesh) are only overwritten: emptied
  // and grown again, 16 MiB of zeros a million vertices were written on one core in every run.
  if (o.npcH.size() != mesh.vertexCount()) {
    o.npcH.clear();
    o.outcodes.clear();
    o.npcH.reserve(mesh.vertexCount());
    o.outcodes.reserve(mesh.vertexCount());
  }
  o.fate.resize(mesh.faceCount());
  o.clippedFaces.clear();
  o.clippedStart.assign(1, 0);
  o.clippedRefs.clear();
  o.createdNpcH.clear();
  o.createdOnPlanes.clear();
  o.values.clear();
  if (++o.generation == 0) {  // the slots' run numbers wrapped around: forget them all
    std::fill(o.valueSlots.begin(), o.valueSlots.end(), 0);
    o.generation = 1;
  }
  if (!run.options.clipEdges) o.edges.clear();  // else listed once per mesh (PipelineJob: startEdges)

  o.box = BoxVerdict::notTested;
  if (run.options.boundingBoxTest) {
    Outcode common = 0;
    o.box = boxVerdict(mesh, o.npcFromMc, run.userPlanesNpc, common);
    o.boxCode = o.box == BoxVerdict::inside ? 0 : common;
    ++stats.objectsBoxTested;
  }
  if (o.classified()) stats.verticesClassified += mesh.vertexCount();
}

// The object's edges known (listed, or none clipped): their ranges sized and counted.
void startEdges(ObjectRun& o, PipelineStats& stats) {
  o.edgeFate.resize(o.edges.size());
  o.clippedEdges.clear();
  o.clippedEdgeRanges.clear();
  stats.edges += o.edges.size();
}

// The units of work a cluster's listing counts for: three a face (a face's share of the sorting, 9 ns,
// is about three vertices of the vertex pass, a unit each), so that a step's budget takes as long in
// this phase as in the others.
constexpr uint64_t kClusterUnits = 3 * FaceCluster::kFaces;

// Whether the face pass has the mesh's clusters (or needs none: an object its box decides has no face pass).
bool clustersListed(const ObjectRun& o) {
  return !o.classified() || o.faceClusters.size() == clusterCount(*o.mesh);
}

// Clusters [from, to) of the object's mesh appended, in chunks of 512 (about a millisecond each; on
// every core when `parallel`).
void listClusters(ObjectRun& o, size_t from, size_t to, bool parallel) {
  o.faceClusters.resize(to);
  forChunks(
      from, to, parallel,
      [&](size_t b, size_t e, size_t) {
        std::vector<uint32_t> scratch;
        for (size_t c = b; c < e; ++c) o.faceClusters[c] = faceCluster(*o.mesh, c, scratch);
      },
      512);
}

// Vertices [begin, end) of an object started by startObject, in chunks (on every core when `parallel`).
void passVertices(ObjectRun& o, PipelineStats& stats, size_t begin, size_t end, bool parallel) {
  if (o.npcH.size() < end) {
    o.npcH.resize(end);
    o.outcodes.resize(end);
  }
  std::atomic<uint64_t> mapped = 0;
  forChunks(begin, end, parallel, [&](size_t b, size_t e, size_t) {
    if (o.classified()) {
      mapped += classifyVertices(o, b, e);
    } else {
      // Decided by the box: the vertices are transformed (and those inside counted as mapped), not classified.
      mapped += vertexPass(o, [code = o.boxCode](size_t, const Vec4&) { return code; }, b, e);
    }
  });
  stats.verticesOutput += mapped;
}

uint32_t uniformFaceSize(const Mesh& mesh) {
  if (mesh.faceCount() == 0) return 0;
  const uint32_t size = mesh.faceStart[1] - mesh.faceStart[0];
  for (size_t f = 1; f < mesh.faceCount(); ++f)
    if (mesh.faceStart[f + 1] - mesh.faceStart[f] != size) return 0;
  return size;
}

}  // namespace

// The run's phases for each object, in order; the units of work are its vertices, faces, edges.
// listEdges only for a mesh whose edges this run buffer has not listed yet (the viewer clips edges).
// listClusters for a mesh whose face clusters this run buffer has not listed yet.
enum class PipelineJob::Phase : uint8_t { start, listEdges, listClusters, vertices, faces, edges, finish };

PipelineJob::~PipelineJob() = default;

PipelineJob::PipelineJob(const Scene& scene, const PipelineOptions& options, PipelineRun& run)
    : run_(run) {
  // Every matrix first: an invalid camera or transform throws before `run` changes.
  const VrcAxes frame = vrcAxes(scene.camera);
  const Mat4 vrcFromWcM = vrcFromWc(frame, scene.camera.vrp);
  const Mat4 npcFromVrcM = npcFromVrc(scene.camera, frame);
  std::vector<Mat4> wcFromMcs;
  std::vector<size_t> visible;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& so = scene.objects[i];
    if (!so.visible || !so.mesh) continue;
    try {
      wcFromMcs.push_back(wcFromMc(so.transform));
    } catch (const Error& e) {
      throw Error("object \"" + so.name + "\": " + e.what());
    }
    visible.push_back(i);
  }

  run.camera = scene.camera;
  run.vrc = frame;
  run.device = scene.device;
  run.options = options;
  run.vrcFromWc = vrcFromWcM;
  run.npcFromVrc = npcFromVrcM;
  run.npcFromWc = npcFromVrcM * vrcFromWcM;
  run.wcFromVrc = glm::inverse(vrcFromWcM);
  run.wcFromNpc = glm::inverse(run.npcFromWc);
  run.dcFromNpc = dcFromNpc(scene.device);
  run.userPlanesWc.clear();
  run.userPlanesNpc.clear();
  // A plane's coefficients p (a row) keep the points x with p · x ≥ 0. Pulled back from WC to
  // homogeneous NPC: a point's x_npc = npcFromWc · x_wc with x_wc = (x, y, z, 1), so
  // x_wc = wcFromNpc · x_npc, and p_wc · x_wc = (p_wc · wcFromNpc) · x_npc: the same value at every
  // point (in front of the eye or behind it), so the NPC plane is the row p_npc = p_wc · wcFromNpc.
  // As columns, which is how GLM keeps the coefficients: p_npc = wcFromNpcᵀ · p_wc. Planes map by
  // the transpose of the inverse of the matrix that maps the points.
  const Mat4 npcPlaneFromWcPlane = glm::transpose(run.wcFromNpc);
  for (const UserClipPlane& p : scene.clipPlanes) {
    if (!p.enabled || run.userPlanesWc.size() == size_t(kMaxUserPlanes)) continue;
    run.userPlanesWc.push_back(p.coefficients());
    run.userPlanesNpc.push_back(npcPlaneFromWcPlane * p.coefficients());
  }
  run.sceneIndex = visible;
  run.stats = {};
  run.objects.resize(visible.size());
  for (size_t k = 0; k < visible.size(); ++k) {
    const SceneObject& so = scene.objects[visible[k]];
    ObjectRun& o = run.objects[k];
    if (o.mesh != so.mesh) {  // the edge list, the face size, the clusters and the value cache belong to the mesh
      o.edges.clear();
      o.faceClusters.clear();
      o.uniformFaceSize = uniformFaceSize(*so.mesh);
      o.valueSlots.clear();  // sized when first used (the WC strategy's clipping)
      o.generation = 0;
    }
    o.name = so.name;
    o.nameDe = so.nameDe;
    o.color = so.color;
    o.mesh = so.mesh;
    o.wcFromMc = wcFromMcs[k];
    total_ += so.mesh->vertexCount() + so.mesh->faceCount() + (options.clipEdges ? so.mesh->indices.size() / 2 : 0);  // edges: about half the corners
    if (options.clipEdges && o.edges.empty()) total_ += UniqueEdgesJob::units(*so.mesh);  // about: listing
    if (o.faceClusters.size() < clusterCount(*so.mesh)) total_ += clusterCount(*so.mesh) * kClusterUnits;
  }
  // The clipper's buffers grow to the largest face clipped (no pass over every face to size them).
  run.clipWork.scratch.a.reserve(16);
  run.clipWork.scratch.b.reserve(16);
}

bool PipelineJob::step(uint64_t budget) {
  PipelineRun& run = run_;
  while (!done() && budget > 0) {
    ObjectRun& o = run.objects[object_];
    // Takes up to `budget` units of the phase's `count`; returns the range [next_, end).
    auto take = [&](size_t count) {
      const size_t end = next_ + size_t(std::min<uint64_t>(budget, count - next_));
      budget -= end - next_;
      done_ += end - next_;
      return end;
    };
    auto nextPhase = [&](Phase p) {
      phase_ = p;
      next_ = 0;
    };
    switch (phase_) {
      case Phase::start:
        startObject(o, run, run.stats);
        if (run.options.clipEdges && o.edges.empty() && o.mesh->faceCount() > 0) {
          edgeJob_.emplace(*o.mesh);
          nextPhase(Phase::listEdges);
        } else {
          startEdges(o, run.stats);
          nextPhase(clustersListed(o) ? Phase::vertices : Phase::listClusters);
        }
        break;
      case Phase::listEdges: {
        const uint64_t units = std::min<uint64_t>(budget, UniqueEdgesJob::units(*o.mesh));
        const bool listed = edgeJob_->step(units);
        budget -= units;
        done_ += units;
        if (listed) {
          o.edges = edgeJob_->take();
          edgeJob_.reset();
          startEdges(o, run.stats);
          nextPhase(clustersListed(o) ? Phase::vertices : Phase::listClusters);
        }
        break;
      }
      case Phase::listClusters: {
        // From where the list ends (a dropped job may have left part of it), a cluster a step at least.
        const size_t from = o.faceClusters.size();
        const size_t to = from + size_t(std::min<uint64_t>(clusterCount(*o.mesh) - from,
                                                           std::max<uint64_t>(1, budget / kClusterUnits)));
        listClusters(o, from, to, run.options.parallel);
        const uint64_t units = (to - from) * kClusterUnits;
        budget -= std::min(budget, units);
        done_ += units;
        if (clustersListed(o)) nextPhase(Phase::vertices);
        break;
      }
      case Phase::vertices: {
        const size_t end = take(o.mesh->vertexCount());  // o.vertexCount() may grow with the pass
        passVertices(o, run.stats, next_, end, run.options.parallel);
        next_ = end;
        if (next_ == o.mesh->vertexCount()) nextPhase(o.classified() ? Phase::faces : Phase::finish);
        break;
      }
      case Phase::faces: {
        const size_t end = take(o.faceCount());
        clipFaces(o, run, run.clipWork.scratch, run.clipWork.chunks, run.stats, uint32_t(next_), uint32_t(end));
        next_ = end;
        if (next_ == o.faceCount()) {
          finishFaces(o, run.stats);
          nextPhase(Phase::edges);
        }
        break;
      }
      case Phase::edges: {
        const size_t end = take(o.edges.size());
        clipEdges(o, run.clipWork.chunks, run.stats, next_, end, run.options.parallel);
        next_ = end;
        if (next_ == o.edges.size()) nextPhase(Phase::finish);
        break;
      }
      case Phase::finish:
        if (!o.classified()) {
          decideByBox(o, run.stats);
          done_ += o.faceCount();
        }
        run.stats.verticesOutput += o.createdNpcH.size();  // mapped to DC where read (ObjectRun::createdDc)
        ++object_;
        nextPhase(Phase::start);
        break;
    }
  }
  if (done() && !finished_) {
    finished_ = true;
    run.stats.objects = run.objects.size();
    switch (run.options.strategy) {
      case ClipStrategy::npc: run.stats.operations = npcStrategyCost(run.stats); break;
      case ClipStrategy::wc: run.stats.operations = wcStrategyCost(run.stats); break;
      case ClipStrategy::divideFirst: run.stats.operations = divideFirstCost(run.stats); break;
    }
  }
  return finished_;
}

double PipelineJob::progress() const {
  if (finished_) return 1.0;
  return total_ ? std::min(0.99, double(done_) / double(total_)) : 0.0;
}

void runPipeline(const Scene& scene, const PipelineOptions& options, PipelineRun& run) {
  PipelineJob job(scene, options, run);
  job.step(std::numeric_limits<uint64_t>::max());
}

PipelineRun runPipeline(const Scene& scene, const PipelineOptions& options) {
  PipelineRun run;
  runPipeline(scene, options, run);
  return run;
}

}  // namespace vplab
