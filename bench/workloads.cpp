// Index: 1 the scene  2 the floor pass  3 the textbook baseline  4 the fairness check
//        5 the workloads  6 the report
#include "bench/workloads.h"

#include "pipeline/device_mapping.h"
#include "base/error.h"
#include "pipeline/modeling.h"
#include "pipeline/parallel.h"
#include "pipeline/primitives.h"
#include "pipeline/view_mapping.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <sstream>

namespace vplab::bench {

// ---------------------------------------------------------------- 1 the scene

Scene makeBenchScene(int segments) {
  Scene s;
  // The eye 4 units in front of the sphere's centre plane; the front plane F = 0.6 cuts the cap
  // nearest the eye, the right plane and the top plane cut its side (the sphere sits right of and
  // above the window's centre). B = −2 lies behind the sphere.
  s.camera = {.vrp = {0, 0, 0}, .prp = {0, 0, 4}, .vup = {0, 1, 0}, .window = {-1.2, 1.2, -0.9, 0.9},
              .front = 0.6, .back = -2, .projection = Projection::perspective};
  s.device = {1280, 960};

  SceneObject o;
  o.name = "sphere";
  o.shape = Shape::sphere;  // its triangulation: `mesh` below is what the pipeline uses
  o.segments = segments;
  o.color = {0.93, 0.75, 0.3};
  // Poles turned out of the view direction (a UV sphere's triangles crowd at the poles), then
  // shifted right by 0.65 so about half of the triangles lie outside the view volume.
  o.transform.translate = {0.65, 0.2, 0};
  o.transform.rotations = {{{1, 0, 0}, 90, {}}, {{0, 1, 0}, 20, {}}};
  o.transform.scale = {1, 1, 1};
  o.mesh = std::make_shared<const Mesh>(triangulated(sphere(segments)));
  s.objects.push_back(std::move(o));
  return s;
}

StageMatrices stageMatrices(const Scene& scene) {
  StageMatrices m;
  m.wcFromMc = wcFromMc(scene.objects.at(0).transform);
  m.vrcFromWc = vrcFromWc(scene.camera);
  m.npcFromVrc = npcFromVrc(scene.camera);
  m.dcFromNpc = dcFromNpc(scene.device);
  m.npcFromMc = m.npcFromVrc * m.vrcFromWc * m.wcFromMc;
  return m;
}

// ---------------------------------------------------------------- 2 the floor pass

void floorPass(const Mesh& mesh, const Mat4& npcFromMc, FloorBuffers& out) {
  const size_t n = mesh.positions.size();
  out.npcH.resize(n);
  out.outcodes.resize(n);
  const Vec4 c0(npcFromMc[0]), c1(npcFromMc[1]), c2(npcFromMc[2]), c3(npcFromMc[3]);
  const Vec3* in = mesh.positions.data();
  Vec4* npcH = out.npcH.data();
  Outcode* oc = out.outcodes.data();
  for (size_t i = 0; i < n; ++i) {
    const Vec4 p = c0 * in[i].x + c1 * in[i].y + c2 * in[i].z + c3;
    npcH[i] = p;
    // outcodeOf(boundaryCoordinates(p)) bit for bit, without the array in between: ~7% faster,
    // and a lower bound should be as fast as a straightforward loop can be.
    oc[i] = Outcode((p.x < 0) | (p.w - p.x < 0) << 1 | (p.y < 0) << 2 | (p.w - p.y < 0) << 3 |
                    (p.z < 0) << 4 | (p.w - p.z < 0) << 5);
  }
}

// ---------------------------------------------------------------- 3 the textbook baseline

namespace {

// Written as a student would, straight from the lecture: no shared vertices, no outcodes, no
// trivial accept or reject, every polygon through all six planes. It is not a straw man either:
// each std::vector is reserved once, so it allocates exactly once per plane pass (plus the input
// polygon and the DC polygon), not once per push_back.

double boundaryValue(const Vec4& p, int plane) {
  switch (plane) {
    case 0: return p.x;        // left    x >= 0
    case 1: return p.w - p.x;  // right   x <= w
    case 2: return p.y;        // bottom  y >= 0
    case 3: return p.w - p.y;  // top     y <= w
    case 4: return p.z;        // back    z >= 0
    default: return p.w - p.z; // front   z <= w
  }
}

// One Sutherland–Hodgman pass: a new polygon with the part of `in` where the boundary value >= 0.
std::vector<Vec4> clipAgainstPlane(const std::vector<Vec4>& in, int plane) {
  std::vector<Vec4> out;
  if (in.empty()) return out;
  out.reserve(in.size() + 1);
  Vec4 s = in.back();
  for (const Vec4& p : in) {
    const double bs = boundaryValue(s, plane);
    const double bp = boundaryValue(p, plane);
    if (bp >= 0) {
      if (bs < 0) out.push_back(s + (bs / (bs - bp)) * (p - s));
      out.push_back(p);
    } else if (bs >= 0) {
      out.push_back(s + (bs / (bs - bp)) * (p - s));
    }
    s = p;
  }
  return out;
}

}  // namespace

TextbookPolygons textbookPipeline(const Mesh& mesh, const StageMatrices& m) {
  TextbookPolygons result;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto face = mesh.face(f);
    // Stages 1–3 for every vertex of this polygon, one 4 × 4 product per stage.
    std::vector<Vec4> polygon;
    polygon.reserve(face.size());
    for (uint32_t v : face) {
      const Vec4 mc(mesh.positions[v], 1.0);
      const Vec4 wc = m.wcFromMc * mc;
      const Vec4 vrc = m.vrcFromWc * wc;
      const Vec4 npc = m.npcFromVrc * vrc;
      polygon.push_back(npc);
    }
    // Stage 4: Sutherland–Hodgman against the six planes of the unit cube, before the division.
    for (int plane = 0; plane < 6; ++plane) polygon = clipAgainstPlane(polygon, plane);
    if (polygon.size() < 3) continue;
    // Stage 5: divide by w, then the fourth matrix.
    std::vector<Vec3> dc;
    dc.reserve(polygon.size());
    for (const Vec4& p : polygon) dc.push_back(Vec3(m.dcFromNpc * Vec4(Vec3(p) / p.w, 1.0)));
    result.push_back(std::move(dc));
  }
  return result;
}

// ---------------------------------------------------------------- 4 the fairness check

namespace {

template <class Corner>
void addPolygon(VisibleSummary& s, size_t n, Corner corner) {
  ++s.polygons;
  s.vertices += n;
  double twiceArea = 0;
  for (size_t i = 0; i < n; ++i) {
    const Vec3 p = corner(i), q = corner((i + 1) % n);
    s.sumX += p.x;
    s.sumY += p.y;
    s.sumZ += p.z;
    twiceArea += p.x * q.y - q.x * p.y;
  }
  s.area += 0.5 * std::abs(twiceArea);
}

bool near(double a, double b, double tolerance) {
  return std::abs(a - b) <= tolerance * std::max({std::abs(a), std::abs(b), 1.0});
}

}  // namespace

VisibleSummary summarize(const PipelineRun& run) {
  VisibleSummary s;
  for (const ObjectRun& o : run.objects)
    for (size_t f = 0; f < o.faceCount(); ++f) {
      if (o.fate[f] != Fate::accepted && o.fate[f] != Fate::clipped) continue;
      const auto face = o.clippedFace(f);
      addPolygon(s, face.size(), [&](size_t i) { return o.clippedDc(face[i]); });
    }
  return s;
}

VisibleSummary summarize(const TextbookPolygons& polygons) {
  VisibleSummary s;
  for (const auto& polygon : polygons) addPolygon(s, polygon.size(), [&](size_t i) { return polygon[i]; });
  return s;
}

CheckResult checkSameVisibleResult(const PipelineRun& run, const TextbookPolygons& textbook,
                                   double tolerance) {
  CheckResult r;
  r.tolerance = tolerance;
  r.pipeline = summarize(run);
  r.textbook = summarize(textbook);
  std::ostringstream why;
  why.precision(17);
  const VisibleSummary &a = r.pipeline, &b = r.textbook;
  if (a.polygons != b.polygons) why << "visible polygons " << a.polygons << " vs " << b.polygons << "; ";
  if (a.vertices != b.vertices) why << "vertices " << a.vertices << " vs " << b.vertices << "; ";
  const std::pair<const char*, std::pair<double, double>> sums[] = {
      {"sum x", {a.sumX, b.sumX}}, {"sum y", {a.sumY, b.sumY}},
      {"sum z", {a.sumZ, b.sumZ}}, {"area", {a.area, b.area}}};
  for (const auto& [name, v] : sums)
    if (!near(v.first, v.second, tolerance)) why << name << " " << v.first << " vs " << v.second << "; ";
  r.message = why.str();
  if (!r.message.empty()) r.message = "pipeline vs textbook differ: " + r.message.substr(0, r.message.size() - 2);
  r.ok = r.message.empty();
  return r;
}

// ---------------------------------------------------------------- 5 the workloads

Workloads::Workloads(int segments) : scene_(makeBenchScene(segments)), matrices_(stageMatrices(scene_)) {}

void Workloads::fullPipeline() { runPipeline(scene_, options_, run_); }

void Workloads::everyCore() {
  PipelineOptions o = options_;
  o.parallel = true;
  runPipeline(scene_, o, everyCoreRun_);
}

void Workloads::floor() { floorPass(mesh(), matrices_.npcFromMc, floor_); }

void Workloads::textbook() { textbook_ = textbookPipeline(mesh(), matrices_); }

// ---------------------------------------------------------------- 6 the report

namespace {

using Json = nlohmann::ordered_json;

double threadCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

template <class T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// The every-core run against the one-core run, bit for bit: the counts, every vertex's homogeneous
// NPC and outcode, every face's fate, the clipped polygons and the vertices clipping created.
bool sameResult(const PipelineRun& one, const PipelineRun& every) {
  if (std::memcmp(&one.stats, &every.stats, sizeof one.stats) != 0) return false;
  if (one.objects.size() != every.objects.size()) return false;
  for (size_t k = 0; k < one.objects.size(); ++k) {
    const ObjectRun &a = one.objects[k], &b = every.objects[k];
    if (!sameBytes(a.npcH, b.npcH) || !sameBytes(a.outcodes, b.outcodes) || !sameBytes(a.fate, b.fate) ||
        !sameBytes(a.clippedFaces, b.clippedFaces) || !sameBytes(a.clippedStart, b.clippedStart) ||
        !sameBytes(a.clippedRefs, b.clippedRefs) || !sameBytes(a.createdNpcH, b.createdNpcH) ||
        !sameBytes(a.createdOnPlanes, b.createdOnPlanes) || !sameBytes(a.edgeFate, b.edgeFate))
      return false;
  }
  return true;
}

template <class F>
void time(WorkloadTiming& t, F&& f) {
  const double cpu0 = threadCpuMs();
  const auto t0 = std::chrono::steady_clock::now();
  f();
  const auto t1 = std::chrono::steady_clock::now();
  const double cpu1 = threadCpuMs();
  t.samplesMs.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  t.cpuSamplesMs.push_back(cpu1 - cpu0);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void finish(WorkloadTiming& t) {
  t.medianMs = median(t.samplesMs);
  t.minMs = *std::min_element(t.samplesMs.begin(), t.samplesMs.end());
  t.cpuMedianMs = median(t.cpuSamplesMs);
}

Json toJson(const VisibleSummary& s) {
  return {{"polygons", s.polygons}, {"vertices", s.vertices}, {"sum_x", s.sumX},
          {"sum_y", s.sumY},        {"sum_z", s.sumZ},        {"area", s.area}};
}

}  // namespace

BenchReport runPipelineBenchmarks(int repetitions, int segments) {
  if (repetitions < 1) throw Error("the benchmark needs at least 1 repetition, not " + std::to_string(repetitions));
  Workloads w(segments);
  BenchReport r;
  r.repetitions = repetitions;
  r.segments = segments;

  // Warm-up: the first pipeline run sizes its buffers, the first floor pass its arrays; the
  // textbook's first result is checked against the pipeline's.
  w.fullPipeline();
  w.floor();
  w.textbook();
  w.everyCore();
  r.check = checkSameVisibleResult(w.run(), w.textbookResult());
  r.everyCoreSameResult = sameResult(w.run(), w.everyCoreRun());

  // Each timed call follows a call of the same workload: every workload is measured in its steady
  // state (as the viewer runs the pipeline frame after frame), not cold after another one has
  // thrashed the caches (the textbook's allocations in particular). The workloads of a millisecond or
  // two are timed kShortSamples times a round, the textbook's (a tenth of a second) once: a median of
  // 5 samples of a millisecond moved with a moment's load on the shared machine (one core / every
  // core 1.54 in one run, 1.78–1.94 in the runs around it).
  auto sample = [&](WorkloadTiming& t, auto&& workload) {
    workload();
    for (int k = 0; k < BenchReport::kShortSamples; ++k) time(t, workload);
  };
  for (int i = 0; i < repetitions; ++i) {
    sample(r.full, [&] { w.fullPipeline(); });
    sample(r.floor, [&] { w.floor(); });
    w.textbook();
    time(r.textbook, [&] { w.textbook(); });
    sample(r.everyCore, [&] { w.everyCore(); });
  }
  finish(r.full);
  finish(r.floor);
  finish(r.textbook);
  finish(r.everyCore);
  r.cores = parallelThreads();
  r.oneOverEveryCore = r.full.medianMs / r.everyCore.medianMs;
  r.oneOverEveryCoreMet = r.oneOverEveryCore >= BenchReport::everyCoreTarget(r.cores);

  const PipelineStats& st = w.run().stats;
  r.triangles = st.polygons;
  r.vertices = st.vertices;
  r.accepted = st.polygonsTriviallyAccepted;
  r.rejected = st.polygonsTriviallyRejected;
  r.clipped = st.polygonsClipped;
  r.clippedAway = st.polygonsClippedAway;
  r.verticesCreated = st.verticesCreated;
  r.outsideOrCrossing = r.triangles ? double(r.rejected + r.clipped + r.clippedAway) / double(r.triangles) : 0;

  r.fullOverFloor = r.full.medianMs / r.floor.medianMs;
  r.textbookOverFull = r.textbook.medianMs / r.full.medianMs;
  r.fullOverFloorCpu = r.full.cpuMedianMs / r.floor.cpuMedianMs;
  r.textbookOverFullCpu = r.textbook.cpuMedianMs / r.full.cpuMedianMs;
  r.fullOverFloorMet = r.fullOverFloorCpu <= BenchReport::kFullOverFloorTarget;  // see BenchReport
  r.textbookOverFullMet = r.textbookOverFull >= BenchReport::kTextbookOverFullTarget;
  return r;
}

Json toJson(const BenchReport& r) {
  auto three = [&](auto get) {
    return Json{{"full_pipeline", get(r.full)}, {"floor_pass", get(r.floor)}, {"textbook", get(r.textbook)}};
  };
  Json j;
  j["benchmark"] = "pipeline";
#ifdef NDEBUG
  j["optimized_build"] = true;
#else
  j["optimized_build"] = false;  // assertions on: the figures mean little
#endif
  j["repetitions"] = r.repetitions;
  j["samples_each_round"] = {{"full_pipeline", BenchReport::kShortSamples},
                             {"floor_pass", BenchReport::kShortSamples},
                             {"every_core", BenchReport::kShortSamples},
                             {"textbook", 1}};
  j["threads"] = 1;  // full, floor and textbook; every core: "every_core"
  j["scene"] = {{"segments", r.segments},
                {"triangles", r.triangles},
                {"vertices", r.vertices},
                {"accepted", r.accepted},
                {"rejected", r.rejected},
                {"clipped", r.clipped},
                {"clipped_away", r.clippedAway},
                {"vertices_created", r.verticesCreated},
                {"outside_or_crossing", r.outsideOrCrossing}};
  j["median_ms"] = three([](const WorkloadTiming& t) { return t.medianMs; });
  j["ratios"] = {{"full_over_floor", r.fullOverFloor}, {"textbook_over_full", r.textbookOverFull}};
  j["targets"] = {{"full_over_floor_max", BenchReport::kFullOverFloorTarget},
                  {"full_over_floor_met", r.fullOverFloorMet},
                  {"textbook_over_full_min", BenchReport::kTextbookOverFullTarget},
                  {"textbook_over_full_met", r.textbookOverFullMet}};
  // On a shared machine: the fastest call, and the CPU time (without waiting for a core).
  j["min_ms"] = three([](const WorkloadTiming& t) { return t.minMs; });
  j["median_cpu_ms"] = three([](const WorkloadTiming& t) { return t.cpuMedianMs; });
  j["ratios_cpu"] = {{"full_over_floor", r.fullOverFloorCpu}, {"textbook_over_full", r.textbookOverFullCpu}};
  j["samples_ms"] = three([](const WorkloadTiming& t) { return t.samplesMs; });
  j["every_core"] = {{"threads", r.cores},
                     {"median_ms", r.everyCore.medianMs},
                     {"min_ms", r.everyCore.minMs},
                     {"samples_ms", r.everyCore.samplesMs},
                     {"one_core_over_every_core", r.oneOverEveryCore},
                     {"target_min", BenchReport::everyCoreTarget(r.cores)},
                     {"target_met", r.oneOverEveryCoreMet},
                     {"same_result_bit_for_bit", r.everyCoreSameResult}};
  j["check"] = {{"ok", r.check.ok},
                {"tolerance", r.check.tolerance},
                {"message", r.check.message},
                {"pipeline", toJson(r.check.pipeline)},
                {"textbook", toJson(r.check.textbook)}};
  return j;
}


}  // namespace vplab::bench
