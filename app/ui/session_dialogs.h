// The session's questions and progress as ImGui dialogs (the session itself, app/session/session.h,
// knows no ImGui): the loading bar with Cancel, "recover unsaved changes?", "save before quitting?",
// "discard unsaved changes?", and the file chooser. Each dialog shows what the session asks and gives
// it the answer the user clicked.
#pragma once

#include "app/session/session.h"
#include "app/ui/viewer_state.h"

#include <optional>

namespace vplab {

class SessionDialogs {
 public:
  SessionDialogs(ViewerState& state, Session& session) : s_(state), session_(session) {}

  /// Draws whatever the session asks, at UI scale `scale` (every frame).
  void draw(float scale);
  /// Whether a modal dialog is open or about to open (recovery, unsaved changes, the file chooser):
  /// it takes the keys, and nothing behind it moves (no lesson step, no shortcut).
  bool open() const;
  /// 0 while a question waits for its dialog to open (the next frame shows it), else nothing.
  std::optional<double> wakeIn() const;

 private:
  void loadingWindow(float scale);
  void recoveryDialog();
  void quitDialog();
  void discardDialog();

  ViewerState& s_;
  Session& session_;
  bool shownQuestion_ = false;  // a question's dialog was drawn this frame
};

}  // namespace vplab
