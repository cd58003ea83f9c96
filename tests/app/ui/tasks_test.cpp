// The Tasks panel as a student uses it (issue 40), in German at a projector's 1280 × 720 × 1.6: every
// field of a sheet filled from the keyboard alone (a click into the first field, then text and Tab,
// Ctrl+Enter to check), the verdicts, the student's polygon where the views draw it, Hand in.
//
// Oracles: the exercise's worked solution and the divide-first mistake model's answer
// (course/mistake_models.h), typed as text; the student's outline compared with a render of that
// polygon (ViewRenderer), not with what the viewer computed.
#include "app/practice/practice.h"
#include "app/render/headless.h"
#include "app/render/view_renderer.h"
#include "app/ui/headless_viewer.h"
#include "app/ui/keys.h"
#include "course/mistake_models.h"
#include "course/rational.h"
#include "tests/app/ui/cut_off.h"
#include "tests/support/files.h"
#include "tests/support/gl_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>
#include <cstdio>
#include <tuple>

namespace vplab {
namespace {

using Json = nlohmann::ordered_json;
using ::testing::HasSubstr;

/// A viewer practising `ref` in German at 1280 × 720 × 1.6, settled.
struct Practising {
  HeadlessViewer v{*test::egl().context, defaultScene(), 1280, 720, 1.6f};
  Practising(const ExerciseRef& ref, Reveal reveal) {
    v.state().display.language = Language::de;
    v.frames(2);
    EXPECT_TRUE(v.viewer().session().exercises().open(ref, reveal)) << v.state().status;
    settle();
  }
  ViewerState& s() { return v.state(); }
  /// Frames until every view shows its current image (the render thread draws them).
  void settle() {
    v.frames(3);
    for (int i = 0; i < 600 && !v.viewer().viewsNotReady().empty(); ++i) v.frame();
  }
};

/// A number as a student writes it: the exact fraction where there is one, else 6 decimals with a
/// German decimal comma.
std::string onPaper(double x) {
  if (const auto r = Rational::approximate(x)) return r->text();
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", x);
  std::string t = buf;
  t[t.find('.')] = ',';
  return t;
}

/// What the student types, field after field in the sheet's order (Tab between them): a polygon's
/// vertex count, then its vertices; an outcode as its six bits.
std::vector<std::string> keystrokes(const Practice& p, const Json& answer) {
  std::vector<std::string> out;
  for (const ItemFields& f : p.fields) {
    const Json& v = answer[Json::json_pointer(f.item.path)];
    switch (f.kind) {
      case FieldKind::number: out.push_back(onPaper(v.get<double>())); break;
      case FieldKind::outcode: {
        std::string bits;
        for (int b = 5; b >= 0; --b) bits += (v.get<int>() >> b) & 1 ? '1' : '0';
        out.push_back(bits);
        break;
      }
      case FieldKind::vector:
        for (const Json& x : v) out.push_back(onPaper(x.get<double>()));
        break;
      case FieldKind::polygon: out.push_back(std::to_string(v.size())); [[fallthrough]];
      case FieldKind::matrix:
        for (const Json& row : v)
          for (const Json& x : row) out.push_back(onPaper(x.get<double>()));
        break;
    }
  }
  return out;
}

/// Clicks into the sheet's first field and types `texts`, Tab after each, then Ctrl+Enter.
void typeAndCheck(Practising& p, const std::vector<std::string>& texts) {
  // The given data come first: the wheel brings the first field into sight, as a student scrolls.
  const ItemFields& f = p.s().practice->fields[0];
  const std::string first = "task" + (f.kind == FieldKind::polygon ? f.item.path + "/count" : f.path(0, 0));
  const ImGuiWindow* inspector = ImGui::FindWindowByName("###Inspect");
  ASSERT_NE(inspector, nullptr);
  const ImVec4 panel(inspector->Pos.x, inspector->Pos.y, inspector->Size.x, inspector->Size.y);
  for (int i = 0; i < 40; ++i) {
    const auto seen = p.v.rects().visible.find(first);
    const auto whole = p.v.rects().rects.find(first);
    if (seen != p.v.rects().visible.end() && whole != p.v.rects().rects.end() && seen->second.w >= whole->second.w - 0.5f) break;
    p.v.mouseMove(panel.x + panel.z / 2, panel.y + panel.w / 2);
    p.v.wheel(-1);
    p.v.frames(2);
  }
  // A vertex count's rect holds its − and + buttons after the field: clicked at its left.
  const ImVec4 r = p.v.rects().rects.at(first);
  p.v.click(r.x + r.z * (f.kind == FieldKind::polygon ? 0.2 : 0.5), r.y + r.w / 2);
  p.v.frame();
  ASSERT_TRUE(ImGui::GetIO().WantTextInput) << "the click went into the first field";
  for (size_t i = 0; i < texts.size(); ++i) {
    p.v.type(texts[i]);
    if (i + 1 < texts.size()) p.v.key(keys::kTab);
  }
  p.v.key(keys::kEnter, /*ctrl=*/true);
  p.settle();
}

Json modelAnswer(const Practice& p, Mistake m) {
  for (const auto& [id, dump] : p.grading.models)
    if (id == m) return dump;
  ADD_FAILURE() << "no model " << mistakeModel(m).key;
  return {};
}

/// The student's colour in the dark theme (theme::kDark.student, 255 89 217) and its antialiased
/// edge over the dark ground: clearly magenta; nothing else in the NPC view is.
bool studentColoured(const Rgba& c) { return c.r > 150 && c.b > 120 && c.g < 0.6 * c.r && c.g < 0.75 * c.b; }

std::vector<bool> studentMask(const Image& image) {
  std::vector<bool> mask;
  for (const Rgba& c : image.pixels) mask.push_back(studentColoured(c));
  return mask;
}

TEST(Tasks, EveryFieldOfAPipelineSheetIsFilledFromTheKeyboardAndCheckGivesFullPoints) {
  Practising p({ExerciseSpec{4, ExerciseTopic::pipeline, Projection::perspective}, "100", Language::en}, Reveal::stages);
  ASSERT_TRUE(p.s().practice);
  EXPECT_EQ(p.s().inspectTab, ViewerState::tasksTab) << "opening an exercise brings its Tasks forward";
  const std::vector<std::string> texts = keystrokes(*p.s().practice, p.s().practice->grading.reference);
  ASSERT_GT(texts.size(), 60u) << "the pipeline sheet's matrices, vectors and outcode";
  typeAndCheck(p, texts);
  // Every field holds what was typed into it, in the sheet's order: Tab reached each one.
  size_t i = 0;
  for (const ItemFields& f : p.s().practice->fields)
    for (const std::string& t : f.texts) {
      ASSERT_LT(i, texts.size());
      EXPECT_EQ(t, texts[i++]) << f.item.path;
    }
  ASSERT_TRUE(p.s().check) << "Ctrl+Enter checks";
  EXPECT_EQ(p.s().check->edits, p.s().practice->edits);
  EXPECT_GT(p.s().check->grade.maxPoints, 10);
  EXPECT_DOUBLE_EQ(p.s().check->grade.points, p.s().check->grade.maxPoints) << p.s().check->report.json.dump(1);
  EXPECT_TRUE(p.s().check->report.passed);
  EXPECT_TRUE(p.v.rects().visible.count("task.points")) << "the points are on screen after Check";
  // Their P1 is drawn in the views, on the lab's: the world view shows the student's colour.
  EXPECT_FALSE(p.s().highlights.student.pointsWc.empty());
  writePng(p.v.image(), std::string(VPLAB_TEST_OUTPUT) + "/tasks-pipeline-checked.png");
}

TEST(Tasks, ADivideFirstAnswerIsNamedAndItsPolygonIsDrawnWhereTheModelPutsIt) {
  const ExerciseRef ref{ExerciseSpec{3, ExerciseTopic::clipping, Projection::perspective}, "", Language::en};
  Practising p(ref, Reveal::stages);
  ASSERT_TRUE(p.s().practice);
  const Json dividedFirst = modelAnswer(*p.s().practice, Mistake::divideFirst);
  typeAndCheck(p, keystrokes(*p.s().practice, dividedFirst));
  ASSERT_TRUE(p.s().check);
  ASSERT_TRUE(p.s().check->grade.mistake) << p.s().check->report.json.dump(1);
  EXPECT_EQ(*p.s().check->grade.mistake, Mistake::divideFirst);
  std::string diagnosis;
  for (const std::string& line : p.s().check->report.diagnosis) diagnosis += line;
  EXPECT_THAT(diagnosis, HasSubstr("divide-first"));
  EXPECT_LT(p.s().check->grade.points, p.s().check->grade.maxPoints);

  // The NPC view shows their last pass (the step-through at its start shows no pass): the divided
  // polygon, dashed in their colour. The oracle: a render of the model's last pass, divided by w here,
  // with the viewer's own view settings and size.
  const Json& last = dividedFirst["objects"][0]["polygons"][0]["clip_steps"][5]["polygon"];
  ASSERT_GE(last.size(), 3u);
  RenderRequest request;
  request.view = ViewKind::npc;
  const ImVec4 r = p.v.rects().rects.at("view.npc");
  request.width = int(r.z);
  request.height = int(r.w);
  request.display = p.s().display;
  request.pipeline = p.s().pipeline;
  request.scale = 1.6f;
  for (const Json& v : last)
    request.highlights.student.polygonNpc.push_back(
        Vec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>()) / v[3].get<double>());
  ViewRenderer renderer(*test::egl().context, request.scale);
  const Image expected = renderImage(renderer, p.s().doc.scene(), request);
  const Image shown = test::crop(p.v.image(), int(std::lround(r.x)), int(std::lround(r.y)), request.width, request.height);
  ASSERT_EQ(shown.pixels.size(), expected.pixels.size());
  const std::vector<bool> a = studentMask(shown), b = studentMask(expected);
  size_t both = 0, either = 0, inShown = 0, inExpected = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    both += a[i] && b[i];
    either += a[i] || b[i];
    inShown += a[i];
    inExpected += b[i];
  }
  // Every pixel of their colour shown is one of the rendered outline's (3 %: antialiased edges), and most
  // of the outline is shown: the viewer draws the lab's step-through and the vertex names over parts of it.
  EXPECT_GT(inExpected, 150u) << "the rendered outline is visible";
  EXPECT_GE(double(both), 0.97 * double(inShown)) << "shown " << inShown << ", rendered " << inExpected << ", both " << both;
  EXPECT_GT(double(both), 0.6 * double(inExpected)) << "shown " << inShown << ", rendered " << inExpected << ", both " << both;
  (void)either;
  writePng(p.v.image(), std::string(VPLAB_TEST_OUTPUT) + "/tasks-divide-first.png");
}

TEST(Tasks, HandInWritesTheAnswerThatTheGraderGivesTheSamePoints) {
  Practising p({ExerciseSpec{4, ExerciseTopic::pipeline, Projection::perspective}, "100", Language::en}, Reveal::stages);
  Practice& practice = *p.s().practice;
  practice.fields[0].texts = {"1", "0", "0", "5/2", "0", "1", "0", "1", "0", "0", "1", "3/2", "0", "0", "0", "1"};
  ++practice.edits;
  p.v.viewer().session().exercises().check();
  test::TempDir dir;
  p.v.viewer().session().exercises().writeAnswer(dir.path / "answer.json");
  const Json handedIn = parseAnswer(test::readFile(dir.path / "answer.json"), "answer.json");
  EXPECT_EQ(handedIn["objects"][0]["wc_from_mc"][0][3], "5/2") << "the text as typed";
  const Assignment assignment = exerciseAssignment(practice.exercise, practice.solution, Language::de);
  const NumbersGrade again = gradeNumbers(handedIn, "answer.json", practice.exercise.scene, assignment.tolerance, &assignment);
  EXPECT_DOUBLE_EQ(again.points, p.s().check->grade.points);
  EXPECT_DOUBLE_EQ(again.points, 2) << "wcFromMc right, nothing else given";
}

/// Fills the fields with `answer`'s values as `keystrokes` writes them, without typing (the cut-off
/// test looks at the panel, not at the keys).
void fillWith(Practice& p, const Json& answer) {
  const std::vector<std::string> texts = keystrokes(p, answer);
  size_t i = 0;
  for (ItemFields& f : p.fields) {
    if (f.kind == FieldKind::polygon) f.setRows(std::stoi(texts[i++]));
    for (std::string& t : f.texts) t = texts[i++];
  }
  ++p.edits;
}

// The Tasks at a projector's 1280 × 720 × 1.6 and on a phone (upright, the page's scale), in English
// and in German, with a sheet checked (its verdicts and diagnosis shown): no text cut off at the side
// of the panel, a column or a field's frame (ui::textCutOff, paged through the scrolled panel).
TEST(Tasks, NoTextOfTheTasksIsCutOffAtAProjectorsScaleOrOnAPhone) {
  struct Screen {
    const char* name;
    int width, height;
    float scale;
    bool compact;
  };
  for (const Screen& screen : {Screen{"projector", 1280, 720, 1.6f, false}, Screen{"phone", 780, 1688, 2.f * 0.886f, true}})
    for (const Language lang : {Language::en, Language::de})
      for (const auto& [topic, seed, model] : {std::tuple{ExerciseTopic::pipeline, 4, Mistake::transposed},
                                               std::tuple{ExerciseTopic::clipping, 3, Mistake::divideFirst}}) {
        SCOPED_TRACE(std::string(screen.name) + " " + std::string(toString(topic)) + (lang == Language::de ? " de" : " en"));
        HeadlessViewer v(*test::egl().context, defaultScene(), screen.width, screen.height, screen.scale);
        v.state().compactAllowed = screen.compact;
        v.state().display.language = lang;
        v.frames(2);
        ASSERT_TRUE(v.viewer().session().exercises().open({ExerciseSpec{uint64_t(seed), topic, Projection::perspective}, "100", Language::en},
                                                          Reveal::values));
        v.frames(2);
        if (screen.compact) {
          const auto [x, y] = v.centreOf("switch.tasks");
          v.click(x, y);
          v.frames(2);
        }
        fillWith(*v.state().practice, modelAnswer(*v.state().practice, model));
        v.viewer().session().exercises().check();
        v.frames(3);
        ASSERT_TRUE(v.rects().rects.count("task.check")) << "the Tasks are shown";
        const std::string prefix = std::string("tasks-") + screen.name + "-" + std::string(toString(topic)) + (lang == Language::de ? "-de" : "-en");
        const std::vector<std::string> problems = test::clippedTextOfEveryPage(v, prefix);
        writePng(v.image(), test::outputDir() / (prefix + ".png"));
        std::string list;
        for (size_t i = 0; i < std::min<size_t>(problems.size(), 6); ++i) list += "\n  " + problems[i];
        EXPECT_TRUE(problems.empty()) << problems.size() << " places:" << list;
      }
}

}  // namespace
}  // namespace vplab
