// The link's state (app/ui/url_state.h): exact round trips, short numbers, hostile fragments, and
// the viewer showing a link as it was written.
#include "app/ui/url_state.h"

#include "app/ui/headless_viewer.h"
#include "pipeline/error.h"
#include "tests/app/gl_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace vplab {
namespace {

using ::testing::HasSubstr;

UrlState everything() {
  UrlState s;
  s.scene = "perspective";
  Camera c;
  c.vrp = {0.1, -0.7684708290995371, 1e-7};
  c.prp = {3, 2.4, 7.5};
  c.vup = {0, 1, 1e-300};
  c.window = {-2.4, 2.4, -1.8, 1.8};
  c.front = 3;
  c.back = -3.2;
  c.projection = Projection::oblique;
  c.oblique = kCavalier;
  s.camera = cameraLinkOf(c);
  s.cameraStyle = Style::wire;
  s.worldStyle = Style::hiddenLine;
  s.npcStyle = Style::flat;
  s.worldOrbit = Orbit{{-0.77, 0.5, 1.78}, 76.80140948635182, 28, 15.5, 40};
  s.npcOrbit = Orbit{{0.5, 0.5, 0.5}, 38, -24, 3.3, 40};
  s.strategy = ClipStrategy::divideFirst;
  return s;
}

TEST(UrlState, RoundTripsExactly) {
  const UrlState s = everything();
  const std::string text = encodeUrlState(s);
  EXPECT_EQ(decodeUrlState(text), s) << text;
  EXPECT_EQ(decodeUrlState("#" + text), s);
  EXPECT_THAT(text, HasSubstr("scene=perspective&vrp=0.1,-0.7684708290995371,1e-07&"));
}

// Every finite double reads back to itself: 10 000 random bit patterns (NaN and infinity skipped).
TEST(UrlState, ShortestNumberReadsBackExactly) {
  std::mt19937_64 random(7);
  for (int i = 0; i < 10000; ++i) {
    const uint64_t bits = random();
    double v = 0;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isfinite(v)) continue;
    const std::string s = shortestNumber(v);
    EXPECT_EQ(std::strtod(s.c_str(), nullptr), v) << s;
  }
  EXPECT_EQ(shortestNumber(40), "40");
  EXPECT_EQ(shortestNumber(-3.2), "-3.2");
  EXPECT_EQ(shortestNumber(-0.0), "0");
  EXPECT_EQ(shortestNumber(1e20), "1e+20");
}

// A link's camera parts replace only themselves; whether they make a camera is known over the scene's.
TEST(UrlState, CameraPartsGoOverTheScenesCamera) {
  Camera base;
  base.vrp = {1, 2, 3};
  base.window = {-2, 2, -1.5, 1.5};
  const Camera c = decodeUrlState("prp=4,5,6&front=1").camera.over(base);
  EXPECT_EQ(c.prp, Vec3(4, 5, 6));
  EXPECT_EQ(c.front, 1);
  EXPECT_EQ(c.vrp, base.vrp);
  EXPECT_EQ(c.window, base.window);
  EXPECT_EQ(c.back, base.back);
  auto invalid = [&](const char* fragment) {
    try {
      decodeUrlState(fragment).camera.over(base);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(invalid("prp=1,2,3"), HasSubstr("the link's camera is not valid"));  // PRP on VRP
  EXPECT_THAT(invalid("front=-5&back=5"), HasSubstr("the link's camera is not valid"));
  EXPECT_EQ(decodeUrlState("").camera.over(base), base);
}

TEST(UrlState, AnEmptyFragmentGivesNothing) {
  EXPECT_EQ(decodeUrlState(""), UrlState{});
  EXPECT_EQ(decodeUrlState("#"), UrlState{});
  EXPECT_EQ(encodeUrlState(UrlState{}), "");
}

TEST(UrlState, HostileFragmentsAreNamedErrors) {
  auto error = [](const std::string& fragment) {
    try {
      decodeUrlState(fragment);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(error("vrp=1,2"), HasSubstr("vrp=\"1,2\" has 2 numbers, 3 expected"));
  EXPECT_THAT(error("vrp=1,2,3,4"), HasSubstr("more than 3"));
  EXPECT_THAT(error("front=nan"), HasSubstr("front=\"nan\" is not 1 finite number"));
  EXPECT_THAT(error("back=-inf"), HasSubstr("not 1 finite number"));
  EXPECT_THAT(error("back=1e999"), HasSubstr("not 1 finite number"));
  EXPECT_THAT(error("front=3x"), HasSubstr("not 1 finite number"));
  EXPECT_THAT(error("projection=fisheye"), HasSubstr("not perspective, parallel or oblique"));
  EXPECT_THAT(error("camera-style=pretty"), HasSubstr("is not a style"));
  EXPECT_THAT(error("world=0,0,0,0,95,10,40"), HasSubstr("is no observer"));
  EXPECT_THAT(error("world=0,0,0,0,0,-1,40"), HasSubstr("is no observer"));
  EXPECT_THAT(error("strategy=fast"), HasSubstr("not npc, wc or divide-first"));
  EXPECT_THAT(error("scene=../../etc/passwd"), HasSubstr("not the name of a bundled scene"));
  EXPECT_THAT(error("zoom=2"), HasSubstr("\"zoom\" is not a key vplab knows"));
  EXPECT_THAT(error("vrp"), HasSubstr("is not KEY=VALUE"));
  EXPECT_THAT(error(std::string(5000, 'a')), HasSubstr("5000 characters long"));
  EXPECT_THAT(error("zoom\x01=2"), HasSubstr("\"zoom?\""));  // control characters are not echoed
}

// ---------------------------------------------------------------- the viewer and a link

TEST(UrlState, AViewerShowsALinkAsItWasWritten) {
  HeadlessViewer a(*test::egl().context, defaultScene(), 1280, 720);
  a.frames(2);
  EXPECT_EQ(a.viewer().session().urlState().scene, "default") << "the built-in scene is the bundled default.json";
  a.viewer().session().showUrlState(decodeUrlState("scene=perspective&camera-style=wire&strategy=wc"), true);
  a.frames(2);
  Camera& c = a.state().doc.scene().camera;
  c.prp += Vec3(0.25, -0.5, 0.125);
  a.state().display.world.orbit.yawDeg = 12.5;
  a.frames(2);
  const std::string link = encodeUrlState(a.viewer().session().urlState());
  EXPECT_THAT(link, HasSubstr("scene=perspective&"));
  EXPECT_THAT(link, HasSubstr("camera-style=wire"));
  EXPECT_THAT(link, HasSubstr("strategy=wc"));

  HeadlessViewer b(*test::egl().context, defaultScene(), 1280, 720);
  b.viewer().session().showUrlState(decodeUrlState(link), true);
  b.frames(2);
  EXPECT_EQ(b.viewer().session().urlState(), a.viewer().session().urlState());
  EXPECT_EQ(b.state().doc.path().filename(), "perspective.json");
  EXPECT_FALSE(b.state().doc.dirty()) << "a link opens a document, it is not an edit";
  EXPECT_EQ(b.image().pixels, a.image().pixels) << "the same link draws the same window";
}

TEST(UrlState, ALinkToTheOpenSceneKeepsItsDocument) {
  HeadlessViewer v(*test::egl().context, defaultScene(), 1280, 720);
  v.frames(2);
  v.viewer().session().showUrlState(decodeUrlState("scene=default&prp=1,2,9"), true);
  v.frames(2);
  EXPECT_EQ(v.state().doc.path(), "") << "the built-in scene stays the built-in one, not default.json";
  EXPECT_EQ(v.state().doc.scene().camera.prp, Vec3(1, 2, 9));
}

TEST(UrlState, ACameraAloneIsAnEditAndAnUnknownSceneIsAnError) {
  HeadlessViewer v(*test::egl().context, defaultScene(), 1280, 720);
  v.frames(2);
  const Camera before = v.state().doc.scene().camera;
  v.viewer().session().showUrlState(decodeUrlState("prp=1,2,9"), false);
  v.frames(2);
  EXPECT_EQ(v.state().doc.scene().camera.prp, Vec3(1, 2, 9));
  EXPECT_EQ(v.state().doc.scene().camera.window, before.window) << "what the link does not give stays the scene's";
  EXPECT_EQ(v.state().doc.scene().camera.front, before.front);
  EXPECT_TRUE(v.state().doc.dirty()) << "a camera alone is an edit of the open scene";
  EXPECT_THROW(v.viewer().session().showUrlState(decodeUrlState("prp=0,0,0"), false), Error) << "PRP on VRP";
  EXPECT_EQ(v.state().doc.scene().camera.prp, Vec3(1, 2, 9)) << "an invalid link changes nothing";
  EXPECT_THROW(v.viewer().session().showUrlState(decodeUrlState("scene=no-such-scene"), false), Error);
}

}  // namespace
}  // namespace vplab
