// Where the user picks the files the viewer opens and saves: an interface with two sides. On the
// desktop, FileDialog, a small ImGui file chooser (Dear ImGui has none): a directory listing filtered
// by extension, a path field, and OK/Cancel. In the browser, the page's file picker and downloads
// (app/web/page_services.h). Used to open and save scenes, to export views and to load OBJ meshes.
#pragma once

#include "base/language.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vplab {

class FileChooser {
 public:
  enum class Mode { open, save };
  virtual ~FileChooser() = default;
  /// Asks for a file; `onChosen` gets its path when the user confirms (never when they cancel). In
  /// save mode `start` suggests the name (and, on the desktop, the folder).
  virtual void open(std::string title, Mode mode, std::vector<std::string> extensions, std::filesystem::path start,
                    std::function<void(const std::filesystem::path&)> onChosen) = 0;
  /// Draws the chooser while it is open, its buttons in `lang` (call every frame; the browser's draws
  /// nothing).
  virtual void draw(Language /*lang*/) {}
  virtual bool isOpen() const = 0;
  /// Whether a saved file goes to the user as a download (the browser), never over a file: Save
  /// then always names a new one, and there is no "save a copy" of a bundled scene to ask for.
  virtual bool downloads() const { return false; }
};

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
