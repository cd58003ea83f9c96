// Issue 38: the mistakes a lecture's sheets are made to catch, named on the sheets themselves, over
// several hundred sheets of each topic they apply to. Each answer is the key changed by the test's
// own formulas (GLM and the lecture notes' definitions), not by the mistake models' code:
//
//   forgot T(−VRP)      vrcFromWc = R (its translation column zero); P1 in VRC = R · P1 in WC and every
//                       later value of P1 from it (orientation and pipeline sheets)
//   outcode reversed    the outcode's six bits in reverse order (mapping and pipeline sheets)
//   divide first        P1's boundary coordinates and outcode from (x/w, y/w, z/w, 1) (mapping and
//                       pipeline sheets; the clipping sheet's passes: follow_through_test.cpp)
//
// Each must be named, and the points must be what the rule gives: the item that holds the mistake
// loses its points; later items computed right from it follow through, except after dividing first,
// which removes the homogeneous items' subject (course/assignment.h).
#include "course/grading.h"
#include "course/mistake_models.h"
#include "tests/course/sheets.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace vplab {
namespace {

using Json = nlohmann::ordered_json;
using test::describe;
using test::hasItem;
using test::itemAt;
using test::kPolygon;
using test::Sheet;
using test::sheetOf;

// Per topic; under the sanitizers (several times slower, where memory errors rather than rare
// sheets are sought) the same checks on fewer.
#ifdef VPLAB_SANITIZED
constexpr uint64_t kSheets = 70;
#else
constexpr uint64_t kSheets = 200;
#endif

Json::json_pointer at(const std::string& p) { return Json::json_pointer(p); }

glm::dvec4 vec4Of(const Json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>(), j[3].get<double>()}; }
// A matrix as the answer writes it (rows), as GLM holds it ([column][row]).
glm::dmat4 matrixOf(const Json& rows) {
  glm::dmat4 m(1.0);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = rows[size_t(r)][size_t(c)].get<double>();
  return m;
}
Json rowsOf(const glm::dmat4& m) {
  Json out = Json::array();
  for (int r = 0; r < 4; ++r) out.push_back(Json::array({m[0][r], m[1][r], m[2][r], m[3][r]}));
  return out;
}

// Boundary coordinates (left, right, bottom, top, back, front) and the outcode (bit i: BCi < 0).
std::array<double, 6> boundaryOf(const glm::dvec4& p) { return {p.x, p.w - p.x, p.y, p.w - p.y, p.z, p.w - p.z}; }
int outcodeOf(const std::array<double, 6>& bc) {
  int code = 0;
  for (int i = 0; i < 6; ++i) code |= (bc[size_t(i)] < 0) << i;
  return code;
}

// P1's values from homogeneous NPC on, as the sheet asks them, written into the answer where it has them.
void writeFromNpcH(Json& answer, const glm::dvec4& h, const Json& dcFromNpc) {
  if (answer.contains(at(kPolygon + "/npc_h/0"))) answer[at(kPolygon + "/npc_h/0")] = Json::array({h.x, h.y, h.z, h.w});
  const std::array<double, 6> bc = boundaryOf(h);
  if (answer.contains(at(kPolygon + "/boundary/0"))) answer[at(kPolygon + "/boundary/0")] = Json(std::vector<double>(bc.begin(), bc.end()));
  if (answer.contains(at(kPolygon + "/outcodes/0"))) answer[at(kPolygon + "/outcodes/0")] = outcodeOf(bc);
  const glm::dvec4 n(h.x / h.w, h.y / h.w, h.z / h.w, 1);
  if (answer.contains(at(kPolygon + "/npc/0"))) answer[at(kPolygon + "/npc/0")] = Json::array({n.x, n.y, n.z});
  if (answer.contains(at(kPolygon + "/dc/0"))) {
    const glm::dvec4 dc = matrixOf(dcFromNpc) * n;
    answer[at(kPolygon + "/dc/0")] = Json::array({dc.x, dc.y, dc.z});
  }
}

// ---------------------------------------------------------------- forgot T(−VRP)

TEST(SheetMistakes, ForgettingTMinusVrpIsNamedAndOnlyVrcFromWcLosesItsPoints) {
  for (ExerciseTopic topic : {ExerciseTopic::orientation, ExerciseTopic::pipeline})
    for (uint64_t seed = 1; seed <= kSheets; ++seed) {
      const Sheet s = sheetOf(seed, topic);
      // No sheet puts VRP at the origin, where T(−VRP) is the identity and nothing could be forgotten.
      ASSERT_NE(s.exercise.scene.camera.vrp, Vec3(0.0)) << toString(topic) << " seed " << seed;
      const Json& ref = s.reference.reference;
      glm::dmat4 r = matrixOf(ref["matrices"]["vrc_from_wc"]);
      r[3] = glm::dvec4(0, 0, 0, 1);  // the translation column: T(−VRP) left out
      const Json& wcJson = ref[at(kPolygon + "/wc/0")];
      const glm::dvec4 vrc = r * glm::dvec4(wcJson[0].get<double>(), wcJson[1].get<double>(), wcJson[2].get<double>(), 1);
      Json answer = s.key;
      answer["matrices"]["vrc_from_wc"] = rowsOf(r);
      answer[at(kPolygon + "/vrc/0")] = Json::array({vrc.x, vrc.y, vrc.z});
      if (topic == ExerciseTopic::pipeline)
        writeFromNpcH(answer, matrixOf(ref["matrices"]["npc_from_vrc"]) * vrc, ref["matrices"]["dc_from_npc"]);
      const NumbersGrade g = gradeNumbers(answer, "a.json", s.reference, s.assignment.tolerance, &s.assignment);
      const std::string where = std::string(toString(topic)) + " seed " + std::to_string(seed) + ": " + describe(g);
      ASSERT_TRUE(g.mistake.has_value() && *g.mistake == Mistake::forgotTranslation) << where;
      EXPECT_EQ(g.points, g.maxPoints - itemAt(g, "/matrices/vrc_from_wc").points) << where;
      EXPECT_EQ(g.firstStage, 2) << where;
    }
}

// ---------------------------------------------------------------- the outcode's bits reversed

TEST(SheetMistakes, TheOutcodesBitsInReverseOrderAreNamedAndCostTheOutcode) {
  size_t graded = 0;
  for (ExerciseTopic topic : {ExerciseTopic::mapping, ExerciseTopic::pipeline})
    for (uint64_t seed = 1; seed <= kSheets; ++seed) {
      const Sheet s = sheetOf(seed, topic);
      const int code = s.key[at(kPolygon + "/outcodes/0")].get<int>();
      int reversed = 0;
      for (int bit = 0; bit < 6; ++bit) reversed |= ((code >> bit) & 1) << (5 - bit);
      if (reversed == code) continue;  // 0, 12, 33, …: the same read either way
      Json answer = s.key;
      answer[at(kPolygon + "/outcodes/0")] = reversed;
      const NumbersGrade g = gradeNumbers(answer, "a.json", s.reference, s.assignment.tolerance, &s.assignment);
      const std::string where = std::string(toString(topic)) + " seed " + std::to_string(seed) + ": " + describe(g);
      ASSERT_TRUE(g.mistake.has_value() && *g.mistake == Mistake::outcodeReversed) << where;
      EXPECT_EQ(g.points, g.maxPoints - itemAt(g, kPolygon + "/outcodes/0").points) << where;
      ++graded;
    }
  // P1 is inside (outcode 0) on the even seeds' sheets, and some outcodes read the same reversed.
  EXPECT_GE(graded, kSheets / 4) << "sheets whose outcode is not a palindrome";
}

// ---------------------------------------------------------------- divide first, P1

// The boundary coordinates of P1 divided first: (x/w, 1 − x/w, …), and the outcode from them. The
// boundary coordinates are wrong and named; the outcode earns its point only where it is right
// (P1 before the eye), never by following the divided boundary coordinates.
TEST(SheetMistakes, DividingFirstOnTheMappingAndPipelineSheetsIsNamedWithoutFollowThrough) {
  size_t behind = 0;
  for (ExerciseTopic topic : {ExerciseTopic::mapping, ExerciseTopic::pipeline})
    for (uint64_t seed = 1; seed <= kSheets; ++seed) {
      const Sheet s = sheetOf(seed, topic);
      const glm::dvec4 h = vec4Of(s.key[at(kPolygon + "/npc_h/0")]);
      const std::array<double, 6> bc = boundaryOf(glm::dvec4(h.x / h.w, h.y / h.w, h.z / h.w, 1));
      Json answer = s.key;
      answer[at(kPolygon + "/boundary/0")] = Json(std::vector<double>(bc.begin(), bc.end()));
      answer[at(kPolygon + "/outcodes/0")] = outcodeOf(bc);
      const NumbersGrade g = gradeNumbers(answer, "a.json", s.reference, s.assignment.tolerance, &s.assignment);
      const std::string where = std::string(toString(topic)) + " seed " + std::to_string(seed) + ": " + describe(g);
      ASSERT_TRUE(g.mistake.has_value() && *g.mistake == Mistake::divideFirst) << where;
      const ItemGrade& outcode = itemAt(g, kPolygon + "/outcodes/0");
      EXPECT_FALSE(outcode.followsThrough) << where;
      EXPECT_EQ(outcode.right(), h.w > 0) << where;
      EXPECT_EQ(g.points, g.maxPoints - itemAt(g, kPolygon + "/boundary/0").points - (h.w > 0 ? 0 : outcode.points)) << where;
      behind += h.w < 0;
    }
  // The pipeline sheets of odd seeds put P1 behind the eye (course/exercise.h).
  EXPECT_GE(behind, kSheets / 4) << "sheets with P1 behind the eye, where the outcode shows the mistake";
}

// ---------------------------------------------------------------- the sheet's precision

// Each number of `j` rounded to `decimals` places; every other one written with a decimal comma.
Json roundedAsWritten(const Json& j, int decimals, size_t& count) {
  if (j.is_number_float()) {
    const double f = std::pow(10.0, decimals);
    const double r = std::round(j.get<double>() * f) / f;
    if (count++ % 2 == 0) return r;
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, r);
    std::string t = text;
    if (const size_t dot = t.find('.'); dot != std::string::npos) t[dot] = ',';
    return t;
  }
  if (j.is_structured()) {
    Json out = j;
    auto in = j.begin();
    for (auto it = out.begin(); it != out.end(); ++it, ++in) *it = roundedAsWritten(*in, decimals, count);
    return out;
  }
  return j;
}

// The sheet says "at least 3 decimals; rounding to 3 decimals costs nothing" (exercise_writer.cpp):
// the key rounded so, half of it with decimal commas, earns every point on every topic's sheets.
TEST(SheetMistakes, RoundingToTheSheetsPrecisionCostsNothing) {
  for (ExerciseTopic topic : {ExerciseTopic::orientation, ExerciseTopic::mapping, ExerciseTopic::clipping, ExerciseTopic::pipeline})
    for (uint64_t seed = 1; seed <= 60; ++seed) {
      const Sheet s = sheetOf(seed, topic);
      size_t count = 0;
      const Json answer = roundedAsWritten(s.key, 3, count);
      const NumbersGrade g = gradeNumbers(answer, "a.json", s.reference, s.assignment.tolerance, &s.assignment);
      EXPECT_EQ(g.points, g.maxPoints) << toString(topic) << " seed " << seed << ": " << describe(g);
    }
}

}  // namespace
}  // namespace vplab
