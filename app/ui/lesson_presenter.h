// Presenting a lesson in the viewer (docs/lecturers.md "Lessons"): the keys a lecturer and a presentation
// clicker use, the move into a step applied frame by frame, the caption box, and the step's
// highlights in the views. The lesson itself and its moves are GL- and UI-free
// (app/lessons/lesson_player.h); this applies them to the ViewerState.
//
// Keys while a lesson is open: → Space Page Down the next step, ← Page Up the one before, Home and
// End the first and the last, a number and Enter that step, Esc the typed number (a second Esc
// closes the lesson). The digits then type a step number instead of choosing the styles.
#pragma once

#include "app/ui/layout.h"
#include "app/ui/viewer_state.h"

namespace vplab::ui {

/// Goes to step `step` (from 0; clamped) at ImGui time `now`: the lab moves there from what it shows.
void goToStep(ViewerState& s, size_t step, double now);
/// The lesson's keys (not while a field takes text). Returns whether a lesson is open (the digits
/// are then its, not the styles').
bool lessonKeys(ViewerState& s, double now);
/// At the frame's start, before the panels: the state of this moment of the move into the step,
/// applied to the document and the views; once the move is over, the step's own tab, probe,
/// step-through and highlights.
void lessonFrame(ViewerState& s, double now);
/// Whether the document is being moved into a step at `now`: it records no undo step until the
/// move is over, then one.
bool lessonMoving(const ViewerState& s, double now);
/// After the document recorded the frame (Document::endFrame): a step just reached is what the
/// lesson file says, so it leaves nothing unsaved.
void lessonEndFrame(ViewerState& s, double now);
/// The caption box's height for the current step's caption (at least two lines) at `width` pixels (0: no lesson).
float lessonCaptionHeight(const ViewerState& s, float width);
/// The caption box in `rect`: the lesson's title, the step and its section, the caption with its
/// mathematics, the buttons back, next and close.
void lessonCaption(ViewerState& s, const Rect& rect, double now);
/// The step's highlights added to this frame's marks: its handles hot, its planes and axis, its
/// vertices marked as the probe is (when the step has no probe of its own).
void addLessonMarks(const ViewerState& s, Highlights& hl);

}  // namespace vplab::ui
