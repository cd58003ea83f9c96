// Where the user picks the files the viewer opens and saves: an interface with two sides. On the
// desktop, FileDialog (app/ui/file_dialog.h), a small ImGui file chooser. In the browser, the page's
// file picker and downloads (app/web/page_services.h). The session (app/session/session.h) asks
// through it to open and save scenes; the menus to export views, the scene panel to load OBJ meshes.
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

}  // namespace vplab
