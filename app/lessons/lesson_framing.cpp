#include "app/lessons/lesson_framing.h"

#include "pipeline/clip_steps.h"
#include "base/error.h"
#include "pipeline/modeling.h"
#include "pipeline/pipeline.h"
#include "pipeline/view_mapping.h"

#include <algorithm>
#include <cmath>

namespace vplab {

std::vector<Vec3> steppedPolygonPoints(const Scene& scene, const LessonStepThrough& step) {
  if (sceneError(scene)) return {};
  const PipelineRun run = runPipeline(scene);
  for (size_t i = 0; i < run.sceneIndex.size(); ++i) {
    if (run.sceneIndex[i] != step.object) continue;
    const ObjectRun& o = run.objects[i];
    if (step.face < 0 || size_t(step.face) >= o.faceCount()) return {};
    std::vector<Vec3> points;
    auto add = [&](const std::vector<ClipVertex>& polygon) {
      for (const ClipVertex& v : polygon)
        if (v.p.w > 0) points.push_back(glm::clamp(Vec3(v.p) / v.p.w, Vec3(0), Vec3(1)));
    };
    const std::vector<ClipStep> passes = clipSteps(run, o, size_t(step.face));
    if (passes.empty()) return {};
    // The polygon the step shows: as it enters (plane 0), else after its pass.
    const size_t pass = std::min(passes.size(), size_t(std::max(step.plane, 1))) - 1;
    add(step.plane <= 0 ? passes.front().input : passes[pass].output);
    return points;
  }
  return {};
}

std::vector<Vec3> probedObjectPoints(const Scene& scene, const Probe& probe) {
  if (probe.object >= scene.objects.size()) return {};
  const SceneObject& o = scene.objects[probe.object];
  if (!o.mesh) return {};
  Mat4 wcFromMcMatrix;
  try {
    wcFromMcMatrix = wcFromMc(o.transform);
  } catch (const Error&) {
    return {};
  }
  std::vector<Vec3> points;
  points.reserve(o.mesh->positions.size());
  for (const Vec3& p : o.mesh->positions) points.push_back(Vec3(wcFromMcMatrix * Vec4(p, 1.0)));
  return points;
}

namespace {

/// The orbit turned on the points: its target at their centre (framed() pans in the plane through
/// the target and zooms towards it, so a target far from the points would zoom past them), then
/// framed, its angles kept.
Orbit framedOn(Orbit orbit, const std::vector<Vec3>& points, double aspect) {
  Vec3 centre(0);
  for (const Vec3& p : points) centre += p;
  orbit.target = centre / double(points.size());
  return framed(orbit, points, aspect, kLessonFramingFill);
}

/// How much of a view of `aspect` the points' bounding box covers through the orbit (0 to 1).
double coverage(const Orbit& orbit, const std::vector<Vec3>& points, double aspect) {
  const Camera c = observerCamera(orbit, aspect);
  const Mat4 npcFromWc = npcFromVrc(c) * vrcFromWc(c);
  Vec2 lo(1e300), hi(-1e300);
  for (const Vec3& p : points) {
    const Vec4 h = npcFromWc * Vec4(p, 1.0);
    if (h.w <= 0) return 0;  // a point behind the observer: not this way
    lo = glm::min(lo, Vec2(h) / h.w);
    hi = glm::max(hi, Vec2(h) / h.w);
  }
  lo = glm::max(lo, Vec2(0));
  hi = glm::min(hi, Vec2(1));
  return hi.x > lo.x && hi.y > lo.y ? (hi.x - lo.x) * (hi.y - lo.y) : 0;
}

/// The orbit's angles that show the polygon largest once framed: a polygon seen almost edge-on (the
/// white sliver of lesson 05's pentagon), or a tall one in a wide view, covers little of it. Every
/// 15° of yaw and of pitch (within ±75°) is tried; of those within a few per cent of the best, the
/// nearest to where the orbit looked wins, so the move into the step turns no more than it must.
Orbit turnedTowards(const Orbit& orbit, const std::vector<Vec3>& points, double aspect) {
  struct Candidate {
    Orbit orbit;
    double covered, turn;
  };
  std::vector<Candidate> candidates;
  for (int dy = -12; dy < 12; ++dy)
    for (int pitch = -75; pitch <= 75; pitch += 15) {
      Orbit o = orbit;
      o.yawDeg = orbit.yawDeg + 15.0 * dy;
      o.pitchDeg = pitch;
      o = framedOn(o, points, aspect);
      candidates.push_back({o, coverage(o, points, aspect), std::abs(15.0 * dy) + std::abs(pitch - orbit.pitchDeg)});
    }
  double best = 0;
  for (const Candidate& c : candidates) best = std::max(best, c.covered);
  const Candidate* chosen = nullptr;
  for (const Candidate& c : candidates)
    if (c.covered >= 0.95 * best && (!chosen || c.turn < chosen->turn)) chosen = &c;
  return chosen ? chosen->orbit : framedOn(orbit, points, aspect);
}

}  // namespace

void frameStepObjects(LessonState& state, double aspect, bool ownWorldOrbit, bool ownNpcOrbit) {
  if (state.stepThrough && !ownNpcOrbit) {
    const std::vector<Vec3> points = steppedPolygonPoints(state.scene, *state.stepThrough);
    if (points.size() >= 3) state.display.npc.orbit = turnedTowards(state.display.npc.orbit, points, aspect);
  }
  if (state.probe && !ownWorldOrbit) {
    const std::vector<Vec3> points = probedObjectPoints(state.scene, *state.probe);
    if (points.size() >= 2) state.display.world.orbit = framedOn(state.display.world.orbit, points, aspect);
  }
}

}  // namespace vplab
