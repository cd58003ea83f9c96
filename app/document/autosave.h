// Autosave and crash recovery (docs/lecturers.md "The viewer": documents and saving): a few seconds after the
// open scene last changed, and at once when the process is asked to end (SIGTERM, SIGINT) with unsaved
// changes, the scene is written atomically to the user's state directory
// ($XDG_STATE_HOME/vplab, by default ~/.local/state/vplab) as recovery-PID.json. A session that
// ends normally (quit, saved or discarded) removes its file; so a file whose process is gone was
// left by a crash or a signal, and the next start offers to recover it.
//
// The file: {"scene_path": the scene's own file or "" for the built-in one, "saved_at": local
// time, "scene": the scene the views showed in the scene format (io/scene_io.h), and what else was
// on screen (RecoveryView): "lesson" {"file", "step"}, "views" (the views' settings as a link's
// fragment, app/document/url_state.h) and "edited_camera" (the camera as typed while it was invalid,
// its numbers as they were)}. Mesh files are resolved relative to scene_path's directory, as when
// the scene itself is opened.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/document/document.h"

namespace vplab {

/// Seconds after the last change at which the open scene is autosaved (the desktop and the page).
inline constexpr double kAutosaveDelay = 3.0;

/// What was on screen besides the scene, so that recovery shows exactly that again (issue 37).
struct RecoveryView {
  std::filesystem::path lesson;  // the lesson presented (empty: none)
  size_t step = 0;               // its step, from 0
  std::string views;             // the views' styles, observers and the strategy, as a link's fragment
  /// Read back only (the writer takes it from the document): the camera in the fields when it
  /// differs from the scene's (an invalid one typed; the views kept the last valid camera).
  std::optional<Camera> editedCamera;
  /// Likewise the objects' transforms in the fields where they differ (a scale of 0 typed): by the
  /// object's index in the scene.
  std::vector<std::pair<size_t, ModelTransform>> editedTransforms;
  bool operator==(const RecoveryView&) const = default;
};

/// A recovery file left by an earlier session.
struct Recovery {
  std::filesystem::path file;       // the recovery file
  std::filesystem::path scenePath;  // the scene it is an unsaved version of (empty: the built-in scene)
  std::string savedAt;              // local time, for the question asked
};

class Autosave {
 public:
  /// $XDG_STATE_HOME/vplab, else $HOME/.local/state/vplab; empty when neither variable is set.
  static std::filesystem::path defaultDirectory();

  /// Autosaves into `directory` (created when first needed) `delaySeconds` after the last change.
  Autosave(std::filesystem::path directory, double delaySeconds);

  /// Call after every frame with the time in seconds (any monotonic clock): writes the scene when a
  /// change is `delay` old; removes the file when the document is clean (saved or replaced).
  /// `view`: what else is on screen, written with the scene.
  void update(const Document& doc, double now, const RecoveryView& view = {});
  /// Seconds until update() has work to do (the viewer's event wait wakes by then); a large number
  /// when nothing is pending.
  double dueIn(double now) const;
  /// Writes the scene now if it has unsaved changes (asked to end by a signal). Returns whether a
  /// recovery file exists afterwards.
  bool writeNow(const Document& doc, const RecoveryView& view = {});
  /// The session ends normally: its recovery file goes.
  void removeFile();

  const std::filesystem::path& file() const { return file_; }
  /// The last autosave's error (the state directory not writable, …); empty after a success.
  const std::string& error() const { return error_; }

  /// Every recovery file in `directory` whose process has ended, newest first (several sessions
  /// may have crashed, or several browser tabs been closed, each with its own unsaved scene).
  static std::vector<Recovery> findAll(const std::filesystem::path& directory);
  /// The newest of findAll, if any.
  static std::optional<Recovery> find(const std::filesystem::path& directory);
  /// `file` as a recovery file (any name): nothing when it is not one of ours or is damaged
  /// (load() would say why).
  static std::optional<Recovery> read(const std::filesystem::path& file);
  /// Reads a recovery file's scene. Throws vplab::Error naming the file.
  static Scene load(const Recovery& recovery);
  /// Reads what else was on screen; what a file does not have (an older one) or cannot be read as
  /// such stays empty: the scene is what matters.
  static RecoveryView loadView(const Recovery& recovery);
  /// Removes a recovery file (recovered or declined).
  static void discard(const Recovery& recovery);

 private:
  void write(const Document& doc, const RecoveryView& view);

  std::filesystem::path directory_, file_;
  double delay_;
  unsigned savedRevision_ = 0;  // the revision in the file (0: none written)
  unsigned seenRevision_ = 0;   // the revision update() saw last
  double changedAt_ = 0;        // when seenRevision_ was first seen
  bool pending_ = false;        // a dirty revision not yet written
  std::string error_;
  RecoveryView writtenView_;    // the view in the file
};

}  // namespace vplab
