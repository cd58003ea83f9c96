// The controls and inspector windows beside the views, and the compact layout's switcher (a phone's
// screen): each window's row of tabs and the panel (app/ui/panels.h) of the tab chosen, handed the
// parts of the state it uses; the status line under the controls.
#pragma once

#include "app/session/session.h"
#include "app/ui/viewer_state.h"

namespace vplab {

class PanelWindows {
 public:
  PanelWindows(ViewerState& state, Session& session) : s_(state), session_(session) {}

  /// The controls (Camera, Scene, Clipping, Display, Lecture) and the status line, at UI scale
  /// `scale`; `relayout`: placed where the layout says (a resize, a new scale), else where the user left it.
  void controls(float scale, bool relayout);
  /// The inspector (Vertex probe, Matrices, Depth); a new probe brings its tab forward.
  void inspect(float scale, bool relayout);
  /// The compact layout's switcher: the three views one at a time, and the two panels.
  void compactSwitcher(float scale);

 private:
  ViewerState& s_;
  Session& session_;
};

}  // namespace vplab
