// What holds for every view: its batches are in its observer's space or its pixels, widths and
// sizes grow with the text scale, labels stay inside, and the names of views and styles.
#include "io/scene_io.h"
#include "tests/views/view_test_support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vplab {
namespace {

using namespace draw;
namespace fs = std::filesystem;

std::vector<std::pair<std::string, Scene>> presets() {
  std::vector<std::pair<std::string, Scene>> out;
  for (const auto& entry : fs::directory_iterator(fs::path(VPLAB_ASSETS) / "scenes"))
    if (entry.path().extension() == ".json" && entry.path().stem() != "large-mesh")  // slow
      out.emplace_back(entry.path().stem().string(), loadScene(entry.path()));
  return out;
}

constexpr Style kStyles[] = {Style::flat, Style::shaded, Style::wire, Style::hiddenLine, Style::hiddenRemoved};
constexpr ViewKind kViews[] = {ViewKind::camera, ViewKind::world, ViewKind::npc, ViewKind::morph};

Space spaceOf(const Batch& b) {
  return std::visit(
      [](const auto& x) {
        if constexpr (requires { x.space; }) return x.space;
        else return Space::pixels;
      },
      b);
}

TEST(Views, EveryBatchIsInTheObserversSpaceOrInPixels) {
  for (const auto& [name, scene] : presets())
    for (Style style : kStyles) {
      test::ViewFixture f(scene, style);
      f.settings.overlays.vanishingPoints = f.settings.overlays.cpuPolygons = true;
      f.highlights.vanishingObject = 0;
      for (ViewKind kind : kViews) {
        const DisplayList list = buildPicture(kind, f.input()).panels.at(0).list;
        ASSERT_FALSE(list.batches.empty()) << name;
        for (const Batch& b : list.batches) {
          const Space s = spaceOf(b);
          EXPECT_TRUE(s == list.observer.space || s == Space::pixels)
              << name << ", " << toString(kind) << ", " << toString(style) << ": " << test::describe(b);
        }
      }
    }
}

TEST(Views, LabelsNeverLeaveTheView) {
  for (const auto& [name, scene] : presets()) {
    test::ViewFixture f(scene, Style::shaded, 320, 240);
    f.settings.overlays.vanishingPoints = true;
    f.highlights.vanishingObject = 0;
    f.highlights.handles = {{scene.camera.prp, "PRP handle", true}, {scene.camera.vrp, "VRP", false}};
    for (ViewKind kind : kViews) {
      const DisplayList list = buildPicture(kind, f.input()).panels.at(0).list;
      for (const PlacedLabel& l : list.labels()) {
        EXPECT_GE(l.topLeft.x, 0) << name << ", " << toString(kind) << ": " << l.text;
        EXPECT_GE(l.topLeft.y, 0) << name << ", " << toString(kind) << ": " << l.text;
        EXPECT_LE(l.topLeft.x + l.extent.x, f.width) << name << ", " << toString(kind) << ": " << l.text;
        EXPECT_LE(l.topLeft.y + l.extent.y, f.height) << name << ", " << toString(kind) << ": " << l.text;
      }
    }
  }
}

// Lecture mode (OverlayRenderer::setScale did this): widths and sizes × scale, dashes as they are.
TEST(Views, LineWidthsAndPointSizesGrowWithTheTextScale) {
  for (Style style : kStyles) {
    test::ViewFixture one(defaultScene(), style), two(defaultScene(), style, 400, 300, 2.f);
    for (test::ViewFixture* f : {&one, &two}) {
      f->highlights.probeWc = f->highlights.probeNpc = Vec3(0.5);
      f->highlights.probeDc = Vec3(100, 100, 0.5);
    }
    for (ViewKind kind : kViews) {
      const DisplayList a = buildPicture(kind, one.input()).panels[0].list;
      const DisplayList b = buildPicture(kind, two.input()).panels[0].list;
      ASSERT_EQ(a.batches.size(), b.batches.size());
      size_t compared = 0;
      for (size_t i = 0; i < a.batches.size(); ++i) {
        if (const Lines* la = std::get_if<Lines>(&a.batches[i])) {
          const Lines& lb = std::get<Lines>(b.batches[i]);
          EXPECT_FLOAT_EQ(lb.widthPx, 2 * la->widthPx);
          EXPECT_EQ(lb.dashPx, la->dashPx);
          ++compared;
        }
        if (const Points* pa = std::get_if<Points>(&a.batches[i])) {
          EXPECT_FLOAT_EQ(std::get<Points>(b.batches[i]).sizePx, 2 * pa->sizePx);
          ++compared;
        }
      }
      EXPECT_GT(compared, 0u) << toString(kind);
    }
  }
}

TEST(Views, NamesRoundTrip) {
  for (ViewKind v : {ViewKind::camera, ViewKind::world, ViewKind::npc, ViewKind::all, ViewKind::morph})
    EXPECT_EQ(fromString<ViewKind>(toString(v)), v);
  for (Style s : kStyles) EXPECT_EQ(fromString<Style>(toString(s)), s);
  EXPECT_EQ(fromString<Style>("hidden-line"), Style::hiddenLine);
  EXPECT_FALSE(fromString<ViewKind>("cam"));
  EXPECT_FALSE(fromString<Style>("hiddenLine"));
}

}  // namespace
}  // namespace vplab
