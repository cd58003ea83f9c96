#include "course/exercise.h"

#include "base/error.h"
#include "course/rational.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <bit>
#include <random>

namespace vplab {

namespace {

// The same draws on every platform: mt19937_64 is fully specified; `% n` instead of the library's
// distributions, whose algorithms differ between standard libraries.
struct Draw {
  std::mt19937_64 g;
  size_t pick(size_t n) { return size_t(g() % n); }
  template <class T, size_t N>
  const T& of(const T (&options)[N]) { return options[pick(N)]; }
  /// A multiple of 1/2 in [lo, hi].
  double half(double lo, double hi) { return lo + 0.5 * double(pick(size_t((hi - lo) * 2) + 1)); }
};

// PRP − VRP: Pythagorean directions, so that N = (PRP − VRP)/VPD has exact fractions, and U, V too.
constexpr Vec3 kDirections[] = {{0, 0, 5}, {3, 0, 4}, {-3, 0, 4}, {4, 0, 3}, {-4, 0, 3},
                                {0, 3, 4}, {0, 0, 4}, {0, 0, 6}};
constexpr ObliqueParams kObliques[] = {kCavalier, kCabinet, {1, 45}, {0.5, 30}};

// Integer quaternions (w, x, y, z) whose rotations have rational entries with denominator
// n = w² + x² + y² + z² from 3 to 9: U, V, N are their rows (a right-handed orthonormal basis).
// (None turns about z alone: that would keep N = (0, 0, 1), the gentle case's.)
constexpr int kQuaternions[][4] = {{1, 1, 1, 0}, {1, -1, 0, 1}, {1, 0, 1, -1}, {2, 1, 0, 0}, {2, 0, -1, 0},
                                   {2, 1, 1, 1}, {1, 2, -1, 1}, {2, 2, 1, 0}, {1, 2, 0, 2}, {2, -1, 2, 0},
                                   {2, 0, 1, -2}};
constexpr size_t kOrientations = std::size(kQuaternions);
// Orientations are numbered: kQuaternions' first, then kDirections' (the gentle case, VUP along y),
// then kAnyGentle: any of kDirections, drawn anew with each attempt.
constexpr size_t kGentle = kOrientations, kAnyGentle = kGentle + std::size(kDirections);

std::array<Vec3, 3> rotationRows(const int (&q)[4]) {
  const double w = q[0], x = q[1], y = q[2], z = q[3], n = w * w + x * x + y * y + z * z;
  // clang-format off
  return {Vec3(w * w + x * x - y * y - z * z, 2 * (x * y - w * z),             2 * (x * z + w * y)) / n,
          Vec3(2 * (x * y + w * z),           w * w - x * x + y * y - z * z,   2 * (y * z - w * x)) / n,
          Vec3(2 * (x * z - w * y),           2 * (y * z + w * x),             w * w - x * x - y * y + z * z) / n};
  // clang-format on
}

Camera drawCamera(Draw& d, Projection projection, size_t orientation) {
  Camera c;
  const double offsets[] = {0, 0, 0, 0.5, -0.5, 1, -1};
  c.vrp = {d.of(offsets), d.of(offsets), d.of(offsets)};
  if (orientation >= kGentle) {
    // The lecture's gentle case: N in a coordinate plane, VUP along y.
    c.prp = c.vrp + (orientation == kAnyGentle ? d.of(kDirections) : kDirections[orientation - kGentle]);
    c.vup = d.pick(4) == 0 ? Vec3(0, 2, 0) : Vec3(0, 1, 0);
  } else {
    // A general orientation: U, V, N from a rational rotation; VPD its denominator (3 to 9) or twice
    // it when small, so PRP is VRP plus an integer vector; VUP leans towards N or away from it.
    const auto& q = kQuaternions[orientation];
    const std::array<Vec3, 3> rows = rotationRows(q);
    const double n = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    const double vpd = n < 5 ? 2 * n : n;
    c.prp = c.vrp + vpd * rows[2];
    c.vup = n * rows[1] + double(d.of({0, 0, 1, -1})) * n * rows[2];
  }
  // The device is 400 × 300: windows of the same aspect ratio, 4 × 3 or 2 × 1.5, some off centre.
  if (d.pick(2) == 0) {
    c.window.xmin = -2 + d.of({-0.5, 0.0, 0.0, 0.5});
    c.window.ymin = -1.5 + d.of({-0.5, 0.0, 0.0, 0.5});
    c.window.xmax = c.window.xmin + 4, c.window.ymax = c.window.ymin + 3;
  } else {
    c.window.xmin = -1 + d.of({-0.5, 0.0, 0.0, 0.5});
    c.window.ymin = d.of({-0.5, -1.0});
    c.window.xmax = c.window.xmin + 2, c.window.ymax = c.window.ymin + 1.5;
  }
  const double vpd = glm::length(c.prp - c.vrp);
  c.front = d.half(0.5, std::min(3.0, vpd - 1.5));
  c.back = d.of({-1.0, -1.5, -2.0, -3.0, -4.0});
  c.projection = projection;
  c.oblique = d.of(kObliques);
  return c;
}

SceneObject drawPolygon(Draw& d, const Camera& camera, bool behindEye) {
  SceneObject o;
  o.name = "P";
  o.shape = Shape::polygon;
  o.color = {0.86, 0.33, 0.27};
  // MC: a convex polygon in z = 0, counter-clockwise, P1 first.
  const size_t n = 3 + d.pick(2);
  for (;;) {
    o.vertices.clear();
    const Vec3 p1{d.half(-1, 1), d.half(-1, 1), 0};
    o.vertices.push_back(p1);
    for (size_t i = 1; i < n; ++i) {
      // y is drawn before x: the order GCC gave the unsequenced arguments of Vec3(d.half(), d.half(), 0)
      // that this once was, so that every sheet written stays what it was, and the page (Clang) draws
      // the same (issue 40).
      const double y = d.half(-4, 4), x = d.half(-4, 4);
      o.vertices.push_back(p1 + Vec3(x, y, 0));
    }
    bool convex = true;
    double area = 0;
    for (size_t i = 0; i < n; ++i) {
      const Vec3 a = o.vertices[i], b = o.vertices[(i + 1) % n], c = o.vertices[(i + 2) % n];
      const double cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
      convex = convex && cross > 0;
      area += a.x * b.y - b.x * a.y;
    }
    if (convex && area >= 2) break;
  }
  // Placed by T · R · S: 90° rotations and scales 1, 2, 1/2 keep the numbers exact.
  const double scale = d.of({1.0, 1.0, 2.0, 0.5});
  o.transform.scale = Vec3(scale);
  const Rotation rotations[] = {{{0, 0, 1}, 90, {}}, {{0, 1, 0}, 90, {}}, {{1, 0, 0}, -90, {}},
                                {{0, 1, 0}, -90, {}}, {{0, 0, 1}, 180, {}}};
  if (d.pick(4) != 0) o.transform.rotations.push_back(d.of(rotations));
  // Where P1 should land in WC: near VRP, or beyond the eye along N (behind the eye).
  const Vec3 axis = camera.prp - camera.vrp;
  // z, y, x: the order of the draws as GCC made them (see above).
  const double dz = d.half(-1.5, 1.5), dy = d.half(-1.5, 1.5), dx = d.half(-1.5, 1.5);
  Vec3 target = camera.vrp + Vec3(dx, dy, dz);
  if (behindEye) target += axis * d.of({1.5, 2.0});
  const Vec3 placed = transformAffine(wcFromMc(o.transform), o.vertices[0]);  // R · S · P1 (no translation yet)
  const Vec3 t = target - placed;
  o.transform.translate = {std::round(2 * t.x) / 2, std::round(2 * t.y) / 2, std::round(2 * t.z) / 2};
  return o;
}

// The given data and the stages of P1: denominators up to 100; the clipping's t and new vertices,
// which divide by differences of boundary values, up to 1000.
constexpr int64_t kGivenDen = 100, kClipDen = 1000;
bool isSmallRational(double x, int64_t maxDen = kGivenDen) { return Rational::approximate(x, maxDen).has_value(); }
bool isSmallRational(const Vec3& v, int64_t maxDen = kGivenDen) {
  return isSmallRational(v.x, maxDen) && isSmallRational(v.y, maxDen) && isSmallRational(v.z, maxDen);
}
bool isSmallRational(const Vec4& v, int64_t maxDen = kGivenDen) {
  return isSmallRational(Vec3(v), maxDen) && isSmallRational(v.w, maxDen);
}
bool isSmallRational(const Mat4& m) {
  for (int c = 0; c < 4; ++c)
    if (!isSmallRational(m[c])) return false;
  return true;
}

bool wellPosed(const Exercise& e, const ExerciseSolution& s) {
  const bool clippingTopic = e.spec.topic == ExerciseTopic::clipping || e.spec.topic == ExerciseTopic::pipeline;
  if (e.pointBehindEye ? !(s.point.npcH.w < 0) : s.point.outcode != 0) return false;
  Outcode any = 0;
  for (const PointStages& v : s.vertices) {
    any |= v.outcode;
    if (std::abs(v.npcH.w) < 1e-9) return false;  // a vertex in the eye's plane: no NPC, no DC
  }
  if (clippingTopic && (std::popcount(unsigned(any)) < 2 || s.fate != Fate::clipped)) return false;
  // The topic promises two planes cutting the polygon: two passes must create vertices.
  size_t cutting = 0;
  for (const ClipStep& step : s.steps)
    cutting += std::find(step.created.begin(), step.created.end(), true) != step.created.end();
  if (clippingTopic && cutting < 2) return false;
  if (!clippingTopic && (s.fate == Fate::rejected || s.fate == Fate::clippedAway)) return false;
  // No boundary value exactly 0 (a vertex on a plane makes a degenerate step) and, where the inputs
  // allow, exact fractions everywhere.
  for (const ClipStep& step : s.steps)
    for (double bc : step.boundary)
      if (std::abs(bc) < 1e-9) return false;
  const bool exact = e.scene.camera.projection != Projection::oblique;
  if (!isSmallRational(s.wcFromMc) || !isSmallRational(s.run.vrcFromWc) || !isSmallRational(s.run.vrc.u) ||
      !isSmallRational(s.run.vrc.v) || !isSmallRational(s.run.vrc.n))
    return false;
  if (!exact) return true;
  if (!isSmallRational(s.run.npcFromVrc)) return false;
  for (const PointStages& v : s.vertices)
    if (!isSmallRational(v.wc) || !isSmallRational(v.vrc) || !isSmallRational(v.npcH)) return false;
  if (!e.pointBehindEye && (!isSmallRational(s.point.npc) || !isSmallRational(s.point.dc))) return false;
  for (const auto& step : s.intersections)
    for (const ClipIntersection& c : step)
      if (!isSmallRational(c.t, kClipDen) || !isSmallRational(c.vertex, kClipDen)) return false;
  for (const Vec3& p : s.clippedDc)
    if (!isSmallRational(p, kClipDen)) return false;
  return true;
}

bool alongZ(const Vec3& direction) { return direction.x == 0 && direction.y == 0; }

}  // namespace

bool identityOrientation(const Camera& camera) {
  const VrcAxes o = vrcAxes(camera);
  auto is = [](const Vec3& a, const Vec3& b) { return glm::length(a - b) < 1e-9; };
  return is(o.u, {1, 0, 0}) && is(o.v, {0, 1, 0}) && is(o.n, {0, 0, 1});
}

Exercise generateExercise(const ExerciseSpec& spec, std::string_view studentId) {
  // A student's variant draws from the exercise's number and the id (FNV-1a of the id's bytes).
  uint64_t variant = 0;
  if (!studentId.empty()) {
    variant = 14695981039346656037ull;
    for (unsigned char ch : studentId) variant = (variant ^ ch) * 1099511628211ull;
  }
  Draw d{std::mt19937_64((spec.seed * 4 + uint64_t(spec.topic)) ^ variant)};
  Exercise e;
  e.spec = spec;
  e.studentId = std::string(studentId);
  const bool clippingTopic = spec.topic == ExerciseTopic::clipping || spec.topic == ExerciseTopic::pipeline;
  e.pointBehindEye = clippingTopic && spec.projection == Projection::perspective && spec.seed % 2 == 1;
  e.scene.title = "Exercise " + std::to_string(spec.seed) + (studentId.empty() ? "" : " for " + std::string(studentId));
  e.scene.device = {400, 300};
  e.scene.background = {1, 1, 1};
  // Orientation and mapping sheets: one in four keeps the lecture's gentle orientation, the others a
  // general one, chosen once, so that retrying a draw that is not well posed does not drift towards
  // easier cases. Clipping and pipeline sheets keep the gentle ones: a polygon reaching behind the eye
  // and cut by two planes is rarely found with a general N among the sheets' small numbers.
  size_t orientation = clippingTopic       ? kAnyGentle
                       : d.pick(4) == 0 ? kGentle + d.pick(std::size(kDirections))
                                        : d.pick(kOrientations);
  // Issue 38: equally hard variants. PRP − VRP along z with VUP along y would make U, V, N the
  // identity (nothing to compute): such a gentle orientation is drawn again (only then, so the other
  // seeds keep their sheets).
  while (orientation >= kGentle && orientation < kAnyGentle && alongZ(kDirections[orientation - kGentle]))
    orientation = kGentle + d.pick(std::size(kDirections));
  for (int attempt = 0; attempt < 50000; ++attempt) {
    e.scene.camera = drawCamera(d, spec.projection, orientation);
    if (cameraError(e.scene.camera)) continue;
    e.scene.objects = {drawPolygon(d, e.scene.camera, e.pointBehindEye)};
    e.scene.objects[0].mesh = primitiveMesh(e.scene.objects[0]);
    // An identity orientation is rejected after the draw and the check, so that every other seed's
    // draws, and so its sheet, stay what they were.
    const ExerciseSolution s = solveExercise(e);
    if (wellPosed(e, s) && !identityOrientation(e.scene.camera) &&
        outsideDifficultyBand(spec.topic, exerciseDifficulty(e, s)).empty())
      return e;
  }
  throw Error("no well-posed exercise found for seed " + std::to_string(spec.seed) + ", topic " +
              std::string(toString(spec.topic)));
}

ExerciseDifficulty exerciseDifficulty(const Exercise& exercise, const ExerciseSolution& solution) {
  ExerciseDifficulty d;
  for (const Vec3& axis : {solution.run.vrc.u, solution.run.vrc.v, solution.run.vrc.n}) {
    int zeros = 0;
    for (int i = 0; i < 3; ++i) {
      zeros += std::abs(axis[i]) < 1e-12;
      const std::optional<Rational> r = Rational::approximate(axis[i], kGivenDen);
      d.denominator = std::max(d.denominator, r ? int(r->den()) : int(kGivenDen) + 1);
    }
    d.axesOffAxis += zeros < 2;
  }
  for (int i = 0; i < 3; ++i) d.vrpNonZero += exercise.scene.camera.vrp[i] != 0;
  for (const ClipStep& step : solution.steps)
    d.cuts += std::find(step.created.begin(), step.created.end(), true) != step.created.end();
  d.clippedVertices = int(solution.clippedNpcH.size());
  return d;
}

std::string outsideDifficultyBand(ExerciseTopic topic, const ExerciseDifficulty& d) {
  const bool clippingTopic = topic == ExerciseTopic::clipping || topic == ExerciseTopic::pipeline;
  if (d.vrpNonZero == 0) return "VRP at the origin";
  if (d.axesOffAxis < 2) return std::to_string(d.axesOffAxis) + " of U, V, N off the axes (at least 2)";
  if (!clippingTopic && (d.denominator < 3 || d.denominator > 9))
    return "denominator " + std::to_string(d.denominator) + " (3 to 9)";
  if (clippingTopic && (d.cuts < 2 || d.cuts > 4)) return std::to_string(d.cuts) + " cutting planes (2 to 4)";
  if (clippingTopic && (d.clippedVertices < 3 || d.clippedVertices > 7))
    return std::to_string(d.clippedVertices) + " clipped vertices (3 to 7)";
  return {};
}

ExerciseSolution solveExercise(const Exercise& exercise) {
  ExerciseSolution s;
  s.run = runPipeline(exercise.scene);
  const ObjectRun& o = s.run.objects.at(0);
  s.wcFromMc = o.wcFromMc;
  for (uint32_t v : o.mesh->face(0)) {
    PointStages p;
    p.mc = o.mesh->positions[v];
    p.wc = o.wc(v);
    p.vrc = o.vrc(v);
    p.npcH = o.npcH[v];
    p.bc = boundaryCoordinates(p.npcH);
    p.outcode = o.outcodes[v];
    p.npc = divideByW(p.npcH);
    p.dc = transformAffine(s.run.dcFromNpc, p.npc);
    s.vertices.push_back(p);
  }
  s.point = s.vertices.at(0);
  s.steps = clipSteps(s.run, o, 0);
  // Each pass's new vertices, matched to the edges that made them in the clipper's edge order
  // (from the last vertex to the first, then on around).
  for (const ClipStep& step : s.steps) {
    std::vector<ClipIntersection> cuts;
    if (!step.skipped) {
      std::vector<Vec4> created;
      for (size_t i = 0; i < step.output.size(); ++i)
        if (step.created[i]) created.push_back(step.output[i].p);
      const size_t n = step.input.size();
      for (size_t k = 0; k < n; ++k) {
        const size_t a = (k + n - 1) % n, b = k;
        if ((step.boundary[a] >= 0) == (step.boundary[b] >= 0)) continue;
        ClipIntersection c;
        c.inside = step.boundary[a] >= 0 ? a : b;
        c.outside = step.boundary[a] >= 0 ? b : a;
        c.t = step.boundary[c.inside] / (step.boundary[c.inside] - step.boundary[c.outside]);
        if (cuts.size() < created.size()) c.vertex = created[cuts.size()];
        cuts.push_back(c);
      }
    }
    s.intersections.push_back(std::move(cuts));
  }
  s.fate = o.fate[0];
  for (uint32_t ref : o.clippedFace(0)) {
    s.clippedNpcH.push_back(o.clippedNpcH(ref));
    s.clippedDc.push_back(o.clippedDc(ref));
  }
  return s;
}

}  // namespace vplab
