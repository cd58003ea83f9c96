// German throughout (issue 37 item 5): a scene's title, caption and object names are shown in the
// viewer's language where the scene gives them ("title_de", "caption_de", "name_de"), in the
// controls, in lecture mode, in the Scene tab's list and the inspector; English where it does not.
#include "app/ui/headless_viewer.h"
#include "app/ui/keys.h"
#include "io/scene_io.h"
#include "tests/app/ui/screen_text.h"
#include "tests/support/gl_test_support.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vplab {
namespace {

struct GermanViewer {
  HeadlessViewer v{*test::egl().context, defaultScene(), 1280, 720, 1.6f};
  GermanViewer() {
    v.state().display.language = Language::de;
    v.frames(3);
  }
};

TEST(SceneWords, AGermanViewerShowsTheDefaultScenesGermanTitleCaptionAndNames) {
  GermanViewer g;
  std::vector<test::ScreenLine> shown = test::screenText();
  EXPECT_TRUE(test::onScreen(shown, "Standard-Vorlesungsszene")) << test::screenTextDump(shown);
  EXPECT_TRUE(test::onScreen(shown, "Würfel, Tetraeder, Zylinder"));
  EXPECT_FALSE(test::onScreen(shown, "Default lecture scene"));
  // The Scene tab's list and the inspector's modeling matrix name the objects in German.
  g.v.state().controlsTab = ViewerState::sceneTab;
  g.v.state().inspectTab = ViewerState::matricesTab;
  g.v.frames(3);
  shown = test::screenText();
  EXPECT_TRUE(test::onScreen(shown, "Tetraeder")) << test::screenTextDump(shown);
  EXPECT_TRUE(test::onScreen(shown, "wcFromMc — Würfel")) << test::screenTextDump(shown);
  EXPECT_FALSE(test::onScreen(shown, "tetrahedron"));
  // Lecture mode (F11) puts the title and caption over the view.
  g.v.key(keys::kF11);
  g.v.frames(3);
  ASSERT_TRUE(g.v.state().lectureMode);
  shown = test::screenText();
  EXPECT_TRUE(test::onScreen(shown, "Standard-Vorlesungsszene")) << test::screenTextDump(shown);
  EXPECT_FALSE(test::onScreen(shown, "Default lecture scene"));
}

TEST(SceneWords, AnEnglishViewerAndAGermanOneWithoutGermanWordsShowTheSceneAsWritten) {
  HeadlessViewer v{*test::egl().context, defaultScene(), 1280, 720, 1.f};
  v.frames(3);
  std::vector<test::ScreenLine> shown = test::screenText();
  EXPECT_TRUE(test::onScreen(shown, "Default lecture scene")) << test::screenTextDump(shown);
  EXPECT_FALSE(test::onScreen(shown, "Standard-Vorlesungsszene"));
  Scene plain = defaultScene();
  plain.titleDe.clear();
  plain.captionDe.clear();
  for (SceneObject& o : plain.objects) o.nameDe.clear();
  HeadlessViewer de{*test::egl().context, plain, 1280, 720, 1.f};
  de.state().display.language = Language::de;
  de.frames(3);
  shown = test::screenText();
  EXPECT_TRUE(test::onScreen(shown, "Default lecture scene")) << test::screenTextDump(shown);
  EXPECT_TRUE(test::onScreen(shown, "Steuerung")) << "the panels speak German";
}

}  // namespace
}  // namespace vplab
