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
  s.camera = c;
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
  EXPECT_THAT(error("prp=0,0,0&vrp=0,0,0"), HasSubstr("camera is not valid"));
  EXPECT_THAT(error("front=-5&back=5"), HasSubstr("camera is not valid"));
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
  EXPECT_EQ(a.viewer().urlState().scene, "default") << "the built-in scene is the bundled default.json";
  a.viewer().showUrlState(decodeUrlState("scene=perspective&camera-style=wire&strategy=wc"), true);
  a.frames(2);
  Camera& c = a.state().doc.scene().camera;
  c.prp += Vec3(0.25, -0.5, 0.125);
  a.state().frame.world.orbit.yawDeg = 12.5;
  a.frames(2);
  const std::string link = encodeUrlState(a.viewer().urlState());
  EXPECT_THAT(link, HasSubstr("scene=perspective&"));
  EXPECT_THAT(link, HasSubstr("camera-style=wire"));
  EXPECT_THAT(link, HasSubstr("strategy=wc"));

  HeadlessViewer b(*test::egl().context, defaultScene(), 1280, 720);
  b.viewer().showUrlState(decodeUrlState(link), true);
  b.frames(2);
  EXPECT_EQ(b.viewer().urlState(), a.viewer().urlState());
  EXPECT_EQ(b.state().doc.path().filename(), "perspective.json");
  EXPECT_FALSE(b.state().doc.dirty()) << "a link opens a document, it is not an edit";
  EXPECT_EQ(b.image().pixels, a.image().pixels) << "the same link draws the same window";
}

TEST(UrlState, ALinkToTheOpenSceneKeepsItsDocument) {
  HeadlessViewer v(*test::egl().context, defaultScene(), 1280, 720);
  v.frames(2);
  v.viewer().showUrlState(decodeUrlState("scene=default&prp=1,2,9"), true);
  v.frames(2);
  EXPECT_EQ(v.state().doc.path(), "") << "the built-in scene stays the built-in one, not default.json";
  EXPECT_EQ(v.state().doc.scene().camera.prp, Vec3(1, 2, 9));
}

TEST(UrlState, ACameraAloneIsAnEditAndAnUnknownSceneIsAnError) {
  HeadlessViewer v(*test::egl().context, defaultScene(), 1280, 720);
  v.frames(2);
  const Camera before = v.state().doc.scene().camera;
  v.viewer().showUrlState(decodeUrlState("prp=1,2,9"), false);
  v.frames(2);
  EXPECT_EQ(v.state().doc.scene().camera.prp, Vec3(1, 2, 9));
  EXPECT_EQ(v.state().doc.scene().camera.vrp, Camera{}.vrp);  // the link's camera is whole: defaults fill it
  EXPECT_NE(v.state().doc.scene().camera, before);
  EXPECT_THROW(v.viewer().showUrlState(decodeUrlState("scene=no-such-scene"), false), Error);
}

}  // namespace
}  // namespace vplab
