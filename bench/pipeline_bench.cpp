// bench_pipeline: the full CPU pipeline, the floor pass and the textbook baseline on the benchmark
// sphere (bench/workloads.h), in one run, single-threaded; and the full pipeline on every core. Before timing, it checks that the textbook
// baseline draws what the pipeline draws; at the end (console output) it prints the two ratios the
// issues set targets for: full / floor ≤ 1.5 (issue 11), textbook / full ≥ 10 and one core / every
// core ≥ 1.7 on two cores (issue 42).
//
//   build/bench/bench_pipeline                                  one run of all three
//   build/bench/bench_pipeline --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "bench/workloads.h"
#include "pipeline/parallel.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <map>
#include <string>

#include <unistd.h>

namespace {

using vplab::bench::Workloads;

Workloads& workloads() {
  static Workloads w;  // built once (the sphere takes a moment), shared by the three benchmarks
  return w;
}

void addSceneCounters(benchmark::State& state) {
  const vplab::PipelineStats& st = workloads().run().stats;
  state.counters["triangles"] = double(st.polygons);
  // Triangles per second through this workload.
  state.counters["tri/s"] = benchmark::Counter(double(st.polygons), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_FullPipeline(benchmark::State& state) {
  Workloads& w = workloads();
  w.fullPipeline();  // the first run sizes the PipelineRun's buffers; the viewer reuses them too
  for (auto _ : state) {
    w.fullPipeline();
    benchmark::DoNotOptimize(w.run().stats.verticesOutput);
    benchmark::ClobberMemory();
  }
  addSceneCounters(state);
  const vplab::PipelineStats& st = w.run().stats;
  state.counters["accepted"] = double(st.polygonsTriviallyAccepted);
  state.counters["rejected"] = double(st.polygonsTriviallyRejected);
  state.counters["clipped"] = double(st.polygonsClipped + st.polygonsClippedAway);
}

void BM_EveryCore(benchmark::State& state) {
  Workloads& w = workloads();
  w.everyCore();
  for (auto _ : state) {
    w.everyCore();
    benchmark::DoNotOptimize(w.everyCoreRun().stats.verticesOutput);
    benchmark::ClobberMemory();
  }
  addSceneCounters(state);
}

void BM_FloorPass(benchmark::State& state) {
  Workloads& w = workloads();
  w.floor();
  for (auto _ : state) {
    w.floor();
    benchmark::DoNotOptimize(w.floorBuffers().npcH.data());
    benchmark::DoNotOptimize(w.floorBuffers().outcodes.data());
    benchmark::ClobberMemory();
  }
  addSceneCounters(state);
}

void BM_Textbook(benchmark::State& state) {
  Workloads& w = workloads();
  for (auto _ : state) {
    w.textbook();
    benchmark::DoNotOptimize(w.textbookResult().data());
    benchmark::ClobberMemory();
  }
  addSceneCounters(state);
  state.counters["visible"] = double(w.textbookResult().size());
}

BENCHMARK(BM_FullPipeline)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EveryCore)->Unit(benchmark::kMillisecond)->UseRealTime();  // CPU time adds up the cores
BENCHMARK(BM_FloorPass)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Textbook)->Unit(benchmark::kMillisecond);

// The console reporter, plus the ratios of the real times per iteration (medians when repeated).
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  explicit RatioReporter(bool color) : ConsoleReporter(color ? OO_ColorTabular : OO_Tabular) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.error_occurred) continue;
      const std::string name = run.benchmark_name();
      const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
      if (run.run_type == Run::RT_Aggregate && !median) continue;
      const std::string base = name.substr(0, name.find('/'));
      // A median replaces the iterations' values; without repetitions the single run counts.
      if (median || !medians_.count(base)) realMs_[base] = run.GetAdjustedRealTime();
      if (median) medians_[base] = true;
    }
    ConsoleReporter::ReportRuns(runs);
  }

  void Finalize() override {
    ConsoleReporter::Finalize();
    const auto full = realMs_.find("BM_FullPipeline"), floor = realMs_.find("BM_FloorPass"),
               textbook = realMs_.find("BM_Textbook"), every = realMs_.find("BM_EveryCore");
    if (full == realMs_.end()) return;
    if (floor != realMs_.end())
      std::printf("full / floor    = %.2f   (target <= %.1f)\n", full->second / floor->second,
                  vplab::bench::BenchReport::kFullOverFloorTarget);
    if (textbook != realMs_.end())
      std::printf("textbook / full = %.2f   (target >= %.0f)\n", textbook->second / full->second,
                  vplab::bench::BenchReport::kTextbookOverFullTarget);
    if (every != realMs_.end())
      std::printf("one core / every core = %.2f   (target >= %.1f on %u threads)\n", full->second / every->second,
                  vplab::bench::BenchReport::everyCoreTarget(vplab::parallelThreads()),
                  vplab::parallelThreads());
  }

 private:
  std::map<std::string, double> realMs_;
  std::map<std::string, bool> medians_;
};

}  // namespace

int main(int argc, char** argv) {
  // Our console reporter replaces the library's, so it decides about colour as the library would.
  bool console = true, color = isatty(STDOUT_FILENO) != 0;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--benchmark_format=", 19) == 0 && std::strcmp(argv[i] + 19, "console") != 0)
      console = false;
    if (std::strncmp(argv[i], "--benchmark_color=", 18) == 0) {
      const char* v = argv[i] + 18;
      color = std::strcmp(v, "true") == 0 || std::strcmp(v, "yes") == 0 || std::strcmp(v, "1") == 0 ||
              (std::strcmp(v, "auto") == 0 && isatty(STDOUT_FILENO));
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  // Fairness first: the textbook baseline must draw what the pipeline draws.
  Workloads& w = workloads();
  w.fullPipeline();
  w.textbook();
  const vplab::bench::CheckResult check = vplab::bench::checkSameVisibleResult(w.run(), w.textbookResult());
  if (!check.ok) {
    std::fprintf(stderr, "bench_pipeline: %s\n", check.message.c_str());
    return 1;
  }
  const vplab::PipelineStats& st = w.run().stats;
  benchmark::AddCustomContext("triangles", std::to_string(st.polygons));
  benchmark::AddCustomContext("vertices", std::to_string(st.vertices));
  benchmark::AddCustomContext(
      "split", "accepted " + std::to_string(st.polygonsTriviallyAccepted) + ", rejected " +
                   std::to_string(st.polygonsTriviallyRejected) + ", clipped " +
                   std::to_string(st.polygonsClipped) + ", clipped away " +
                   std::to_string(st.polygonsClippedAway));
  char checkText[160];
  std::snprintf(checkText, sizeof checkText,
                "same %llu visible polygons, %llu vertices; DC sums and areas within %g (relative)",
                static_cast<unsigned long long>(check.pipeline.polygons),
                static_cast<unsigned long long>(check.pipeline.vertices), check.tolerance);
  benchmark::AddCustomContext("textbook check", checkText);

  if (console) {
    RatioReporter reporter(color);
    benchmark::RunSpecifiedBenchmarks(&reporter);
  } else {
    benchmark::RunSpecifiedBenchmarks();
  }
  benchmark::Shutdown();
  return 0;
}
