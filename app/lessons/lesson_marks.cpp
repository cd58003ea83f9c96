#include "app/lessons/lesson_marks.h"

#include "app/inspect/picking.h"
#include "pipeline/clip_steps.h"
#include "pipeline/clipping.h"

#include <algorithm>

namespace vplab {

std::optional<Highlights::Step> stepThroughMark(const PipelineRun& run, int object, int face, int step) {
  for (size_t i = 0; i < run.sceneIndex.size(); ++i) {
    if (int(run.sceneIndex[i]) != object) continue;
    const ObjectRun& o = run.objects[i];
    if (face < 0 || size_t(face) >= o.faceCount()) return std::nullopt;
    const std::vector<ClipStep> steps = clipSteps(run, o, size_t(face));
    Highlights::Step h;
    const bool start = step <= 0;
    const ClipStep& pass = steps[size_t(start ? 0 : std::min<int>(step, int(steps.size())) - 1)];
    const std::vector<ClipVertex>& polygon = start ? pass.input : pass.output;
    h.plane = start ? -1 : pass.plane;
    for (size_t k = 0; k < polygon.size(); ++k) {
      Vec4 p = polygon[k].p;
      snapToPlanes(p, polygon[k].onPlanes);
      if (p.w <= 0) continue;  // behind the eye: no point in NPC (only before the first passes)
      h.polygonNpc.push_back(Vec3(p) / p.w);
      h.created.push_back(!start && pass.created[k]);
    }
    return h;
  }
  return std::nullopt;
}

Highlights lessonMarks(const PipelineRun& run, const LessonState& state) {
  Highlights hl;
  std::optional<Probe> probe = state.probe;
  for (const LessonHighlight& h : state.highlights) {
    if (h.kind == LessonHighlight::Kind::handle) hl.handles.push_back({handlePosition(run, h.handle), handleName(h.handle), true});
    if (h.kind == LessonHighlight::Kind::vertex && !probe) probe = h.vertex;
    if (h.kind == LessonHighlight::Kind::plane) hl.planes.push_back(h.plane);
    if (h.kind == LessonHighlight::Kind::axis) hl.axes.push_back(h.axis);
  }
  if (probe) {
    hl.probeWc = probePosition(run, *probe, ViewKind::world);
    hl.probeNpc = probePosition(run, *probe, ViewKind::npc);
    hl.probeDc = probePosition(run, *probe, ViewKind::camera);
  }
  if (state.stepThrough)
    hl.step = stepThroughMark(run, int(state.stepThrough->object), state.stepThrough->face, state.stepThrough->plane);
  hl.vanishingObject = int(state.selected);
  return hl;
}

}  // namespace vplab
