// The workloads of the pipeline benchmark (`bench_pipeline` and `vplab bench --json`), shared by both
// so they measure the same thing:
//
//   full pipeline  vplab::runPipeline over a sphere of about 1M triangles, about half of them outside
//                  or crossing the view volume, reusing one PipelineRun from call to call (as the
//                  viewer does every frame), on one core;
//   every core     the same run on every core (PipelineOptions::parallel; the viewer's), which must
//                  give the one-core run's result bit for bit;
//   floor pass     the lower bound of any pipeline: each mesh vertex transformed once with the one
//                  composite npcFromMc and classified (outcode), both written to arrays;
//   textbook       a straightforward student implementation: per polygon, per vertex, the four
//                  matrices applied one after another (no vertex shared between polygons), then
//                  Sutherland–Hodgman in homogeneous coordinates with a new std::vector per plane,
//                  then the division and DC into a std::vector per polygon.
//
// Targets (issue 11): full pipeline within 1.5× of the floor pass, at least 10× faster than the
// textbook baseline; (issue 42) every core at least 1.7× faster than one on 2 cores, 0.8× the cores
// beyond. checkSameVisibleResult makes sure the textbook baseline draws what the pipeline
// draws, so the comparison is fair.
#pragma once

#include "pipeline/pipeline.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace vplab::bench {

/// Segments of the benchmark sphere: sphere(n) has n triangles at each pole and n(n/2 − 2) quads,
/// so its triangulation has n² − 2n triangles: 1,002,000 for n = 1002 (501,002 vertices).
inline constexpr int kBenchSegments = 1002;

/// The benchmark scene: one sphere (the triangulation of sphere(segments), radius 1) placed so that
/// the right, top and front planes of a perspective view volume cut it, leaving about half of its
/// triangles outside or crossing (for n = 1002: 503,018 accepted, 495,733 rejected, 3,248 clipped,
/// 1 clipped away: 49.8% outside or crossing).
Scene makeBenchScene(int segments = kBenchSegments);

/// The stage matrices of the scene's first object (the benchmark scene has one).
struct StageMatrices {
  Mat4 wcFromMc{1.0};
  Mat4 vrcFromWc{1.0};
  Mat4 npcFromVrc{1.0};
  Mat4 dcFromNpc{1.0};
  Mat4 npcFromMc{1.0};  // npcFromVrc · vrcFromWc · wcFromMc
};
StageMatrices stageMatrices(const Scene& scene);

// ---------------------------------------------------------------- the floor pass

struct FloorBuffers {
  std::vector<Vec4> npcH;  // homogeneous NPC of every mesh vertex
  std::vector<Outcode> outcodes;
};

/// Transform and classify, nothing else: npcH[i] = npcFromMc · (p_i, 1) and its outcode.
void floorPass(const Mesh& mesh, const Mat4& npcFromMc, FloorBuffers& out);

// ---------------------------------------------------------------- the textbook baseline

/// The visible polygons in DC (x, y, z), one std::vector each, as the textbook baseline builds them.
using TextbookPolygons = std::vector<std::vector<Vec3>>;

/// The textbook baseline over every face of the mesh (see the file comment). Returns a new result.
TextbookPolygons textbookPipeline(const Mesh& mesh, const StageMatrices& m);

// ---------------------------------------------------------------- the fairness check

/// What was drawn: visible polygons (at least 3 vertices after clipping), their vertices, the sums of
/// their DC coordinates and of their areas in DC (|shoelace| per polygon; invariant to a repeated
/// vertex).
struct VisibleSummary {
  uint64_t polygons = 0;
  uint64_t vertices = 0;
  double sumX = 0, sumY = 0, sumZ = 0;
  double area = 0;
};
VisibleSummary summarize(const PipelineRun& run);
VisibleSummary summarize(const TextbookPolygons& polygons);

/// Relative tolerance of the sums: the two implementations round differently (the pipeline
/// interpolates the boundary coordinates and snaps created vertices onto the plane; the textbook
/// recomputes them and does not snap), which moves a clipped vertex by a few ulps.
inline constexpr double kCheckTolerance = 1e-9;

struct CheckResult {
  bool ok = false;
  double tolerance = kCheckTolerance;
  VisibleSummary pipeline, textbook;
  std::string message;  // "" when ok, otherwise what differs
};
/// Polygon and vertex counts must be equal; the coordinate and area sums equal within `tolerance`
/// relative to the magnitude of the sum.
CheckResult checkSameVisibleResult(const PipelineRun& run, const TextbookPolygons& textbook,
                                   double tolerance = kCheckTolerance);

// ---------------------------------------------------------------- the three workloads

/// The scene, its matrices and every buffer, built once; each workload call runs one frame.
class Workloads {
 public:
  explicit Workloads(int segments = kBenchSegments);

  void fullPipeline();  // runPipeline(scene, options, run), reusing run, on one core
  void everyCore();     // the same on every core, into its own run
  void floor();         // floorPass into reused buffers
  void textbook();      // textbookPipeline, its result kept until the next call (freeing the old one)

  const Scene& scene() const { return scene_; }
  const Mesh& mesh() const { return *scene_.objects.front().mesh; }
  const StageMatrices& matrices() const { return matrices_; }
  const PipelineRun& run() const { return run_; }
  const PipelineRun& everyCoreRun() const { return everyCoreRun_; }
  const FloorBuffers& floorBuffers() const { return floor_; }
  const TextbookPolygons& textbookResult() const { return textbook_; }

 private:
  Scene scene_;
  StageMatrices matrices_;
  // The defaults (clipping in homogeneous NPC, no bounding-box test) on one core: the floor pass has one.
  PipelineOptions options_{.parallel = false};
  PipelineRun run_, everyCoreRun_;
  FloorBuffers floor_;
  TextbookPolygons textbook_;
};

// ---------------------------------------------------------------- the report

struct WorkloadTiming {
  std::vector<double> samplesMs;     // wall time (steady_clock), one per repetition, in run order
  std::vector<double> cpuSamplesMs;  // this thread's CPU time for the same calls
  double medianMs = 0;
  double minMs = 0;
  double cpuMedianMs = 0;  // on a shared machine: excludes the time the thread waited for a core
};

struct BenchReport {
  /// The workloads of a millisecond or two (full, floor, every core) are timed this many times a
  /// round, the textbook once (runPipelineBenchmarks).
  static constexpr int kShortSamples = 5;
  static constexpr double kFullOverFloorTarget = 1.5;     // at most (issue 11)
  static constexpr double kTextbookOverFullTarget = 10;   // at least
  /// One core's time over every core's, at least (issue 42): 1.7 on 2 cores, 0.8 × the cores beyond;
  /// nothing to gain on one core.
  static constexpr double everyCoreTarget(unsigned cores) { return cores < 2 ? 1 : cores == 2 ? 1.7 : 0.8 * cores; }

  int repetitions = 0;
  int segments = 0;
  uint64_t triangles = 0;
  uint64_t vertices = 0;
  uint64_t accepted = 0;     // trivially accepted
  uint64_t rejected = 0;     // trivially rejected
  uint64_t clipped = 0;      // cut, something remains
  uint64_t clippedAway = 0;  // cut, nothing remains
  uint64_t verticesCreated = 0;
  double outsideOrCrossing = 0;  // (rejected + clipped + clippedAway) / triangles

  WorkloadTiming full, floor, textbook, everyCore;
  unsigned cores = 0;               // the threads oneTBB runs the every-core run on
  double oneOverEveryCore = 0;      // median full / median every core (wall time: CPU time adds up the cores)
  bool oneOverEveryCoreMet = false;
  bool everyCoreSameResult = false;  // its stats, fates and vertices are the one-core run's bit for bit
  double fullOverFloor = 0;     // median full / median floor (wall time)
  double textbookOverFull = 0;  // median textbook / median full (wall time)
  double fullOverFloorCpu = 0;  // the same from the CPU-time medians
  double textbookOverFullCpu = 0;
  bool fullOverFloorMet = false;  // judged by the CPU-time ratio: single-threaded, its CPU time is its cost
  bool textbookOverFullMet = false;

  CheckResult check;
};

/// Builds the workloads, runs each once to warm up, then `repetitions` rounds of full, floor,
/// textbook and every core (interleaved, so a noisy neighbour hits all alike), all but the last
/// single-threaded, timing each call with std::chrono::steady_clock (and the thread's CPU clock); reports
/// the medians. Throws vplab::Error for repetitions < 1. Takes about 0.5 s per repetition.
BenchReport runPipelineBenchmarks(int repetitions = 5, int segments = kBenchSegments);

/// The report as JSON, keys in a fixed order (see toJson in workloads.cpp; times in milliseconds).
nlohmann::ordered_json toJson(const BenchReport& report);

}  // namespace vplab::bench
