// `vplab bench --memory` (app/commands/bench_memory.cpp): where the bytes of the 1M-triangle scene go.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace vplab {

/// The peak memory of `vplab render --view ui` (the viewer's window) on the default and the large
/// scene, and of `vplab render --view all` on the large one (`executable`: vplab itself, run as
/// children). Run it before anything large is allocated: a child's peak includes this process's
/// memory at the moment it is started.
nlohmann::ordered_json memoryPeaks(const std::string& executable, std::ostream& log);
/// The heap bytes of the large scene's structures: its meshes, one run, each view's display list in the
/// shaded and the wire style, the meshes' GPU buffers.
nlohmann::ordered_json memoryStructures(std::ostream& log);

}  // namespace vplab
