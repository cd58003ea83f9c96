// The display lists the viewer's views were last drawn from, built again (the tests read their
// labels and observers: app/views/display_list.h).
#pragma once

#include "app/ui/viewer.h"
#include "app/views/views.h"

namespace vplab::test {

/// The display list the view `kind` was last drawn from (it must have been drawn), built again.
inline draw::DisplayList listOf(const Viewer& viewer, ViewKind kind) {
  const ViewRequest* r = viewer.images().lastRequest(kind);
  const ViewInput in{*r->scene, *r->run, r->settings, r->highlights, r->width, r->height, viewer.viewTextMetrics()};
  switch (kind) {
    case ViewKind::camera:
    case ViewKind::all: {
      const ViewInput device{*r->scene, *r->run, r->settings, r->highlights, r->scene->device.width,
                             r->scene->device.height, viewer.viewTextMetrics()};
      return cameraView(device);
    }
    case ViewKind::npc: return npcView(in);
    case ViewKind::morph: return morphView(in);
    default: return worldView(in);
  }
}

}  // namespace vplab::test
