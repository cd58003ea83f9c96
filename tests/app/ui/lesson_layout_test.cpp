// Every lesson step laid out for the room (issue 37 items 3 and 4): each bundled lesson, in its
// language, walked step by step in the viewer at the two projector sizes the issue names
// (1280 × 720 at UI scale 1.6, 1024 × 768 at 1.25). Each value the caption cites (the step's
// "cites") is on screen, readable, in the panel of the step's tab; in every view each step shows,
// the labels never sit on each other, none leaves its view, and each stays by the point it names.
// The test writes the table of cited values per step (test output: lesson-evidence-*.md).
#include "app/ui/headless_viewer.h"
#include "app/views/views.h"
#include "tests/app/ui/bundled_lessons.h"
#include "tests/app/ui/screen_text.h"
#include "tests/app/ui/view_lists.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace vplab {
namespace {

namespace fs = std::filesystem;

struct ProjectorSize {
  int width, height;
  float scale;
};
constexpr ProjectorSize kSizes[] = {{1280, 720, 1.6f}, {1024, 768, 1.25f}};

Language languageOf(const std::string& file) {
  return file.find(".de.") != std::string::npos ? Language::de : Language::en;
}

std::string describe(const PlacedLabel& l) {
  std::ostringstream out;
  out << "\"" << l.text << "\" at (" << l.topLeft.x << ", " << l.topLeft.y << ") size " << l.extent.x << " × "
      << l.extent.y << " for the point (" << l.anchor.x << ", " << l.anchor.y << ")";
  return out.str();
}

bool intersect(const PlacedLabel& a, const PlacedLabel& b) {
  return a.topLeft.x < b.topLeft.x + b.extent.x && a.topLeft.x + a.extent.x > b.topLeft.x &&
         a.topLeft.y < b.topLeft.y + b.extent.y && a.topLeft.y + a.extent.y > b.topLeft.y;
}

/// The labels' faults in one view: overlaps, labels outside the view, labels far from their point,
/// a name said twice.
std::vector<std::string> labelFaults(const draw::DisplayList& list, float scale) {
  std::vector<std::string> faults;
  const std::vector<PlacedLabel> labels = list.labels();
  for (size_t i = 0; i < labels.size(); ++i) {
    const PlacedLabel& l = labels[i];
    for (size_t j = i + 1; j < labels.size(); ++j)
      if (intersect(l, labels[j])) faults.push_back(describe(l) + " overlaps " + describe(labels[j]));
    if (l.topLeft.x < 0 || l.topLeft.y < 0 || l.topLeft.x + l.extent.x > float(list.width) ||
        l.topLeft.y + l.extent.y > float(list.height))
      faults.push_back(describe(l) + " leaves the " + std::to_string(list.width) + " × " +
                       std::to_string(list.height) + " view");
    // Near enough to name its point: a reader's eye links a label to a point within three lines of
    // text (and the gap a marker keeps, 8 px at scale 1). A fixed label (a title) names no point: reach 0.
    const float near = 3.f * l.extent.y + 8.f * scale;
    // Said once: a name twice (PRP and VRP were, on a tablet) is a point named twice; the axes' ticks repeat.
    if (l.text.find_first_not_of("0123456789.−-") != std::string::npos)
      for (size_t j = i + 1; j < labels.size(); ++j)
        if (labels[j].text == l.text) faults.push_back(describe(l) + " is said again: " + describe(labels[j]));
    if (l.reach > 0 && distanceToBox(l, l.anchor) > near)
      faults.push_back(describe(l) + " is " + std::to_string(distanceToBox(l, l.anchor)) + " px from its point");
  }
  return faults;
}

/// The numbers in a text, as a reader reads them: "−0.33" and "-0.33" alike, "101 060" one number.
std::vector<std::string> numbersIn(std::string text) {
  for (const std::string minus : {"\u2212"})
    for (size_t at; (at = text.find(minus)) != std::string::npos;) text.replace(at, minus.size(), "-");
  text = std::regex_replace(text, std::regex("(\\d)[ \u2009\u202f](\\d{3})(?!\\d)"), "$1$2");
  std::vector<std::string> out;
  const std::regex number("-?\\d+(\\.\\d+)?");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it)
    out.push_back(it->str());
  return out;
}

/// Whether a number shown says the cited value: equal to it when rounded to the cited precision
/// (the caption writes 8.13 where the probe shows 8.128).
bool says(const std::string& shown, const std::string& cited) {
  const auto dot = cited.find('.');
  const int decimals = dot == std::string::npos ? 0 : int(cited.size() - dot - 1);
  const double a = std::stod(shown), b = std::stod(cited), half = 0.5 * std::pow(10.0, -decimals);
  if (decimals == 0 && shown.find('.') != std::string::npos) return std::abs(a - b) < 1e-9;  // 15.000, not 15.2
  return std::abs(a - b) <= half * (1 + 1e-9);
}

/// The window that holds the step's tab: the controls or the inspector.
const char* windowOfTab(const std::string& tab) {
  return tab == "probe" || tab == "matrices" || tab == "depth" ? "###Inspect" : "###Controls";
}

struct CitedFinding {
  std::string value;
  bool shown = false;
};

/// Each cited value: whether a line of text inside the window `window` shows it, whole and unscrolled.
std::vector<CitedFinding> findCited(const std::vector<std::string>& cites, const char* window) {
  const ImGuiWindow* w = ImGui::FindWindowByName(window);
  std::vector<CitedFinding> found;
  const std::vector<test::ScreenLine> lines = test::screenText();
  for (const std::string& cite : cites) {
    CitedFinding f{cite};
    const std::vector<std::string> value = numbersIn(cite);
    for (const test::ScreenLine& l : lines) {
      if (!w || l.min.x < w->Pos.x || l.min.y < w->Pos.y || l.max.x > w->Pos.x + w->Size.x ||
          l.max.y > w->Pos.y + w->Size.y)
        continue;
      for (const std::string& n : numbersIn(l.text))
        if (value.size() == 1 && says(n, value[0])) f.shown = true;
    }
    found.push_back(f);
  }
  return found;
}

/// How much of a view the points' bounding box covers (clamped to the view), 0 to 1.
double coverage(const draw::DisplayList& list, const std::vector<Vec3>& points) {
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const Vec3& p : points) {
    const Projected q = projectToPixels(list.observer.camera, p, list.width, list.height);
    if (!q.visible) continue;
    lo = glm::min(lo, glm::dvec2(q.pixel));
    hi = glm::max(hi, glm::dvec2(q.pixel));
  }
  lo = glm::max(lo, glm::dvec2(0));
  hi = glm::min(hi, glm::dvec2(list.width, list.height));
  if (!(hi.x > lo.x && hi.y > lo.y)) return 0;
  return (hi.x - lo.x) * (hi.y - lo.y) / (double(list.width) * list.height);
}

/// The step's object as the views show it: the stepped polygon (NPC, the NPC view) or the probed
/// object (WC, the world view), from the frame's highlights and run, not from the lesson's framing.
std::optional<std::pair<ViewKind, std::vector<Vec3>>> stepObject(const Viewer& viewer, const LessonState& state) {
  if (state.stepThrough) {
    const ViewRequest* r = viewer.images().lastRequest(ViewKind::npc);
    if (!r || !r->highlights.step) return std::nullopt;
    return std::make_pair(ViewKind::npc, r->highlights.step->polygonNpc);
  }
  if (state.probe) {
    const ViewRequest* r = viewer.images().lastRequest(ViewKind::world);
    if (!r) return std::nullopt;
    for (size_t i = 0; i < r->run->sceneIndex.size(); ++i) {
      if (r->run->sceneIndex[i] != state.probe->object) continue;
      const ObjectRun& o = r->run->objects[i];
      std::vector<Vec3> points;
      for (uint32_t v = 0; v < o.vertexCount(); ++v) points.push_back(o.wc(v));
      return std::make_pair(ViewKind::world, points);
    }
  }
  return std::nullopt;
}

class LessonLayout : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(LessonLayout, EveryStepsLabelsNeverOverlapLeaveTheirViewOrStrayFromTheirPoint) {
  const auto& [file, sizeIndex] = GetParam();
  const ProjectorSize size = kSizes[sizeIndex];
  HeadlessViewer v{*test::egl().context, defaultScene(), size.width, size.height, size.scale};
  v.state().display.language = languageOf(file);
  v.frames(2);
  v.viewer().session().openLesson(fs::path(VPLAB_ASSETS) / "lessons" / file, 0);
  v.frames(2);
  ASSERT_TRUE(v.state().lesson) << v.state().status;
  const size_t steps = v.state().lesson->stepCount();
  size_t views = 0, labels = 0, reasons = 0, framedSteps = 0;
  const std::string sizeName = std::to_string(size.width) + " × " + std::to_string(size.height) + " × " +
                               (sizeIndex == 0 ? "1.6" : "1.25");
  std::ofstream table(test::outputDir() / ("lesson-evidence-" + file.substr(0, file.size() - 5) + "-" +
                                           std::to_string(size.width) + ".md"));
  table << "| " << file << " at " << sizeName << " | cited values | on screen |\n| --- | --- | --- |\n";
  for (size_t step = 0; step < steps; ++step) {
    SCOPED_TRACE("step " + std::to_string(step + 1));
    v.viewer().session().openLesson(fs::path(VPLAB_ASSETS) / "lessons" / file, step);
    v.frames(3);
    ASSERT_EQ(v.state().lesson->step(), step);
    // VPLAB_LESSON_SHOTS=1: every step's window into the test output, to look at.
    if (std::getenv("VPLAB_LESSON_SHOTS")) {
      const std::string name = file.substr(0, file.size() - 5) + "-" + std::to_string(size.width) + "-step" +
                               std::to_string(step + 1) + ".png";
      writePng(v.image(), test::outputDir() / "lesson-layout" / name);
    }
    // The step's evidence: each value its caption cites, in the panel of its tab.
    const LessonStep& current = v.state().lesson->current();
    if (!current.cites.empty()) {
      const char* window = windowOfTab(current.state.tab);
      std::string values, missing;
      for (const CitedFinding& f : findCited(current.cites, window)) {
        values += (values.empty() ? "" : ", ") + f.value;
        if (!f.shown) missing += (missing.empty() ? "" : ", ") + f.value;
      }
      table << "| step " << step + 1 << " | " << values << " | " << (missing.empty() ? "yes" : "no: " + missing) << " |\n";
      EXPECT_TRUE(missing.empty()) << file << " step " << step + 1 << " at " << sizeName << ": " << missing
                                   << " not on screen in " << window << ":\n"
                                   << test::screenTextDump(test::screenText());
    }
    // The step's object, framed: it covers at least a fifth of the view that shows it.
    if (const auto object = stepObject(v.viewer(), current.state)) {
      const double covered = coverage(test::listOf(v.viewer(), object->first), object->second);
      EXPECT_GE(covered, 0.2) << file << " step " << step + 1 << " at " << sizeName << ": the step's object covers "
                              << covered * 100 << " % of the " << toString(object->first) << " view";
      framedSteps++;
      table << "| step " << step + 1 << " | (its object in the " << toString(object->first) << " view) | "
            << int(std::round(covered * 100)) << " % of the view |\n";
    }
    // The caption box's buttons are whole and the heading stays left of them.
    {
      const auto& rects = v.rects().rects;
      const auto& shown = v.rects().visible;
      for (const char* id : {"lesson.back", "lesson.next", "lesson.close"})
        EXPECT_GE(shown.at(id).z, rects.at(id).z - 1) << file << " step " << step + 1 << " at " << sizeName << ": " << id << " is cut off";
      EXPECT_LE(rects.at("lesson.heading").x + rects.at("lesson.heading").z, rects.at("lesson.back").x)
          << file << " step " << step + 1 << " at " << sizeName << ": the heading runs under the buttons";
    }
    // The divide-first reason under the camera view is read whole (it stopped mid-sentence at 1024 × 768).
    if (auto it = v.rects().visible.find("view.divideFirst.reason"); it != v.rects().visible.end()) {
      const ImVec4 whole = v.rects().rects.at("view.divideFirst.reason");
      EXPECT_GE(it->second.w, whole.w - 1) << file << " step " << step + 1 << ": the divide-first reason is cut off";
      ++reasons;
    }
    for (ViewKind kind : v.viewer().images().asked()) {
      if (!v.viewer().images().lastRequest(kind)) continue;
      const draw::DisplayList list = test::listOf(v.viewer(), kind);
      ++views;
      labels += list.labels().size();
      for (const std::string& fault : labelFaults(list, size.scale))
        ADD_FAILURE() << file << " step " << step + 1 << ", " << toString(kind) << " view: " << fault;
    }
  }
  EXPECT_GE(views, steps) << "every step shows a view";
  EXPECT_GT(labels, steps) << "the views have labels to place";
  if (file.rfind("05-clipping", 0) == 0) {
    EXPECT_GE(reasons, 1u) << "its last step shows the divide-first strategy";
  }
}

INSTANTIATE_TEST_SUITE_P(Bundled, LessonLayout,
                         ::testing::Combine(::testing::ValuesIn(test::bundledLessons()), ::testing::Values(0, 1)),
                         [](const auto& param) { return test::lessonTestName(std::get<0>(param.param)) + (std::get<1>(param.param) == 0 ? "_1280x720x1_6" : "_1024x768x1_25"); });

}  // namespace
}  // namespace vplab
