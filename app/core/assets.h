// Where vplab finds its assets (the preset scenes and their meshes), whatever the working directory:
// PREFIX/share/vplab for an installed PREFIX/bin/vplab, assets/ next to the executable or one level
// up, or, for a program in its build tree only, the source tree it was built from.
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
