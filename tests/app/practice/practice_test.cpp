// An exercise practised beside the views (issue 40), without a window: the fields as the sheet shapes
// them, what a student types (fractions, decimal commas, a typographic minus), Check through the
// grader, the marks the views draw of the student's numbers, an exercise's folder opened.
//
// Oracles: the worked solution's own values (course/exercise.h, the pipeline's run) and the mistake
// models' answers (course/mistake_models.h), typed into the fields as text; never the code under test.
#include "app/practice/practice.h"
#include "app/practice/practice_marks.h"

#include "base/error.h"
#include "course/mistake_models.h"
#include "course/rational.h"
#include "course/sheet_values.h"
#include "pipeline/clipping.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace vplab {
namespace {

using Json = nlohmann::ordered_json;
using ::testing::HasSubstr;

ExerciseRef ref(ExerciseTopic topic, uint64_t seed, std::string id = "") {
  return {ExerciseSpec{seed, topic, Projection::perspective}, std::move(id), Language::en};
}

/// A number as a student writes it on paper: the exact fraction where the solution has one
/// ("-3/5"), else 6 decimals; with `comma`, a German decimal comma.
std::string onPaper(double x, bool comma = false) {
  std::string t;
  if (const auto r = Rational::approximate(x)) {
    t = r->text();
  } else {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f", x);
    t = buf;
  }
  if (comma)
    if (const size_t dot = t.find('.'); dot != std::string::npos) t[dot] = ',';
  return t;
}

/// Types every value of `answer` at the fields' places, as text on paper (polygons with their vertex count).
void typeAnswer(Practice& p, const Json& answer, bool comma = false) {
  for (ItemFields& f : p.fields) {
    const Json& v = answer[Json::json_pointer(f.item.path)];
    switch (f.kind) {
      case FieldKind::number: f.texts[0] = onPaper(v.get<double>(), comma); break;
      case FieldKind::outcode: {
        std::string bits;
        for (int b = 5; b >= 0; --b) bits += (v.get<int>() >> b) & 1 ? '1' : '0';
        f.texts[0] = bits;
        break;
      }
      case FieldKind::vector:
        for (int c = 0; c < f.columns; ++c) f.text(0, c) = onPaper(v[size_t(c)].get<double>(), comma);
        break;
      case FieldKind::polygon: f.setRows(int(v.size())); [[fallthrough]];
      case FieldKind::matrix:
        for (int r = 0; r < f.rows; ++r)
          for (int c = 0; c < f.columns; ++c) f.text(r, c) = onPaper(v[size_t(r)][size_t(c)].get<double>(), comma);
        break;
    }
  }
  ++p.edits;
}

const Json& referenceOf(const Practice& p) { return p.grading.reference; }

Json modelAnswer(const Practice& p, Mistake m) {
  for (const auto& [id, dump] : p.grading.models)
    if (id == m) return dump;
  ADD_FAILURE() << "no model " << mistakeModel(m).key;
  return {};
}

// ---------------------------------------------------------------- fields

TEST(PracticeFields, ThePipelineSheetHasAFieldOfTheRightShapeForEveryItem) {
  const Practice p = openPractice(ref(ExerciseTopic::pipeline, 4, "100"), Reveal::stages, Language::en);
  ASSERT_EQ(p.fields.size(), p.assignment.items.size());
  auto fieldAt = [&](const std::string& path) -> const ItemFields& {
    for (const ItemFields& f : p.fields)
      if (f.item.path == path) return f;
    throw Error("no field " + path);
  };
  EXPECT_EQ(fieldAt("/matrices/vrc_from_wc").kind, FieldKind::matrix);
  EXPECT_EQ(fieldAt("/matrices/vrc_from_wc").texts.size(), 16u);
  EXPECT_EQ(fieldAt("/camera/n").kind, FieldKind::vector);
  EXPECT_EQ(fieldAt("/camera/n").columns, 3);
  EXPECT_EQ(fieldAt("/camera/vpd").kind, FieldKind::number);
  EXPECT_EQ(fieldAt("/objects/0/polygons/0/npc_h/0").columns, 4);
  EXPECT_EQ(fieldAt("/objects/0/polygons/0/outcodes/0").kind, FieldKind::outcode);
  // The tasks hold the fields in the sheet's order, every field once.
  size_t counted = 0;
  for (const ExerciseTask& t : p.tasks) counted += t.items.size();
  EXPECT_EQ(counted, p.fields.size());
  EXPECT_EQ(p.firstField(1), p.tasks[0].items.size());
}

TEST(PracticeFields, AClippingPassIsAPolygonWhoseVertexCountIsTheStudents) {
  Practice p = openPractice(ref(ExerciseTopic::clipping, 7, "100"), Reveal::stages, Language::en);
  ItemFields& pass = p.fields[0];
  EXPECT_EQ(pass.kind, FieldKind::polygon);
  EXPECT_EQ(pass.rows, 0);
  EXPECT_EQ(pass.columns, 4);
  EXPECT_TRUE(practiceAnswer(p)[Json::json_pointer(pass.item.path)].is_null()) << "a pass not begun is not answered";
  pass.setRows(2);
  pass.text(0, 0) = "1/2";
  EXPECT_EQ(practiceAnswer(p)[Json::json_pointer(pass.item.path)].dump(), R"([["1/2",null,null,null],[null,null,null,null]])");
  pass.setRows(1000);
  EXPECT_EQ(pass.rows, kMaxPolygonVertices);
  pass.setRows(-3);
  EXPECT_EQ(pass.rows, 0);
  EXPECT_TRUE(pass.texts.empty());
}

TEST(PracticeFields, TextIsKeptAsTypedWithoutBlanksAndWithAPlainMinus) {
  EXPECT_EQ(normalizedField(" \u2212 3 / 5 "), "-3/5");
  EXPECT_EQ(normalizedField("\u20130,25"), "-0,25");
  EXPECT_EQ(normalizedField(std::string(100, '1')).size(), kMaxFieldText);
  EXPECT_TRUE(readableField(FieldKind::number, "-3/5"));
  EXPECT_TRUE(readableField(FieldKind::number, "0,6"));
  EXPECT_TRUE(readableField(FieldKind::number, ""));
  EXPECT_FALSE(readableField(FieldKind::number, "3/0"));
  EXPECT_FALSE(readableField(FieldKind::number, "1/2/3"));
  EXPECT_FALSE(readableField(FieldKind::number, "abc"));
  EXPECT_FALSE(readableField(FieldKind::number, "1,5.2"));
  EXPECT_TRUE(readableField(FieldKind::outcode, "100010"));
  EXPECT_TRUE(readableField(FieldKind::outcode, "34"));
  EXPECT_FALSE(readableField(FieldKind::outcode, "64"));
  EXPECT_FALSE(readableField(FieldKind::outcode, "10201"));
}

TEST(PracticeFields, AKeptAnswerFillsTheFieldsItHasAndSkipsWhatHasAnotherShape) {
  Practice p = openPractice(ref(ExerciseTopic::pipeline, 4, "100"), Reveal::stages, Language::en);
  Json kept = practiceAnswer(p);
  kept["camera"]["n"] = Json::array({"4/5", 0, "3/5"});
  kept["camera"]["vpd"] = 5.0;
  kept["matrices"]["vrc_from_wc"] = Json::array({1, 2});  // not 4 rows: skipped
  EXPECT_EQ(fillFields(p.fields, kept), 4u);
  const Json back = practiceAnswer(p);
  EXPECT_EQ(back["camera"]["n"].dump(), R"(["4/5","0","3/5"])");
  EXPECT_EQ(back["camera"]["vpd"], "5");
  EXPECT_TRUE(back["matrices"]["vrc_from_wc"][0][0].is_null());
}

// ---------------------------------------------------------------- Check

TEST(PracticeCheck, TheSolutionTypedOnPaperEarnsFullPoints) {
  for (const bool comma : {false, true}) {
    Practice p = openPractice(ref(ExerciseTopic::pipeline, 4, "100"), Reveal::stages, Language::de);
    typeAnswer(p, referenceOf(p), comma);
    const PracticeCheck c = checkPractice(p, Language::de);
    EXPECT_EQ(c.edits, p.edits);
    EXPECT_GT(c.grade.maxPoints, 0);
    EXPECT_DOUBLE_EQ(c.grade.points, c.grade.maxPoints) << c.report.json.dump(1);
    EXPECT_TRUE(c.report.passed);
    EXPECT_EQ(c.report.lang, Language::de);
    for (const ItemFields& f : p.fields)
      for (int r = 0; r < f.rows; ++r)
        for (int col = 0; col < f.columns; ++col) EXPECT_EQ(fieldVerdict(c, f, r, col), FieldVerdict::right) << f.path(r, col);
  }
}

TEST(PracticeCheck, ADivideFirstAnswerIsNamedAndItsPassesMarkedWrongWithoutRevealingTheValues) {
  Practice p = openPractice(ref(ExerciseTopic::clipping, 3), Reveal::stages, Language::en);
  ASSERT_TRUE(p.exercise.pointBehindEye) << "odd seeds put P1 behind the eye";
  typeAnswer(p, modelAnswer(p, Mistake::divideFirst));
  const PracticeCheck c = checkPractice(p, Language::en);
  ASSERT_TRUE(c.grade.mistake.has_value()) << c.report.json.dump(1);
  EXPECT_EQ(*c.grade.mistake, Mistake::divideFirst);
  EXPECT_LT(c.grade.points, c.grade.maxPoints);
  std::string diagnosis;
  for (const std::string& line : c.report.diagnosis) diagnosis += line + "\n";
  EXPECT_THAT(diagnosis, HasSubstr("divide-first"));
  // stages: which values are wrong, never the reference's ("…, expected 3/5" is what values shows).
  EXPECT_EQ(reportText(c.report).find(", expected "), std::string::npos) << reportText(c.report);
  size_t wrongFields = 0;
  for (const ItemFields& f : p.fields)
    for (int r = 0; r < f.rows; ++r)
      for (int col = 0; col < f.columns; ++col) wrongFields += fieldVerdict(c, f, r, col) == FieldVerdict::wrong;
  EXPECT_GT(wrongFields, 0u);
}

TEST(PracticeCheck, OneWrongEntryIsThatFieldsVerdictAndTheRestStayRight) {
  Practice p = openPractice(ref(ExerciseTopic::pipeline, 4, "100"), Reveal::values, Language::en);
  typeAnswer(p, referenceOf(p));
  ItemFields* n = nullptr;
  for (ItemFields& f : p.fields)
    if (f.item.path == "/camera/n") n = &f;
  ASSERT_NE(n, nullptr);
  n->text(0, 0) = "7";
  ++p.edits;
  const PracticeCheck c = checkPractice(p, Language::en);
  EXPECT_EQ(fieldVerdict(c, *n, 0, 0), FieldVerdict::wrong);
  EXPECT_EQ(fieldVerdict(c, *n, 0, 1), FieldVerdict::right);
  EXPECT_LT(c.grade.points, c.grade.maxPoints);
  // values: the report shows the reference beside the wrong value.
  EXPECT_THAT(reportText(c.report), HasSubstr("/camera/n/0: \"7\", expected "));
}

TEST(PracticeCheck, AnUnreadableEntryIsNamedAndCheckStillGradesTheRest) {
  Practice p = openPractice(ref(ExerciseTopic::pipeline, 4, "100"), Reveal::none, Language::en);
  typeAnswer(p, referenceOf(p));
  p.fields[0].texts[0] = "zwei";
  const PracticeCheck c = checkPractice(p, Language::en);
  EXPECT_EQ(fieldVerdict(c, p.fields[0], 0, 0), FieldVerdict::unreadable);
  EXPECT_GT(c.grade.points, 0);
  EXPECT_LT(c.grade.points, c.grade.maxPoints);
}

// ---------------------------------------------------------------- the marks in the views

TEST(PracticeMarks, TheRightNumbersLandOnTheLabsPointsInEverySpace) {
  Practice p = openPractice(ref(ExerciseTopic::pipeline, 4, "100"), Reveal::stages, Language::en);
  EXPECT_TRUE(practiceMarks(p, std::nullopt).empty()) << "nothing typed, nothing drawn";
  typeAnswer(p, referenceOf(p));
  const Highlights::Student s = practiceMarks(p, std::nullopt);
  const PointStages& P1 = p.solution.point;
  // Tolerance: the typed values are the solution's to 6 decimals or exact: 1e-5 in WC and NPC, 1e-3 px in DC.
  ASSERT_EQ(s.pointsWc.size(), 2u) << "P1 from WC and from VRC";
  for (const Vec3& q : s.pointsWc) EXPECT_LT(glm::length(q - P1.wc), 1e-5);
  ASSERT_EQ(P1.outcode, 0) << "seed 4 keeps P1 inside";
  ASSERT_EQ(s.pointsNpc.size(), 2u) << "P1 from homogeneous NPC and from NPC";
  for (const Vec3& q : s.pointsNpc) EXPECT_LT(glm::length(q - P1.npc), 1e-5);
  ASSERT_EQ(s.pointsDc.size(), 1u);
  EXPECT_LT(glm::length(s.pointsDc[0] - P1.dc), 1e-3);
  EXPECT_TRUE(s.labWc.empty()) << "stages reveal no value, the lab's P1 neither";
  // Their matrices give the lab's view volume, corner for corner.
  ASSERT_EQ(s.volumeWc.size(), 8u);
  for (int i = 0; i < 8; ++i) {
    const Vec3 c(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    EXPECT_LT(glm::length(s.volumeWc[size_t(i)] - p.solution.run.wcOfNpc(c)), 1e-4) << "corner " << i;
  }
  ASSERT_EQ(s.polygonWc.size(), p.exercise.scene.objects[0].vertices.size());
  EXPECT_LT(glm::length(s.polygonWc[0] - P1.wc), 1e-5);
  p.reveal = Reveal::values;
  EXPECT_EQ(practiceMarks(p, std::nullopt).labWc.size(), 1u);
}

TEST(PracticeMarks, ThePassShownIsTheirPolygonDividedAndADivideFirstOneLiesElsewhere) {
  Practice p = openPractice(ref(ExerciseTopic::clipping, 3), Reveal::stages, Language::en);
  const Json reference = referenceOf(p);
  typeAnswer(p, reference);
  for (int pass = 1; pass <= kPlaneCount; ++pass) {
    const Highlights::Student s = practiceMarks(p, pass);
    // The clipper's output after the pass, as the reference answer gives it (snapped: its vertices lie on
    // the planes; 1e-5: the typed 6 decimals).
    const Json& polygon = reference["objects"][0]["polygons"][0]["clip_steps"][size_t(pass - 1)]["polygon"];
    ASSERT_EQ(s.polygonNpc.size(), polygon.size()) << "pass " << pass;
    for (size_t i = 0; i < polygon.size(); ++i) {
      const Vec4 h(polygon[i][0].get<double>(), polygon[i][1].get<double>(), polygon[i][2].get<double>(), polygon[i][3].get<double>());
      EXPECT_LT(glm::length(s.polygonNpc[i] - Vec3(h) / h.w), 1e-4) << "pass " << pass << " vertex " << i;
    }
  }
  EXPECT_EQ(practiceMarks(p, std::nullopt).polygonNpc, practiceMarks(p, kPlaneCount).polygonNpc) << "no pass shown: their last";
  const std::vector<Vec3> right = practiceMarks(p, kPlaneCount).polygonNpc;
  typeAnswer(p, modelAnswer(p, Mistake::divideFirst));
  const std::vector<Vec3> dividedFirst = practiceMarks(p, kPlaneCount).polygonNpc;
  ASSERT_FALSE(dividedFirst.empty());
  EXPECT_NE(dividedFirst, right) << "P1 behind the eye: dividing first keeps the wrong part";
  ASSERT_FALSE(practiceMarks(p, std::nullopt).polygonDc.empty());
}

TEST(PracticeMarks, ValuesThatCannotBeDrawnAreLeftOut) {
  Practice p = openPractice(ref(ExerciseTopic::pipeline, 4, "100"), Reveal::stages, Language::en);
  for (ItemFields& f : p.fields) {
    if (f.item.path == "/objects/0/polygons/0/npc_h/0") f.texts = {"1", "2", "3", "0"};  // w = 0: no place in NPC
    if (f.item.path == "/objects/0/polygons/0/wc/0") f.texts = {"1", "", "3"};           // not all given
    if (f.item.path == "/matrices/vrc_from_wc") f.texts.assign(16, "0");                 // singular
  }
  const Highlights::Student s = practiceMarks(p, std::nullopt);
  EXPECT_TRUE(s.pointsWc.empty());
  EXPECT_TRUE(s.pointsNpc.empty());
  EXPECT_TRUE(s.volumeWc.empty());
}

// ---------------------------------------------------------------- texts and folders

TEST(PracticeTexts, TheSheetsMathReadsAsPlainText) {
  EXPECT_EQ(plainMath("Compute $\\mathit{wcFromMc}$ and $P_1$ in WC."), "Compute wcFromMc and P1 in WC.");
  EXPECT_EQ(plainMath("$p' = M \\cdot p$, $0 \\le x$, $R(90^\\circ)$, $x_{min}$"), "p' = M · p, 0 ≤ x, R(90°), xmin");
  const Practice p = openPractice(ref(ExerciseTopic::clipping, 7, "100"), Reveal::stages, Language::de);
  const std::vector<std::string> given = givenLines(p, Language::de);
  ASSERT_GE(given.size(), 7u);
  EXPECT_THAT(given[0], HasSubstr("VRP = (-1, -1/2, 1/2)"));
  EXPECT_THAT(given.back(), HasSubstr("homogenen NPC"));
}

TEST(PracticeTexts, TheLanguageChangesTheTasksAndKeepsWhatWasTyped) {
  Practice p = openPractice(ref(ExerciseTopic::pipeline, 4, "100"), Reveal::stages, Language::en);
  p.fields[0].texts[0] = "1";
  setPracticeLanguage(p, Language::de);
  EXPECT_THAT(p.tasks[0].text, HasSubstr("Berechnen Sie"));
  EXPECT_EQ(p.fields[0].texts[0], "1");
}

TEST(PracticeFolder, AFolderOpensItsExerciseWithTheStudentsAnswerAndNamesWhatIsWrong) {
  test::TempDir dir;
  const ExerciseRef r = ref(ExerciseTopic::pipeline, 4, "100");
  dir.write("exercise.json", exerciseFileJson(r));
  Practice fresh = openPractice(r, Reveal::stages, Language::en);
  Json answer = practiceAnswer(fresh);
  answer["camera"]["n"] = Json::array({"4/5", "0", "3/5"});
  dir.write("answer.json", answer.dump());
  const Practice p = openPracticeFolder(dir.path, Reveal::stages, Language::en);
  EXPECT_EQ(p.folder, dir.path);
  EXPECT_EQ(p.ref, r);
  EXPECT_EQ(practiceAnswer(p)["camera"]["n"].dump(), R"(["4/5","0","3/5"])");

  dir.write("answer.json", "[1, 2");
  try {
    openPracticeFolder(dir.path, Reveal::stages, Language::en);
    FAIL() << "a broken answer.json must be named";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("answer.json"));
  }
  test::TempDir empty;
  try {
    openPracticeFolder(empty.path, Reveal::stages, Language::en);
    FAIL() << "a folder without exercise.json is no exercise";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("exercise.json"));
  }
}

TEST(PracticeFolder, AHostileExerciseFileIsRefusedNamingTheValue) {
  for (const char* text : {R"({"vplab_exercise": 1, "topic": "nope", "seed": 1})",
                           R"({"vplab_exercise": 1, "topic": "mapping", "seed": -1})",
                           R"({"vplab_exercise": 1, "topic": "mapping", "seed": 1e30})",
                           R"({"vplab_exercise": 1, "topic": "mapping", "seed": 1, "student_id": "../../etc"})",
                           R"({"vplab_exercise": 2, "topic": "mapping", "seed": 1})",
                           R"({"vplab_exercise": 1, "topic": "mapping", "seed": 1, "extra": 0})"}) {
    EXPECT_THROW(parseExerciseFile(text, "exercise.json"), Error) << text;
  }
  EXPECT_EQ(parseExerciseFile(exerciseFileJson(ref(ExerciseTopic::mapping, 12, "a.b@c")), "x").studentId, "a.b@c");
}

TEST(PracticeFolder, AnAnswerHandedInOpensOnItsOwnWithItsValuesAndIsGradedWithoutAWarning) {
  test::TempDir dir;
  const ExerciseRef r = ref(ExerciseTopic::clipping, 3, "100");
  Practice p = openPractice(r, Reveal::stages, Language::en);
  typeAnswer(p, modelAnswer(p, Mistake::divideFirst), true);
  const PracticeCheck before = checkPractice(p, Language::en);
  // Hand in's file names its exercise; no folder beside it (the page: a file the student downloaded).
  const Json handedIn = practiceAnswer(p);
  ASSERT_TRUE(handedIn.contains("exercise"));
  EXPECT_EQ(handedIn.begin().key(), "exercise") << "read first by a person opening the file";
  dir.write("my answer.json", handedIn.dump(2));
  const Practice reopened = openPracticeFile(dir.path / "my answer.json", Reveal::stages, Language::de);
  EXPECT_EQ(reopened.ref, r);
  EXPECT_TRUE(reopened.answerOpened) << "what the student opened is shown, not the answer kept of it";
  EXPECT_EQ(reopened.folder, dir.path);
  for (size_t i = 0; i < p.fields.size(); ++i) EXPECT_EQ(reopened.fields[i].texts, p.fields[i].texts) << p.fields[i].item.path;
  const PracticeCheck after = checkPractice(reopened, Language::en);
  EXPECT_EQ(after.grade.points, before.grade.points);
  EXPECT_EQ(after.report.diagnosis, before.report.diagnosis);
  // The exercise it names is a label, as a file's name is: the grader says nothing of it.
  const NumbersGrade graded = gradeNumbers(handedIn, "answer.json", p.grading, p.assignment.tolerance, &p.assignment);
  EXPECT_TRUE(graded.warnings.empty()) << graded.warnings.front();

  // exercise.json opens its folder; the template `vplab exercise` writes opens as an empty sheet.
  dir.write("exercise.json", exerciseFileJson(r));
  EXPECT_FALSE(openPracticeFile(dir.path / "exercise.json", Reveal::stages, Language::en).answerOpened);
  dir.write("answer.json", answerNamingExercise(p.answerTemplate, r).dump());
  const Practice blank = openPracticeFile(dir.path / "answer.json", Reveal::stages, Language::en);
  for (const ItemFields& f : blank.fields)
    for (const std::string& t : f.texts) EXPECT_EQ(t, "") << f.item.path;
}

TEST(PracticeFolder, AFileThatNamesNoExerciseOrAWrongOneIsRefusedNamingIt) {
  test::TempDir dir;
  dir.write("scene.json", R"({"vplab_scene": 1})");
  dir.write("bare.json", R"({"camera": {"n": [0, 0, 1]}})");
  dir.write("wrong.json", R"({"exercise": {"vplab_exercise": 1, "topic": "clipping", "seed": "3"}, "camera": {}})");
  dir.write("list.json", R"([1, 2, 3])");
  for (const auto& [file, said] : {std::pair{"scene.json", "names its exercise"}, std::pair{"bare.json", "names its exercise"},
                                   std::pair{"wrong.json", "/exercise/seed"}, std::pair{"list.json", "list.json"},
                                   std::pair{"missing.json", "missing.json"}}) {
    try {
      openPracticeFile(dir.path / file, Reveal::stages, Language::en);
      ADD_FAILURE() << file << " opened";
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr(said)) << file;
      EXPECT_THAT(e.what(), HasSubstr(file));
    }
  }
}

}  // namespace
}  // namespace vplab
