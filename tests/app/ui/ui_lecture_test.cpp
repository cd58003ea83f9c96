// The viewer as a lecture uses it (issue 11): what the panels show is right side up, says what the
// geometry says, applies typed values once, and reads on a projector. Drives the headless viewer
// (app/ui/headless_viewer.h) with synthetic input, like ui_test.cpp.
#include "app/views/image.h"
#include "app/export/cpu_raster.h"
#include "app/ui/headless_viewer.h"
#include "app/ui/text_fit.h"
#include "app/ui/keys.h"
#include "tests/app/ui/cut_off.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>

#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace vplab {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

std::unique_ptr<HeadlessViewer> makeViewer(Scene scene = defaultScene(), float scale = 1.f) {
  auto v = std::make_unique<HeadlessViewer>(*test::egl().context, std::move(scene), kWidth, kHeight, scale);
  v->frames(3);
  return v;
}

Image cropRect(const Image& image, const ImVec4& r) {
  return test::crop(image, int(std::lround(r.x)), int(std::lround(r.y)), int(r.z), int(r.w));
}

/// `image` resampled (nearest pixel) to width × height, upside down when `flip`.
Image resampled(const Image& image, int width, int height, bool flip) {
  Image out(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int sx = std::min(image.width - 1, int((x + 0.5) * image.width / width));
      int sy = std::min(image.height - 1, int((y + 0.5) * image.height / height));
      if (flip) sy = image.height - 1 - sy;
      out.at(x, y) = image.at(sx, sy);
    }
  return out;
}

/// The mean absolute difference of two images of the same size, per channel (0 … 255).
double meanDifference(const Image& a, const Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  double sum = 0;
  for (size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i)
    sum += std::abs(a.pixels[i].r - b.pixels[i].r) + std::abs(a.pixels[i].g - b.pixels[i].g) +
           std::abs(a.pixels[i].b - b.pixels[i].b);
  return sum / (3.0 * double(a.pixels.size()));
}

// ---------------------------------------------------------------- item 1: the divide-first comparison

// The "wrong" picture beside the camera view is the CPU's divide-first polygons as they are: the
// panel (divideFirstView's display list drawn by the GL backend) matches the independent CPU raster
// of them (cpu_raster) upright and not upside down. Tolerance: a mean difference below 12 levels
// per channel from the panel's scaling (linear filtering) and the caption over it; measured 5.9
// upright (the same as when the panel showed the raster itself), 35.7 flipped.
TEST(UiLecture, DivideFirstComparisonIsUpright) {
  auto v = makeViewer();
  v->key(keys::kC);
  v->key(keys::kC);
  ASSERT_EQ(v->state().pipeline.strategy, ClipStrategy::divideFirst);
  v->frames(2);
  const ImVec4 r = v->rects().rects.at("view.divideFirst");
  const Image shown = cropRect(v->image(), r);
  const Device& d = v->state().doc.shown().device;
  const Image cpu = rasterizeClippedPolygons(v->state().run(), v->state().doc.shown().background, d.width, d.height);
  const double upright = meanDifference(shown, resampled(cpu, shown.width, shown.height, false));
  const double flipped = meanDifference(shown, resampled(cpu, shown.width, shown.height, true));
  EXPECT_LT(upright, 12.0);
  EXPECT_LT(upright * 3, flipped) << "upright " << upright << ", flipped " << flipped;
}

// ---------------------------------------------------------------- item 5: `vplab render --view ui`

// The command line's ui view with --strategy divide-first is the viewer after the user chose that
// strategy (key C twice): the same pixels, the comparison included.
TEST(UiLecture, RenderUiShowsWhatTheViewerShowsForTheSameOptions) {
  const std::filesystem::path out = test::outputDir() / "render-ui-divide-first.png";
  const std::string command = std::string(VPLAB_EXE) + " render --view ui --strategy divide-first --out " + out.string();
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Image cli = readPng(out);
  auto v = makeViewer();
  const Image before = v->image();
  v->key(keys::kC);
  v->key(keys::kC);
  v->frames(3);
  const Image viewer = v->image();
  ASSERT_EQ(cli.width, viewer.width);
  EXPECT_GT(test::differingPixels(before, viewer), 1000u) << "the strategy changes the window";
  EXPECT_LT(meanDifference(cli, viewer), 0.5);
}

}  // namespace
}  // namespace vplab

namespace vplab {
namespace {

// ---------------------------------------------------------------- item 6: nothing cut off

/// The world view's labels (TextRenderer's placed rectangles) that overlap another.
int overlappingLabels(const std::vector<glm::vec4>& r) {
  int n = 0;
  for (size_t i = 0; i < r.size(); ++i)
    for (size_t j = i + 1; j < r.size(); ++j)
      n += r[i].x < r[j].z && r[j].x < r[i].z && r[i].y < r[j].w && r[j].y < r[i].w;
  return n;
}

struct Shown {
  const char* what;
  std::function<void(HeadlessViewer&)> show;
};

// Every panel and tab at 1280 × 720 and UI scale 1, 1.6 and 2, in English and in German: no text
// cut off at the side of its window, column or child window, no name shortened with "…". The
// pictures are left in the test output directory to look at.
TEST(UiLecture, NoTextIsCutOffAtAnyScale) {
  auto clickTab = [](HeadlessViewer& v, const std::string& id) {
    const auto [x, y] = v.centreOf(id);
    v.click(x, y);
    v.frames(2);
  };
  std::vector<Shown> shown;
  for (const char* tab : {"Camera", "Scene", "Clipping", "Display", "Lecture"})
    shown.push_back({tab, [=](HeadlessViewer& v) { clickTab(v, std::string("tab.controls.") + tab); }});
  for (const char* tab : {"Vertex probe", "Matrices", "Depth"})
    shown.push_back({tab, [=](HeadlessViewer& v) { clickTab(v, std::string("tab.inspect.") + tab); }});
  shown.push_back({"oblique camera", [&](HeadlessViewer& v) {
                     clickTab(v, "tab.controls.Camera");
                     v.state().doc.scene().camera.projection = Projection::oblique;
                     v.frames(2);
                   }});
  shown.push_back({"probe and step-through", [&](HeadlessViewer& v) {
                     v.state().probe = Probe{0, 0};
                     v.state().stepThrough = {true, 2, 0, 3};
                     v.state().display.overlays.vanishingPoints = true;
                     v.frames(2);
                     clickTab(v, "tab.controls.Lecture");
                   }});
  shown.push_back({"divide first", [&](HeadlessViewer& v) {
                     v.state().pipeline.strategy = ClipStrategy::divideFirst;
                     v.frames(2);
                   }});
  shown.push_back({"help", [&](HeadlessViewer& v) { v.key(keys::kF1); }});
  // German words are longer (issue 22 item 4): both languages, every scale.
  for (const Language lang : {Language::en, Language::de})
  for (float scale : {1.f, 1.6f, 2.f}) {
    auto v = makeViewer(defaultScene(), scale);
    v->state().display.language = lang;
    v->frames(2);
    const char* code = lang == Language::de ? "de" : "en";
    for (const Shown& s : shown) {
      SCOPED_TRACE(std::string(s.what) + " at UI scale " + std::to_string(scale) + " in " + code);
      s.show(*v);
      char prefix[128];
      std::snprintf(prefix, sizeof prefix, "ui-%s-%.1f-%s", code, scale, s.what);
      std::vector<std::string> problems = test::clippedTextOfEveryPage(*v, prefix);
      if (std::string(s.what) == "Depth") {  // the plot at least ten lines high at every scale
        EXPECT_GE(v->rects().rects.at("depth.plot").w, 10 * ImGui::GetTextLineHeight());
      }
      char name[128];
      std::snprintf(name, sizeof name, "ui-%s-%.1f-%s.png", code, scale, s.what);
      writePng(v->image(), test::outputDir() / name);
      std::string list;
      for (size_t i = 0; i < std::min<size_t>(problems.size(), 6); ++i) list += "\n  " + problems[i];
      EXPECT_TRUE(problems.empty()) << problems.size() << " places:" << list;
    }
  }
}


// ---------------------------------------------------------------- issue 24 item 2: a phone's screen

bool windowShown(const char* name) {
  // A window's id is its English name after "###", in either language (app/text/ui_menus.inc).
  const ImGuiWindow* w = ImGui::FindWindowByName(("###" + std::string(name)).c_str());
  return w && w->Active;
}

// A phone (390 × 844 CSS px at a pixel ratio of 2, upright and on its side) gets the compact layout:
// one view at a time filling the screen, chosen in the switcher, and the panels below or beside it.
// Every view and every panel's tab is reached from the switcher, with no text cut off.
TEST(UiCompact, APhoneShowsOneViewAtATimeAndEveryPanelWithNothingCutOff) {
  const float scale = 2.f * 0.886f;  // the page's: the pixel ratio × the CSS size's factor (page.cpp)
  for (const Language lang : {Language::en, Language::de})
  for (const auto& [w, h] : {std::pair{780, 1688}, std::pair{1688, 780}}) {
    const bool upright = h > w;
    SCOPED_TRACE(std::string(upright ? "upright" : "on its side") + (lang == Language::de ? " in German" : " in English"));
    auto v = std::make_unique<HeadlessViewer>(*test::egl().context, defaultScene(), w, h, scale);
    v->state().compactAllowed = true;
    v->state().display.language = lang;
    v->frames(3);
    const std::map<ViewKind, const char*> windows = {
        {ViewKind::world, "World view (WC)"}, {ViewKind::camera, "Camera view (DC)"}, {ViewKind::npc, "NPC view"}};
    for (const auto& [kind, id] : {std::pair{ViewKind::camera, "switch.camera"}, std::pair{ViewKind::npc, "switch.npc"},
                                   std::pair{ViewKind::world, "switch.world"}}) {
      const auto [x, y] = v->centreOf(id);
      v->click(x, y);
      v->frames(2);
      for (const auto& [k, name] : windows) EXPECT_EQ(windowShown(name), k == kind) << name << " after " << id;
      const ImGuiWindow* shown = ImGui::FindWindowByName((std::string("###") + windows.at(kind)).c_str());
      EXPECT_GE(shown->Size.x, 0.99f * float(w)) << windows.at(kind) << " does not fill the screen's width";
      EXPECT_GE(shown->Size.y, 0.8f * float(h)) << windows.at(kind) << " does not fill the screen's height";
      EXPECT_FALSE(windowShown("Controls") || windowShown("Inspect"));
    }
    char name[64];
    std::snprintf(name, sizeof name, "compact-%s-%s-world.png", lang == Language::de ? "de" : "en", upright ? "upright" : "side");
    writePng(v->image(), test::outputDir() / name);

    for (const auto& [panel, tabs] :
         {std::pair{"Controls", std::vector<std::string>{"Camera", "Scene", "Clipping", "Display", "Lecture"}},
          std::pair{"Inspect", std::vector<std::string>{"Vertex probe", "Matrices", "Depth"}}}) {
      const std::string lower = panel == std::string("Controls") ? "controls" : "inspect";
      const auto [x, y] = v->centreOf("switch." + lower);
      v->click(x, y);
      v->frames(2);
      ASSERT_TRUE(windowShown(panel)) << panel << " does not open";
      EXPECT_TRUE(windowShown("World view (WC)")) << "the view is not in sight beside the open panel";
      const ImGuiWindow* p = ImGui::FindWindowByName((std::string("###") + panel).c_str());
      EXPECT_GE(p->Size.x, (upright ? 0.99f : 0.49f) * float(w)) << "the panel is not below (upright) or beside the view";
      for (const std::string& tab : tabs) {
        SCOPED_TRACE(tab);
        const auto [tx, ty] = v->centreOf("tab." + lower + "." + tab);
        v->click(tx, ty);
        v->frames(2);
        std::snprintf(name, sizeof name, "compact-%s-%s-%s", lang == Language::de ? "de" : "en", upright ? "upright" : "side",
                      tab.c_str());
        writePng(v->image(), test::outputDir() / (std::string(name) + ".png"));
        const std::vector<std::string> problems = test::clippedTextOfEveryPage(*v, name);
        std::string list;
        for (size_t i = 0; i < std::min<size_t>(problems.size(), 6); ++i) list += "\n  " + problems[i];
        EXPECT_TRUE(problems.empty()) << problems.size() << " places:" << list;
      }
    }
    EXPECT_FALSE(windowShown("Controls")) << "opening the inspector leaves the controls open";
    const auto [x, y] = v->centreOf("switch.inspect");
    v->click(x, y);
    v->frames(2);
    EXPECT_FALSE(windowShown("Inspect")) << "the inspector's button does not close it again";
  }
}

// The desktop window keeps its layout at any size; a large page keeps the desktop's.
TEST(UiCompact, TheDesktopLayoutStaysWhereItFitsOrIsNotAllowed) {
  auto v = makeViewer();
  v->state().compactAllowed = true;  // 1280 × 720 at scale 1 holds the desktop layout
  v->frames(2);
  EXPECT_TRUE(windowShown("World view (WC)") && windowShown("Camera view (DC)") && windowShown("NPC view") &&
              windowShown("Controls") && windowShown("Inspect"));
  auto small = std::make_unique<HeadlessViewer>(*test::egl().context, defaultScene(), 700, 900, 1.f);
  small->frames(3);  // not allowed (the desktop window): all five windows, squeezed as the user made it
  EXPECT_TRUE(windowShown("World view (WC)") && windowShown("Camera view (DC)") && windowShown("Controls"));
}

}  // namespace
}  // namespace vplab

#include "app/inspect/picking.h"
#include "app/inspect/vanishing_text.h"
#include "pipeline/clip_steps.h"
#include "io/scene_io.h"

namespace vplab {
namespace {

// ---------------------------------------------------------------- item 3: typed values

/// Ctrl+click on a one-field drag makes it a text field; the characters come one frame each.
void typeSlowly(HeadlessViewer& v, const char* id, const char* text) {
  const auto [x, y] = v.centreOf(id);
  ImGui::GetIO().KeyCtrl = true;
  v.click(x - 20, y);
  ImGui::GetIO().KeyCtrl = false;
  for (const char* c = text; *c; ++c) {
    const char one[2] = {*c, 0};
    ImGui::GetIO().AddInputCharactersUTF8(one);
    v.frames(1);
  }
}

TEST(UiLecture, TypedValuesApplyWhenTheFieldLosesFocus) {
  auto v = makeViewer();
  ASSERT_EQ(v->state().doc.scene().camera.front, 3.0);
  typeSlowly(*v, "camera.front", "2.5");
  EXPECT_EQ(v->state().doc.scene().camera.front, 3.0) << "applied while typing";
  EXPECT_FALSE(v->state().doc.canUndo());
  const ImGuiWindow* controls = ImGui::FindWindowByName("###Controls");  // its bottom is empty
  ASSERT_NE(controls, nullptr);
  v->click(controls->Pos.x + 20, controls->Pos.y + controls->Size.y - 20);  // the field loses focus
  EXPECT_EQ(v->state().doc.scene().camera.front, 2.5);
  v->key(keys::kZ, true);
  EXPECT_EQ(v->state().doc.scene().camera.front, 3.0) << "one undo step for the typed value";
}

// ---------------------------------------------------------------- item 4: vanishing points

// ---------------------------------------------------------------- items 7, 9: copies and tabs

TEST(UiLecture, CopyingALatexMatrixSaysSoAndPastesAsDisplayMath) {
  auto v = makeViewer();
  const auto [tx, ty] = v->centreOf("tab.inspect.Matrices");
  v->click(tx, ty);
  v->frames(2);
  const auto [x, y] = v->centreOf("copy.wcFromMc.latex");
  v->click(x, y);
  v->frames(1);
  EXPECT_EQ(v->state().widgets.copied.id, "copy.wcFromMc.latex");
  const char* clip = ImGui::GetClipboardText();
  const std::string text = clip ? clip : "";
  EXPECT_NE(text.find("\\[\n\\begin{bmatrix}"), std::string::npos) << text;
}

/// A vertex of the run away from the camera view's edges, where the view draws it (in the window's pixels).
std::optional<std::pair<double, double>> aVertexInTheCameraView(HeadlessViewer& v) {
  const PipelineRun& run = v.state().run();
  const ImVec4 r = v.rects().rects.at("view.camera");
  const Device& d = run.device;
  for (size_t k = 0; k < run.objects.size(); ++k)
    for (uint32_t i = 0; i < run.objects[k].vertexCount(); ++i)
      if (const auto dc = probePosition(run, Probe{run.sceneIndex[k], i}, ViewKind::camera))
        if (dc->x > 40 && dc->x < d.width - 40 && dc->y > 40 && dc->y < d.height - 40)
          return std::pair(r.x + dc->x * r.z / d.width, r.y + dc->y * r.w / d.height);
  return std::nullopt;
}

/// Shift+click on the middle of a recorded widget or view (in the camera view: the step-through of the
/// probed vertex's polygon).
void shiftClick(HeadlessViewer& v, const char* id) {
  const auto [x, y] = v.centreOf(id);
  ImGui::GetIO().KeyShift = true;
  v.click(x, y);
  ImGui::GetIO().KeyShift = false;
  v.frames(1);
}

TEST(UiLecture, ClickingAVertexShowsTheProbeAndShiftClickTheStepThrough) {
  auto v = makeViewer();
  const auto [tx, ty] = v->centreOf("tab.inspect.Matrices");
  v->click(tx, ty);
  v->frames(2);
  ASSERT_EQ(v->state().inspectTab, ViewerState::matricesTab);
  const auto at = aVertexInTheCameraView(*v);
  ASSERT_TRUE(at);
  v->click(at->first, at->second);
  v->frames(1);
  ASSERT_TRUE(v->state().probe);
  EXPECT_EQ(v->state().inspectTab, ViewerState::probeTab);

  ASSERT_EQ(v->state().controlsTab, ViewerState::cameraTab);
  shiftClick(*v, "view.camera");
  ASSERT_TRUE(v->state().stepThrough.active);
  EXPECT_EQ(v->state().controlsTab, ViewerState::lectureTab);
  // Back is greyed at the start: a click on it changes nothing.
  const auto [bx, by] = v->centreOf("step.back");
  v->click(bx, by);
  EXPECT_EQ(v->state().stepThrough.step, 0);
  const auto [nx, ny] = v->centreOf("step.next");
  v->click(nx, ny);
  EXPECT_EQ(v->state().stepThrough.step, 1);
}

// A pass typed into the step-through's slider (Ctrl+click) is held to the passes there are: the
// monkey test typed "99999999999", which ImGui reads as 1215752192, and the panel indexed its passes
// with it. Typed below the first, it is the first.
TEST(UiLecture, APassTypedBeyondTheLastIsTheLast) {
  auto v = makeViewer();
  const auto at = aVertexInTheCameraView(*v);
  ASSERT_TRUE(at);
  v->click(at->first, at->second);  // the probe's polygon is the one stepped through
  v->frames(1);
  ASSERT_TRUE(v->state().probe);
  shiftClick(*v, "view.camera");
  ASSERT_TRUE(v->state().stepThrough.active);
  const StepThrough& st = v->state().stepThrough;
  const PipelineRun& run = v->state().run();
  const ObjectRun* o = nullptr;
  for (size_t k = 0; k < run.objects.size(); ++k)
    if (run.sceneIndex[k] == size_t(st.object)) o = &run.objects[k];
  ASSERT_NE(o, nullptr);
  const int passes = int(clipSteps(run, *o, size_t(st.face)).size());
  ASSERT_GT(passes, 0);
  v->frames(2);  // the Lecture tab, opened by the Shift+click, settles its layout

  typeSlowly(*v, "step.slider", "99999999999");
  v->key(keys::kEnter);
  v->frames(2);
  EXPECT_EQ(v->state().stepThrough.step, passes);
  typeSlowly(*v, "step.slider", "-99999999999");
  v->key(keys::kEnter);
  v->frames(2);
  EXPECT_EQ(v->state().stepThrough.step, 0);
}

}  // namespace
}  // namespace vplab

#include "app/render/headless.h"

namespace vplab {
namespace {

// The world view's labels of the default scene (front, VUP, V, VRP, the window's, PRP's…) at UI
// scale 1, 1.6 and 2, at the size the viewer shows it at 1280 × 720: no two overlap, and none
// covers a labelled point's marker (PRP's label sat on PRP's marker).
TEST(UiLecture, WorldViewLabelsDoNotOverlap) {
  ViewRenderer& renderer = *test::egl().renderer;
  const Scene scene = defaultScene();
  for (float scale : {1.f, 1.6f, 2.f}) {
    SCOPED_TRACE(scale);
    renderer.setScale(scale);
    RenderRequest request;
    request.view = ViewKind::world;
    request.style = Style::shaded;
    request.width = 518;
    request.height = 370;
    const Image image = renderImage(renderer, scene, request);
    const std::vector<glm::vec4> labels = renderer.labelsPlaced();
    EXPECT_GE(labels.size(), 8u);
    EXPECT_EQ(overlappingLabels(labels), 0);
    // PRP's marker: where the observer sees PRP.
    const PipelineRun run = runPipeline(scene);
    const ViewCamera observer = viewCameraOf(observerCamera(defaultWorldOrbit(scene, 518.0 / 370), 518.0 / 370));
    const Projected prp = projectToPixels(observer, scene.camera.prp, 518, 370);
    ASSERT_TRUE(prp.visible);
    for (const glm::vec4& r : labels)
      EXPECT_FALSE(prp.pixel.x > r.x - 3 && prp.pixel.x < r.z + 3 && prp.pixel.y > r.y - 3 && prp.pixel.y < r.w + 3)
          << "a label on PRP's marker";
    char name[64];
    std::snprintf(name, sizeof name, "world-labels-%.1f.png", scale);
    writePng(image, test::outputDir() / name);
  }
  renderer.setScale(1.f);
}

}  // namespace
}  // namespace vplab

namespace vplab {
namespace {

// Lecture mode's title and caption sit on a dark panel: over a white scene they stay readable
// (the caption's rectangle is mostly dark, not the white behind it).
TEST(UiLecture, LectureCaptionHasABackground) {
  Scene scene = defaultScene();
  scene.background = Vec3(1, 1, 1);
  scene.device.width = kWidth;  // the camera view fills the window, under the caption
  scene.device.height = kHeight;
  auto v = makeViewer(scene);
  v->state().lectureView = ViewKind::camera;
  v->key(keys::kF11);
  v->frames(2);
  ASSERT_TRUE(v->state().lectureMode);
  const Image caption = cropRect(v->image(), v->rects().rects.at("lecture.caption"));
  ASSERT_GT(caption.pixels.size(), 1000u);
  double luminance = 0;
  for (const Rgba& p : caption.pixels) luminance += 0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b;
  luminance /= double(caption.pixels.size());
  EXPECT_LT(luminance, 110.0) << "the caption is on the white scene without a panel";
}

}  // namespace
}  // namespace vplab

namespace vplab {
namespace {

// `vplab render --view ui --tab NAME` shows that tab as a click on it does in the viewer.
TEST(UiLecture, RenderUiShowsTheTabAsked) {
  const std::filesystem::path out = test::outputDir() / "render-ui-tab-matrices.png";
  const std::string command = std::string(VPLAB_EXE) + " render --view ui --tab lecture --tab matrices --out " + out.string();
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  auto v = makeViewer();
  for (const char* tab : {"tab.controls.Lecture", "tab.inspect.Matrices"}) {
    const auto [x, y] = v->centreOf(tab);
    v->click(x, y);
  }
  v->mouseMove(-1, -1);  // nothing hovered, as in the command line's frames
  v->frames(3);
  EXPECT_LT(meanDifference(readPng(out), v->image()), 0.5);
  const std::string bad = std::string(VPLAB_EXE) + " render --view ui --tab nowhere --out /dev/null 2>/dev/null";
  EXPECT_NE(std::system(bad.c_str()), 0);
}

}  // namespace
}  // namespace vplab

namespace vplab {
namespace {

// The depth plot's legend lies above the plot (off the curves), and each visible object has a
// named depth bar below it.
TEST(UiLecture, DepthPlotLegendIsOffTheCurvesAndTheBarsAreNamed) {
  auto v = makeViewer();
  const auto [x, y] = v->centreOf("tab.inspect.Depth");
  v->click(x, y);
  v->frames(2);
  const ImVec4 legend = v->rects().rects.at("depth.legend"), plot = v->rects().rects.at("depth.plot");
  EXPECT_LE(legend.y + legend.w, plot.y + 1) << "the legend overlaps the plot";
  for (const ObjectRun& o : v->state().run().objects)
    EXPECT_EQ(v->rects().rects.count("depth.bar." + o.name), 1u) << o.name;
}

// The step-through lists the coordinates of the vertices a pass creates: the tetrahedron of the
// default scene crosses the window's edges, so some pass over one of its clipped faces creates some.
TEST(UiLecture, StepThroughListsTheNewVertices) {
  auto v = makeViewer();
  const PipelineRun& run = v->state().run();
  std::optional<std::pair<int, int>> clipped;
  for (size_t k = 0; k < run.objects.size() && !clipped; ++k)
    for (size_t f = 0; f < run.objects[k].faceCount() && !clipped; ++f)
      if (run.objects[k].fate[f] == Fate::clipped) clipped = std::pair(int(run.sceneIndex[k]), int(f));
  ASSERT_TRUE(clipped);
  v->state().controlsTab = ViewerState::lectureTab;
  v->state().stepThrough = {true, clipped->first, clipped->second, 0};
  v->frames(2);
  bool listed = false;
  for (int step = 1; step <= 6 && !listed; ++step) {
    const auto [x, y] = v->centreOf("step.next");
    v->click(x, y);
    for (const auto& [id, rect] : v->rects().rects) listed |= id.rfind("step.new.", 0) == 0 && rect.z > 0;
  }
  EXPECT_TRUE(listed);
  // At the last pass "next" is greyed: a click changes nothing.
  for (int i = 0; i < 8 && v->state().stepThrough.step < 6; ++i) {
    const auto [x, y] = v->centreOf("step.next");
    v->click(x, y);
  }
  const int last = v->state().stepThrough.step;
  ASSERT_EQ(last, 6) << "the six planes of the view volume";
  const auto [x, y] = v->centreOf("step.next");
  v->click(x, y);
  EXPECT_EQ(v->state().stepThrough.step, last);
}

}  // namespace
}  // namespace vplab

namespace vplab {
namespace {

// The NPC cube's translucent front face (z = 1) and a polygon lying in the front plane: the
// polygon, drawn first, must keep one colour (flat style) where the face overlaps it, not a
// speckle of tinted and untinted pixels from equal depths (z-fighting).
TEST(UiLecture, NpcCubeFaceDoesNotZFightWithTheScene) {
  Scene scene = defaultScene();
  scene.objects.resize(1);
  SceneObject& square = scene.objects[0];
  square.name = "square in the front plane";
  square.shape = Shape::polygon;
  // In VRC z = F: the default camera's frame, so that NPC z = 1 (up to rounding).
  const PipelineRun before = runPipeline(scene);
  const Mat4& wcFromVrc = before.wcFromVrc;
  const Vec3 centre = transformAffine(wcFromVrc, {0, 0, scene.camera.front});
  square.vertices = {};
  for (auto [x, y] : {std::pair(-0.6, -0.6), {0.6, -0.6}, {0.6, 0.6}, {-0.6, 0.6}})
    square.vertices.push_back(transformAffine(wcFromVrc, {x, y, scene.camera.front}) - centre);
  square.transform = {};
  square.transform.translate = centre;
  square.color = Vec3(0.9, 0.3, 0.2);
  square.mesh = primitiveMesh(square);
  RenderRequest request;
  request.view = ViewKind::npc;
  request.style = Style::flat;
  request.width = 640;
  request.height = 480;
  const PipelineRun run = runPipeline(scene);
  ASSERT_EQ(run.objects.size(), 1u);
  ASSERT_GT(run.objects[0].faceCount(), 0u);
  const Image image = renderImage(*test::egl().renderer, scene, request);
  writePng(image, test::outputDir() / "npc-front-plane-square.png");
  // The square's pixels: reddish (r well above g and b, also when tinted by the face); its inside
  // (pixels whose eight neighbours are the square's too) leaves out the outline and antialiasing.
  auto reddish = [&](int x, int y) {
    const Rgba& p = image.at(x, y);
    return p.r > 120 && p.r > p.g + 60 && p.r > p.b + 60;
  };
  std::map<uint32_t, size_t> colours;
  size_t square_ = 0;
  for (int y = 1; y + 1 < image.height; ++y)
    for (int x = 1; x + 1 < image.width; ++x) {
      bool inside = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) inside = inside && reddish(x + dx, y + dy);
      if (!inside) continue;
      const Rgba& p = image.at(x, y);
      ++square_;
      ++colours[uint32_t(p.r) << 16 | uint32_t(p.g) << 8 | p.b];
    }
  ASSERT_GT(square_, 2000u) << "the square is not drawn";
  // Flat style: one colour inside. Z-fighting tinted about half of it (53 % in the main colour);
  // without, 98 % (the rest lies along the seams of its triangles, where no depth offset changes
  // anything), so 95 % separates the two.
  size_t main = 0;
  for (const auto& [c, n] : colours) main = std::max(main, n);
  EXPECT_GT(double(main) / double(square_), 0.95) << colours.size() << " colours inside the square";
}

}  // namespace
}  // namespace vplab

namespace vplab {
namespace {

// The inspector's tabs stay where they are while the matrices scroll under them.
TEST(UiLecture, InspectTabsStayWhileThePanelScrolls) {
  auto v = makeViewer();
  const auto [x, y] = v->centreOf("tab.inspect.Matrices");
  v->click(x, y);
  v->frames(2);
  const ImVec4 before = v->rects().rects.at("tab.inspect.Matrices");
  const ImVec4 firstCopy = v->rects().rects.at("copy.wcFromMc.text");
  v->mouseMove(firstCopy.x + 5, firstCopy.y + 5);
  for (int i = 0; i < 6; ++i) {  // the wheel over the panel
    v->wheel(-3);
    v->frames(1);
  }
  v->frames(1);
  EXPECT_LT(v->rects().rects.at("copy.wcFromMc.text").y, firstCopy.y - 20) << "the panel did not scroll";
  EXPECT_EQ(v->rects().rects.at("tab.inspect.Matrices").y, before.y);
}

}  // namespace
}  // namespace vplab
