// The exercises of `vplab exercise` (issue 14): a random but well-posed camera, point and polygon
// for one topic of the lecture notes, and the worked solution's values, all taken from the
// pipeline's own run (no second implementation of any stage).
//
// Well posed: VRP, the window, F and B are small integers and halves; U, V, N are the rows of a
// rational rotation (orientation and mapping sheets: from an integer quaternion, denominators 3 to 9,
// in three sheets of four) or PRP − VRP is one of the Pythagorean directions in a coordinate plane with
// VUP along y; PRP = VRP + VPD · N and VUP = a multiple of V plus one of N, so N, U, V and VPD are exact
// fractions; the polygon lies in MC's z = 0
// plane (convex, counter-clockwise) and is placed by T · R · S with 90° rotations and scales 1, 2
// or 1/2. The point P1 is the polygon's first vertex. For `clipping` and `pipeline` the polygon
// crosses at least two planes of the view volume and something of it remains; in the perspective
// "behind the eye" variant (odd seeds) P1 lies behind the eye (w < 0). Otherwise P1 is inside the
// view volume; no vertex has w = 0 exactly, and a clipping polygon is cut by at least two planes
// (two passes create vertices). Except for the oblique projection's cos φ and sin φ, every value the solution shows
// is a fraction with a denominator of at most 1000 (Rational::approximate).
#pragma once
#include "pipeline/clip_steps.h"
#include "base/enum_table.h"
#include "pipeline/pipeline.h"

#include <cstdint>
#include <string>
#include <optional>
#include <string_view>
#include <vector>

namespace vplab {

enum class ExerciseTopic { orientation, mapping, clipping, pipeline };
/// The command line's and assignment.json's "topic".
inline constexpr EnumTable<ExerciseTopic, 4> kExerciseTopicNames = {
    {{ExerciseTopic::orientation, "orientation"}, {ExerciseTopic::mapping, "mapping"},
     {ExerciseTopic::clipping, "clipping"}, {ExerciseTopic::pipeline, "pipeline"}}};
constexpr const auto& namesOf(ExerciseTopic) { return kExerciseTopicNames; }

struct ExerciseSpec {
  uint64_t seed = 1;  // the exercise's number: the same for the whole class
  ExerciseTopic topic = ExerciseTopic::pipeline;
  Projection projection = Projection::perspective;
  bool operator==(const ExerciseSpec&) const = default;
};

struct Exercise {
  ExerciseSpec spec;
  std::string studentId;        // whose variant this is; empty: the class's sheet
  Scene scene;                  // the camera, a 400 × 300 device, one polygon object "P"
  bool pointBehindEye = false;  // the variant in which P1 lies behind the eye
};

/// The exercise of a seed: the same spec always gives the same exercise (a fixed 64-bit Mersenne
/// twister and no library distributions). Throws vplab::Error if no well-posed exercise was found
/// (which the tests show does not happen for any topic and projection over many seeds).
/// `studentId`: a student's own variant of exercise `seed` (vplab exercise --student-id): other numbers,
/// the same tasks and difficulty (P1 behind the eye or not follows `seed`); empty: the class's sheet.
Exercise generateExercise(const ExerciseSpec& spec, std::string_view studentId = {});

/// Whether the camera's U, V, N are the WC axes x, y, z (an orientation with nothing to compute:
/// generateExercise never gives one, issue 38).
bool identityOrientation(const Camera& camera);

/// P1 through the stages (lecture notes 15.2): MC, WC, VRC, homogeneous NPC, its boundary
/// coordinates and outcode (Hill 7.4), NPC after the division and DC (meaningful when inside).
struct PointStages {
  Vec3 mc, wc, vrc;
  Vec4 npcH;
  Boundary bc{};
  Outcode outcode = 0;
  Vec3 npc, dc;
};

/// One intersection of a Sutherland–Hodgman pass: the edge from input vertex `from` (inside) to
/// `to` (outside) or back, t measured from the inside endpoint (t = BC(in) / (BC(in) − BC(out)),
/// the clipper's own rule), and the new vertex in homogeneous NPC as the clipper made it.
struct ClipIntersection {
  size_t inside = 0, outside = 0;  // indices into the step's input
  double t = 0;
  Vec4 vertex;
};

struct ExerciseSolution {
  PipelineRun run;                 // the reference run of the exercise's scene
  Mat4 wcFromMc{1.0};
  PointStages point;
  std::vector<PointStages> vertices;  // every polygon vertex (P1 first)
  std::vector<ClipStep> steps;        // the clipper's passes over the polygon (clip_steps.h)
  std::vector<std::vector<ClipIntersection>> intersections;  // per step
  Fate fate = Fate::accepted;
  std::vector<Vec4> clippedNpcH;   // the clipped polygon, homogeneous NPC (snapped, as the pipeline keeps it)
  std::vector<Vec3> clippedDc;     // the same in DC, as the pipeline maps it
};

/// Runs the exercise's scene through the pipeline and collects what the solution shows.
ExerciseSolution solveExercise(const Exercise& exercise);

/// How hard a variant is, in what a student computes (issue 38: every student's variant of a sheet
/// within one band, so that no one gets the easy one):
struct ExerciseDifficulty {
  int axesOffAxis = 0;    // of U, V, N, how many are not along a WC axis (0: the identity, nothing to compute)
  int denominator = 1;    // the largest denominator among U's, V's and N's exact components
  int vrpNonZero = 0;     // VRP's non-zero coordinates (0: T(−VRP) changes nothing, forgetting it is unseen)
  int cuts = 0;           // Sutherland–Hodgman passes that create vertices
  int clippedVertices = 0;  // the clipped polygon's vertices
};
ExerciseDifficulty exerciseDifficulty(const Exercise& exercise, const ExerciseSolution& solution);

/// The band every variant of a topic lies in: orientation and mapping sheets at least two of U, V,
/// N off the axes with denominators 3 to 9; clipping and pipeline sheets (the lecture's gentle
/// orientation) two off the axes, two to four cutting planes and three to seven clipped vertices;
/// every sheet a VRP away from the origin. Empty when `d` lies in it, else what is out of it.
std::string outsideDifficultyBand(ExerciseTopic topic, const ExerciseDifficulty& d);

}  // namespace vplab
