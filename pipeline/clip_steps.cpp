#include "pipeline/clip_steps.h"

namespace vplab {

std::vector<ClipStep> clipSteps(const PipelineRun& run, const ObjectRun& o, size_t face) {
  std::vector<ClipVertex> polygon;
  const size_t users = run.userPlanesNpc.size();
  for (uint32_t v : o.mesh->face(face)) {
    std::array<double, kMaxUserPlanes> user{};
    for (size_t k = 0; k < users; ++k) user[k] = glm::dot(run.userPlanesNpc[k], o.npcH[v]);
    polygon.push_back({o.npcH[v], clipValues(boundaryCoordinates(o.npcH[v]), {user.data(), users}), v});
  }
  std::vector<ClipStep> steps;
  for (int plane = 0; plane < kPlaneCount + int(users); ++plane) {
    ClipStep step;
    step.plane = plane;
    step.input = polygon;
    bool anyOutside = false;
    for (const ClipVertex& c : polygon) {
      step.boundary.push_back(c.bc[plane]);
      anyOutside = anyOutside || c.bc[plane] < 0;
    }
    step.skipped = !anyOutside;
    if (step.skipped || polygon.size() < 3) {
      step.output = polygon;
    } else {
      // Not snapped between passes, exactly as the pipeline clips (it snaps only what it keeps).
      clipPolygonAgainstPlane(polygon, plane, step.output);
    }
    for (const ClipVertex& c : step.output) {
      bool fromInput = false;
      for (const ClipVertex& in : polygon) fromInput = fromInput || (in.p == c.p && in.source == c.source);
      step.created.push_back(!fromInput);
    }
    polygon = step.output;
    steps.push_back(std::move(step));
  }
  // Fewer than three vertices left is no polygon, as the clipper decides.
  if (steps.back().output.size() < 3) steps.back().output.clear();
  return steps;
}

}  // namespace vplab
