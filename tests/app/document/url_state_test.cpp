// The link's state (app/document/url_state.h): exact round trips, short numbers, hostile fragments
// (the viewer showing a link: tests/app/ui/links_test.cpp).
#include "app/document/url_state.h"

#include "base/error.h"

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

/// What decoding `fragment` says is wrong, in English, every problem, or "no error".
std::string error(const std::string& fragment, Language lang = Language::en) {
  const UrlState s = decodeUrlState(fragment);
  return s.problems.empty() ? std::string("no error") : saidTogether(s.problems, lang);
}

/// The keys of the problems decoding `fragment` finds, in order.
std::vector<std::string> badKeys(const std::string& fragment) {
  std::vector<std::string> keys;
  for (const LinkProblem& p : decodeUrlState(fragment).problems) keys.push_back(p.key);
  return keys;
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
  EXPECT_EQ(decodeUrlState("prp=1,2,3").camera.applied(base).prp, Vec3(1, 2, 3)) << "applied, valid or not";
  EXPECT_EQ(decodeUrlState("").camera.over(base), base);
}

TEST(UrlState, AnEmptyFragmentGivesNothing) {
  EXPECT_EQ(decodeUrlState(""), UrlState{});
  EXPECT_EQ(decodeUrlState("#"), UrlState{});
  EXPECT_EQ(encodeUrlState(UrlState{}), "");
}

TEST(UrlState, HostileFragmentsAreNamedErrors) {
  EXPECT_THAT(error("vrp=1,2"), HasSubstr("vrp=\"1,2\": 3 finite numbers separated by commas expected"));
  EXPECT_THAT(error("vrp=1,2,3,4"), HasSubstr("3 finite numbers"));
  EXPECT_THAT(error("front=nan"), HasSubstr("front=\"nan\": a finite number expected"));
  EXPECT_THAT(error("back=-inf"), HasSubstr("a finite number expected"));
  EXPECT_THAT(error("back=1e999"), HasSubstr("a finite number expected"));
  EXPECT_THAT(error("front=3x"), HasSubstr("a finite number expected"));
  EXPECT_THAT(error("projection=fisheye"), HasSubstr("not perspective, parallel or oblique"));
  EXPECT_THAT(error("camera-style=pretty"), HasSubstr("not a style"));
  EXPECT_THAT(error("world=0,0,0,0,95,10,40"), HasSubstr("no observer"));
  EXPECT_THAT(error("world=0,0,0,0,0,-1,40"), HasSubstr("no observer"));
  EXPECT_THAT(error("strategy=fast"), HasSubstr("not npc, wc or divide-first"));
  EXPECT_THAT(error("scene=../../etc/passwd"), HasSubstr("not the name of a bundled scene"));
  EXPECT_THAT(error("zoom=2"), HasSubstr("zoom=\"2\": not a key vplab knows"));
  EXPECT_THAT(error("vrp"), HasSubstr("vrp: not KEY=VALUE"));
  EXPECT_THAT(error(std::string(5000, 'a')), HasSubstr("5000 characters long"));
  EXPECT_THAT(error("zoom\x01=2"), HasSubstr("zoom?=")) << "control characters are not echoed";
  EXPECT_THAT(error("embed=camera,tv"), HasSubstr("\"tv\" is not one of the views"));
  EXPECT_THAT(error("step=3"), HasSubstr("a step without lesson=NAME"));
}

// Issue 41: a link explains itself. Every bad part is named at once, in the fragment's order and in
// the UI's language, and every good part is kept as if the bad ones were not there.
TEST(UrlState, EveryBadPartIsNamedAndTheRestIsKept) {
  EXPECT_EQ(badKeys("scene=nope!&vrp=1,2"), (std::vector<std::string>{"scene", "vrp"}));
  EXPECT_EQ(badKeys("lesson=nope!&step=abc"), (std::vector<std::string>{"lesson", "step"}));
  const UrlState s = decodeUrlState("lesson=05-clipping&step=abc&zoom=2&prp=1,x,3");
  EXPECT_EQ(s.lesson, "05-clipping") << "the valid lesson is kept";
  EXPECT_EQ(s.step, 0u) << "the bad step is ignored: the lesson opens at its first";
  EXPECT_EQ(badKeys("lesson=05-clipping&step=abc&zoom=2&prp=1,x,3"), (std::vector<std::string>{"step", "zoom", "prp"}));
  const UrlState camera = decodeUrlState("scene=perspective&vrp=1,2&prp=0,0,9&front=x");
  EXPECT_EQ(camera.scene, "perspective");
  EXPECT_FALSE(camera.camera.vrp);
  EXPECT_EQ(camera.camera.prp, Vec3(0, 0, 9));
  EXPECT_FALSE(camera.camera.front);
  // In German, the reasons are the lecture's words; the parts as written.
  EXPECT_THAT(error("scene=nope!&vrp=1,2", Language::de),
              HasSubstr("scene=\"nope!\": nicht der Name einer mitgelieferten Szene"));
  EXPECT_THAT(error("scene=nope!&vrp=1,2", Language::de), HasSubstr("vrp=\"1,2\": 3 endliche Zahlen"));
}

// An exercise (issue 40): its topic, seed, student's id and projection, and what Check reveals; the
// whole state, as a lesson's step is.
TEST(UrlState, AnExerciseLinkRoundTripsAndItsProjectionIsTheExercises) {
  const UrlState s = decodeUrlState("#exercise=clipping&seed=7&id=100&projection=parallel&reveal=values");
  ASSERT_TRUE(s.exercise);
  EXPECT_EQ(s.exercise->spec.topic, ExerciseTopic::clipping);
  EXPECT_EQ(s.exercise->spec.seed, 7u);
  EXPECT_EQ(s.exercise->spec.projection, Projection::parallel);
  EXPECT_EQ(s.exercise->studentId, "100");
  EXPECT_EQ(s.reveal, Reveal::values);
  EXPECT_TRUE(s.camera.empty()) << "projection= is the exercise's";
  EXPECT_EQ(encodeUrlState(s), "exercise=clipping&seed=7&id=100&projection=parallel&reveal=values");
  EXPECT_EQ(decodeUrlState(encodeUrlState(s)), s);
  const UrlState plain = decodeUrlState("exercise=pipeline&seed=4");
  EXPECT_EQ(plain.exercise->spec.projection, Projection::perspective);
  EXPECT_EQ(encodeUrlState(plain), "exercise=pipeline&seed=4");
}

TEST(UrlState, ABadExerciseLinkNamesItsKey) {
  EXPECT_THAT(error("exercise=shading&seed=1"), HasSubstr("exercise=\"shading\""));
  EXPECT_THAT(error("exercise=clipping&seed=-3"), HasSubstr("seed=\"-3\""));
  EXPECT_THAT(error("exercise=clipping&seed=1234567890123456789"), HasSubstr("seed="));
  EXPECT_THAT(error("exercise=clipping&seed=1&id=../etc"), HasSubstr("id=\"../etc\""));
  EXPECT_THAT(error("exercise=clipping&seed=1&reveal=all"), HasSubstr("reveal=\"all\""));
  EXPECT_THAT(error("exercise=clipping"), HasSubstr("needs its seed"));
  EXPECT_THAT(error("seed=3"), HasSubstr("no exercise=TOPIC"));
  EXPECT_THAT(error("exercise=clipping&seed=3&vrp=1,2,3"), HasSubstr("an exercise is its own scene"));
  EXPECT_THAT(error("exercise=clipping&seed=3&lesson=01-synthetic-camera"), HasSubstr("an exercise is its own scene"));
  // The exercise is kept; what else the link gave is left out.
  const UrlState s = decodeUrlState("exercise=clipping&seed=3&lesson=01-synthetic-camera");
  ASSERT_TRUE(s.exercise);
  EXPECT_TRUE(s.lesson.empty());
}

}  // namespace
}  // namespace vplab
