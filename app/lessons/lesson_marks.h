// The marks a view draws for a state of the lab (app/views/views.h, Highlights): where the probed
// vertex lands in each view, the clipping step-through's polygon, the highlighted handles. The viewer
// adds them to its frame's marks (app/ui/view_panes.cpp); a lesson's pictures are drawn with them
// (app/commands/lesson_export.h).
#pragma once

#include "app/lessons/lesson.h"
#include "app/views/views.h"
#include "pipeline/pipeline.h"

#include <optional>

namespace vplab {

/// The step-through's polygon of face `face` of scene object `object` after `step` passes (0: as it
/// enters; lecture notes 15.3, Hill 7.4), in NPC, with the vertices the last pass created and the
/// plane it applied. Nullopt when the object is not in the run or has no such face.
std::optional<Highlights::Step> stepThroughMark(const PipelineRun& run, int object, int face, int step);

/// A lesson step's marks over `run` (the run of its scene): its probe (or else its highlighted
/// vertex) in every view, its step-through, its highlighted handles (hot, with their names) and the
/// selected object's vanishing points.
Highlights lessonMarks(const PipelineRun& run, const LessonState& state);

}  // namespace vplab
