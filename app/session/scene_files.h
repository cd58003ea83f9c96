// The scene's files (docs/lecturers.md "The viewer"): choosing one to open, a file given by the platform
// (a drop, the browser's picker), Save and Save as, never over a scene shipped with vplab. Part of the
// session (app/session/session.h), through which it opens and replaces documents.
#pragma once

#include "app/document/assets.h"
#include "app/session/file_chooser.h"
#include "app/session/viewer_model.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace vplab {

class Session;

class SceneFiles {
 public:
  SceneFiles(ViewerModel& state, Session& session, std::unique_ptr<FileChooser> chooser);

  /// File > Open: the chooser, then the scene (or, in the browser, an OBJ) it names.
  void chooseFileToOpen();
  /// Opens a file given by the platform (a drop, the browser's picker): an OBJ joins the scene as a
  /// mesh object, anything else is opened as a scene (asking first when changes would be lost).
  void openFile(const std::filesystem::path& file);
  /// Save (a bundled or built-in scene: as a copy), Save as.
  void save() { saveScene(state_.doc.path()); }
  void saveAs();
  /// Saves before quitting (the quit question's Save): a bundled or built-in scene as a copy first.
  void saveBeforeQuitting();
  /// Whether `file` is one of the scenes shipped with vplab (assets/scenes/): Save never writes there.
  bool isBundled(const std::filesystem::path& file) const;
  /// The scenes bundled with vplab (assets/scenes/), for the presets menu and links.
  const std::vector<SceneFileInfo>& presets() const { return presets_; }
  FileChooser& fileDialog() { return *dialog_; }
  /// Replaces the file chooser (the browser's picker and downloads); `browser`: the shortcuts the
  /// browser owns (Ctrl+S, Ctrl+O, Ctrl+N, Ctrl+Q, F11, F12) are left to it and Quit is not offered.
  void useFileChooser(std::unique_ptr<FileChooser> chooser, bool browser);
  bool browser() const { return browser_; }

 private:
  Language language() const { return state_.display.language; }
  void saveScene(const std::filesystem::path& file);
  void writeScene(const std::filesystem::path& file);

  ViewerModel& state_;
  Session& session_;
  std::unique_ptr<FileChooser> dialog_;
  bool browser_ = false;
  std::vector<SceneFileInfo> presets_;
};

}  // namespace vplab
