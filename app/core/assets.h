// Where vplab finds its assets (the preset scenes), whatever the working directory: next to the
// executable (an installed tree), one level up (the build tree: build/vplab and assets/), or the
// source tree it was built from.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vplab {

/// The assets directory, or an empty path when none is found.
std::filesystem::path assetsDirectory();

struct SceneFileInfo {
  std::filesystem::path file;
  std::string title;  // the scene's "title", or its file name
};
/// The scenes in assets/scenes/, the default lecture scene first, then by file name.
std::vector<SceneFileInfo> listPresetScenes();

}  // namespace vplab
