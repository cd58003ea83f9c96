// Issue 38: follow-through that cannot be gamed, and the mistakes a lecture's sheets are made to
// catch, named. Each answer here is made by the test's own code, not by the grader's or the mistake
// models': a Sutherland–Hodgman clipper written from the lecture notes (15.3; Blinn & Newell's
// boundary coordinates) below, the matrices and points of the reference answer changed with GLM.
// The sheets are `vplab exercise`'s own, over every topic and many seeds.
//
// The rule (course/follow_through.h, the German exam's Folgefehler): credit for correct work on a
// wrong earlier value, unless the earlier error made the later work essentially easier. A pass of
// the clipper whose plane cuts the key's polygon earns follow-through only when it had a cut to make
// on the student's own polygon; after dividing by w first, the sheet's homogeneous items (the
// passes, the clipped polygon, the boundary coordinates and the outcode) earn none.
//
// Tolerance: the grader's default (1e-3 relative). The test's clipper computes t and the new vertex
// as the pipeline does up to rounding order (a few ulps), far inside it.
#include "course/exercise.h"
#include "course/exercise_answer.h"
#include "course/grading.h"
#include "course/mistake_models.h"
#include "course/sheet_values.h"
#include "tests/course/clip_oracle.h"
#include "tests/course/sheets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace vplab {
namespace {

using Json = nlohmann::ordered_json;
using test::boundary;
using test::clipPass;
using test::describe;
using test::itemAt;
using test::jsonOf;
using test::needsCut;
using test::P4;
using test::Polygon;
using test::kPolygon;
using test::Sheet;
using test::sheetOf;

// Per topic and case: every grade runs the pipeline once per model. Under the sanitizers (several
// times slower, where memory errors rather than rare sheets are sought) the same checks on fewer.
#ifdef VPLAB_SANITIZED
constexpr uint64_t kSheets = 100;
#else
constexpr uint64_t kSheets = 300;
#endif

// ---------------------------------------------------------------- the test's own clipper (clip_oracle.h)

Polygon polygonOf(const Json& j) {
  Polygon p;
  for (const Json& v : j) p.push_back({v[0].get<double>(), v[1].get<double>(), v[2].get<double>(), v[3].get<double>()});
  return p;
}
// DC of a homogeneous polygon with the sheet's dcFromNpc (rows as the answer writes them).
Json dcOf(const Polygon& p, const Json& dcFromNpc) {
  Json out = Json::array();
  if (p.size() < 3) return out;
  for (const P4& v : p) {
    const double n[4] = {v[0] / v[3], v[1] / v[3], v[2] / v[3], 1};
    Json q = Json::array();
    for (int r = 0; r < 3; ++r) {
      double s = 0;
      for (int c = 0; c < 4; ++c) s += dcFromNpc[size_t(r)][size_t(c)].get<double>() * n[c];
      q.push_back(s);
    }
    out.push_back(q);
  }
  return out;
}

Json::json_pointer pass(int k) { return Json::json_pointer(kPolygon + "/clip_steps/" + std::to_string(k) + "/polygon"); }

// ---------------------------------------------------------------- clipping: divide first

// The student divides every vertex by w, then clips each pass right: (x/w, y/w, z/w, 1) through the
// six planes, and maps the result to DC. Only dcFromNpc earns its point; the mistake is named.
TEST(FollowThrough, DividingFirstOnTheClippingSheetEarnsNoFollowThroughAndIsNamed) {
  size_t graded = 0;
  for (uint64_t seed = 1; seed <= kSheets; ++seed) {
    const Sheet s = sheetOf(seed, ExerciseTopic::clipping);
    Polygon p = polygonOf(s.reference.reference[Json::json_pointer(kPolygon + "/npc_h")]);
    for (P4& v : p) v = {v[0] / v[3], v[1] / v[3], v[2] / v[3], 1};
    Json answer = s.key;
    for (int k = 0; k < 6; ++k) answer[pass(k)] = jsonOf(p = clipPass(p, k));
    answer[Json::json_pointer(kPolygon + "/clipped_dc")] = dcOf(p, s.key["matrices"]["dc_from_npc"]);
    const NumbersGrade g = gradeNumbers(answer, "a.json", s.reference, s.assignment.tolerance, &s.assignment);
    ++graded;
    ASSERT_TRUE(g.mistake.has_value() && *g.mistake == Mistake::divideFirst) << "seed " << seed << ": " << describe(g);
    // Every pass is wrong (written with w = 1); the clipped polygon in DC is right where no vertex lay
    // behind the eye (then dividing first changes nothing there) and earns its points only then.
    for (const ItemGrade& i : g.items) {
      EXPECT_FALSE(i.followsThrough) << "seed " << seed << ": " << describe(g);
      EXPECT_EQ(i.earned, i.right() ? i.points : 0) << "seed " << seed << ": " << describe(g);
      if (i.path.find("clip_steps") != std::string::npos) {
        EXPECT_FALSE(i.right()) << "seed " << seed;
      }
    }
    bool behind = false;
    for (const P4& v : polygonOf(s.reference.reference[Json::json_pointer(kPolygon + "/npc_h")])) behind |= v[3] < 0;
    EXPECT_EQ(itemAt(g, kPolygon + "/clipped_dc").right(), !behind) << "seed " << seed << ": " << describe(g);
    EXPECT_EQ(g.firstStage, 4) << "seed " << seed << ": the first departure is clipping";
  }
  EXPECT_EQ(graded, kSheets);
}

// ---------------------------------------------------------------- clipping: the final polygon copied

// Every pass given as the final polygon: a pass earns only where it is right, or where the key's pass
// had nothing to cut either (then copying did not make it easier).
TEST(FollowThrough, TheFinalPolygonCopiedIntoEveryPassEarnsNothingForTheCutsItSkipped) {
  for (uint64_t seed = 1; seed <= kSheets; ++seed) {
    const Sheet s = sheetOf(seed, ExerciseTopic::clipping);
    const Json& ref = s.reference.reference;
    Polygon keyIn = polygonOf(ref[Json::json_pointer(kPolygon + "/npc_h")]);
    Polygon finalPolygon = keyIn;
    for (int k = 0; k < 6; ++k) finalPolygon = clipPass(finalPolygon, k);
    Json answer = s.key;
    double expected = 0, cuts = 0;
    for (int k = 0; k < 6; ++k) {
      answer[pass(k)] = jsonOf(finalPolygon);
      const bool keyCuts = needsCut(keyIn, k);
      keyIn = clipPass(keyIn, k);
      // Right where the key's pass is the final polygon already (no later pass cuts it).
      bool laterCut = false;
      Polygon q = keyIn;
      for (int j = k + 1; j < 6; ++j) laterCut |= needsCut(q, j), q = clipPass(q, j);
      // Else it follows through where the key had no cut either; the first pass starts from the
      // sheet's polygon, not the student's, and follows nothing.
      expected += (!laterCut || (k > 0 && !keyCuts)) ? 1 : 0;
      cuts += keyCuts;
    }
    expected += 3;  // dcFromNpc and the clipped polygon in DC are right
    const NumbersGrade g = gradeNumbers(answer, "a.json", s.reference, s.assignment.tolerance, &s.assignment);
    EXPECT_EQ(g.points, expected) << "seed " << seed << " (" << cuts << " cutting passes): " << describe(g);
    EXPECT_LE(g.points, g.maxPoints - 1) << "seed " << seed << ": the copy skips at least one cut";
  }
}

// ---------------------------------------------------------------- clipping: an honest slip

// A wrong t in one cutting pass (its first vertex moved a tenth along its edge), every later pass
// done right on the slipped polygon: only the slipped pass loses its point.
TEST(FollowThrough, AnHonestSlipInOnePassCostsOnlyThatPass) {
  size_t graded = 0, skipped = 0;
  for (uint64_t seed = 1; seed <= kSheets; ++seed) {
    const Sheet s = sheetOf(seed, ExerciseTopic::clipping);
    Polygon p = polygonOf(s.reference.reference[Json::json_pointer(kPolygon + "/npc_h")]);
    int slipAt = -1;
    Json answer = s.key;
    bool fair = true;
    for (int k = 0; k < 6; ++k) {
      const bool keyCuts = needsCut(polygonOf(s.reference.reference[k == 0 ? Json::json_pointer(kPolygon + "/npc_h") : pass(k - 1)]), k);
      if (slipAt >= 0 && keyCuts && !needsCut(p, k)) fair = false;  // the slip removed a later cut: not this case
      p = clipPass(p, k);
      if (slipAt < 0 && keyCuts && p.size() >= 3) {
        slipAt = k;
        for (int j = 0; j < 4; ++j) p[0][size_t(j)] += 0.1 * (p[1][size_t(j)] - p[0][size_t(j)]);
      }
      answer[pass(k)] = jsonOf(p);
    }
    answer[Json::json_pointer(kPolygon + "/clipped_dc")] = dcOf(p, s.key["matrices"]["dc_from_npc"]);
    if (slipAt < 0 || !fair) {
      ++skipped;
      continue;
    }
    const NumbersGrade g = gradeNumbers(answer, "a.json", s.reference, s.assignment.tolerance, &s.assignment);
    EXPECT_EQ(g.points, g.maxPoints - 1) << "seed " << seed << ", the slip in pass " << slipAt << ": " << describe(g);
    EXPECT_FALSE(itemAt(g, pass(slipAt).to_string()).followsThrough);
    ++graded;
  }
  EXPECT_GE(graded, kSheets * 9 / 10) << skipped << " sheets skipped";
}

}  // namespace
}  // namespace vplab
