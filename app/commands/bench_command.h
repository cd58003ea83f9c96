// `vplab bench` (app/commands/bench_command.cpp): what the issues ask to be measured, in one run on this machine:
//   pipeline   the CPU pipeline on ~1M triangles against the floor pass and the textbook baseline
//   frames     median and 95th-percentile frame time per view at 1280 × 720 (default scene and a
//              ~1M-triangle mesh), and the three views of the default scene together
//   startup    from starting `vplab render` to the PNG on disk
//   input      from an input event (a drag on the VRP field) to the updated frame, all three views
//   memory     where the bytes of the 1M-triangle scene go, by structure, and the peak memory of the
//              viewer and of `vplab render --view all` showing it (app/commands/bench_memory.cpp)
#pragma once

#include <string>
#include <vector>

namespace vplab {

struct BenchOptions {
  bool json = false;
  int repetitions = 5;   // pipeline rounds
  int frames = 40;       // frames per view measurement
  std::vector<std::string> only;  // empty: everything; else a subset of pipeline, frames, startup, input, memory
  std::string executable;         // vplab itself, for the start-up measurement
};

int runBench(const BenchOptions& options);

}  // namespace vplab
