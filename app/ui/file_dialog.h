// The desktop's side of the FileChooser (app/session/file_chooser.h): a small ImGui file chooser (Dear
// ImGui has none): a directory listing filtered by extension, a path field, and OK/Cancel.
#pragma once

#include "app/session/file_chooser.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vplab {

class FileDialog final : public FileChooser {
 public:
  void open(std::string title, Mode mode, std::vector<std::string> extensions, std::filesystem::path start,
            std::function<void(const std::filesystem::path&)> onChosen) override;
  void draw(Language lang) override;
  bool isOpen() const override { return open_ || pending_; }

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
