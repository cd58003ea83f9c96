// Between two steps (app/lessons/lesson_transition.h): the ends are the steps' states exactly, and every
// camera on the way is valid, for random cameras and for every transition of the bundled lessons.
#include "app/lessons/lesson_transition.h"

#include "app/lessons/lesson_player.h"
#include "base/error.h"
#include "pipeline/modeling.h"

#include "app/document/assets.h"

#include <gtest/gtest.h>

#include <random>

namespace vplab {
namespace {

/// Random valid cameras: any orientation (VUP nearly parallel to N included), eyes near and far,
/// every projection, parallel cameras whose front plane lies beyond the eye.
Camera randomCamera(std::mt19937& rng) {
  std::uniform_real_distribution<double> coord(-20, 20), size(0.1, 10), unit(-1, 1);
  std::uniform_int_distribution<int> projection(0, 2);
  for (;;) {
    Camera c;
    c.vrp = {coord(rng), coord(rng), coord(rng)};
    c.prp = c.vrp + Vec3(unit(rng), unit(rng), unit(rng)) * size(rng) * 2.0;
    c.vup = Vec3(unit(rng), unit(rng), unit(rng));
    if (unit(rng) > 0.8) c.vup = c.prp - c.vrp + Vec3(1e-3, 0, 0);  // nearly along N
    const double x = coord(rng) / 4, y = coord(rng) / 4;
    c.window = {x, x + size(rng), y, y + size(rng)};
    c.projection = allOf<Projection>()[size_t(projection(rng))];
    c.front = coord(rng);
    c.back = c.front - size(rng);
    c.oblique = {size(rng) / 5, coord(rng) * 9};
    if (!cameraError(c)) return c;
  }
}

TEST(LessonTransition, TheEndsAreTheCamerasThemselves) {
  std::mt19937 rng(7);
  for (int i = 0; i < 100; ++i) {
    const Camera a = randomCamera(rng), b = randomCamera(rng);
    EXPECT_EQ(cameraBetween(a, b, 0), a);
    EXPECT_EQ(cameraBetween(a, b, 1), b);
  }
}

TEST(LessonTransition, EveryCameraOnTheWayIsValid) {
  // 2000 random pairs at 101 points each. The orientation is a rotation at every t (the slerp's
  // quaternion has length 1 up to rounding, ~1e-16), so VUP = V is perpendicular to N; the strict
  // inequalities hold by linearity, with margins far above rounding for these ranges.
  std::mt19937 rng(11);
  for (int i = 0; i < 2000; ++i) {
    const Camera a = randomCamera(rng), b = randomCamera(rng);
    for (int k = 0; k <= 100; ++k) {
      const Camera c = cameraBetween(a, b, k / 100.0);
      const auto error = cameraError(c);
      ASSERT_FALSE(error) << "pair " << i << ", t = " << k / 100.0 << ": " << *error;
    }
  }
}

TEST(LessonTransition, TheEyeTurnsHalfRoundWithoutPassingThroughVrp) {
  // N reversed: a straight blend of PRP would pass through VRP at t = 0.5.
  Camera a;
  a.prp = {0, 0, 5};
  Camera b = a;
  b.prp = {0, 0, -5};
  for (int k = 0; k <= 20; ++k) {
    const Camera c = cameraBetween(a, b, k / 20.0);
    EXPECT_FALSE(cameraError(c));
    EXPECT_NEAR(glm::length(c.prp - c.vrp), 5.0, 1e-12);  // the eye keeps its distance (VPD 5 at both ends)
  }
}

TEST(LessonTransition, AProjectionChangesWhereNoConstraintBreaks) {
  Camera parallel;
  parallel.projection = Projection::parallel;
  parallel.prp = {0, 0, 2};
  parallel.front = 4;  // beyond the eye: a parallel camera may
  parallel.back = -1;
  Camera perspective;
  perspective.prp = {0, 0, 10};
  EXPECT_EQ(cameraBetween(parallel, perspective, 0.99).projection, Projection::parallel);
  EXPECT_EQ(cameraBetween(perspective, parallel, 0.01).projection, Projection::parallel);
}

TEST(LessonTransition, TheObserverTurnsTheShorterWayAndZoomsEvenly) {
  Orbit a, b;
  a.yawDeg = 350;
  b.yawDeg = 10;
  a.distance = 2;
  b.distance = 8;
  const Orbit half = orbitBetween(a, b, 0.5);
  EXPECT_NEAR(std::remainder(half.yawDeg, 360.0), 0.0, 1e-12);
  EXPECT_NEAR(half.distance, 4.0, 1e-12);  // the geometric mean: each half zooms by 2
  EXPECT_EQ(orbitBetween(a, b, 1), b);
}

TEST(LessonTransition, WhatHasNoBetweenChangesHalfwayAndAnotherSceneAtOnce) {
  LessonState a, b;
  a.scene.objects.push_back({});
  b.scene = a.scene;
  b.scene.objects[0].visible = false;
  b.scene.objects[0].transform.translate = {2, 0, 0};
  b.display.world.style = Style::wire;
  b.strategy = ClipStrategy::wc;
  b.tab = "matrices";
  const LessonState early = stateBetween(a, b, 0.25), late = stateBetween(a, b, 0.75);
  EXPECT_TRUE(early.scene.objects[0].visible);
  EXPECT_EQ(early.display.world.style, Style::shaded);
  EXPECT_EQ(early.scene.objects[0].transform.translate, Vec3(0.5, 0, 0));
  EXPECT_FALSE(late.scene.objects[0].visible);
  EXPECT_EQ(late.strategy, ClipStrategy::wc);
  EXPECT_EQ(late.tab, "matrices");

  LessonState other = b;
  other.scene.objects.push_back({});
  EXPECT_EQ(stateBetween(a, other, 0.1).scene.objects.size(), 2u);
}

TEST(LessonTransition, EveryTransitionOfTheBundledLessonsShowsOnlyValidScenes) {
  LessonContext context;
  context.scenesDirectory = std::filesystem::path(VPLAB_ASSETS) / "scenes";
  size_t transitions = 0;
  for (const Language language : {Language::en, Language::de}) {
    for (const LessonFileInfo& info : listBundledLessons(language)) {
      SCOPED_TRACE(info.file.string());
      const Lesson lesson = loadLesson(info.file, context);
      // Forwards and backwards (← goes back), at 61 points each.
      for (size_t i = 0; i + 1 < lesson.steps.size(); ++i) {
        for (const auto& [from, to] : {std::pair{i, i + 1}, std::pair{i + 1, i}}) {
          ++transitions;
          for (int k = 0; k <= 60; ++k) {
            const LessonState s = stateBetween(lesson.steps[from].state, lesson.steps[to].state, easeInOut(k / 60.0));
            const auto error = sceneError(s.scene);
            ASSERT_FALSE(error) << "step " << from << " to " << to << " at t = " << k / 60.0 << ": " << *error;
          }
        }
      }
    }
  }
  EXPECT_GT(transitions, 40u);
}

// Issue 37: in lesson 02's free step the class types PRP = (0, 8, 0), VUP (0, 1, 0) parallel to N,
// then presses ←. The move from that invalid camera has no valid first half (there is no U, V, N to
// turn from): it is a cut to the step's own state, at once, and no state on the way throws.
TEST(LessonTransition, AMoveFromOrToAnInvalidCameraIsACut) {
  LessonState valid;
  valid.scene.objects.push_back({});
  valid.scene.camera.vrp = {0, 0, 0};
  valid.scene.camera.prp = {0, 2, 8};
  valid.scene.camera.vup = {0, 1, 0};
  LessonState invalid = valid;
  invalid.scene.camera.prp = {0, 8, 0};  // N along VUP
  ASSERT_TRUE(cameraError(invalid.scene.camera));
  EXPECT_TRUE(blendable(valid, valid));
  EXPECT_FALSE(blendable(invalid, valid));
  EXPECT_FALSE(blendable(valid, invalid));
  for (double t : {0.01, 0.5, 0.99}) {
    EXPECT_EQ(stateBetween(invalid, valid, t).scene.camera, valid.scene.camera) << "t = " << t;
    EXPECT_EQ(stateBetween(valid, invalid, t).scene.camera, invalid.scene.camera) << "t = " << t;
  }
  // An invalid transform (a scale of 0) has no blend either.
  LessonState flat = valid;
  flat.scene.objects[0].transform.scale = {0, 1, 1};
  ASSERT_THROW(wcFromMc(flat.scene.objects[0].transform), Error);
  EXPECT_FALSE(blendable(flat, valid));

  Lesson lesson;
  lesson.steps.resize(2);
  lesson.steps[0].state = valid;
  lesson.steps[1].state = valid;
  LessonPlayer player(lesson, 1);
  player.go(0, invalid, /*now=*/10, /*seconds=*/0.8);
  EXPECT_FALSE(player.moving(10)) << "a move from an invalid camera must be a cut";
  EXPECT_EQ(player.stateAt(10).scene.camera, valid.scene.camera);
  player.go(1, valid, 20, 0.8);
  EXPECT_TRUE(player.moving(20.1)) << "between valid steps the move is still a blend";
}

}  // namespace
}  // namespace vplab
