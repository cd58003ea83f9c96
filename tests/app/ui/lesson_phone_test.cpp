// Every lesson step on a phone (issue 41 item 2): each bundled lesson, in its language, walked step
// by step in the page's compact layout at 390 × 844 and 844 × 390 CSS px (devicePixelRatio 3, the
// page's UI scale there, a finger's style). On every step nothing is cut off (the page's own check,
// every scrolled panel paged through), the caption can be read to its last line, the heading says
// which step this is beside, never under, the lesson's buttons, and the buttons are whole and a
// finger's size.
#include "app/ui/headless_viewer.h"
#include "app/ui/touch.h"
#include "app/views/views.h"
#include "tests/app/ui/cut_off.h"
#include "tests/app/ui/bundled_lessons.h"
#include "tests/app/ui/screen_text.h"
#include "tests/app/ui/view_lists.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

namespace vplab {
namespace {

namespace fs = std::filesystem;

struct PhoneSize {
  int width, height;  // device pixels: CSS px × 3
  const char* name;
};
// The page's UI scale on a phone: devicePixelRatio × the shorter CSS side / 440 (app/web/page.cpp pageScale).
constexpr float kRatio = 3, kScale = kRatio * 390.f / 440.f;
constexpr PhoneSize kPhones[] = {{1170, 2532, "upright"}, {2532, 1170, "on its side"}};

bool overlap(const ImVec4& a, const ImVec4& b) {
  return a.x < b.x + b.z && a.x + a.z > b.x && a.y < b.y + b.w && a.y + a.w > b.y;
}

class LessonOnAPhone : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(LessonOnAPhone, EveryStepIsReadWholeWithItsButtonsAFingersSize) {
  const auto& [file, phoneIndex] = GetParam();
  const PhoneSize phone = kPhones[phoneIndex];
  HeadlessViewer v{*test::egl().context, defaultScene(), phone.width, phone.height, kScale};
  v.state().compactAllowed = true;
  v.state().inBrowser = true;
  v.state().touch = true;
  v.state().cssPixel = kRatio;
  v.state().display.language = file.find(".de.") != std::string::npos ? Language::de : Language::en;
  v.frames(2);
  const fs::path path = fs::path(VPLAB_ASSETS) / "lessons" / file;
  v.viewer().session().openLesson(path, 0);
  v.frames(2);
  ASSERT_TRUE(v.state().lesson) << v.state().status;
  const size_t steps = v.state().lesson->stepCount();
  const std::string prefix = "phone-" + file.substr(0, file.size() - 5) + "-" + std::to_string(phone.width);
  for (size_t step = 0; step < steps; ++step) {
    const std::string where = file + " step " + std::to_string(step + 1) + " " + phone.name;
    v.viewer().session().openLesson(path, step);
    v.frames(3);
    ASSERT_EQ(v.state().lesson->step(), step);
    ASSERT_TRUE(v.rects().rects.count("switch.world")) << where << ": the phone got the desktop's layout";
    if (v.state().lesson->current().state.stepThrough) {
      EXPECT_EQ(v.state().compactView, ViewKind::npc) << where << ": a step through a polygon shows another view than the NPC view";
    }

    // The heading names the step, and it is on screen.
    const std::string stepOf = text::fill(v.state().lesson->lesson().language, "step {1} / {2}",
                                          {std::to_string(step + 1), std::to_string(steps)});
    const std::vector<test::ScreenLine> lines = test::screenText();
    EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [&](const test::ScreenLine& l) { return l.text.find(stepOf) != std::string::npos; }))
        << where << ": \"" << stepOf << "\" is not on screen\n" << test::screenTextDump(lines);

    // The buttons: whole, a finger's size, and the heading never under them.
    const auto& rects = v.rects().rects;
    const auto& shown = v.rects().visible;
    for (const char* id : {"lesson.back", "lesson.next", "lesson.close"}) {
      ASSERT_TRUE(rects.count(id)) << where << ": " << id << " was not drawn";
      EXPECT_GE(shown.at(id).z, rects.at(id).z - 1) << where << ": " << id << " is cut off at the side";
      EXPECT_GE(shown.at(id).w, rects.at(id).w - 1) << where << ": " << id << " is cut off below";
      EXPECT_GE(rects.at(id).w, ui::kTouchTargetPx * kRatio - 1) << where << ": " << id << " is too low for a finger";
      EXPECT_FALSE(overlap(rects.at("lesson.heading"), rects.at(id))) << where << ": the heading runs under " << id;
    }

    // Each label said once in the view shown (PRP and VRP were named twice on a tablet).
    for (ViewKind kind : v.viewer().images().asked()) {
      if (!v.viewer().images().lastRequest(kind)) continue;
      std::vector<std::string> texts;
      for (const PlacedLabel& l : test::listOf(v.viewer(), kind).labels())
        if (l.text.find_first_not_of("0123456789.−-") != std::string::npos) texts.push_back(l.text);  // not the axes' ticks
      std::sort(texts.begin(), texts.end());
      const auto twice = std::adjacent_find(texts.begin(), texts.end());
      EXPECT_TRUE(twice == texts.end()) << where << ": \"" << *twice << "\" twice in the " << toString(kind) << " view";
    }

    // The caption to its last line: whole in its box, or the box scrolls to its end.
    const ImVec4 text = rects.at("lesson.text"), textShown = shown.at("lesson.text");
    if (textShown.w < text.w - 1) {
      const ImGuiWindow* scrolled = nullptr;
      for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
        if (w->Active && std::string(w->Name).find("##lesson") != std::string::npos && w->ScrollMax.y > 0) scrolled = w;
      ASSERT_NE(scrolled, nullptr) << where << ": the caption is " << text.w << " px high, " << textShown.w
                                   << " px of it shown, and nothing scrolls it";
      EXPECT_GE(scrolled->ScrollMax.y + textShown.w, text.w - 1) << where << ": the caption cannot be scrolled to its end";
    }

    // Nothing cut off, every scrolled panel (the caption too) paged from top to bottom.
    const std::vector<std::string> problems = test::clippedTextOfEveryPage(v, prefix + "-step" + std::to_string(step + 1));
    EXPECT_TRUE(problems.empty()) << where << ":\n" << testing::PrintToString(problems);
    if (!problems.empty() || std::getenv("VPLAB_LESSON_SHOTS")) {
      fs::create_directories(test::outputDir() / "lesson-phone");
      writePng(v.image(), test::outputDir() / "lesson-phone" / (prefix + "-step" + std::to_string(step + 1) + ".png"));
    }
  }
}

/// The corners of the NPC cube outside the list's view (pixels), described.
std::string cornersOutside(const draw::DisplayList& list) {
  std::string outside;
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    const Projected p = projectToPixels(list.observer.camera, corner, list.width, list.height);
    if (!p.visible || p.pixel.x < 0 || p.pixel.y < 0 || p.pixel.x > list.width || p.pixel.y > list.height)
      outside += " (" + std::to_string(int(corner.x)) + ", " + std::to_string(int(corner.y)) + ", " + std::to_string(int(corner.z)) +
                 ") at (" + std::to_string(p.pixel.x) + ", " + std::to_string(p.pixel.y) + ")";
  }
  return outside;
}

// The NPC view on an upright phone shows the cube whole (its eight corners in the view), in a new
// document and in a lesson's step; on its side too; the user's own turn of the view is kept.
TEST(NpcViewOnAPhone, TheCubeIsWholeUprightAndOnItsSide) {
  for (const PhoneSize& phone : kPhones) {
    SCOPED_TRACE(phone.name);
    HeadlessViewer v{*test::egl().context, defaultScene(), phone.width, phone.height, kScale};
    v.state().compactAllowed = true;
    v.state().inBrowser = true;
    v.state().touch = true;
    v.state().cssPixel = kRatio;
    v.state().compactView = ViewKind::npc;
    v.frames(3);
    draw::DisplayList list = test::listOf(v.viewer(), ViewKind::npc);
    EXPECT_EQ(cornersOutside(list), "") << "the cube is cut off in a " << list.width << " × " << list.height << " view";
    v.viewer().session().openLesson(fs::path(VPLAB_ASSETS) / "lessons" / "03-view-mapping.en.json", 0);
    v.frames(3);
    ASSERT_TRUE(v.state().lesson) << v.state().status;
    v.state().compactView = ViewKind::npc;
    v.frames(2);
    list = test::listOf(v.viewer(), ViewKind::npc);
    EXPECT_EQ(cornersOutside(list), "") << "in the lesson the cube is cut off in a " << list.width << " × " << list.height << " view";
    if (phone.height > phone.width) writePng(v.image(), test::outputDir() / "phone-npc-upright.png");
  }
}

// The embed form on an upright phone (`#embed=camera,world&lesson=01-synthetic-camera&step=2`, the
// step about PRP): the page opens the lesson from the link before the views have a shape; the world
// view, a tall strip beside the camera view, is framed for its shape once it has one, so PRP and
// VRP are in it. The step and the document stay the lesson's.
TEST(EmbedOnAPhone, TheWorldViewFramesPrpAndVrpForItsShape) {
  HeadlessViewer v{*test::egl().context, defaultScene(), 1170, 2532, kScale};
  v.state().inBrowser = true;
  v.state().touch = true;
  v.state().cssPixel = kRatio;
  v.state().embedViews = {ViewKind::camera, ViewKind::world};
  v.viewer().session().openLesson(fs::path(VPLAB_ASSETS) / "lessons" / "01-synthetic-camera.en.json", 1);
  ASSERT_TRUE(v.state().lesson) << v.state().status;
  v.state().setStatus("zoom=\"2\": not a key of a link", true);  // what the link said, as the page shows it
  v.frames(6);
  ASSERT_TRUE(v.state().lesson);
  EXPECT_EQ(v.state().lesson->step(), 1u);
  EXPECT_FALSE(v.state().doc.dirty());
  EXPECT_EQ(v.state().status, "zoom=\"2\": not a key of a link") << "framing the lesson again took the link's note away";
  const ImVec4 view = v.rects().rects.at("view.world");
  EXPECT_LT(view.z, view.w / 2) << "the world view is not the tall strip this test is about";
  for (const char* id : {"handle.prp", "handle.vrp"}) {
    const auto [x, y] = v.centreOf(id);
    EXPECT_TRUE(x > view.x && x < view.x + view.z && y > view.y && y < view.y + view.w)
        << id << " at (" << x << ", " << y << ") outside the world view (" << view.x << ", " << view.y << ") "
        << view.z << " × " << view.w;
  }
  writePng(v.image(), test::outputDir() / "phone-embed-camera-world.png");
}

// A narrow phone (320 CSS px, the smallest still sold) with the UI scale raised by half (View ▸ UI
// scale, for larger text): "Schritt 10 / 11" does not fit beside the three buttons, so the heading
// takes its own line and the buttons share the row under it.
TEST(LessonOnANarrowPhone, TheHeadingTakesItsOwnLineAndTheButtonsShareTheRowUnderIt) {
  const float scale = 1.5f * kRatio * 320.f / 440.f;
  HeadlessViewer v{*test::egl().context, defaultScene(), 960, 1704, scale};
  v.state().compactAllowed = true;
  v.state().inBrowser = true;
  v.state().touch = true;
  v.state().cssPixel = kRatio;
  v.state().display.language = Language::de;
  v.frames(2);
  v.viewer().session().openLesson(fs::path(VPLAB_ASSETS) / "lessons" / "05-clipping.de.json", 9);
  v.frames(3);
  ASSERT_TRUE(v.state().lesson) << v.state().status;
  const auto& rects = v.rects().rects;
  const ImVec4 heading = rects.at("lesson.heading"), back = rects.at("lesson.back"), next = rects.at("lesson.next"),
               close = rects.at("lesson.close"), box = rects.at("lesson.caption");
  EXPECT_LE(heading.y + heading.w, back.y) << "the heading is not above the buttons";
  EXPECT_FLOAT_EQ(back.z, next.z);
  EXPECT_FLOAT_EQ(back.z, close.z);
  EXPECT_GE(back.z + next.z + close.z, 0.85f * box.z) << "the buttons do not share the row";
  EXPECT_EQ(back.y, close.y);
  const std::vector<test::ScreenLine> lines = test::screenText();
  EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [](const test::ScreenLine& l) { return l.text.find("Schritt 10 / 11") != std::string::npos; }))
      << test::screenTextDump(lines);
  const std::vector<std::string> problems = test::clippedTextOfEveryPage(v, "phone-narrow");
  EXPECT_TRUE(problems.empty()) << testing::PrintToString(problems);
  fs::create_directories(test::outputDir() / "lesson-phone");
  writePng(v.image(), test::outputDir() / "lesson-phone" / "phone-narrow-05-clipping.de-step10.png");
}

INSTANTIATE_TEST_SUITE_P(Bundled, LessonOnAPhone, ::testing::Combine(::testing::ValuesIn(test::bundledLessons()), ::testing::Values(0, 1)),
                         [](const auto& param) { return test::lessonTestName(std::get<0>(param.param)) + (std::get<1>(param.param) == 0 ? "_upright" : "_on_its_side"); });

}  // namespace
}  // namespace vplab
