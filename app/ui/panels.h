// The viewer's panels, one function each (docs/lecturers.md "The viewer"). They edit the document's scene and
// the view settings in place; the viewer records every change for undo.
#pragma once

#include "app/ui/file_dialog.h"
#include "app/ui/viewer_state.h"

namespace vplab::ui {

void cameraPanel(ViewerState& s);
void scenePanel(ViewerState& s, FileChooser& dialog);
void clippingPanel(ViewerState& s);
void displayPanel(ViewerState& s);
void matricesPanel(ViewerState& s);
void probePanel(ViewerState& s);
void lecturePanel(ViewerState& s);
void depthPanel(ViewerState& s);

/// Adds an object of `shape` where the camera looks, selected (the scene panel's "+ cube" …). A mesh
/// (an OBJ `file`) is read on the viewer's worker thread: it joins the scene when loaded.
void addObject(ViewerState& s, Shape shape, std::string file = {});

}  // namespace vplab::ui
