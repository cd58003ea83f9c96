// The document's life beyond editing (docs/lecturers.md "The viewer"): opening a scene (read on a worker
// thread, with progress and Cancel) or adding an OBJ, saving (never over a scene shipped with
// vplab), autosave and recovery after a crash, links (app/document/url_state.h), and asking before
// unsaved changes are lost. The viewer composes the frame; this owns what happens to the file.
#pragma once

#include "app/document/autosave.h"
#include "app/ui/file_dialog.h"
#include "app/document/loader.h"
#include "app/document/url_state.h"
#include "app/ui/viewer_state.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace vplab {

class Session {
 public:
  /// Works on `state` (its document, presets, status and view settings). `changed` runs after
  /// something the frame shows changed (a new document, a link, a load started or cancelled): the
  /// viewer runs the pipeline if its input changed and asks for frames.
  Session(ViewerState& state, std::function<void()> changed);

  // ------------------------------------------------------------ commands (menus, keys, the page)
  /// New: the default lecture scene, asking first when changes would be lost.
  void newDocument();
  /// File > Open: the chooser, then the scene (or, in the browser, an OBJ) it names.
  void chooseFileToOpen();
  /// Opens a scene file on a worker thread (File > Open, presets); the views keep drawing the open
  /// scene, with a progress bar and Cancel, until it has loaded.
  void openScene(const std::filesystem::path& file);
  /// Opens a file given by the platform (a drop, the browser's picker): an OBJ joins the scene as a
  /// mesh object, anything else is opened as a scene (asking first when changes would be lost).
  void openFile(const std::filesystem::path& file);
  /// Save (a bundled or built-in scene: as a copy), Save as.
  void save() { saveScene(state_.doc.path()); }
  void saveAs();
  /// Cancel of the loading bar.
  void cancelLoading();
  /// Runs `action` (which replaces the scene) at once, or after the user agreed to lose unsaved changes.
  void unlessUnsaved(std::function<void()> action);
  /// A new document (opened, preset, New, recovered): clean unless recovered, no undo history, and
  /// the view settings of a fresh start (a style chosen for the old scene, e.g. hidden-line, may be
  /// far too slow for the new one; docs/lecturers.md "The viewer").
  void startDocument(Scene scene, bool dirty = false);

  /// Opens a lesson (docs/lecturers.md "Lessons") at `step` (from 0), asking first when changes would be
  /// lost: its first step's scene becomes a new document and the caption box shows the step. A lesson
  /// that cannot be read leaves everything as it was and says why in the status line.
  void openLesson(const std::filesystem::path& file, size_t step = 0);
  /// What a lesson's steps are resolved against: the bundled scenes and a fresh document's views.
  LessonContext lessonContext() const;

  // ------------------------------------------------------------ each frame
  /// At the frame's start: an OBJ the scene panel asked for starts loading; a finished load arrives.
  /// Returns whether something arrived (the frame then settles again).
  bool beginFrame();
  /// At the frame's end, ImGui time `now` (s): the autosave writes what is due.
  void endFrame(double now);
  /// The loading bar, the recovery, quit and discard dialogs and the file chooser, at UI scale `scale`.
  void drawDialogs(float scale);
  /// Whether a modal dialog is open or about to open (recovery, unsaved changes, the file chooser):
  /// it takes the keys, and nothing behind it moves (no lesson step, no shortcut).
  bool dialogOpen() const;
  /// Seconds until the session needs a frame: 0 while a file loads or a dialog is about to open, the
  /// next autosave, else nothing.
  std::optional<double> wakeIn(double now) const;

  // ------------------------------------------------------------ autosave and recovery
  /// Turns on autosave into `directory` (Autosave::defaultDirectory() in the window).
  void enableAutosave(const std::filesystem::path& directory, double delaySeconds);
  const Autosave* autosave() const { return autosave_.get(); }
  /// Asked to end by a signal: writes the recovery file if there are unsaved changes. Returns it, or
  /// an empty path when nothing needed saving.
  std::filesystem::path writeRecoveryNow();
  /// A normal end (quit): this session leaves no recovery file.
  void endSession();
  /// At start: earlier sessions (crashed processes, closed browser tabs) left unsaved changes,
  /// newest first; a dialog offers to recover one of them (this session's document) or discard
  /// each. What is neither stays kept and is offered again at the next start.
  void offerRecoveries(std::vector<Recovery> recoveries);
  void offerRecovery(Recovery recovery) { offerRecoveries({std::move(recovery)}); }
  bool recoveryOffered() const { return !recoveries_.empty(); }
  /// How many kept scenes the dialog offers.
  size_t recoveriesOffered() const { return recoveries_.size(); }

  // ------------------------------------------------------------ files and links
  /// Whether `file` is one of the scenes shipped with vplab (assets/scenes/): Save never writes there.
  bool isBundled(const std::filesystem::path& file) const;
  const FileChooser& fileDialog() const { return *dialog_; }
  FileChooser& fileDialog() { return *dialog_; }
  /// Replaces the ImGui file dialog (the browser's picker and downloads); `browser`: the shortcuts
  /// the browser owns (Ctrl+S, Ctrl+O, Ctrl+N, Ctrl+Q, F11, F12) are left to it and Quit is not offered.
  void useFileChooser(std::unique_ptr<FileChooser> chooser, bool browser);
  bool browser() const { return browser_; }
  const SceneLoader& loader() const { return loader_; }
  SceneLoader& loader() { return loader_; }
  /// What is shown, for a link: the bundled scene's name, the camera, the views' styles and
  /// observers, the clipping strategy.
  UrlState urlState() const;
  /// Shows a link's state. A named bundled scene starts a new document with the link's camera (at
  /// start, or asking first when changes would be lost); a camera alone is an edit of the open
  /// scene (undoable). Throws vplab::Error when the scene is not bundled or cannot be read.
  void showUrlState(const UrlState& link, bool atStart);

  /// The status line's message.
  void setStatus(std::string message, bool error);

  // ------------------------------------------------------------ preferences
  /// View > Language: the menus', panels' and views' language from the next frame on, remembered
  /// through `remember` (the window: the preferences file; the page: localStorage). A choice that
  /// cannot be remembered still applies, and the status line says why it is not kept.
  void chooseLanguage(Language lang);
  /// How a chosen language is kept for the next start; throws vplab::Error when it cannot be.
  void rememberLanguageWith(std::function<void(Language)> remember) { rememberLanguage_ = std::move(remember); }

 private:
  /// The views of a fresh start (see the constructor); the user's preferences (theme, labels'
  /// language) kept.
  DisplaySettings freshDisplay() const;
  void saveScene(const std::filesystem::path& file);
  void writeScene(const std::filesystem::path& file);
  void loadingWindow(float scale);
  void recoveryDialog();
  void recover(size_t i);
  /// The views' part of a link: each view's style and observer, the clipping strategy.
  void addViews(UrlState& u) const;
  /// Shows what a link gives of the views (addViews' parts); the others stay.
  void applyViews(const UrlState& link);
  /// What else is on screen, for the recovery file: the lesson and its step, the views' settings.
  RecoveryView recoveryView() const;
  /// A recovered document shows what was on screen: the lesson at its step, the views, the typed camera.
  void showRecoveredView(const RecoveryView& view);
  void quitDialog();
  void discardDialog();

  ViewerState& state_;
  std::function<void()> changed_;
  std::function<void(Language)> rememberLanguage_;
  std::unique_ptr<FileChooser> dialog_ = std::make_unique<FileDialog>();
  bool browser_ = false;
  std::function<void()> pendingReplace_;  // waiting for "discard the unsaved changes?"
  bool askDiscard_ = false;
  SceneLoader loader_;
  // A link naming another bundled scene, while the page's worker reads it (showUrlState): its camera
  // and views apply once the scene is there.
  struct PendingLink {
    UrlState link;
    std::function<void()> showViews;
  };
  std::optional<PendingLink> pendingLink_;
  std::unique_ptr<Autosave> autosave_;
  std::string autosaveError_;  // the last one shown
  std::vector<Recovery> recoveries_;
  bool askRecovery_ = false;
};

}  // namespace vplab
