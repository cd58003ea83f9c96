// The viewer's panels, one function each (docs/lecturers.md "The viewer"). They edit the document's scene and
// the view settings in place; the viewer records every change for undo.
#pragma once

#include "app/session/exercises.h"
#include "app/session/file_chooser.h"
#include "app/ui/widgets.h"

namespace vplab::ui {

// Each panel is handed the widgets it draws with (the language, what the widgets remember:
// app/ui/widgets.h) and the parts of the state it reads (const) and edits (app/session/viewer_model.h).

/// The synthetic camera: VRP, PRP, VUP, the window, F and B, the projection; U, V, N derived.
void cameraPanel(Widgets& w, DocumentPart& d, const RunPart& r, LayoutPart& l);
/// The objects, their modeling transforms, user clip planes; OBJ meshes through `dialog`.
void scenePanel(Widgets& w, DocumentPart& d, EditPart& e, StatusPart& status, FileChooser& dialog);
/// The clipping strategy, the bounding-box test and the counts of the run.
void clippingPanel(Widgets& w, ViewsPart& v, const RunPart& r);
/// The views' styles and overlays, antialiasing, the observers.
void displayPanel(Widgets& w, ViewsPart& v, const DocumentPart& d, LayoutPart& l);
/// The matrices of the five stages (the lecture notes' row-vector form on request).
void matricesPanel(Widgets& w, const RunPart& r, const EditPart& e, LecturePart& lec);
/// The probed vertex through the stages, with its outcode.
void probePanel(Widgets& w, const RunPart& r, EditPart& e);
/// The stage morph, the clipping step-through, vanishing points, lecture mode.
void lecturePanel(Widgets& w, ViewsPart& v, const DocumentPart& d, const RunPart& r, const EditPart& e, LecturePart& lec,
                  LayoutPart& l);
/// The depth plot: NPC z against VRC z, and what depth buffers resolve.
void depthPanel(Widgets& w, const RunPart& r, const LayoutPart& l);
/// An exercise's tasks, the student's fields, Check and Hand in (issue 40). With `mayFocus`, an
/// exercise just opened gives its first field the keys (a phone's compact layout would open the
/// on-screen keyboard unasked: there the student taps a field).
void tasksPanel(Widgets& w, PracticePart& p, Exercises& exercises, bool mayFocus);

}  // namespace vplab::ui
