// The viewer's logic without a display: HeadlessViewer (app/ui/headless_viewer.h) draws the whole
// window off-screen on the EGL context and takes synthetic mouse and keyboard input, so the tests
// use the viewer as a user does: through the recorded widget rects (ui::RectLog, app/ui/widgets.h), the views'
// own projections and the key codes of app/ui/keys.h. Each test checks the state the input must
// change and the pixels that must (and must not) change with it.
#include "app/ui/headless_viewer.h"
#include "app/ui/keys.h"
#include "app/inspect/picking.h"
#include "tests/support/gl_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>
#include <string>

namespace vplab {
namespace {

using ::testing::HasSubstr;

constexpr int kWidth = 1280, kHeight = 720;

/// A fresh viewer of the default scene, settled (ImGui lays out over the first two frames). One at a
/// time: each Viewer owns an ImGui context, and synthetic input goes to the current one.
std::unique_ptr<HeadlessViewer> makeViewer() {
  auto v = std::make_unique<HeadlessViewer>(*test::egl().context, defaultScene(), kWidth, kHeight);
  v->frames(3);
  return v;
}

struct PixelRect {
  int x = 0, y = 0, w = 0, h = 0;
};

PixelRect rectOf(HeadlessViewer& v, const std::string& id) {
  const auto& rects = v.rects().rects;
  const auto it = rects.find(id);
  EXPECT_NE(it, rects.end()) << "no widget " << id;
  if (it == rects.end()) return {};
  const ImVec4 r = it->second;
  return {int(std::lround(r.x)), int(std::lround(r.y)), int(r.z), int(r.w)};
}

/// The inside of an ImGui window, below its title bar (the inspector and the controls have no
/// recorded rect of their own; the title bar's colour shows which window has the focus, which a
/// click elsewhere changes).
PixelRect windowRect(const char* name) {
  // A window's id is its English name after "###", in either language (app/text/ui_menus.inc).
  const ImGuiWindow* w = ImGui::FindWindowByName(("###" + std::string(name)).c_str());
  EXPECT_NE(w, nullptr) << name;
  if (!w) return {};
  const float title = w->TitleBarHeight();
  return {int(w->Pos.x), int(w->Pos.y + title), int(w->Size.x), int(w->Size.y - title)};
}

Image region(HeadlessViewer& v, const PixelRect& r) { return test::crop(v.image(), r.x, r.y, r.w, r.h); }

/// Whether two pictures of a region differ in a noticeable share of their pixels (a changed view, not
/// a blinking pixel).
bool differsNoticeably(const Image& a, const Image& b, double share = 0.01) {
  return double(test::differingPixels(a, b)) > share * double(a.pixels.size());
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const Vec4& v) { return finite(Vec3(v)) && std::isfinite(v.w); }
bool finite(const Mat4& m) {
  for (int c = 0; c < 4; ++c)
    if (!finite(m[c])) return false;
  return true;
}

/// No NaN or infinity anywhere the views or panels read from.
void expectRunFinite(const PipelineRun& run) {
  EXPECT_TRUE(finite(run.vrcFromWc));
  EXPECT_TRUE(finite(run.npcFromVrc));
  EXPECT_TRUE(finite(run.dcFromNpc));
  EXPECT_TRUE(finite(run.npcFromWc));
  EXPECT_TRUE(finite(run.vrc.u) && finite(run.vrc.v) && finite(run.vrc.n));
  EXPECT_TRUE(std::isfinite(run.vrc.vpd) && std::isfinite(run.vrc.dmin) && std::isfinite(run.vrc.dmax));
  size_t values = 0, bad = 0;
  for (const ObjectRun& o : run.objects) {
    for (uint32_t v = 0; v < o.vertexCount(); ++v) bad += !finite(o.wc(v)) + !finite(o.vrc(v)), values += 2;
    for (const Vec4& p : o.npcH) bad += !finite(p), ++values;
    for (const Vec4& p : o.createdNpcH) bad += !finite(p), ++values;
    for (size_t f = 0; f < o.faceCount(); ++f)
      for (uint32_t ref : o.clippedFace(f)) bad += !finite(o.clippedDc(ref)), ++values;
  }
  EXPECT_GT(values, 100u);
  EXPECT_EQ(bad, 0u) << "non-finite values in the run";
}

/// Pixels of the colour ui::errorText draws with (ImVec4(1, 0.38, 0.35) → 255, 97, 89), blended
/// with the dark panel by the glyphs' antialiasing: clearly red, nothing else in the panels is.
size_t errorTextPixels(const Image& image) {
  size_t n = 0;
  for (const Rgba& p : image.pixels) n += p.r >= 110 && p.r > 2 * p.g && p.r > 2 * p.b;
  return n;
}

/// Where a vertex of the run is drawn in the camera view's rect (the device's DC scaled to fit).
std::pair<double, double> screenOfDc(HeadlessViewer& v, const Vec3& dc) {
  const ImVec4 r = v.rects().rects.at("view.camera");
  const Device& d = v.state().run().device;
  return {r.x + dc.x * r.z / d.width, r.y + dc.y * r.w / d.height};
}

/// Vertices of the run that lie well inside the camera view with no other vertex within `gap`
/// pixels on screen, so a click on one picks it and nothing else.
std::vector<Probe> isolatedVertices(HeadlessViewer& v, double gap) {
  const PipelineRun& run = v.state().run();
  const ImVec4 r = v.rects().rects.at("view.camera");
  std::vector<std::pair<Probe, std::pair<double, double>>> all;
  for (size_t k = 0; k < run.objects.size(); ++k) {
    for (uint32_t i = 0; i < run.objects[k].vertexCount(); ++i) {
      const Probe p{run.sceneIndex[k], i};
      if (const auto dc = probePosition(run, p, ViewKind::camera)) all.push_back({p, screenOfDc(v, *dc)});
    }
  }
  std::vector<Probe> out;
  for (const auto& [probe, s] : all) {
    if (s.first < r.x + 20 || s.first > r.x + r.z - 20 || s.second < r.y + 20 || s.second > r.y + r.w - 20) continue;
    bool alone = true;
    for (const auto& [other, t] : all)
      if (!(other == probe) && std::hypot(s.first - t.first, s.second - t.second) < gap) alone = false;
    if (alone) out.push_back(probe);
  }
  return out;
}

/// The world view's observer as the viewer uses it for picking and dragging (its rect's size).
ViewCamera worldObserver(HeadlessViewer& v, int* w, int* h) {
  const ImVec4 r = v.rects().rects.at("view.world");
  *w = int(r.z);
  *h = int(r.w);
  return viewCameraOf(observerCamera(v.state().display.world.orbit, double(*w) / *h));
}

/// A WC point's position in the window, seen through the world view's observer.
std::pair<double, double> screenInWorldView(HeadlessViewer& v, const Vec3& wc) {
  int w = 0, h = 0;
  const ViewCamera observer = worldObserver(v, &w, &h);
  const Projected p = projectToPixels(observer, wc, w, h);
  EXPECT_TRUE(p.visible);
  const ImVec4 r = v.rects().rects.at("view.world");
  return {r.x + p.pixel.x, r.y + p.pixel.y};
}

// ---------------------------------------------------------------- the camera panel

TEST(Ui, WidgetsAndViewsAreRecorded) {
  auto v = makeViewer();
  for (const char* id : {"camera.vrp", "camera.prp", "camera.vup", "camera.xmin", "camera.front", "view.world",
                         "view.camera", "view.npc"}) {
    const PixelRect r = rectOf(*v, id);
    EXPECT_GT(r.w, 10) << id;
    EXPECT_GT(r.h, 10) << id;
    EXPECT_GE(r.x, 0) << id;
    EXPECT_LE(r.x + r.w, kWidth) << id;
    EXPECT_LE(r.y + r.h, kHeight) << id;
  }
  // The camera view keeps the device's aspect ratio (4 : 3), within a pixel.
  const ImVec4 c = v->rects().rects.at("view.camera");
  EXPECT_NEAR(c.z / c.w, defaultScene().device.aspect(), 4.0 / c.w);
}

// Dragging the VRP's x field to the right moves VRP along x (ImGui: 0.02 per pixel once the drag
// passes its threshold of a few pixels), and both the camera and world views change; one drag is
// one undo step.
TEST(Ui, DraggingTheVrpFieldMovesVrpAndChangesTheViews) {
  auto v = makeViewer();
  const Vec3 before = v->state().doc.scene().camera.vrp;
  const Image cameraBefore = region(*v, rectOf(*v, "view.camera"));
  const Image worldBefore = region(*v, rectOf(*v, "view.world"));
  const ImVec4 r = v->rects().rects.at("camera.vrp");
  const double x = r.x + 20, y = r.y + r.w / 2;  // inside the first (x) of the three fields
  v->drag(x, y, x + 50, y);
  v->frames(2);

  const Vec3 after = v->state().doc.scene().camera.vrp;
  // 50 pixels at 0.02 each, less the few pixels ImGui's drag threshold swallows.
  EXPECT_GT(after.x - before.x, 0.8);
  EXPECT_LE(after.x - before.x, 1.0 + 1e-9);
  EXPECT_EQ(after.y, before.y);
  EXPECT_EQ(after.z, before.z);
  EXPECT_EQ(v->state().run().camera.vrp, after) << "the views use the new camera";
  EXPECT_TRUE(v->state().doc.error().empty());
  EXPECT_TRUE(differsNoticeably(region(*v, rectOf(*v, "view.camera")), cameraBefore));
  EXPECT_TRUE(differsNoticeably(region(*v, rectOf(*v, "view.world")), worldBefore));

  v->key(keys::kZ, /*ctrl=*/true);
  EXPECT_EQ(v->state().doc.scene().camera.vrp, before) << "the whole drag is one undo step";
  EXPECT_FALSE(v->state().doc.canUndo());
}

// ---------------------------------------------------------------- the vertex probe

TEST(Ui, ClickingAVertexInTheCameraViewProbesIt) {
  auto v = makeViewer();
  const std::vector<Probe> candidates = isolatedVertices(*v, 15);
  ASSERT_GE(candidates.size(), 2u) << "no isolated vertices to click in the camera view";
  const Image inspectEmpty = region(*v, windowRect("Inspect"));
  const Image cameraBefore = region(*v, rectOf(*v, "view.camera"));
  ASSERT_FALSE(v->state().probe);

  const Probe first = candidates.front();
  const Vec3 dc = *probePosition(v->state().run(), first, ViewKind::camera);
  const auto [x, y] = screenOfDc(*v, dc);
  v->click(x, y);
  v->frames(1);
  ASSERT_TRUE(v->state().probe) << "nothing picked at " << x << ", " << y;
  EXPECT_EQ(*v->state().probe, first);
  // Every view marks it: its position in DC, WC and NPC.
  const Highlights& hl = v->state().highlights;
  ASSERT_TRUE(hl.probeDc && hl.probeWc && hl.probeNpc);
  EXPECT_EQ(*hl.probeDc, dc);
  // The probe panel (the inspector's first tab) shows it instead of its hint, and the camera view
  // shows its mark.
  const Image inspectFirst = region(*v, windowRect("Inspect"));
  EXPECT_TRUE(differsNoticeably(inspectFirst, inspectEmpty, 0.02));
  EXPECT_GT(test::differingPixels(region(*v, rectOf(*v, "view.camera")), cameraBefore), 50u);

  // Another vertex: the panel shows other numbers.
  const Probe second = candidates.back();
  const auto [x2, y2] = screenOfDc(*v, *probePosition(v->state().run(), second, ViewKind::camera));
  v->click(x2, y2);
  v->frames(1);
  ASSERT_TRUE(v->state().probe);
  EXPECT_EQ(*v->state().probe, second);
  EXPECT_GT(test::differingPixels(region(*v, windowRect("Inspect")), inspectFirst), 100u);

  // Esc clears the probe: the panel and the camera view are as before.
  v->key(keys::kEscape);
  EXPECT_FALSE(v->state().probe);
  EXPECT_EQ(test::differingPixels(region(*v, windowRect("Inspect")), inspectEmpty), 0u);
  EXPECT_EQ(test::differingPixels(region(*v, rectOf(*v, "view.camera")), cameraBefore), 0u);
}

TEST(Ui, ClickingEmptySpaceProbesNothing) {
  auto v = makeViewer();
  // The camera view's top-left corner (background, no vertex within the pick radius there).
  const ImVec4 r = v->rects().rects.at("view.camera");
  for (const Probe& p : isolatedVertices(*v, 0)) {
    const auto [sx, sy] = screenOfDc(*v, *probePosition(v->state().run(), p, ViewKind::camera));
    ASSERT_GT(std::hypot(sx - (r.x + 3), sy - (r.y + 3)), 20) << "a vertex near the corner";
  }
  v->click(r.x + 3, r.y + 3);
  EXPECT_FALSE(v->state().probe);
}

// ---------------------------------------------------------------- handles, undo and redo

// The PRP handle in the world view follows the mouse (it moves parallel to the observer's view
// plane), Ctrl+Z restores PRP exactly, Ctrl+Shift+Z and Ctrl+Y bring the change back.
TEST(Ui, DraggingThePrpHandleChangesPrpAndUndoRedoWork) {
  auto v = makeViewer();
  const Camera original = v->state().doc.scene().camera;
  const Image worldBefore = region(*v, rectOf(*v, "view.world"));
  const Image cameraBefore = region(*v, rectOf(*v, "view.camera"));
  const auto [x, y] = screenInWorldView(*v, handlePosition(v->state().run(), Handle::prp));
  {
    int w = 0, h = 0;
    const ViewCamera observer = worldObserver(*v, &w, &h);
    const ImVec4 r = v->rects().rects.at("view.world");
    ASSERT_EQ(pickHandle(v->state().run(), observer, w, h, Vec2(x - r.x, y - r.y), 12), Handle::prp);
  }
  {  // The browser tests grab the handle at its recorded rect (ui::RectLog "handle.prp").
    const ImVec4 r = v->rects().rects.at("handle.prp");
    EXPECT_NEAR(r.x + r.z / 2, x, 1e-3);
    EXPECT_NEAR(r.y + r.w / 2, y, 1e-3);
    EXPECT_TRUE(v->rects().rects.count("handle.vrp") && v->rects().rects.count("handle.xmin"));
  }
  const double dx = 40, dy = 25;
  v->drag(x, y, x + dx, y + dy);
  v->frames(1);

  const Camera dragged = v->state().doc.scene().camera;
  EXPECT_NE(dragged.prp, original.prp);
  EXPECT_EQ(dragged.vrp, original.vrp);
  EXPECT_EQ(dragged.vup, original.vup);
  EXPECT_EQ(dragged.window, original.window);
  // The handle is where the mouse let go of it, within a pixel.
  const auto [hx, hy] = screenInWorldView(*v, dragged.prp);
  EXPECT_NEAR(hx, x + dx, 1.0);
  EXPECT_NEAR(hy, y + dy, 1.0);
  EXPECT_EQ(v->state().run().camera.prp, dragged.prp);
  EXPECT_TRUE(differsNoticeably(region(*v, rectOf(*v, "view.world")), worldBefore));
  EXPECT_TRUE(differsNoticeably(region(*v, rectOf(*v, "view.camera")), cameraBefore));
  ASSERT_TRUE(v->state().doc.canUndo());

  v->key(keys::kZ, /*ctrl=*/true);
  EXPECT_EQ(v->state().doc.scene().camera, original);
  EXPECT_EQ(v->state().run().camera, original);
  EXPECT_FALSE(v->state().doc.canUndo()) << "the drag was one step";
  EXPECT_TRUE(v->state().doc.canRedo());
  EXPECT_EQ(test::differingPixels(region(*v, rectOf(*v, "view.camera")), cameraBefore), 0u);

  v->key(keys::kZ, /*ctrl=*/true, /*shift=*/true);
  EXPECT_EQ(v->state().doc.scene().camera, dragged);
  EXPECT_EQ(v->state().run().camera, dragged);
  v->key(keys::kZ, true);
  EXPECT_EQ(v->state().doc.scene().camera, original);
  v->key(keys::kY, true);
  EXPECT_EQ(v->state().doc.scene().camera, dragged);
  EXPECT_FALSE(v->state().doc.canRedo());
}

// ---------------------------------------------------------------- invalid cameras

/// The upper half of a view: the note of an invalid camera lies across its bottom.
Image upperHalf(HeadlessViewer& v, const char* id) {
  PixelRect r = rectOf(v, id);
  r.h /= 2;
  return region(v, r);
}
/// The lower half of a view, where the note of an invalid camera is.
Image lowerHalf(HeadlessViewer& v, const char* id) {
  PixelRect r = rectOf(v, id);
  r.y += r.h / 2;
  r.h -= r.h / 2;
  return region(v, r);
}

/// Pixels of the error colour in a field's frame: bands 3 pixels wide along the inside of its left
/// and right sides (the fields are stacked, so a neighbour's frame never reaches its sides).
size_t frameErrorPixels(HeadlessViewer& v, const char* id) {
  const PixelRect r = rectOf(v, id);
  const Image left = test::crop(v.image(), r.x, r.y, 3, r.h);
  const Image right = test::crop(v.image(), r.x + r.w - 3, r.y, 3, r.h);
  return errorTextPixels(left) + errorTextPixels(right);
}

// PRP = VRP (set through the document, as a preset or a script might): the camera panel shows the
// error in red and frames PRP and VRP, each view keeps showing the last valid camera and says so
// across its bottom (issue 37 item 2: seen where people look), nothing in the run is NaN.
TEST(Ui, PrpOnVrpShowsAnErrorAndKeepsTheLastValidCamera) {
  auto v = makeViewer();
  const Camera valid = v->state().doc.scene().camera;
  const PixelRect controls = windowRect("Controls");
  ASSERT_EQ(errorTextPixels(region(*v, controls)), 0u);
  const Image cameraBefore = upperHalf(*v, "view.camera");
  const Image worldBefore = upperHalf(*v, "view.world");
  const size_t worldRedBefore = errorTextPixels(lowerHalf(*v, "view.world"));
  const size_t npcRedBefore = errorTextPixels(lowerHalf(*v, "view.npc"));
  EXPECT_EQ(frameErrorPixels(*v, "camera.prp"), 0u);

  v->state().doc.scene().camera.prp = valid.vrp;
  v->frames(2);
  EXPECT_THAT(v->state().doc.error(), HasSubstr("PRP"));
  EXPECT_THAT(v->state().doc.error(), HasSubstr("VRP"));
  EXPECT_GT(errorTextPixels(region(*v, controls)), 30u) << "no error text in the camera panel";
  EXPECT_GT(frameErrorPixels(*v, "camera.prp"), 20u) << "PRP is not framed";
  EXPECT_GT(frameErrorPixels(*v, "camera.vrp"), 20u) << "VRP is not framed";
  EXPECT_EQ(frameErrorPixels(*v, "camera.vup"), 0u) << "VUP is not at fault";
  EXPECT_EQ(v->state().doc.shown().camera, valid);
  EXPECT_EQ(v->state().run().camera, valid);
  expectRunFinite(v->state().run());
  EXPECT_EQ(test::differingPixels(upperHalf(*v, "view.camera"), cameraBefore), 0u);
  EXPECT_EQ(test::differingPixels(upperHalf(*v, "view.world"), worldBefore), 0u);
  EXPECT_GT(errorTextPixels(lowerHalf(*v, "view.camera")), 60u) << "the camera view does not say it";
  EXPECT_GT(errorTextPixels(lowerHalf(*v, "view.world")), worldRedBefore + 60) << "the world view does not say it";
  EXPECT_GT(errorTextPixels(lowerHalf(*v, "view.npc")), npcRedBefore + 60) << "the NPC view does not say it";

  // Valid again: the error, the frames and the notes go.
  v->state().doc.scene().camera.prp = valid.prp;
  v->frames(2);
  EXPECT_TRUE(v->state().doc.error().empty());
  EXPECT_EQ(errorTextPixels(region(*v, controls)), 0u);
  EXPECT_EQ(frameErrorPixels(*v, "camera.prp"), 0u);
  EXPECT_EQ(errorTextPixels(lowerHalf(*v, "view.world")), worldRedBefore);
}

/// Types `text` into field `field` (0, 1, 2) of a three-field drag widget: Ctrl+click turns an ImGui
/// drag field into a text field with its text selected, typed characters replace it (ImGui applies
/// them as they are typed). With `finish`, a click on empty space in the controls ends the edit.
void typeInto(HeadlessViewer& v, const char* id, const char* label, int field, const char* text, bool finish) {
  const ImVec4 r = v.rects().rects.at(id);
  const ImGuiStyle& style = ImGui::GetStyle();
  const float fields = r.z - ImGui::CalcTextSize(label).x - style.ItemInnerSpacing.x;  // the label is on the right
  const double x = r.x + fields * (field + 0.5) / 3, y = r.y + r.w / 2;
  ImGui::GetIO().KeyCtrl = true;
  v.click(x, y);
  ImGui::GetIO().KeyCtrl = false;
  ImGui::GetIO().AddInputCharactersUTF8(text);
  v.frames(2);
  if (finish) {
    const PixelRect controls = windowRect("Controls");  // its bottom is empty
    v.click(controls.x + 20, controls.y + controls.h - 20);
  }
}

// VUP typed parallel to N, field by field: the intermediate VUPs are valid and shown; the last one
// is not: the error names it, the views keep the last valid camera, no NaN. Undo makes it valid.
TEST(Ui, TypingVupParallelToNShowsAnErrorAndKeepsTheLastValidCamera) {
  auto v = makeViewer();
  const Camera start = v->state().doc.scene().camera;
  const Vec3 n = start.prp - start.vrp;  // (3, 2.4, 7.5) in the default scene
  ASSERT_EQ(n, Vec3(3, 2.4, 7.5));
  const PixelRect controls = windowRect("Controls");

  typeInto(*v, "camera.vup", "VUP", 0, "3", true);
  typeInto(*v, "camera.vup", "VUP", 1, "2.4", true);
  EXPECT_EQ(v->state().doc.scene().camera.vup, Vec3(3, 2.4, 0));
  EXPECT_TRUE(v->state().doc.error().empty()) << v->state().doc.error();
  const Camera lastValid = v->state().doc.scene().camera;
  EXPECT_EQ(v->state().run().camera, lastValid);
  const Image cameraValid = upperHalf(*v, "view.camera");

  typeInto(*v, "camera.vup", "VUP", 2, "7.5", true);
  EXPECT_EQ(v->state().doc.scene().camera.vup, n);
  EXPECT_THAT(v->state().doc.error(), HasSubstr("VUP"));
  EXPECT_THAT(v->state().doc.error(), HasSubstr("parallel"));
  EXPECT_GT(errorTextPixels(region(*v, controls)), 30u) << "no error text in the camera panel";
  EXPECT_EQ(v->state().run().camera, lastValid);
  expectRunFinite(v->state().run());
  EXPECT_EQ(test::differingPixels(upperHalf(*v, "view.camera"), cameraValid), 0u);
  EXPECT_GT(frameErrorPixels(*v, "camera.vup"), 20u) << "VUP is not framed";

  v->key(keys::kZ, true);  // each finished field edit is one step
  EXPECT_EQ(v->state().doc.scene().camera.vup, lastValid.vup);
  EXPECT_TRUE(v->state().doc.error().empty());
  EXPECT_EQ(errorTextPixels(region(*v, controls)), 0u);
  v->key(keys::kZ, true);
  EXPECT_EQ(v->state().doc.scene().camera.vup, Vec3(3, 1, 0));
  v->key(keys::kZ, true);
  EXPECT_EQ(v->state().doc.scene().camera.vup, start.vup);
}

// Going straight from one field into the next keeps an item active in every frame; the change of the
// active item still ends one undo step and begins the next.
TEST(Ui, EditingTwoFieldsInARowGivesTwoUndoSteps) {
  auto v = makeViewer();
  typeInto(*v, "camera.vup", "VUP", 0, "3", false);
  typeInto(*v, "camera.vup", "VUP", 1, "2", true);
  ASSERT_EQ(v->state().doc.scene().camera.vup, Vec3(3, 2, 0));
  v->key(keys::kZ, true);
  EXPECT_EQ(v->state().doc.scene().camera.vup, Vec3(3, 1, 0)) << "undo skipped the first edit";
}

// Two viewers in one process: each has its own ImGui context (ImGui 1.86's CreateContext makes a
// new context current only when none is) and input goes to the viewer it is fed to.
TEST(Ui, TwoViewersCoexist) {
  HeadlessViewer a(*test::egl().context, defaultScene(), 640, 360);
  a.frames(3);
  HeadlessViewer b(*test::egl().context, defaultScene(), 640, 360);
  b.frames(3);
  a.frames(1);
  EXPECT_EQ(test::differingPixels(a.image(), b.image()), 0u) << "the same scene at the same size";
  // Input to b changes b only.
  const ImVec4 r = b.rects().rects.at("view.world");
  const double x = r.x + 30, y = r.y + r.w - 30;  // the bottom-left corner: no handle there
  b.drag(x, y, x + 60, y);
  a.frames(1);
  EXPECT_NE(b.state().display.world.orbit.yawDeg, a.state().display.world.orbit.yawDeg);
}

// ---------------------------------------------------------------- the observer

// Left-dragging the world view away from the handles orbits its observer (0.4° of yaw per pixel):
// the world view changes, the scene camera and its view do not, and nothing is recorded for undo.
TEST(Ui, OrbitingTheWorldViewChangesTheObserverOnly) {
  auto v = makeViewer();
  const Orbit before = v->state().display.world.orbit;
  const Camera camera = v->state().doc.scene().camera;
  const Image worldBefore = region(*v, rectOf(*v, "view.world"));
  const Image cameraBefore = region(*v, rectOf(*v, "view.camera"));
  const ImVec4 r = v->rects().rects.at("view.world");
  const double x = r.x + 30, y = r.y + r.w - 30;  // the bottom-left corner: no handle there
  {
    int w = 0, h = 0;
    const ViewCamera observer = worldObserver(*v, &w, &h);
    ASSERT_EQ(pickHandle(v->state().run(), observer, w, h, Vec2(30, r.w - 30), 12), Handle::none);
  }
  v->drag(x, y, x + 60, y);
  v->frames(1);

  const Orbit after = v->state().display.world.orbit;
  EXPECT_NEAR(std::remainder(before.yawDeg - after.yawDeg, 360.0), 60 * 0.4, 1e-6);
  EXPECT_EQ(after.pitchDeg, before.pitchDeg);
  EXPECT_EQ(after.distance, before.distance);
  EXPECT_EQ(v->state().doc.scene().camera, camera);
  EXPECT_FALSE(v->state().doc.canUndo());
  EXPECT_FALSE(v->state().probe) << "a drag is not a click";
  EXPECT_TRUE(differsNoticeably(region(*v, rectOf(*v, "view.world")), worldBefore, 0.05));
  EXPECT_EQ(test::differingPixels(region(*v, rectOf(*v, "view.camera")), cameraBefore), 0u);

  // The wheel zooms the same observer.
  v->mouseMove(x, y);
  v->wheel(2);
  v->frames(2);
  EXPECT_NEAR(v->state().display.world.orbit.distance, after.distance * 0.88 * 0.88, 1e-9);
}

// The style keys 1 … 5 set every view's style; the camera view's pixels change with it.
TEST(Ui, StyleKeysSetEveryView) {
  auto v = makeViewer();
  const Image shaded = region(*v, rectOf(*v, "view.camera"));
  v->key(keys::kDigit1 + 2);  // 3: wire
  EXPECT_EQ(v->state().display.camera.style, Style::wire);
  EXPECT_EQ(v->state().display.world.style, Style::wire);
  EXPECT_EQ(v->state().display.npc.style, Style::wire);
  EXPECT_TRUE(differsNoticeably(region(*v, rectOf(*v, "view.camera")), shaded, 0.1));
  v->key(keys::kDigit1 + 1);  // 2: shaded, as the viewer starts
  EXPECT_EQ(test::differingPixels(region(*v, rectOf(*v, "view.camera")), shaded), 0u);
}

}  // namespace
}  // namespace vplab

namespace vplab {
namespace {

// A touch lands far from where the last one lifted: the frame of the press holds that jump in
// ImGui's MouseDelta, which must not turn the observer (only the motion after the press does).
TEST(Ui, APressFarFromTheLastPointerPositionDoesNotTurnTheWorldView) {
  auto v = makeViewer();
  const PixelRect r = rectOf(*v, "view.world");
  const double x0 = r.x + r.w * 0.2, y0 = r.y + r.h * 0.85, x1 = r.x + r.w * 0.8, y1 = r.y + r.h * 0.15;
  v->mouseMove(x0, y0);
  v->frames(2);
  const Orbit before = v->state().display.world.orbit;
  v->mouseMove(x1, y1);  // the jump and the press in one frame, as a touch arrives
  v->mouseButton(0, true);
  v->frame();
  EXPECT_EQ(v->state().display.world.orbit, before);
  v->mouseMove(x1 + 10, y1);
  v->frame();
  v->mouseButton(0, false);
  v->frame();
  EXPECT_NEAR(v->state().display.world.orbit.yawDeg, before.yawDeg - 4, 1e-9) << "10 px at 0.4 degrees per pixel";
  EXPECT_EQ(v->state().display.world.orbit.pitchDeg, before.pitchDeg);
}

}  // namespace
}  // namespace vplab
