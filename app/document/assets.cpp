#include "app/document/assets.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace vplab {

namespace {

bool within(const std::filesystem::path& file, const std::filesystem::path& dir) {
  const auto [d, f] = std::mismatch(dir.begin(), dir.end(), file.begin(), file.end());
  return d == dir.end();
}

}  // namespace

std::filesystem::path assetsDirectory() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  std::vector<fs::path> candidates;
  if (!ec) {
    const fs::path bin = exe.parent_path();
    // Installed (cmake --install, the .deb): PREFIX/bin/vplab reads PREFIX/share/vplab, the GNU
    // layout's data directory relative to its binary directory (GNUInstallDirs).
    candidates = {(bin / VPLAB_DATA_FROM_BIN).lexically_normal(), bin / "assets", bin.parent_path() / "assets"};
  }
  // The source tree it was built from, only for a program in its build tree (the tests' programs too):
  // an installed vplab never reads a source tree.
  if (ec || within(exe, VPLAB_BUILD_DIR)) candidates.push_back(VPLAB_SOURCE_ASSETS);
  for (const fs::path& p : candidates)
    if (fs::is_directory(p / "scenes", ec)) return p;
  return {};
}

std::filesystem::path iconFile() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  std::vector<fs::path> candidates;
  if (const fs::path data = assetsDirectory(); !data.empty())
    candidates.push_back((data / "../icons/hicolor/256x256/apps/vplab.png").lexically_normal());
  if (!ec && within(exe, VPLAB_BUILD_DIR)) candidates.push_back(fs::path(VPLAB_BUILD_DIR) / "generated/vplab-icon.png");
  for (const fs::path& p : candidates)
    if (fs::is_regular_file(p, ec)) return p;
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
    SceneFileInfo info{e.path(), e.path().stem().string(), {}};
    // Only the title is read here; the scene is loaded (and checked) when chosen.
    std::ifstream in(e.path());
    const auto j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_object() && j.contains("title") && j["title"].is_string()) info.title = j["title"].get<std::string>();
    if (j.is_object() && j.contains("title_de") && j["title_de"].is_string()) info.titleDe = j["title_de"].get<std::string>();
    scenes.push_back(std::move(info));
  }
  std::sort(scenes.begin(), scenes.end(), [](const SceneFileInfo& a, const SceneFileInfo& b) {
    const bool da = a.file.stem() == "default", db = b.file.stem() == "default";
    return da != db ? da : a.file.filename() < b.file.filename();
  });
  return scenes;
}

}  // namespace vplab
