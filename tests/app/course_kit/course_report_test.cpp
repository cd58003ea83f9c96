// The reports of `vplab grade` (app/course_kit/grade_report.h, issue 21): hints that do not contradict
// themselves and only when a model explains most of what is wrong, counts that are right ("… and N
// more"), German feedback, and a report (JUnit with an <error>) for an answer that cannot be graded.
#include "app/course_kit/image_report.h"
#include "course/mistake_models.h"
#include "io/scene_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace vplab {
namespace {

using Json = nlohmann::ordered_json;
using ::testing::HasSubstr;
using ::testing::Not;

Scene asset(const char* name) { return loadScene(std::string(VPLAB_ASSETS) + "/scenes/" + name); }

std::string textOf(const Json& answer, const Scene& scene, Language lang = Language::en) {
  return reportText(numbersReport(gradeNumbers(answer, "a.json", scene), "a.json", "s.json", lang));
}

TEST(GradeReport, AModelThatExplainsEveryWrongValueButChangesRightOnesSaysSo) {
  const Scene scene = asset("behind-the-eye.json");
  // y not flipped in dcFromNpc, but the clipped polygons in DC right: the model explains the matrix
  // and would change the polygons.
  Json answer = referenceDump(scene);
  answer["matrices"]["dc_from_npc"] = mistakeDump(scene, Mistake::yNotFlipped)["matrices"]["dc_from_npc"];
  const std::string text = textOf(answer, scene);
  EXPECT_THAT(text, HasSubstr("The mistake model \"y-not-flipped\""));
  EXPECT_THAT(text, HasSubstr("explains all"));
  EXPECT_THAT(text, HasSubstr("you got right: you made this mistake in a part of your work"));
  EXPECT_THAT(text, Not(HasSubstr("No mistake model explains all")));
}

TEST(GradeReport, APartialHintOnlyWhenTheModelExplainsMostOfWhatIsWrong) {
  const Scene scene = asset("behind-the-eye.json");
  Json answer = referenceDump(scene);
  // y not flipped in one clipped vertex only, and many other values wrong for another reason.
  const double h = answer["device"]["height"].get<double>();
  Json& v = answer["objects"][0]["polygons"][0]["clipped_dc"][0];
  v[1] = h - v[1].get<double>();
  for (Json& row : answer["matrices"]["npc_from_vrc"])
    for (Json& x : row) x = x.get<double>() + 0.5;
  const std::string text = textOf(answer, scene);
  EXPECT_THAT(text, Not(HasSubstr("explains 1 of"))) << text;
  EXPECT_THAT(text, HasSubstr("None of the mistake models explains your numbers."));
}

TEST(GradeReport, TheCountOfWhatIsNotListedIsRight) {
  ImageGrade g;
  g.comparison.pixelCount = 120000;
  g.comparison.differingPixels = 627;
  g.comparison.differingShare = 627.0 / 120000;
  g.comparison.actualWidth = g.comparison.expectedWidth = 400;
  g.comparison.actualHeight = g.comparison.expectedHeight = 300;
  for (int i = 0; i < 11; ++i) g.comparison.worst.push_back({i, 0, {0, 0, 0, 255}, {255, 255, 255, 255}, 255});
  const std::string text = reportText(imageReport(g, "a.png", "s.json", ""));
  EXPECT_THAT(text, HasSubstr("… and 619 more")) << text;  // 627 wrong, 8 listed
}

TEST(GradeReport, FeedbackInGerman) {
  const Scene scene = asset("behind-the-eye.json");
  // vrcFromWc in row form, npcFromVrc in column form: the transposed one is the mistake.
  const Json answer = {{"matrices", {{"vrc_from_wc", mistakeDump(scene, Mistake::transposed)["matrices"]["vrc_from_wc"]},
                                     {"npc_from_vrc", referenceDump(scene)["matrices"]["npc_from_vrc"]}}}};
  const GradeReport r = numbersReport(gradeNumbers(answer, "a.json", scene), "a.json", "s.json", Language::de);
  const std::string text = reportText(r);
  EXPECT_THAT(text, HasSubstr("NICHT BESTANDEN"));
  EXPECT_THAT(text, HasSubstr("Stufe"));
  EXPECT_THAT(text, HasSubstr("Fehlermodell"));
  EXPECT_THAT(r.json["diagnosis"].dump(), HasSubstr("Stufe"));
  EXPECT_THAT(reportJunit(r), HasSubstr("falsch"));
}

TEST(GradeReport, EveryMatrixInRowFormIsANotationAndTheReportSaysSo) {
  const Scene scene = asset("behind-the-eye.json");
  const Json answer = {{"matrices", mistakeDump(scene, Mistake::transposed)["matrices"]}};
  const GradeReport r = numbersReport(gradeNumbers(answer, "a.json", scene), "a.json", "s.json", Language::de);
  EXPECT_TRUE(r.passed);
  EXPECT_THAT(reportText(r), HasSubstr("Zeilenvektor-Form des Skripts"));
}

TEST(GradeReport, AnAnswerThatCannotBeGradedGetsAJunitErrorNamingTheProblem) {
  const GradeReport r = errorReport("numbers", "answers/alice.json", "s.json", "alice.json: /camera/u: 2 numbers where 3 are expected");
  const std::string xml = reportJunit(r);
  EXPECT_THAT(xml, HasSubstr("errors=\"1\""));
  EXPECT_THAT(xml, HasSubstr("classname=\"alice\""));
  EXPECT_THAT(xml, HasSubstr("<error message=\"alice.json: /camera/u: 2 numbers where 3 are expected\">"));
  EXPECT_THAT(reportText(r), HasSubstr("NOT GRADED"));
  EXPECT_EQ(r.json["passed"], false);
}

}  // namespace
}  // namespace vplab
