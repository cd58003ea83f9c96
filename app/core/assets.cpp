#include "app/core/assets.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace vplab {

std::filesystem::path assetsDirectory() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  std::vector<fs::path> candidates;
  if (!ec) candidates = {exe.parent_path() / "assets", exe.parent_path().parent_path() / "assets"};
  candidates.push_back(VPLAB_SOURCE_ASSETS);
  for (const fs::path& p : candidates)
    if (fs::is_directory(p / "scenes", ec)) return p;
  return {};
}

std::vector<SceneFileInfo> listPresetScenes() {
  namespace fs = std::filesystem;
  std::vector<SceneFileInfo> scenes;
  const fs::path dir = assetsDirectory();
  if (dir.empty()) return scenes;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir / "scenes", ec)) {
    if (e.path().extension() != ".json") continue;
    SceneFileInfo info{e.path(), e.path().stem().string()};
    // Only the title is read here; the scene is loaded (and checked) when chosen.
    std::ifstream in(e.path());
    const auto j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_object() && j.contains("title") && j["title"].is_string()) info.title = j["title"].get<std::string>();
    scenes.push_back(std::move(info));
  }
  std::sort(scenes.begin(), scenes.end(), [](const SceneFileInfo& a, const SceneFileInfo& b) {
    const bool da = a.file.stem() == "default", db = b.file.stem() == "default";
    return da != db ? da : a.file.filename() < b.file.filename();
  });
  return scenes;
}

}  // namespace vplab
