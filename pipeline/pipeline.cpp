// Index: 1 names  2 stages 1–3 (batch transforms)  3 stage 4 (classification, per-face clipping,
//        edges, bounding box)  4 stage 5 (division, device mapping)  5 the run
#include "pipeline/pipeline.h"

#include "pipeline/error.h"
#include "pipeline/view_mapping.h"

namespace vplab {

// ---------------------------------------------------------------- 1 names

std::string_view toString(ClipStrategy s) {
  switch (s) {
    case ClipStrategy::npc: return "npc";
    case ClipStrategy::wc: return "wc";
    case ClipStrategy::divideFirst: return "divide-first";
  }
  return "?";
}

std::optional<ClipStrategy> clipStrategyFromString(std::string_view s) {
  for (ClipStrategy c : {ClipStrategy::npc, ClipStrategy::wc, ClipStrategy::divideFirst})
    if (toString(c) == s) return c;
  return std::nullopt;
}

std::string_view toString(Fate f) {
  switch (f) {
    case Fate::accepted: return "accepted";
    case Fate::rejected: return "rejected";
    case Fate::clipped: return "clipped";
    case Fate::clippedAway: return "clipped_away";
  }
  return "?";
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
    if (ref < bc.size())
      for (int p = 0; p < kPlaneCount; ++p) on |= unsigned(bc[ref][p] == 0) << p;
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

constexpr Outcode kAllPlanes = (1u << kMaxClipPlanes) - 1;

// ---------------------------------------------------------------- 2 stages 1–3

// Stages 1 and 2 are affine: 9 multiplications per point, no w.
void transformAffine(const Mat4& m, std::span<const Vec3> in, std::vector<Vec3>& out) {
  out.resize(in.size());
  const Vec3 c0(m[0]), c1(m[1]), c2(m[2]), c3(m[3]);
  Vec3* o = out.data();
  for (size_t i = 0; i < in.size(); ++i) o[i] = c0 * in[i].x + c1 * in[i].y + c2 * in[i].z + c3;
}

// Stage 3 is projective: the result keeps its w (in VRC → homogeneous NPC).
void transformProjective(const Mat4& m, std::span<const Vec3> in, std::vector<Vec4>& out) {
  out.resize(in.size());
  const Vec4 c0(m[0]), c1(m[1]), c2(m[2]), c3(m[3]);
  Vec4* o = out.data();
  for (size_t i = 0; i < in.size(); ++i) o[i] = c0 * in[i].x + c1 * in[i].y + c2 * in[i].z + c3;
}

// ---------------------------------------------------------------- 3 stage 4

// How each strategy presents a mesh vertex to the clipper, and what a created vertex becomes.
struct NpcSource {
  const ObjectRun& o;
  ClipVertex vertex(uint32_t v) const { return {o.npcH[v], o.clipValuesOf(v), v}; }
  Vec4 npcH(const ClipVertex& c) const {
    Vec4 p = c.p;
    snapToPlanes(p, c.onPlanes);
    return p;
  }
};

struct WcSource {
  const ObjectRun& o;
  const Mat4& npcFromWc;
  ClipVertex vertex(uint32_t v) const { return {Vec4(o.wc[v], 1.0), o.clipValuesOf(v), v}; }
  Vec4 npcH(const ClipVertex& c) const {
    Vec4 p = npcFromWc * c.p;  // the plane equations were exact in WC; snap away the rounding
    snapToPlanes(p, c.onPlanes);
    return p;
  }
};

struct DivideFirstSource {
  const ObjectRun& o;
  ClipVertex vertex(uint32_t v) const { return {Vec4(divideByW(o.npcH[v]), 1.0), o.clipValuesOf(v), v}; }
  Vec4 npcH(const ClipVertex& c) const {
    Vec4 p = c.p;
    snapToPlanes(p, c.onPlanes);
    return p;
  }
};

void classifyNpc(ObjectRun& o) {
  const size_t n = o.npcH.size();
  o.bc.resize(n);
  o.outcodes.resize(n);
  for (size_t i = 0; i < n; ++i) {
    o.bc[i] = boundaryCoordinates(o.npcH[i]);
    o.outcodes[i] = outcodeOf(o.bc[i]);
  }
}

void classifyWc(ObjectRun& o, const std::array<Vec4, kPlaneCount>& planes) {
  const size_t n = o.wc.size();
  o.bc.resize(n);
  o.outcodes.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const Vec4 p(o.wc[i], 1.0);
    for (int k = 0; k < kPlaneCount; ++k) o.bc[i][k] = glm::dot(planes[k], p);
    o.outcodes[i] = outcodeOf(o.bc[i]);
  }
}

void classifyDivideFirst(ObjectRun& o) {
  const size_t n = o.npcH.size();
  o.bc.resize(n);
  o.outcodes.resize(n);
  for (size_t i = 0; i < n; ++i) {
    o.bc[i] = boundaryCoordinates(Vec4(divideByW(o.npcH[i]), 1.0));
    o.outcodes[i] = outcodeOf(o.bc[i]);
  }
}

// The user clip planes (seed 003): one more linear form per plane, evaluated where the strategy
// clips (homogeneous NPC, WC, or NPC after the division), its sign in outcode bits 6 … 11.
void classifyUserPlanes(ObjectRun& o, const PipelineRun& run) {
  const size_t planes = run.userPlanesWc.size();
  o.userPlaneCount = int(planes);
  if (planes == 0) {
    o.userValues.clear();
    return;
  }
  const size_t n = o.npcH.size();
  o.userValues.resize(n);
  for (size_t i = 0; i < n; ++i) {
    Vec4 p = o.npcH[i];
    switch (run.options.strategy) {
      case ClipStrategy::npc: p = o.npcH[i]; break;
      case ClipStrategy::wc: p = Vec4(o.wc[i], 1.0); break;
      case ClipStrategy::divideFirst: p = Vec4(divideByW(o.npcH[i]), 1.0); break;
    }
    const std::vector<Vec4>& forms = run.options.strategy == ClipStrategy::wc ? run.userPlanesWc : run.userPlanesNpc;
    for (size_t k = 0; k < planes; ++k) {
      const double u = glm::dot(forms[k], p);
      o.userValues[i][k] = u;
      if (u < 0) o.outcodes[i] |= Outcode(1u << (kPlaneCount + k));
    }
  }
}

// Trivial accept and reject by the outcodes (seed 15.2.4), Sutherland–Hodgman for the rest.
template <class Source>
void clipFaces(ObjectRun& o, const Source& source, ClipScratch& scratch, PipelineStats& stats) {
  const Mesh& mesh = *o.mesh;
  const size_t faces = mesh.faceCount();
  const uint32_t nv = uint32_t(o.vertexCount());
  const uint32_t* idx = mesh.indices.data();
  const uint32_t* start = mesh.faceStart.data();
  const Outcode* oc = o.outcodes.data();
  o.clippedRefs.reserve(mesh.indices.size());
  for (size_t f = 0; f < faces; ++f) {
    o.clippedStart[f] = uint32_t(o.clippedRefs.size());
    const uint32_t b = start[f], e = start[f + 1];
    Outcode all = kAllPlanes, any = 0;
    for (uint32_t k = b; k < e; ++k) {
      all &= oc[idx[k]];
      any |= oc[idx[k]];
    }
    if (all) {
      o.fate[f] = Fate::rejected;
      ++stats.polygonsTriviallyRejected;
    } else if (!any) {
      o.clippedRefs.insert(o.clippedRefs.end(), idx + b, idx + e);
      o.fate[f] = Fate::accepted;
      ++stats.polygonsTriviallyAccepted;
    } else {
      scratch.a.clear();
      for (uint32_t k = b; k < e; ++k) scratch.a.push_back(source.vertex(idx[k]));
      const auto out = clipPolygon(any, scratch);
      o.fate[f] = out.empty() ? Fate::clippedAway : Fate::clipped;
      ++(out.empty() ? stats.polygonsClippedAway : stats.polygonsClipped);
      for (const ClipVertex& c : out) {
        if (c.source != ClipVertex::kCreated) {
          o.clippedRefs.push_back(c.source);
          continue;
        }
        o.clippedRefs.push_back(nv + uint32_t(o.createdNpcH.size()));
        o.createdNpcH.push_back(source.npcH(c));
        o.createdOnPlanes.push_back(c.onPlanes);
      }
    }
  }
  o.clippedStart[faces] = uint32_t(o.clippedRefs.size());
  stats.verticesCreated += o.createdNpcH.size();
}

void clipEdges(ObjectRun& o, PipelineStats& stats) {
  o.edgeRanges.resize(o.edges.size());
  for (size_t i = 0; i < o.edges.size(); ++i) {
    const Edge& e = o.edges[i];
    const Outcode a = o.outcodes[e.a], b = o.outcodes[e.b];
    if (a & b) {
      o.edgeRanges[i] = {0, 0, false};
      ++stats.edgesRejected;
    } else if (!(a | b)) {
      o.edgeRanges[i] = {0, 1, true};
      ++stats.edgesAccepted;
    } else {
      o.edgeRanges[i] = clipEdge(o.clipValuesOf(e.a), o.clipValuesOf(e.b), a | b);
      ++(o.edgeRanges[i].visible ? stats.edgesClipped : stats.edgesRejected);
    }
  }
}

// Seed 15.3.4: one test of the object's bounding box can decide all its polygons at once.
BoxVerdict boxVerdict(const Mesh& mesh, const Mat4& npcFromMc, const std::vector<Vec4>& userPlanesNpc,
                      Outcode& common) {
  Outcode all = kAllPlanes, any = 0;
  for (const Vec3& corner : bounds(mesh).corners()) {
    const Vec4 h = npcFromMc * Vec4(corner, 1.0);
    Outcode c = outcodeOf(boundaryCoordinates(h));
    for (size_t k = 0; k < userPlanesNpc.size(); ++k)
      if (glm::dot(userPlanesNpc[k], h) < 0) c |= Outcode(1u << (kPlaneCount + k));
    all &= c;
    any |= c;
  }
  common = all;
  return all ? BoxVerdict::outside : any ? BoxVerdict::crossing : BoxVerdict::inside;
}

void decideByBox(ObjectRun& o, BoxVerdict verdict, Outcode common, PipelineStats& stats) {
  const Mesh& mesh = *o.mesh;
  const bool inside = verdict == BoxVerdict::inside;
  o.bc.clear();
  o.outcodes.assign(o.vertexCount(), inside ? 0 : common);
  std::fill(o.fate.begin(), o.fate.end(), inside ? Fate::accepted : Fate::rejected);
  if (inside) {
    o.clippedRefs = mesh.indices;
    std::copy(mesh.faceStart.begin(), mesh.faceStart.end(), o.clippedStart.begin());
  } else {
    std::fill(o.clippedStart.begin(), o.clippedStart.end(), 0u);
  }
  ++(inside ? stats.objectsAcceptedByBox : stats.objectsRejectedByBox);
  stats.polygonsDecidedByBox += mesh.faceCount();
  if (!o.edges.empty()) {
    o.edgeRanges.assign(o.edges.size(), inside ? EdgeRange{0, 1, true} : EdgeRange{0, 0, false});
    (inside ? stats.edgesAccepted : stats.edgesRejected) += o.edges.size();
  }
}

// ---------------------------------------------------------------- 4 stage 5

// Divide by w only now, after clipping: every vertex used has w > 0.
void mapToDevice(ObjectRun& o, const Mat4& dcFromNpc, PipelineStats& stats) {
  const size_t n = o.vertexCount();
  o.dc.resize(n);
  uint64_t mapped = 0;
  for (size_t i = 0; i < n; ++i) {
    if (o.outcodes[i] != 0) {
      o.dc[i] = Vec3(0);  // not used by any clipped polygon
      continue;
    }
    o.dc[i] = Vec3(dcFromNpc * Vec4(divideByW(o.npcH[i]), 1.0));
    ++mapped;
  }
  o.createdDc.resize(o.createdNpcH.size());
  for (size_t i = 0; i < o.createdNpcH.size(); ++i)
    o.createdDc[i] = Vec3(dcFromNpc * Vec4(divideByW(o.createdNpcH[i]), 1.0));
  stats.verticesOutput += mapped + o.createdNpcH.size();
}

// ---------------------------------------------------------------- 5 the run

void runObject(ObjectRun& o, const PipelineRun& run, ClipScratch& scratch, PipelineStats& stats) {
  const Mesh& mesh = *o.mesh;
  // Stages 1–3, each a batch over the whole vertex array.
  transformAffine(o.wcFromMc, mesh.positions, o.wc);
  transformAffine(run.vrcFromWc, o.wc, o.vrc);
  transformProjective(run.npcFromVrc, o.vrc, o.npcH);
  stats.vertices += mesh.vertexCount();
  stats.verticesTransformed += mesh.vertexCount();
  stats.polygons += mesh.faceCount();

  o.fate.resize(mesh.faceCount());
  o.clippedStart.resize(mesh.faceCount() + 1);
  o.clippedRefs.clear();
  o.createdNpcH.clear();
  o.createdOnPlanes.clear();
  if (run.options.clipEdges && o.edges.empty()) o.edges = uniqueEdges(mesh);
  if (!run.options.clipEdges) o.edges.clear();
  o.edgeRanges.clear();
  stats.edges += o.edges.size();

  // Stage 4.
  o.box = BoxVerdict::notTested;
  if (run.options.boundingBoxTest) {
    Outcode common = 0;
    o.box = boxVerdict(mesh, run.npcFromWc * o.wcFromMc, run.userPlanesNpc, common);
    ++stats.objectsBoxTested;
    if (o.box != BoxVerdict::crossing) decideByBox(o, o.box, common, stats);
  }
  if (o.box == BoxVerdict::notTested || o.box == BoxVerdict::crossing) {
    stats.verticesClassified += mesh.vertexCount();
    switch (run.options.strategy) {
      case ClipStrategy::npc: classifyNpc(o); break;
      case ClipStrategy::wc: classifyWc(o, frustumPlanesWc(run.npcFromWc)); break;
      case ClipStrategy::divideFirst: classifyDivideFirst(o); break;
    }
    classifyUserPlanes(o, run);
    switch (run.options.strategy) {
      case ClipStrategy::npc: clipFaces(o, NpcSource{o}, scratch, stats); break;
      case ClipStrategy::wc: clipFaces(o, WcSource{o, run.npcFromWc}, scratch, stats); break;
      case ClipStrategy::divideFirst: clipFaces(o, DivideFirstSource{o}, scratch, stats); break;
    }
    if (!o.edges.empty()) clipEdges(o, stats);
  }

  // Stage 5.
  mapToDevice(o, run.dcFromNpc, stats);
}

}  // namespace

void runPipeline(const Scene& scene, const PipelineOptions& options, PipelineRun& run) {
  // Every matrix first: an invalid camera or transform throws before `run` changes.
  const ViewFrame frame = viewFrame(scene.camera);
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
  run.frame = frame;
  run.device = scene.device;
  run.options = options;
  run.vrcFromWc = vrcFromWcM;
  run.npcFromVrc = npcFromVrcM;
  run.npcFromWc = npcFromVrcM * vrcFromWcM;
  run.dcFromNpc = dcFromNpc(scene.device);
  run.userPlanesWc.clear();
  run.userPlanesNpc.clear();
  const Mat4 npcToWcTransposed = glm::transpose(glm::inverse(run.npcFromWc));
  for (const UserClipPlane& p : scene.clipPlanes) {
    if (!p.enabled || run.userPlanesWc.size() == size_t(kMaxUserPlanes)) continue;
    run.userPlanesWc.push_back(p.coefficients());
    run.userPlanesNpc.push_back(npcToWcTransposed * p.coefficients());  // plane_wc · wcFromNpc
  }
  run.sceneIndex = visible;
  run.stats = {};
  run.objects.resize(visible.size());

  ClipScratch scratch;
  size_t maxFace = 0;
  for (size_t i : visible) maxFace = std::max(maxFace, scene.objects[i].mesh->maxFaceSize());
  scratch.a.reserve(maxFace + kPlaneCount);
  scratch.b.reserve(maxFace + kPlaneCount);

  for (size_t k = 0; k < visible.size(); ++k) {
    const SceneObject& so = scene.objects[visible[k]];
    ObjectRun& o = run.objects[k];
    if (o.mesh != so.mesh) o.edges.clear();  // the edge list belongs to the mesh
    o.name = so.name;
    o.color = so.color;
    o.mesh = so.mesh;
    o.wcFromMc = wcFromMcs[k];
    runObject(o, run, scratch, run.stats);
  }
  run.stats.objects = visible.size();
  switch (options.strategy) {
    case ClipStrategy::npc: run.stats.operations = npcStrategyCost(run.stats); break;
    case ClipStrategy::wc: run.stats.operations = wcStrategyCost(run.stats); break;
    case ClipStrategy::divideFirst: run.stats.operations = divideFirstCost(run.stats); break;
  }
}

PipelineRun runPipeline(const Scene& scene, const PipelineOptions& options) {
  PipelineRun run;
  runPipeline(scene, options, run);
  return run;
}

}  // namespace vplab
