// Issue 14, the pure part: the rational type, the exercise generator (same seed, same exercise;
// well posed for every topic and projection), the mistake models and the grading of numbers.
#include "base/error.h"
#include "course/exercise.h"
#include "course/grading.h"
#include "course/mistake_models.h"
#include "course/rational.h"
#include "io/scene_io.h"

#include <gtest/gtest.h>

#include <bit>
#include <random>

namespace vplab {
namespace {

using Json = nlohmann::ordered_json;

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// ---- Rational ---------------------------------------------------------------------------------

TEST(Rational, ReducesAndKeepsTheSignInTheNumerator) {
  EXPECT_EQ(Rational(6, -8), Rational(-3, 4));
  EXPECT_EQ(Rational(6, -8).num(), -3);
  EXPECT_EQ(Rational(6, -8).den(), 4);
  EXPECT_EQ(Rational(0, 5), Rational(0));
  EXPECT_EQ(Rational(0, 5).den(), 1);
}

TEST(Rational, Arithmetic) {
  EXPECT_EQ(Rational(1, 2) + Rational(1, 3), Rational(5, 6));
  EXPECT_EQ(Rational(1, 2) - Rational(3, 4), Rational(-1, 4));
  EXPECT_EQ(Rational(2, 3) * Rational(9, 4), Rational(3, 2));
  EXPECT_EQ(Rational(2, 3) / Rational(-4, 9), Rational(-3, 2));
  EXPECT_TRUE(Rational(1, 3) < Rational(1, 2));
  EXPECT_FALSE(Rational(-1, 2) < Rational(-2, 3));
  EXPECT_DOUBLE_EQ(Rational(-7, 8).toDouble(), -0.875);
}

TEST(Rational, ErrorsInsteadOfWrapping) {
  EXPECT_THROW(Rational(1, 0), Error);
  EXPECT_THROW(Rational(1) / Rational(0), Error);
  const Rational big(int64_t(1) << 62);
  EXPECT_THROW(big * big, Error);
  EXPECT_THROW(big + big, Error);
}

TEST(Rational, ApproximatesSmallFractionsOnly) {
  EXPECT_EQ(Rational::approximate(0.3), Rational(3, 10));
  EXPECT_EQ(Rational::approximate(-2.5), Rational(-5, 2));
  EXPECT_EQ(Rational::approximate(1.0 / 3.0), Rational(1, 3));
  EXPECT_EQ(Rational::approximate(0.1 + 0.2), Rational(3, 10));  // rounding of the double does not matter
  EXPECT_EQ(Rational::approximate(132.0 / 25.0), Rational(132, 25));
  EXPECT_EQ(Rational::approximate(6.123233995736766e-17), Rational(0));  // cos 90° in doubles
  EXPECT_FALSE(Rational::approximate(std::sqrt(2.0)));
  EXPECT_FALSE(Rational::approximate(kPi));
  EXPECT_FALSE(Rational::approximate(1.0 / 1009.0));  // denominator above 1000
  EXPECT_FALSE(Rational::approximate(std::nan("")));
  // Regression: a decimal that lies within 1e-9 (relative) of a fraction by chance is no fraction.
  // An oblique exercise printed the DC x 315.56349… as 39761/126.
  EXPECT_FALSE(Rational::approximate(39761.0 / 126.0 + 1e-7));
  EXPECT_FALSE(Rational::approximate(INFINITY));
}

TEST(Rational, Text) {
  EXPECT_EQ(Rational(-3, 10).text(), "-3/10");
  EXPECT_EQ(Rational(4).text(), "4");
  EXPECT_EQ(Rational(-3, 10).latex(), "-\\frac{3}{10}");
  EXPECT_EQ(latexNumber(0.5), "\\frac{1}{2}");
  EXPECT_EQ(latexNumber(std::sqrt(0.5)), "0.7071");
  EXPECT_EQ(latexNumber(-1e-17), "0");
  EXPECT_EQ(plainNumber(-std::sqrt(2.0)), "-1.4142");
}

// ---- The exercise generator -------------------------------------------------------------------

TEST(Exercise, TheSameSeedGivesTheSameExercise) {
  for (ExerciseTopic t : {ExerciseTopic::orientation, ExerciseTopic::clipping}) {
    const ExerciseSpec spec{42, t, Projection::perspective};
    EXPECT_EQ(sceneToJson(generateExercise(spec).scene), sceneToJson(generateExercise(spec).scene));
  }
  EXPECT_NE(sceneToJson(generateExercise({42}).scene), sceneToJson(generateExercise({43}).scene));
}

TEST(Exercise, EveryTopicAndProjectionIsWellPosed) {
  for (ExerciseTopic topic : {ExerciseTopic::orientation, ExerciseTopic::mapping, ExerciseTopic::clipping,
                              ExerciseTopic::pipeline})
    for (Projection projection : {Projection::perspective, Projection::parallel, Projection::oblique})
      for (uint64_t seed = 1; seed <= 8; ++seed) {
        SCOPED_TRACE(std::string(toString(topic)) + " " + std::string(toString(projection)) + " " + std::to_string(seed));
        const Exercise e = generateExercise({seed, topic, projection});
        const Camera& c = e.scene.camera;
        EXPECT_FALSE(cameraError(c));
        // Small integers and halves.
        for (double x : {c.vrp.x, c.vrp.y, c.vrp.z, c.prp.x, c.prp.y, c.prp.z, c.vup.y, c.window.xmin, c.window.xmax,
                         c.window.ymin, c.window.ymax, c.front, c.back})
          EXPECT_EQ(2 * x, std::round(2 * x)) << x;
        const ExerciseSolution s = solveExercise(e);
        const bool clipping = topic == ExerciseTopic::clipping || topic == ExerciseTopic::pipeline;
        Outcode any = 0;
        for (const PointStages& v : s.vertices) any |= v.outcode;
        if (clipping) {
          EXPECT_GE(std::popcount(unsigned(any)), 2) << "the polygon crosses at least two planes";
          EXPECT_EQ(s.fate, Fate::clipped);
          EXPECT_FALSE(s.clippedDc.empty());
        }
        EXPECT_EQ(e.pointBehindEye, clipping && projection == Projection::perspective && seed % 2 == 1);
        if (e.pointBehindEye) EXPECT_LT(s.point.npcH.w, 0);
        else EXPECT_EQ(s.point.outcode, 0);
        if (projection != Projection::oblique) {
          EXPECT_TRUE(Rational::approximate(s.run.npcFromVrc[2][2]));
          for (const Vec3& p : s.clippedDc)
            EXPECT_TRUE(Rational::approximate(p.x) && Rational::approximate(p.y) && Rational::approximate(p.z));
        }
      }
}

// The fractions a solution prints are exact, not near misses: each stage's product, redone in
// exact rational arithmetic from the printed matrix and point, gives the printed result.
TEST(Exercise, PrintedFractionsAreExact) {
  auto exact = [](double x) {
    const auto r = Rational::approximate(x);
    EXPECT_TRUE(r) << x;
    return r.value_or(Rational(0));
  };
  auto product = [&](const Mat4& m, const Vec4& p) {
    std::array<Rational, 4> out{};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) out[size_t(r)] = out[size_t(r)] + exact(m[c][r]) * exact(p[c]);
    return out;
  };
  size_t checked = 0;
  for (Projection projection : {Projection::perspective, Projection::parallel})
    for (uint64_t seed = 1; seed <= 6; ++seed) {
      const Exercise e = generateExercise({seed, ExerciseTopic::pipeline, projection});
      const ExerciseSolution s = solveExercise(e);
      const PointStages& p = s.point;
      const auto wc = product(s.wcFromMc, Vec4(p.mc, 1));
      const auto vrc = product(s.run.vrcFromWc, Vec4(p.wc, 1));
      const auto npcH = product(s.run.npcFromVrc, Vec4(p.vrc, 1));
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(wc[size_t(i)], exact(p.wc[i]));
        EXPECT_EQ(vrc[size_t(i)], exact(p.vrc[i]));
      }
      for (int i = 0; i < 4; ++i) EXPECT_EQ(npcH[size_t(i)], exact(p.npcH[i]));
      if (p.outcode == 0) {
        // The division and the device mapping, exactly.
        const Rational w = npcH[3];
        const auto dc = product(s.run.dcFromNpc, Vec4(p.npc, 1));
        EXPECT_EQ(exact(p.npc.x), npcH[0] / w);
        EXPECT_EQ(exact(p.dc.x), dc[0]);
        EXPECT_EQ(exact(p.dc.y), dc[1]);
      }
      ++checked;
    }
  EXPECT_EQ(checked, 12u);
}

TEST(Exercise, IntersectionsAreTheClippersOwnVertices) {
  const Exercise e = generateExercise({5, ExerciseTopic::clipping, Projection::perspective});
  const ExerciseSolution s = solveExercise(e);
  size_t cuts = 0;
  for (size_t k = 0; k < s.steps.size(); ++k)
    for (const ClipIntersection& c : s.intersections[k]) {
      ++cuts;
      EXPECT_GT(c.t, 0);
      EXPECT_LT(c.t, 1);
      // The new vertex lies on the step's plane and on the edge at t from the inside endpoint.
      const Vec4 expected = glm::mix(s.steps[k].input[c.inside].p, s.steps[k].input[c.outside].p, c.t);
      for (int i = 0; i < 4; ++i) EXPECT_NEAR(c.vertex[i], expected[i], 1e-9);
      EXPECT_NEAR(boundaryCoordinates(c.vertex)[size_t(s.steps[k].plane)], 0, 1e-12);
    }
  EXPECT_GE(cuts, 2u);
}

// ---- Mistake models and grading ----------------------------------------------------------------

Scene asset(const char* name) { return loadScene(std::string(VPLAB_ASSETS) + "/scenes/" + name); }

// The scene a model is tested on: one where the mistake shows (a rotation and a point behind the
// eye; the oblique projection for the shear's sign).
Scene sceneFor(Mistake m) {
  if (m == Mistake::forgotTranslation) return asset("clipping-wc-vs-npc.json");  // VRP away from the origin
  return asset(m == Mistake::obliqueShearSign ? "oblique-cabinet.json" : "behind-the-eye.json");
}

// What a student making the mistake prints: the model's dump; for transposed, one matrix in row
// form among the others in column form (every matrix in row form is a notation, issue 38).
Json mistakeAnswer(const Scene& scene, Mistake m) {
  if (m != Mistake::transposed) return mistakeDump(scene, m);
  Json answer = referenceDump(scene);
  answer["matrices"]["vrc_from_wc"] = mistakeDump(scene, m)["matrices"]["vrc_from_wc"];
  return answer;
}

TEST(Grading, TheReferenceItselfPasses) {
  const Scene scene = asset("behind-the-eye.json");
  const NumbersGrade g = gradeNumbers(referenceDump(scene), "answer.json", scene);
  EXPECT_TRUE(g.passed());
  EXPECT_GT(g.values.size(), 100u);
  EXPECT_FALSE(g.firstStage);
  EXPECT_FALSE(g.mistake);
}

TEST(Grading, EveryMistakeModelIsRecognisedAsItselfAndNotAsAnother) {
  for (const MistakeModel& model : mistakeModels()) {
    SCOPED_TRACE(std::string(model.key));
    const Scene scene = sceneFor(model.id);
    const NumbersGrade g = gradeNumbers(mistakeAnswer(scene, model.id), "answer.json", scene);
    EXPECT_FALSE(g.passed());
    ASSERT_TRUE(g.mistake);
    EXPECT_EQ(*g.mistake, model.id);
    size_t matching = 0;
    for (const ModelMatch& m : g.models) matching += m.contradicted == 0;
    EXPECT_EQ(matching, 1u) << "exactly one model matches every value";
  }
}

TEST(Grading, FirstDepartingStage) {
  const Scene scene = asset("behind-the-eye.json");
  auto stageOf = [&](Mistake m) { return gradeNumbers(mistakeAnswer(scene, m), "a.json", scene).firstStage.value_or(-1); };
  EXPECT_EQ(stageOf(Mistake::leftHandedN), 2);
  EXPECT_EQ(stageOf(Mistake::degreesAsRadians), 1);
  EXPECT_EQ(stageOf(Mistake::frontBackSwapped), 3);
  EXPECT_EQ(stageOf(Mistake::divideFirst), 4);
  EXPECT_EQ(stageOf(Mistake::yNotFlipped), 5);
  EXPECT_EQ(stageOf(Mistake::transposed), 2);  // vrcFromWc in row form
  EXPECT_EQ(gradeNumbers(mistakeAnswer(sceneFor(Mistake::forgotTranslation), Mistake::forgotTranslation), "a.json",
                         sceneFor(Mistake::forgotTranslation)).firstStage.value_or(-1), 2);
  EXPECT_EQ(stageOf(Mistake::outcodeReversed), 4);
}

TEST(Grading, ASubsetIsGradedOnItsOwn) {
  const Scene scene = asset("behind-the-eye.json");
  // Only one object's npc_h, from the divide-first model: npc_h is the same before the division,
  // so this subset is right.
  Json answer = {{"objects", Json::array({{{"polygons", Json::array({{{"npc_h", referenceDump(scene)["objects"][0]["polygons"][0]["npc_h"]}}})}}})}};
  EXPECT_TRUE(gradeNumbers(answer, "a.json", scene).passed());
  // Only the matrices, every one in the lecture notes' row form: a notation, read transposed.
  const Json transposedMatrices = mistakeDump(scene, Mistake::transposed)["matrices"];
  const NumbersGrade rows = gradeNumbers(Json{{"matrices", transposedMatrices}}, "a.json", scene);
  EXPECT_TRUE(rows.passed());
  EXPECT_TRUE(rows.rowVectorForm);
  // One of them in row form among the others in column form: that one is the mistake.
  Json matrices = {{"matrices", referenceDump(scene)["matrices"]}};
  matrices["matrices"]["npc_from_vrc"] = transposedMatrices["npc_from_vrc"];
  const NumbersGrade g = gradeNumbers(matrices, "a.json", scene);
  size_t asymmetric = 0;  // the entries a transpose changes
  const Json reference = referenceDump(scene);
  const Json& m = reference["matrices"]["npc_from_vrc"];
  for (size_t r = 0; r < 4; ++r)
    for (size_t c = 0; c < 4; ++c)
      asymmetric += std::abs(m[r][c].get<double>() - m[c][r].get<double>()) > 1e-3 * std::max(1.0, std::abs(m[r][c].get<double>()));
  EXPECT_GT(asymmetric, 2u);
  EXPECT_EQ(g.wrong, asymmetric);
  EXPECT_FALSE(g.rowVectorForm);
  ASSERT_TRUE(g.mistake);
  EXPECT_EQ(*g.mistake, Mistake::transposed);
}

TEST(Grading, NoiseWithinTheToleranceStillPasses) {
  const Scene scene = asset("behind-the-eye.json");
  Json answer = referenceDump(scene);
  std::mt19937_64 rng(7);
  size_t perturbed = 0;
  std::function<void(Json&)> jitter = [&](Json& j) {
    if (j.is_number_float()) {
      const double r = j.get<double>();
      const double u = double(rng() % 2001) / 1000.0 - 1.0;  // [-1, 1]
      j = r + 0.9e-3 * std::max(1.0, std::abs(r)) * u;       // within the default tolerance 1e-3
      ++perturbed;
    } else if (j.is_structured()) {
      for (Json& e : j) jitter(e);
    }
  };
  jitter(answer["objects"]);
  jitter(answer["matrices"]);
  EXPECT_GT(perturbed, 100u);
  EXPECT_TRUE(gradeNumbers(answer, "a.json", scene).passed());
  // Twice the tolerance off in one value: wrong, and named.
  answer["matrices"]["npc_from_vrc"][0][0] = answer["matrices"]["npc_from_vrc"][0][0].get<double>() + 2.5e-3;
  const NumbersGrade g = gradeNumbers(answer, "a.json", scene);
  EXPECT_EQ(g.wrong, 1u);
  EXPECT_EQ(g.firstStage, 3);
}

TEST(Grading, AClippedPolygonMayStartAtAnyVertex) {
  const Scene scene = asset("behind-the-eye.json");
  Json answer = referenceDump(scene);
  size_t rotated = 0;
  for (Json& o : answer["objects"])
    for (Json& p : o["polygons"]) {
      Json& dc = p["clipped_dc"];
      if (dc.size() < 3) continue;
      Json r = Json::array();
      for (size_t i = 0; i < dc.size(); ++i) r.push_back(dc[(i + 1) % dc.size()]);
      dc = r;
      ++rotated;
    }
  EXPECT_GT(rotated, 0u);
  EXPECT_TRUE(gradeNumbers(answer, "a.json", scene).passed());
}

// Issue 38: one bad value costs one item. A value in a form that cannot be graded is wrong and named
// at its path; the rest of the answer is graded; only what is no answer at all is the file's error.
TEST(Grading, AMalformedValueIsThatValuesErrorAndTheRestIsGraded) {
  const Scene scene = asset("behind-the-eye.json");
  const Json reference = referenceDump(scene);
  // The problem named for the one malformed value of `j`, after the right N beside it was graded.
  auto problem = [&](Json j) {
    j["camera"]["n"] = reference["camera"]["n"];
    const NumbersGrade g = gradeNumbers(j, "alice.json", scene);
    std::string out;
    size_t right = 0;
    for (const GradedValue& v : g.values) {
      if (v.malformed()) out += (out.empty() ? "" : "; ") + v.path + ": " + v.problem;
      right += v.right;
    }
    EXPECT_EQ(right, 3u) << "N is graded beside it";
    return out;
  };
  EXPECT_EQ(problem({{"matrices", {{"vrc_from_wc", "identity"}}}}), "/matrices/vrc_from_wc: a string where a list is expected");
  EXPECT_EQ(problem({{"camera", {{"vpd", "five"}}}}), "/camera/vpd: a string where a number is expected (a fraction is written \"-3/5\")");
  EXPECT_EQ(problem({{"camera", {{"vpd", {5}}}}}), "/camera/vpd: an array where a number is expected");
  EXPECT_EQ(problem({{"camera", {{"u", {1, 0}}}}}), "/camera/u: 2 numbers where 3 are expected");
  EXPECT_EQ(problem({{"matrices", {{"npc_from_vrc", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}}}),
            "/matrices/npc_from_vrc: not a 4 × 4 matrix (4 rows of 4 numbers)");
  Json tooMany = {{"objects", Json::array()}};
  for (int i = 0; i < 50; ++i) tooMany["objects"].push_back(Json::object());
  EXPECT_NE(problem(tooMany).find("/objects: 50 entries, but the scene has only"), std::string::npos);
  const Json badOutcode = {{"objects", Json::array({{{"polygons", Json::array({{{"outcodes", {1.5}}}})}}})}};
  EXPECT_EQ(problem(badOutcode), "/objects/0/polygons/0/outcodes/0: not a whole number where one is expected");
  // An unknown key is warned about and not graded.
  const NumbersGrade unknown = gradeNumbers(Json{{"note", "see the back"}, {"camera", {{"n", reference["camera"]["n"]}}}}, "a.json", scene);
  EXPECT_TRUE(unknown.passed());
  ASSERT_EQ(unknown.warnings.size(), 1u);
  EXPECT_NE(unknown.warnings[0].find("/note: unknown key"), std::string::npos) << unknown.warnings[0];
  EXPECT_EQ(errorOf([&] { gradeNumbers(Json::array(), "alice.json", scene); }),
            "alice.json: /: an array where an answer (a JSON object) is expected");
  EXPECT_EQ(errorOf([] { parseAnswer("{\n  \"camera\": {,\n}", "bob.json"); }).substr(0, 32),
            "bob.json:2:14: JSON syntax error");
  // Hostile answers: nesting deeper than the limit and duplicate keys are refused, naming the place.
  const std::string deep = errorOf([] { parseAnswer(std::string(100000, '['), "deep.json"); });
  EXPECT_EQ(deep.rfind("deep.json: /0/0/0/", 0), 0u) << deep;
  EXPECT_NE(deep.find(": objects and arrays nested deeper than 32 levels (the limit)"), std::string::npos) << deep;
  EXPECT_EQ(errorOf([] { parseAnswer(R"({"camera": {"vpd": 1, "vpd": 2}})", "twice.json"); }),
            "twice.json: /camera/vpd: the key \"vpd\" is given twice in this object");
}

}  // namespace
}  // namespace vplab
