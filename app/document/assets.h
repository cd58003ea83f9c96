// Where vplab finds its assets (the preset scenes and their meshes), whatever the working directory:
// PREFIX/share/vplab for an installed PREFIX/bin/vplab, assets/ next to the executable or one level
// up, or, for a program in its build tree only, the source tree it was built from.
#pragma once

#include "base/language.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vplab {

/// The assets directory, or an empty path when none is found.
std::filesystem::path assetsDirectory();

/// vplab's icon (256 × 256 PNG, drawn by `vplab render` at build time): PREFIX/share/icons/hicolor/
/// 256x256/apps/vplab.png beside an installed vplab's data, or the build tree's generated/vplab-icon.png
/// for a program in its build tree. Empty when there is none (the window then has the desktop's default).
std::filesystem::path iconFile();

struct SceneFileInfo {
  std::filesystem::path file;
  std::string title;  // the scene's "title", or its file name
  std::string titleDe;  // its "title_de" (empty: none)
  const std::string& titleIn(Language lang) const { return lang == Language::de && !titleDe.empty() ? titleDe : title; }
};
/// The scenes in assets/scenes/, the default lecture scene first, then by file name.
std::vector<SceneFileInfo> listPresetScenes();

}  // namespace vplab
