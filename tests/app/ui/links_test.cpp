// The viewer showing a link as it was written (the link's codec: tests/app/document/url_state_test.cpp).
#include "app/document/url_state.h"

#include "app/ui/headless_viewer.h"
#include "base/error.h"
#include "tests/support/gl_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace vplab {
namespace {

using ::testing::HasSubstr;

// ---------------------------------------------------------------- the viewer and a link

TEST(UrlState, AViewerShowsALinkAsItWasWritten) {
  HeadlessViewer a(*test::egl().context, defaultScene(), 1280, 720);
  a.frames(2);
  EXPECT_EQ(a.viewer().session().links().urlState().scene, "default") << "the built-in scene is the bundled default.json";
  a.viewer().session().links().showUrlState(decodeUrlState("scene=perspective&camera-style=wire&strategy=wc"), true);
  a.frames(2);
  Camera& c = a.state().doc.scene().camera;
  c.prp += Vec3(0.25, -0.5, 0.125);
  a.state().display.world.orbit.yawDeg = 12.5;
  a.frames(2);
  const std::string link = encodeUrlState(a.viewer().session().links().urlState());
  EXPECT_THAT(link, HasSubstr("scene=perspective&"));
  EXPECT_THAT(link, HasSubstr("camera-style=wire"));
  EXPECT_THAT(link, HasSubstr("strategy=wc"));

  HeadlessViewer b(*test::egl().context, defaultScene(), 1280, 720);
  b.viewer().session().links().showUrlState(decodeUrlState(link), true);
  b.frames(2);
  EXPECT_EQ(b.viewer().session().links().urlState(), a.viewer().session().links().urlState());
  EXPECT_EQ(b.state().doc.path().filename(), "perspective.json");
  EXPECT_FALSE(b.state().doc.dirty()) << "a link opens a document, it is not an edit";
  EXPECT_EQ(b.image().pixels, a.image().pixels) << "the same link draws the same window";
}

TEST(UrlState, ALinkToTheOpenSceneKeepsItsDocument) {
  HeadlessViewer v(*test::egl().context, defaultScene(), 1280, 720);
  v.frames(2);
  v.viewer().session().links().showUrlState(decodeUrlState("scene=default&prp=1,2,9"), true);
  v.frames(2);
  EXPECT_EQ(v.state().doc.path(), "") << "the built-in scene stays the built-in one, not default.json";
  EXPECT_EQ(v.state().doc.scene().camera.prp, Vec3(1, 2, 9));
}

TEST(UrlState, ACameraAloneIsAnEditAndAnUnknownSceneIsAnError) {
  HeadlessViewer v(*test::egl().context, defaultScene(), 1280, 720);
  v.frames(2);
  const Camera before = v.state().doc.scene().camera;
  v.viewer().session().links().showUrlState(decodeUrlState("prp=1,2,9"), false);
  v.frames(2);
  EXPECT_EQ(v.state().doc.scene().camera.prp, Vec3(1, 2, 9));
  EXPECT_EQ(v.state().doc.scene().camera.window, before.window) << "what the link does not give stays the scene's";
  EXPECT_EQ(v.state().doc.scene().camera.front, before.front);
  EXPECT_TRUE(v.state().doc.dirty()) << "a camera alone is an edit of the open scene";
  v.viewer().session().links().showUrlState(decodeUrlState("prp=0,0,0"), false);  // PRP on VRP
  EXPECT_EQ(v.state().doc.scene().camera.prp, Vec3(1, 2, 9)) << "an invalid camera changes nothing";
  EXPECT_EQ(v.state().linkProblems.size(), 1u) << "and is named";
  v.viewer().session().links().showUrlState(decodeUrlState("scene=no-such-scene"), false);
  ASSERT_EQ(v.state().linkProblems.size(), 1u);
  EXPECT_EQ(v.state().linkProblems[0].key, "scene");
}

// Issue 41: what a link left out is seen where people look, on any screen: over the first view
// (on a phone, the one view shown), in the UI's language.
TEST(UrlState, WhatALinkLeftOutIsNamedOverTheViews) {
  HeadlessViewer v(*test::egl().context, defaultScene(), 1280, 720);
  v.frames(2);
  const Image clean = v.image();
  v.viewer().session().links().showUrlState(decodeUrlState("scene=nope&vrp=1,2&zoom=3"), false);
  v.frames(3);
  const Image noted = v.image();
  const ImVec4 world = v.viewer().rects().rects.at("view.world");
  // The note's amber text over a dark band at the top of the world view; the rest of the window as before.
  size_t amber = 0, amberBefore = 0;
  for (int y = int(world.y); y < int(world.y + world.w * 0.5f); ++y)
    for (int x = int(world.x); x < int(world.x + world.z); ++x) {
      auto isAmber = [](const Rgba& c) { return c.r > 200 && c.g > 150 && c.g < 220 && c.b < 120; };
      amber += isAmber(noted.pixels[size_t(y) * size_t(noted.width) + size_t(x)]);
      amberBefore += isAmber(clean.pixels[size_t(y) * size_t(clean.width) + size_t(x)]);
    }
  EXPECT_GT(amber, amberBefore + 300) << "the note's text is drawn over the view";
  v.state().linkProblems.clear();  // the user changed what the link showed (the page clears them)
  v.frames(2);
  const Image after = v.image();
  size_t differing = 0;  // in the world view (the status line still says what the link left out)
  for (int y = int(world.y); y < int(world.y + world.w); ++y)
    for (int x = int(world.x); x < int(world.x + world.z); ++x) {
      const size_t i = size_t(y) * size_t(after.width) + size_t(x);
      differing += !(after.pixels[i] == clean.pixels[i]);
    }
  EXPECT_EQ(differing, 0u) << "and it goes";
}

}  // namespace
}  // namespace vplab
