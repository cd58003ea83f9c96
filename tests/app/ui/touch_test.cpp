// A finger is not a mouse pointer (issue 41, app/ui/touch.h): with the last pointer a finger, every
// field, tab, button and menu entry is at least a finger's 44 px tall (a CSS pixel is a pixel here:
// UI scale 1) and a handle is grabbed within a finger's radius of 20 px; a mouse keeps its compact
// targets and its 9 px reach, and the same press 15 px off a handle turns the view.
#include "app/inspect/picking.h"
#include "app/ui/headless_viewer.h"
#include "app/ui/touch.h"
#include "app/views/observer.h"
#include "app/views/view_camera.h"
#include "tests/app/ui/screen_text.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <cctype>
#include <cstring>
#include <memory>
#include <utility>
#include <regex>
#include <string>

namespace vplab {
namespace {

std::unique_ptr<HeadlessViewer> viewerWith(bool touch) {
  auto v = std::make_unique<HeadlessViewer>(*test::egl().context, defaultScene(), 1280, 720);
  v->state().touch = touch;
  v->frames(3);  // the style is set up again at the next frame, and ImGui lays out over two
  return v;
}

/// The recorded targets a finger taps: fields, tabs, the menu bar's and the menus' entries, the lesson's buttons.
bool isTarget(const std::string& id) {
  static const std::regex targets(R"(^(camera\.|tab\.|menu\.|lesson\.(back|next|close)$))");
  return std::regex_search(id, targets);
}

TEST(Touch, EveryTargetIsAFingersHeightAndAMouseKeepsItsCompactOnes) {
  auto finger = viewerWith(true);
  finger->click(finger->rects().rects.at("menu.file").x + 5, finger->rects().rects.at("menu.file").y + 5);
  finger->frames(2);  // File's entries recorded
  int measured = 0;
  for (const auto& [id, r] : finger->rects().rects) {
    if (!isTarget(id) || r.w <= 0) continue;
    ++measured;
    // Rounded to whole pixels by the style (setUpStyle rounds the padding up).
    EXPECT_GE(r.w, ui::kTouchTargetPx) << id << " is " << r.w << " px tall for a finger";
  }
  EXPECT_GE(measured, 15) << "too few targets recorded to say anything";
  EXPECT_TRUE(finger->rects().rects.count("menu.openExercise")) << "File's entries were not measured";

  auto mouse = viewerWith(false);
  EXPECT_LT(mouse->rects().rects.at("camera.prp").w, ui::kTouchTargetPx / 1.5f) << "a mouse's fields grew too";
  EXPECT_LT(mouse->rects().rects.at("menu.file").w, ui::kTouchTargetPx / 1.5f);
}

TEST(Touch, AFingerGrabsAHandle15PxOffItsCentreWhereAMouseTurnsTheView) {
  for (const bool touch : {true, false}) {
    SCOPED_TRACE(touch ? "a finger" : "a mouse");
    auto v = viewerWith(touch);
    const Camera before = v->state().doc.scene().camera;
    const Orbit orbitBefore = v->state().display.world.orbit;
    const ImVec4 handle = v->rects().rects.at("handle.prp");
    // The recorded rect is the reach: a finger's 2 × 20 px, a mouse's 2 × 9 px.
    EXPECT_FLOAT_EQ(handle.z, touch ? 2 * ui::kTouchRadiusPx : 2 * 9.f);
    const float x = handle.x + handle.z / 2 + 15, y = handle.y + handle.w / 2;
    v->drag(x, y, x, y - 40);
    v->frames(1);
    const Camera after = v->state().doc.scene().camera;
    if (touch) {
      EXPECT_NE(after.prp, before.prp) << "the finger missed PRP";
      EXPECT_EQ(after.vrp, before.vrp);
      EXPECT_EQ(v->state().display.world.orbit, orbitBefore) << "the view turned under the finger";
    } else {
      EXPECT_EQ(after, before) << "a mouse 15 px away grabbed PRP";
      EXPECT_NE(v->state().display.world.orbit, orbitBefore) << "the mouse's drag did not turn the view";
    }
  }
}

TEST(Touch, TheNearestHandleWinsWithinAFingersRadius) {
  auto v = viewerWith(true);
  const ImVec4 world = v->rects().rects.at("view.world");
  // Every handle's recorded centre picks that handle, even where a finger's radius reaches another.
  for (Handle h : kHandles) {
    std::string id = std::string("handle.") + handleName(h);
    for (char& c : id) c = c == ' ' ? '-' : char(std::tolower(static_cast<unsigned char>(c)));
    const auto it = v->rects().rects.find(id);
    if (it == v->rects().rects.end()) continue;
    const ImVec4 r = it->second;
    const int w = int(world.z), hgt = int(world.w);
    const ViewCamera observer = viewCameraOf(observerCamera(v->state().display.world.orbit, double(w) / hgt));
    EXPECT_EQ(pickHandle(v->state().run(), observer, w, hgt,
                         Vec2(r.x + r.z / 2 - world.x, r.y + r.w / 2 - world.y), ui::kTouchRadiusPx),
              h)
        << id;
  }
}

/// The Controls' tab, the region below the tabs that scrolls (a child of the window named
/// "###Controls", app/text/ui_menus.inc).
ImGuiWindow* controls() {
  const ImGuiWindow* panel = ImGui::FindWindowByName("###Controls");
  for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
    if (panel && w->ParentWindow == panel && w->Active && (w->Flags & ImGuiWindowFlags_ChildWindow)) return w;
  return nullptr;
}

/// A point at the tab's right edge, left of its scrollbar, halfway down: beyond the fields' labels
/// (text, which a press does not take), on no widget.
std::pair<float, float> inTheMargin() {
  const ImGuiWindow* w = controls();
  return {w->Pos.x + w->Size.x - w->ScrollbarSizes.x - 4, w->Pos.y + w->Size.y / 2};
}

// A swipe scrolls a panel and coasts on after the finger lifts (issue 41); a mouse's drag at the
// same place does nothing, and a drag that starts on a field still edits the field.
TEST(Touch, ASwipeScrollsAPanelAndItCoasts) {
  auto v = viewerWith(true);
  ASSERT_NE(controls(), nullptr);
  ASSERT_GT(controls()->ScrollMax.y, 100) << "the Controls fit: nothing to scroll";
  const Camera before = v->state().doc.scene().camera;
  const auto [x, y] = inTheMargin();
  v->drag(x, y, x, y - 120);  // 120 px in 8 frames of 1/60 s: a flick of 900 px/s
  const float afterSwipe = controls()->Scroll.y;
  EXPECT_GT(afterSwipe, 60) << "the panel did not follow the finger";
  v->frames(20);
  const float coasted = controls()->Scroll.y;
  EXPECT_GT(coasted, afterSwipe + 20) << "the panel stopped as the finger lifted";
  v->frames(60);
  const float stopped = controls()->Scroll.y;
  v->frames(10);
  EXPECT_EQ(controls()->Scroll.y, stopped) << "the coast never ends";
  EXPECT_EQ(v->state().doc.scene().camera, before) << "the swipe changed the camera";

  // A swipe back down the other way returns to the top (clamped, never beyond).
  v->drag(x, y, x, y + 600);
  v->frames(80);
  EXPECT_EQ(controls()->Scroll.y, 0.f);
  EXPECT_EQ(v->state().doc.scene().camera, before) << "the swipes changed the camera";

  // A drag that starts on PRP's field edits the field (a drag field follows the finger across),
  // though the finger also moves up; the panel stays.
  const ImVec4 prp = v->rects().rects.at("camera.prp");
  v->drag(prp.x + prp.z / 6, prp.y + prp.w / 2, prp.x + prp.z / 6 + 60, prp.y + prp.w / 2 - 60);
  v->frames(30);
  EXPECT_EQ(controls()->Scroll.y, 0.f) << "a drag on a field scrolled the panel";
  EXPECT_NE(v->state().doc.scene().camera.prp, before.prp) << "a drag on a field no longer edits it";

  auto mouse = viewerWith(false);
  const auto [mx, my] = inTheMargin();
  mouse->drag(mx, my, mx, my - 120);
  mouse->frames(20);
  EXPECT_EQ(controls()->Scroll.y, 0.f) << "a mouse's drag on text scrolled the panel";
}

// On a tablet (1024 × 768 at devicePixelRatio 2: UI scale 2, a finger's style) the camera panel's
// derived distances wrap: never inside one ("dmax =" at a line's end, "11.63" on the next).
TEST(Touch, OnATabletTheDerivedDistancesWrapBetweenThemNeverInsideOne) {
  auto v = std::make_unique<HeadlessViewer>(*test::egl().context, defaultScene(), 2048, 1536, 2.f);
  v->state().touch = true;
  v->state().cssPixel = 2;
  v->frames(3);
  ImGuiWindow* tab = controls();  // the camera tab, scrolled to its end, where the derived values are
  ASSERT_NE(tab, nullptr);
  ImGui::SetScrollY(tab, tab->ScrollMax.y);
  v->frames(2);
  const std::vector<test::ScreenLine> lines = test::screenText();
  int seen = 0;
  for (const char* name : {"VPD", "dmin", "dmax"})
    for (const test::ScreenLine& l : lines) {
      const size_t at = l.text.find(name);
      if (at == std::string::npos || l.text.find(" = ", at) != at + std::strlen(name)) continue;
      ++seen;
      EXPECT_TRUE(std::regex_search(l.text.substr(at), std::regex(R"(^\w+ = [0-9.−-]+)")))
          << name << "'s value is not on its line: \"" << l.text << "\"\n" << test::screenTextDump(lines);
    }
  EXPECT_EQ(seen, 3) << test::screenTextDump(lines);
}

}  // namespace
}  // namespace vplab
