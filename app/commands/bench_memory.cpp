// `vplab bench --memory` (issue 42): where the bytes of the 1M-triangle scene go, structure by
// structure, and the peak memory of the processes that show it.
//   structures  exact heap bytes (capacity × element size) of the scene's meshes, one pipeline run,
//               each view's display list in the scene's style and in the wire style, and the GPU
//               buffers of the meshes (on llvmpipe and SwiftShader: the process's own memory)
//   processes   peak resident memory (getrusage of a child: ru_maxrss) of `vplab render --view ui`,
//               the viewer's whole window, on the default scene and on the large one (the difference
//               per triangle is the figure), and of `vplab render --view all`
#include "app/commands/bench_memory.h"

#include "app/document/assets.h"
#include "app/render/headless.h"
#include "app/render/view_renderer.h"
#include "app/views/render_request.h"
#include "app/views/views.h"
#include "base/error.h"
#include "io/scene_io.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace vplab {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr double kMiB = 1024.0 * 1024.0;

// The goals of issue 42.
constexpr double kViewerBytesPerTriangleGoal = 150;  // the viewer's peak for the large scene over the default's
constexpr double kRenderAllPeakGoalMiB = 250;         // vplab render --view all of it

/// The triangles the GPU draws of a scene: each face fan-triangulated.
size_t trianglesOf(const Scene& scene) {
  size_t n = 0;
  for (const SceneObject& o : scene.objects)
    if (o.mesh)
      for (size_t f = 0; f < o.mesh->faceCount(); ++f) n += std::max<size_t>(o.mesh->face(f).size(), 2) - 2;
  return n;
}

Json toJson(const MemoryUse& use) {
  Json parts = Json::array();
  for (const MemoryPart& p : sortedLargestFirst(use)) parts.push_back({{"part", p.name}, {"mib", p.bytes / kMiB}});
  return {{"total_mib", totalBytes(use) / kMiB}, {"parts", parts}};
}

/// Runs `vplab ARGS` as a child (its standard output to /dev/null: ours may carry the JSON) and
/// returns its peak resident memory in MiB.
double peakMiBOf(const std::string& executable, const std::vector<std::string>& args) {
  std::vector<std::string> all{executable};
  all.insert(all.end(), args.begin(), args.end());
  std::string command;
  for (const std::string& a : all) command += (command.empty() ? "" : " ") + a;
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t child = 0;
  const int spawned = posix_spawn(&child, executable.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw Error("bench --memory: cannot start `" + command + "`");
  int status = 0;
  rusage usage{};
  if (::wait4(child, &status, 0, &usage) != child || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error("bench --memory: `" + command + "` failed");
  return double(usage.ru_maxrss) * 1024.0 / kMiB;  // Linux: kilobytes
}

/// This process's resident memory now, in MiB (/proc/self/status VmRSS).
double residentMiB() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) * 1024.0 / kMiB;  // kB
  return 0;
}

}  // namespace

Json memoryPeaks(const std::string& executable, std::ostream& log) {
  const fs::path sceneFile = assetsDirectory() / "scenes" / "large-mesh.json";
  log << "  memory: the peaks of vplab render --view ui and --view all…\n";
  // A child's peak counts this process's resident memory at the spawn (the kernel keeps the larger of
  // the memory it had before its exec and after): so this runs before the other parts allocate, and
  // the scene is read only afterwards.
  const double floor = residentMiB();
  const fs::path out = fs::temp_directory_path() / ("vplab-bench-memory-" + std::to_string(::getpid()) + ".png");
  const double viewerDefault = peakMiBOf(executable, {"render", "--view", "ui", "--out", out.string()});
  const double viewerLarge =
      peakMiBOf(executable, {"render", "--view", "ui", "--scene", sceneFile.string(), "--out", out.string()});
  const double renderAll =
      peakMiBOf(executable, {"render", "--view", "all", "--scene", sceneFile.string(), "--out", out.string()});
  std::error_code ec;
  fs::remove(out, ec);
  const size_t triangles = trianglesOf(loadScene(sceneFile));
  return {
      {"scene", {{"file", "scenes/large-mesh.json"}, {"triangles", triangles}}},
      {"bench_resident_at_spawn_mib", floor},
      {"viewer_default_scene_peak_mib", viewerDefault},
      {"viewer_large_scene_peak_mib", viewerLarge},
      {"viewer_bytes_per_triangle", (viewerLarge - viewerDefault) * kMiB / double(triangles)},
      {"viewer_bytes_per_triangle_max", kViewerBytesPerTriangleGoal},
      {"render_view_all_peak_mib", renderAll},
      {"render_view_all_peak_max_mib", kRenderAllPeakGoalMiB},
  };
}

Json memoryStructures(std::ostream& log) {
  const Scene scene = loadScene(assetsDirectory() / "scenes" / "large-mesh.json");
  log << "  memory: the structures of the large scene…\n";
  Json structures;
  structures["meshes"] = toJson(meshMemoryUse(scene));
  PipelineRun run;
  runPipeline(scene, {ClipStrategy::npc, false, true}, run);  // with the edges, as the viewer runs it
  structures["pipeline_run"] = toJson(memoryUse(run));
  auto context = createHeadlessContext(Backend::automatic, false);
  ViewRenderer renderer(*context);
  const int w = 1280, h = 720;  // each view's, as the viewer shows three on a 1080p screen
  for (Style style : {Style::shaded, Style::wire}) {
    const DisplaySettings settings = displaySettingsFor(scene, style, double(w) / h);
    const Highlights none;
    const ViewInput in{scene, run, settings, none, w, h, renderer.textMetrics()};
    // How long a list takes to build, the first time in this process and again
    // (the median of three more): the list building a frame of the window does (issue 42: ≤ 20 ms).
    Json& times = structures["list_build_ms_" + std::string(toString(style))];
    auto time = [&](const char* view, auto build) {
      std::vector<double> ms;
      for (int i = 0; i < 4; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const draw::DisplayList list = build();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      }
      std::sort(ms.begin() + 1, ms.end());
      times[view] = {{"first", ms[0]}, {"again", ms[2]}};
    };
    time("camera", [&] { return cameraView(in); });
    time("world", [&] { return worldView(in); });
    time("npc", [&] { return npcView(in); });
    structures["display_lists_" + std::string(toString(style))] = {
        {"camera", toJson(draw::memoryUse(cameraView(in)))},
        {"world", toJson(draw::memoryUse(worldView(in)))},
        {"npc", toJson(draw::memoryUse(npcView(in)))}};
    renderer.render(ViewKind::all, scene, run, settings, none, w, h);  // uploads the meshes (and their edges)
  }
  structures["gpu_buffers"] = toJson(renderer.gpuMemoryUse());
  return structures;
}

}  // namespace vplab
