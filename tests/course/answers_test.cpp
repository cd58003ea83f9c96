// Issue 21, the grader must never pass what it did not check: answers that give nothing, leave out
// what an assignment requires, give a clipped polygon the other way round, round their numbers,
// write fractions, or give P1 alone; the assignment file; the sheet's values beyond the dump; and
// the answer template `vplab exercise` writes for every topic.
#include "course/assignment.h"
#include "course/exercise.h"
#include "course/exercise_answer.h"
#include "course/grading.h"
#include "course/mistake_models.h"
#include "course/rational.h"
#include "course/sheet_values.h"
#include "io/scene_io.h"
#include "base/error.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <functional>

namespace vplab {
namespace {

using Json = nlohmann::ordered_json;
using ::testing::HasSubstr;
using test::errorOf;

Scene asset(const char* name) { return loadScene(std::string(VPLAB_ASSETS) + "/scenes/" + name); }

// Every number of `j` rounded to `decimals` places.
Json rounded(const Json& j, int decimals) {
  if (j.is_number_float()) {
    const double f = std::pow(10.0, decimals);
    return std::round(j.get<double>() * f) / f;
  }
  if (j.is_array()) {
    Json out = Json::array();
    for (const Json& e : j) out.push_back(rounded(e, decimals));
    return out;
  }
  if (j.is_object()) {
    Json out = Json::object();
    for (const auto& [k, v] : j.items()) out[k] = rounded(v, decimals);
    return out;
  }
  return j;
}

Assignment assignmentOf(std::vector<AssignmentItem> items) {
  Assignment a;
  a.items = std::move(items);
  return a;
}

// ---------------------------------------------------------------- nothing checked is no pass

TEST(Answers, AnAnswerThatGivesNothingIsAnErrorNotAPass) {
  const Scene scene = asset("behind-the-eye.json");
  EXPECT_THAT(errorOf([&] { gradeNumbers(Json::object(), "a.json", scene); }),
              HasSubstr("a.json: the answer gives no value to check"));
  // The template's empty fields are nothing given either.
  const Json empty = {{"camera", {{"n", {nullptr, nullptr, nullptr}}, {"vpd", nullptr}}}};
  EXPECT_THAT(errorOf([&] { gradeNumbers(empty, "a.json", scene); }), HasSubstr("gives no value to check"));
}

TEST(Answers, ARequiredItemNotGivenFailsNamedAndEarnsNothing) {
  const Scene scene = asset("behind-the-eye.json");
  const Json reference = referenceDump(scene);
  const Assignment a = assignmentOf({{"/camera/n", "N", 1, true, {}},
                                     {"/matrices/vrc_from_wc", "vrcFromWc", 2, true, {}},
                                     {"/matrices/npc_from_vrc", "npcFromVrc", 2, false, {}}});
  // Only the matrices: right as far as they go, but N is missing.
  const Json answer = {{"matrices", reference["matrices"]}};
  const NumbersGrade g = gradeNumbers(answer, "a.json", scene, 1e-3, &a);
  EXPECT_EQ(g.wrong, 0u);
  EXPECT_FALSE(g.passed()) << "N is required";
  ASSERT_EQ(g.items.size(), 3u);
  EXPECT_TRUE(g.items[0].missing());
  EXPECT_TRUE(g.items[1].right());
  EXPECT_EQ(g.points, 4.0);
  EXPECT_EQ(g.maxPoints, 5.0);
  // Without the optional item and with N: passed, the optional item's points not earned.
  const Json withN = {{"camera", {{"n", reference["camera"]["n"]}}}, {"matrices", {{"vrc_from_wc", reference["matrices"]["vrc_from_wc"]}}}};
  const NumbersGrade h = gradeNumbers(withN, "a.json", scene, 1e-3, &a);
  EXPECT_TRUE(h.passed());
  EXPECT_EQ(h.points, 3.0);
  // With an assignment, even an empty answer is graded (every required item missing), not an error.
  const NumbersGrade none = gradeNumbers(Json::object(), "a.json", scene, 1e-3, &a);
  EXPECT_FALSE(none.passed());
  EXPECT_EQ(none.points, 0.0);
}

// ---------------------------------------------------------------- how values may be written

TEST(Answers, AClippedPolygonIsACycleInEitherDirection) {
  const Scene scene = asset("behind-the-eye.json");
  Json answer = referenceDump(scene);
  size_t turned = 0;
  for (Json& o : answer["objects"])
    for (Json& p : o["polygons"]) {
      Json& dc = p["clipped_dc"];
      if (dc.size() < 3) continue;
      Json r = Json::array();
      for (size_t i = 0; i < dc.size(); ++i) r.push_back(dc[(dc.size() + 1 - i) % dc.size()]);  // reversed, shifted
      dc = r;
      ++turned;
    }
  ASSERT_GT(turned, 0u);
  const NumbersGrade g = gradeNumbers(answer, "a.json", scene);
  EXPECT_TRUE(g.passed()) << g.wrong << " wrong";
}

TEST(Answers, RoundedValuesAreBlamedOnRoundingNotOnAStage) {
  const Scene scene = asset("behind-the-eye.json");
  const Json reference = referenceDump(scene);
  const Json answer = {{"camera", rounded(reference["camera"], 2)}, {"matrices", rounded(reference["matrices"], 2)}};
  const NumbersGrade g = gradeNumbers(answer, "a.json", scene);
  EXPECT_FALSE(g.passed()) << "two decimals are outside the tolerance";
  EXPECT_GT(g.wrong, 0u);
  EXPECT_EQ(g.rounded, g.wrong) << "every wrong value is the rounding";
  EXPECT_EQ(g.roundedDecimals, 2);
  EXPECT_FALSE(g.firstStage) << "no stage is to blame";
  EXPECT_FALSE(g.mistake);
  // Off by more than the last digit's half unit is not rounding.
  Json off = answer;
  off["camera"]["vpd"] = reference["camera"]["vpd"].get<double>() + 0.02;
  const NumbersGrade h = gradeNumbers(off, "a.json", scene);
  EXPECT_EQ(h.rounded + 1, h.wrong);
  EXPECT_TRUE(h.firstStage);
}

// A whole number is not "rounding" of a small value: 0 for 0.5 is a mistake, not the last digit's.
TEST(Answers, ZeroForAHalfIsNotRounding) {
  const Scene scene = asset("behind-the-eye.json");
  Json answer = {{"matrices", referenceDump(scene)["matrices"]}};
  // An entry with 0 < |x| <= 0.5: a student's 0 lies within half a unit of its last (whole) digit.
  Json* entry = nullptr;
  for (auto& [key, m] : answer["matrices"].items())
    for (Json& row : m)
      for (Json& x : row)
        if (!entry && std::abs(x.get<double>()) > 0.01 && std::abs(x.get<double>()) <= 0.5) entry = &x;
  ASSERT_TRUE(entry);
  *entry = 0;
  const NumbersGrade g = gradeNumbers(answer, "a.json", scene);
  EXPECT_EQ(g.wrong, 1u);
  EXPECT_EQ(g.rounded, 0u);
  EXPECT_TRUE(g.firstStage);
}

TEST(Answers, AMistakeIsNamedThoughTheValuesAreRounded) {
  const Scene scene = asset("behind-the-eye.json");
  // One matrix in row form among the others in column form (all in row form is a notation).
  Json matrices = referenceDump(scene)["matrices"];
  matrices["vrc_from_wc"] = mistakeDump(scene, Mistake::transposed)["matrices"]["vrc_from_wc"];
  const Json answer = {{"matrices", rounded(matrices, 2)}};
  const NumbersGrade g = gradeNumbers(answer, "a.json", scene);
  ASSERT_TRUE(g.mistake) << g.wrong << " wrong, " << g.rounded << " rounded";
  EXPECT_EQ(*g.mistake, Mistake::transposed);
}

TEST(Answers, FractionsMayBeWrittenAsStrings) {
  const Scene scene = generateExercise({3, ExerciseTopic::orientation, Projection::perspective}).scene;  // N exact
  const Json reference = referenceDump(scene);
  Json answer = {{"camera", {{"n", Json::array()}}}};
  for (const Json& x : reference["camera"]["n"]) {
    const Rational r = Rational::approximate(x.get<double>(), 1000).value();
    answer["camera"]["n"].push_back(r.text());
  }
  const NumbersGrade g = gradeNumbers(answer, "a.json", scene);
  EXPECT_TRUE(g.passed()) << answer.dump();
  // Decimal commas, as German students write them (issue 38).
  Json commas = answer;
  for (size_t i = 0; i < 3; ++i) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4f", reference["camera"]["n"][i].get<double>());
    std::string t = text;
    t[t.find('.')] = ',';
    commas["camera"]["n"][i] = t;
  }
  EXPECT_TRUE(gradeNumbers(commas, "a.json", scene).passed()) << commas.dump();
  for (const char* bad : {"-3/0", "three fifths", "1,2,3", "0x10"}) {
    answer["camera"]["n"][0] = bad;
    const NumbersGrade h = gradeNumbers(answer, "a.json", scene);
    ASSERT_EQ(h.values.size(), 3u);
    EXPECT_EQ(h.values[0].problem, "a string where a number is expected (a fraction is written \"-3/5\")") << bad;
    EXPECT_TRUE(h.values[1].right && h.values[2].right) << "the rest of N is graded";
  }
}

// An outcode as the solution prints it: six bits, the front plane's first ("100010" is 34).
TEST(Answers, AnOutcodeMayBeWrittenAsItsBits) {
  const Scene scene = asset("behind-the-eye.json");
  const Json reference = referenceAnswer(scene);
  const Json& codes = reference["objects"][0]["polygons"][0]["outcodes"];
  Json bits = Json::array();
  for (const Json& c : codes) {
    std::string b;
    for (int bit = 5; bit >= 0; --bit) b += ((c.get<int>() >> bit) & 1) ? '1' : '0';
    bits.push_back(b);
  }
  const Json answer = {{"objects", Json::array({{{"polygons", Json::array({{{"outcodes", bits}}})}}})}};
  const NumbersGrade g = gradeNumbers(answer, "a.json", scene);
  EXPECT_TRUE(g.passed()) << bits.dump();
  EXPECT_EQ(g.values.size(), codes.size());
}

TEST(Answers, P1AloneIsGradedAsP1) {
  const Scene scene = asset("behind-the-eye.json");
  const Json p = referenceAnswer(scene)["objects"][0]["polygons"][0];
  Json polygon = Json::object();
  for (const char* key : {"mc", "wc", "vrc", "npc_h", "outcodes", "boundary", "npc", "dc"}) polygon[key] = Json::array({p[key][0]});
  const Json answer = {{"objects", Json::array({{{"polygons", Json::array({polygon})}}})}};
  const NumbersGrade g = gradeNumbers(answer, "a.json", scene);
  EXPECT_TRUE(g.passed());
  EXPECT_EQ(g.values.size(), 3 + 3 + 3 + 4 + 1 + 6 + 3 + 3u);
}

// ---------------------------------------------------------------- the assignment file

TEST(Answers, AssignmentsAreReadStrictly) {
  const Assignment a = parseAssignment(R"({"vplab_assignment": 1, "scene": "s.json", "tolerance": 0.01,
      "items": [{"path": "/camera/n", "title": "N", "points": 1.5}, {"path": "/camera/u", "required": false}]})",
                                       "a.json");
  ASSERT_EQ(a.items.size(), 2u);
  EXPECT_EQ(a.items[0].points, 1.5);
  EXPECT_EQ(a.items[1].title, "/camera/u");
  EXPECT_FALSE(a.items[1].required);
  EXPECT_EQ(parseAssignment(assignmentJson(a), "again").items[0].path, "/camera/n") << "round trip";
  auto error = [](const std::string& text) { return errorOf([&] { parseAssignment(text, "a.json"); }); };
  EXPECT_THAT(error(R"({"items": [{"path": "/camera/n"}]})"), HasSubstr("a.json: /vplab_assignment: missing"));
  EXPECT_THAT(error(R"({"vplab_assignment": 1, "items": []})"), HasSubstr("/items: a list of at least one item"));
  EXPECT_THAT(error(R"({"vplab_assignment": 1, "items": [{"path": "camera"}]})"), HasSubstr("/items/0/path: \"camera\" is not a JSON pointer"));
  EXPECT_THAT(error(R"({"vplab_assignment": 1, "items": [{"path": "/a"}, {"path": "/a"}]})"), HasSubstr("/items/1/path: \"/a\" is given twice"));
  EXPECT_THAT(error(R"({"vplab_assignment": 1, "items": [{"path": "/a", "points": -1}]})"), HasSubstr("/items/0/points: -1 where a number from 0 to 1000"));
  EXPECT_THAT(error(R"({"vplab_assignment": 1, "items": [{"path": "/a", "weight": 1}]})"), HasSubstr("/items/0/weight: unknown key"));
  EXPECT_THAT(error(R"({"vplab_assignment": 1, "tolerance": 2, "items": [{"path": "/a"}]})"), HasSubstr("/tolerance: 2 where"));
}

// ---------------------------------------------------------------- the sheet's values and template

TEST(Answers, TheSheetsValuesAreTheSolutions) {
  for (uint64_t seed : {1u, 2u, 3u, 4u}) {
    const Exercise e = generateExercise({seed, ExerciseTopic::pipeline, Projection::perspective});
    const ExerciseSolution s = solveExercise(e);
    const Json p = referenceAnswer(e.scene)["objects"][0]["polygons"][0];
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(p["boundary"][0][size_t(i)].get<double>(), s.point.bc[size_t(i)], 1e-12);
    if (s.point.outcode == 0) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(p["npc"][0][size_t(c)].get<double>(), s.point.npc[c], 1e-12);
        EXPECT_NEAR(p["dc"][0][size_t(c)].get<double>(), s.point.dc[c], 1e-9);
      }
    }
    // The six passes end in the clipper's own polygon (before the snapping onto the planes).
    const Json& last = p["clip_steps"][5]["polygon"];
    ASSERT_EQ(last.size(), s.clippedNpcH.size()) << "seed " << seed;
    for (size_t v = 0; v < last.size(); ++v)
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(last[v][size_t(c)].get<double>(), s.clippedNpcH[v][c], 1e-9);
  }
}

// Every topic and projection: the template grades as "everything missing", and filled with the
// solution it earns every point.
TEST(Answers, TheTemplateHoldsEveryTaskOfTheSheet) {
  for (ExerciseTopic topic : {ExerciseTopic::orientation, ExerciseTopic::mapping, ExerciseTopic::clipping, ExerciseTopic::pipeline})
    for (Projection projection : {Projection::perspective, Projection::parallel, Projection::oblique})
      for (uint64_t seed : {1u, 2u}) {
        SCOPED_TRACE(std::string(toString(topic)) + ", " + std::string(toString(projection)) + ", seed " + std::to_string(seed));
        const Exercise e = generateExercise({seed, topic, projection});
        const Assignment a = exerciseAssignment(e, solveExercise(e), Language::en);
        const Json reference = referenceAnswer(e.scene);
        const Json blank = answerTemplate(a, reference);
        const NumbersGrade none = gradeNumbers(blank, "answer.json", e.scene, 1e-3, &a);
        EXPECT_FALSE(none.passed());
        EXPECT_EQ(none.values.size(), 0u) << "the template gives nothing";
        for (const ItemGrade& i : none.items) EXPECT_TRUE(i.missing()) << i.path;
        // Filled in: every item's values from the reference.
        Json filled = blank;
        for (const AssignmentItem& item : a.items) filled[Json::json_pointer(item.path)] = reference[Json::json_pointer(item.path)];
        const NumbersGrade all = gradeNumbers(filled, "answer.json", e.scene, 1e-3, &a);
        EXPECT_TRUE(all.passed());
        EXPECT_EQ(all.points, all.maxPoints);
        EXPECT_GE(a.items.size(), topic == ExerciseTopic::pipeline ? 12u : 4u);  // P1 through every stage
      }
}

// A week's sheet: the pipeline topic follows P1 through every stage (at most 6 tasks' worth, 20
// points) and leaves the polygon's clipping to the clipping sheet; every task is numbered on the
// sheet with the points its items carry in the assignment.
TEST(Answers, EveryTopicIsAWeeksSheetAndItsTasksCarryTheAssignmentsPoints) {
  for (ExerciseTopic topic : {ExerciseTopic::orientation, ExerciseTopic::mapping, ExerciseTopic::clipping, ExerciseTopic::pipeline})
    for (uint64_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(std::string(toString(topic)) + ", seed " + std::to_string(seed));
      const Exercise e = generateExercise({seed, topic, Projection::perspective});
      const ExerciseSolution s = solveExercise(e);
      const std::vector<ExerciseTask> tasks = exerciseTasks(e, s, Language::en);
      const Assignment a = exerciseAssignment(e, s, Language::en);
      double sum = 0;
      size_t items = 0;
      for (const ExerciseTask& t : tasks) {
        EXPECT_FALSE(t.items.empty()) << t.text;
        sum += points(t);
        items += t.items.size();
      }
      double assigned = 0;
      for (const AssignmentItem& i : a.items) assigned += i.points;
      EXPECT_EQ(sum, assigned);
      EXPECT_EQ(items, a.items.size());
      EXPECT_LE(tasks.size(), 4u);
      EXPECT_LE(sum, 20.0);
      const bool clips = std::any_of(a.items.begin(), a.items.end(),
                                     [](const AssignmentItem& i) { return i.path.find("clip_steps") != std::string::npos; });
      EXPECT_EQ(clips, topic == ExerciseTopic::clipping);
    }
}

// Consequential-error credit: wcFromMc wrong (the translation off by one in x), and every later
// value of P1 computed right from it (by the pipeline on the scene with that translation, not by
// the grader's own recomputation): only wcFromMc loses its points.
TEST(Answers, AValueWrongOnlyBecauseAnEarlierOneWasEarnsItsPoints) {
  const Exercise e = generateExercise({2, ExerciseTopic::pipeline, Projection::perspective});
  const Assignment a = exerciseAssignment(e, solveExercise(e), Language::en);
  const Json reference = referenceAnswer(e.scene);
  Scene moved = e.scene;
  moved.objects[0].transform.translate.x += 1;
  moved.objects[0].mesh = primitiveMesh(moved.objects[0]);
  const Json consequent = referenceAnswer(moved);
  Json answer = answerTemplate(a, reference);
  double max = 0, lost = 0;
  for (const AssignmentItem& item : a.items) {
    const Json::json_pointer p(item.path);
    const bool follows = item.path == "/objects/0/wc_from_mc" ||
                         (item.path.find("/polygons/0/") != std::string::npos && item.path.find("clip") == std::string::npos);
    answer[p] = follows ? consequent[p] : reference[p];
    max += item.points;
    if (item.path == "/objects/0/wc_from_mc") lost = item.points;
  }
  const NumbersGrade g = gradeNumbers(answer, "a.json", e.scene, 1e-3, &a);
  EXPECT_GT(g.wrong, 0u) << "the values are still wrong";
  EXPECT_EQ(g.points, max - lost);
  size_t followed = 0;
  for (const ItemGrade& i : g.items) followed += i.followsThrough;
  EXPECT_GE(followed, 4u) << "P1 in WC, VRC, NPC_h and its boundary coordinates at least";
  // A later value that does not follow from the student's earlier ones earns nothing.
  answer["/objects/0/polygons/0/vrc/0/0"_json_pointer] = 1234.5;
  const NumbersGrade h = gradeNumbers(answer, "a.json", e.scene, 1e-3, &a);
  EXPECT_LT(h.points, g.points);
}

}  // namespace
}  // namespace vplab
