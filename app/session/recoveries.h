// Autosave of this session and the recovery of others' unsaved changes (crashed processes, closed
// browser tabs; docs/reliability.md): the file written after a quiet moment, the offer at start, and
// the answers (recover one, discard one, later). Part of the session (app/session/session.h).
#pragma once

#include "app/document/autosave.h"
#include "app/session/viewer_model.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vplab {

class Session;

class Recoveries {
 public:
  Recoveries(ViewerModel& state, Session& session) : state_(state), session_(session) {}

  /// Turns on autosave into `directory` (Autosave::defaultDirectory() in the window).
  void enableAutosave(const std::filesystem::path& directory, double delaySeconds);
  const Autosave* autosave() const { return autosave_.get(); }
  /// At the frame's end, at time `now` (s): the autosave writes what is due, and says a failure once.
  void endFrame(double now);
  /// Seconds until the autosave is due, if it is on.
  std::optional<double> dueIn(double now) const;
  /// Asked to end by a signal: writes the recovery file if there are unsaved changes. Returns it, or
  /// an empty path when nothing needed saving.
  std::filesystem::path writeRecoveryNow();
  /// A normal end (quit): this session leaves no recovery file.
  void endSession();

  /// At start: earlier sessions left unsaved changes, newest first; the user may recover one of them
  /// (this session's document) or discard each. What is neither stays kept for the next start.
  void offerRecoveries(std::vector<Recovery> recoveries);
  const std::vector<Recovery>& recoveries() const { return recoveries_; }
  /// The answers: the i-th kept scene becomes this session's document (the others stay kept for the
  /// next start); the i-th is discarded; all stay kept for later.
  void recover(size_t i);
  void discardRecovery(size_t i);
  void recoverLater();
  /// The kept scene's file, or the built-in scene's name (in German in the dative: it follows "an").
  std::string sceneName(const Recovery& r) const;

 private:
  Language language() const { return state_.display.language; }
  /// What else is on screen, for the recovery file: the lesson and its step, the views' settings.
  RecoveryView recoveryView() const;
  /// A recovered document shows what was on screen: the lesson at its step, the views, the typed camera.
  void showRecoveredView(const RecoveryView& view);

  ViewerModel& state_;
  Session& session_;
  std::unique_ptr<Autosave> autosave_;
  std::string autosaveError_;  // the last one shown
  std::vector<Recovery> recoveries_;
};

}  // namespace vplab
