#include "app/session/viewer_model.h"

#include "app/lessons/tabs.h"

#include <iterator>

namespace vplab {

bool selectTab(LayoutPart& layout, std::string_view name) {
  // kTabNames' order: the controls' five tabs, then the inspector's three.
  constexpr int kControls[] = {LayoutPart::cameraTab, LayoutPart::sceneTab, LayoutPart::clippingTab,
                               LayoutPart::displayTab, LayoutPart::lectureTab};
  constexpr int kInspect[] = {LayoutPart::probeTab, LayoutPart::matricesTab, LayoutPart::depthTab};
  for (size_t i = 0; i < std::size(kTabNames); ++i) {
    if (kTabNames[i] != name) continue;
    if (i < std::size(kControls)) layout.controlsTab = kControls[i];
    else layout.inspectTab = kInspect[i - std::size(kControls)];
    return true;
  }
  return false;
}

}  // namespace vplab
