// Sutherland–Hodgman one plane at a time, for the clipping step-through (docs/lecturers.md
// "The viewer": lecture features): the polygon entering each plane's pass, every vertex's boundary
// coordinate for that plane (Hill 7.4), the polygon leaving it and which of its vertices the pass
// created. Uses the very kernel the pipeline clips with, so the last step equals the clipper's output.
#pragma once

#include "pipeline/pipeline.h"

#include <vector>

namespace vplab {

struct ClipStep {
  int plane = -1;                    // 0..5 (ClipPlane)
  bool skipped = false;              // no vertex outside this plane: the pass changes nothing
  std::vector<ClipVertex> input;     // homogeneous NPC
  std::vector<double> boundary;      // input[i].bc[plane]
  std::vector<ClipVertex> output;    // created vertices not yet snapped onto their planes (as in the
                                     // clipper; snapToPlanes them to draw)
  std::vector<bool> created;         // output[i] was made by this pass
};

/// The passes over face f of an object, clipping in homogeneous NPC: left, right, bottom, top, back,
/// front, then the run's user clip planes (DGL wiki). A trivially accepted polygon has only skipped
/// steps; a trivially rejected one is still stepped through (to show why the outcodes reject it).
std::vector<ClipStep> clipSteps(const PipelineRun& run, const ObjectRun& object, size_t face);

}  // namespace vplab
