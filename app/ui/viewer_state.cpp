#include "app/ui/viewer_state.h"

namespace vplab {

bool selectTab(ViewerState& s, std::string_view name) {
  // kTabNames' order: the controls' five tabs, then the inspector's three.
  constexpr int kControls[] = {ViewerState::cameraTab, ViewerState::sceneTab, ViewerState::clippingTab,
                               ViewerState::displayTab, ViewerState::lectureTab};
  constexpr int kInspect[] = {ViewerState::probeTab, ViewerState::matricesTab, ViewerState::depthTab};
  for (size_t i = 0; i < std::size(kTabNames); ++i) {
    if (kTabNames[i] != name) continue;
    if (i < std::size(kControls)) s.controlsTab = kControls[i];
    else s.inspectTab = kInspect[i - std::size(kControls)];
    return true;
  }
  return false;
}

}  // namespace vplab
