// A small ImGui file chooser (Dear ImGui has none): a directory listing filtered by extension, a
// path field, and OK/Cancel. Used to open and save scenes and to load OBJ meshes.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vplab {

class FileDialog {
 public:
  enum class Mode { open, save };
  /// Opens the dialog; `onChosen` gets the chosen path when the user confirms.
  void open(std::string title, Mode mode, std::vector<std::string> extensions, std::filesystem::path start,
            std::function<void(const std::filesystem::path&)> onChosen);
  /// Draws the dialog while it is open (call every frame).
  void draw();
  bool isOpen() const { return open_ || pending_; }

 private:
  void list();

  std::string title_;
  Mode mode_ = Mode::open;
  std::vector<std::string> extensions_;
  std::filesystem::path directory_;
  std::string name_;
  std::string error_;
  std::vector<std::filesystem::directory_entry> entries_;
  std::function<void(const std::filesystem::path&)> onChosen_;
  bool open_ = false, pending_ = false;
};

}  // namespace vplab
