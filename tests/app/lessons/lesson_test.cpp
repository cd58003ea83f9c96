// Lessons (app/lessons/lesson.h): how a step's state follows from the steps before it, and a lesson
// file read as strictly as a scene: every error names the file, the step and the key.
#include "app/lessons/lesson.h"

#include "io/scene_io.h"
#include "base/error.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace vplab {
namespace {

using ::testing::HasSubstr;
using J = nlohmann::ordered_json;

LessonContext context() {
  LessonContext c;
  c.scenesDirectory = std::filesystem::path(VPLAB_ASSETS) / "scenes";
  c.fresh.camera.style = Style::shaded;
  return c;
}

Lesson parse(const J& j, const LessonContext& c = context()) { return parseLesson(j.dump(), "lesson.json", ".", c); }

/// Three steps over the default scene: the camera moves, then the class looks at a vertex.
J threeSteps() {
  return J{{"title", "View orientation"},
           {"language", "en"},
           {"steps",
            {{{"caption", "The default scene."}, {"section", "15.1"}, {"scene", "default"}},
             {{"caption", "PRP moves onto the z axis: $N$ follows."},
              {"section", "15.2.2"},
              {"camera", {{"prp", {0, 0, 8}}}},
              {"views", {{"world", {{"style", "wire"}, {"orbit", {{"yaw_deg", 80}}}}}}},
              {"overlays", {{"vertex_names", true}}},
              {"morph", 2.5},
              {"tab", "matrices"},
              {"highlight", {{{"handle", "prp"}}, {{"matrix", "vrcFromWc"}, {"row", 2}}, {{"axis", "n"}}}}},
             {{"caption", "A vertex of the cube."},
              {"objects", {{"sphere", {{"visible", false}}}, {"cube", {{"translate", {1, 0, 0}}}}}},
              {"probe", {{"object", "cube"}, {"vertex", 3}}},
              {"strategy", "wc"},
              {"bounding_box", true},
              {"select", "cylinder"},
              {"free", true}}}}};
}

TEST(Lesson, EachStepIsThePreviousStepAsWrittenWithItsOwnChanges) {
  const Lesson lesson = parse(threeSteps());
  ASSERT_EQ(lesson.steps.size(), 3u);
  EXPECT_EQ(lesson.title, "View orientation");
  EXPECT_EQ(lesson.language, Language::en);

  const Scene defaultScene = loadScene(std::filesystem::path(VPLAB_ASSETS) / "scenes" / "default.json");
  const LessonState& s0 = lesson.steps[0].state;
  EXPECT_EQ(s0.scene.camera, defaultScene.camera);
  EXPECT_EQ(s0.display.camera.style, Style::shaded);  // the context's fresh document
  EXPECT_EQ(s0.display.world.orbit, defaultWorldOrbit(defaultScene, context().worldAspect));
  EXPECT_EQ(lesson.steps[0].section, "15.1");

  const LessonState& s1 = lesson.steps[1].state;
  Camera moved = defaultScene.camera;
  moved.prp = {0, 0, 8};
  EXPECT_EQ(s1.scene.camera, moved);  // only PRP changed
  EXPECT_EQ(s1.display.world.style, Style::wire);
  EXPECT_EQ(s1.display.world.orbit.yawDeg, 80);
  EXPECT_EQ(s1.display.world.orbit.pitchDeg, s0.display.world.orbit.pitchDeg);  // the orbit's other parts stay
  EXPECT_TRUE(s1.display.overlays.vertexNames);
  EXPECT_EQ(s1.tab, "matrices");
  EXPECT_EQ(s1.display.morphing.t, 2.5);
  EXPECT_TRUE(s1.morphShown);  // a step giving the morph's t opens its window
  EXPECT_FALSE(s0.morphShown);
  ASSERT_EQ(s1.highlights.size(), 3u);
  EXPECT_EQ(s1.highlights[0].kind, LessonHighlight::Kind::handle);
  EXPECT_EQ(s1.highlights[0].handle, Handle::prp);
  EXPECT_EQ(s1.highlights[1].matrix, "vrcFromWc");
  EXPECT_EQ(s1.highlights[1].row, 2);
  EXPECT_EQ(s1.highlights[1].column, -1);  // the whole row
  EXPECT_EQ(s1.highlights[2].axis, 2);

  // The camera, the views and the tab carry on; the highlights belong to step 1 only.
  const LessonState& s2 = lesson.steps[2].state;
  EXPECT_EQ(s2.scene.camera, moved);
  EXPECT_EQ(s2.display.world.style, Style::wire);
  EXPECT_EQ(s2.tab, "matrices");
  EXPECT_TRUE(s2.highlights.empty());
  EXPECT_FALSE(s2.scene.objects[3].visible);  // the sphere
  EXPECT_EQ(s2.scene.objects[0].transform.translate, Vec3(1, 0, 0));
  EXPECT_EQ(s2.scene.objects[0].transform.rotations, defaultScene.objects[0].transform.rotations);  // not given: kept
  ASSERT_TRUE(s2.probe);
  EXPECT_EQ(s2.probe->object, 0u);
  EXPECT_EQ(s2.probe->vertex, 3u);
  EXPECT_EQ(s2.strategy, ClipStrategy::wc);
  EXPECT_TRUE(s2.boundingBoxTest);
  EXPECT_EQ(s2.selected, 2u);
  EXPECT_TRUE(s2.morphShown);  // carried on
  EXPECT_EQ(s2.display.morphing.t, 2.5);
  EXPECT_TRUE(lesson.steps[2].free);
  EXPECT_FALSE(s1.probe);
}

TEST(Lesson, ANewSceneStartsFromAFreshDocumentsViews) {
  J j = threeSteps();
  j["steps"].push_back({{"caption", "Another scene."}, {"scene", "parallel"}});
  const Lesson lesson = parse(j);
  const LessonState& s3 = lesson.steps[3].state;
  const Scene parallel = loadScene(std::filesystem::path(VPLAB_ASSETS) / "scenes" / "parallel.json");
  EXPECT_EQ(s3.scene.camera, parallel.camera);
  EXPECT_EQ(s3.display.world.style, context().fresh.world.style);
  EXPECT_FALSE(s3.display.overlays.vertexNames);
  EXPECT_EQ(s3.strategy, ClipStrategy::npc);
  EXPECT_EQ(s3.tab, "");
}

TEST(Lesson, AStepMayOpenAFileBesideTheLessonAndTheStepThrough) {
  test::TempDir dir;
  const std::string sceneText =
      test::readFile(std::filesystem::path(VPLAB_ASSETS) / "scenes" / "seed-cube-tetrahedron.json");
  ASSERT_FALSE(sceneText.empty());
  dir.write("mine.json", sceneText);
  J j{{"title", "Clipping"},
      {"language", "de"},
      {"steps",
       {{{"caption", "Das Polygon nach der linken Ebene."},
         {"scene_file", "mine.json"},
         {"step_through", {{"object", "tetrahedron"}, {"face", 2}, {"plane", 1}}},
         {"highlight", {{{"plane", "left"}}}}}}}};
  const std::filesystem::path file = dir.write("clipping.de.json", j.dump());
  const Lesson lesson = loadLesson(file, context());
  EXPECT_EQ(lesson.file, file);
  EXPECT_EQ(lesson.language, Language::de);
  const LessonState& s = lesson.steps[0].state;
  EXPECT_EQ(s.scene.objects.size(), 2u);
  ASSERT_TRUE(s.stepThrough);
  EXPECT_EQ(s.stepThrough->object, 1u);
  EXPECT_EQ(s.stepThrough->face, 2);
  EXPECT_EQ(s.stepThrough->plane, 1);
  EXPECT_EQ(s.highlights[0].plane, 0);
}

struct BadLesson {
  const char* what;
  std::function<void(J&)> edit;
  std::vector<std::string> message;  // parts the error must contain
};

TEST(Lesson, EveryErrorNamesTheFileTheStepAndTheKey) {
  const std::vector<BadLesson> cases = {
      {"unknown top-level key", [](J& j) { j["author"] = "me"; }, {"lesson.json: /author: unknown key", "steps"}},
      {"unknown key in a step", [](J& j) { j["steps"][1]["camara"] = J::object(); },
       {"lesson.json: /steps/1/camara: unknown key", "camera"}},
      {"no caption", [](J& j) { j["steps"][1].erase("caption"); }, {"/steps/1: missing required key \"caption\""}},
      {"a language vplab does not speak", [](J& j) { j["language"] = "fr"; }, {"/language: \"fr\" is not en or de"}},
      {"no steps", [](J& j) { j["steps"] = J::array(); }, {"/steps: a lesson needs at least one step"}},
      {"the first step names no scene", [](J& j) { j["steps"][0].erase("scene"); },
       {"/steps/0: the first step must name a \"scene\""}},
      {"a scene outside the bundled ones", [](J& j) { j["steps"][0]["scene"] = "../secret"; },
       {"/steps/0/scene: \"../secret\" is not the name of a bundled scene"}},
      {"a bundled scene that does not exist", [](J& j) { j["steps"][0]["scene"] = "nonesuch"; },
       {"/steps/0/scene: ", "nonesuch.json"}},
      {"scene and scene_file", [](J& j) { j["steps"][0]["scene_file"] = "x.json"; }, {"/steps/0: a step takes \"scene\" or"}},
      {"an invalid camera (F < B)", [](J& j) { j["steps"][1]["camera"] = {{"front", -9}}; },
       {"/steps/1/camera: invalid camera: "}},
      {"PRP on the view plane", [](J& j) { j["steps"][1]["camera"] = {{"prp", {0, 0, 0}}}; },
       {"/steps/1/camera: invalid camera: "}},
      {"a camera key that is not a number", [](J& j) { j["steps"][1]["camera"] = {{"front", "near"}}; },
       {"/steps/1/camera/front: must be a number, not string"}},
      {"an object the scene lacks", [](J& j) { j["steps"][2]["objects"] = {{"teapot", {{"visible", false}}}}; },
       {"/steps/2/objects/teapot: the scene has no object named \"teapot\"", "\"cube\""}},
      {"an object's key the step cannot change", [](J& j) { j["steps"][2]["objects"] = {{"cube", {{"shape", "sphere"}}}}; },
       {"/steps/2/objects/cube/shape: unknown key"}},
      {"a scale of 0", [](J& j) { j["steps"][2]["objects"] = {{"cube", {{"scale", 0}}}}; },
       {"/steps/2/objects/cube/scale: a scale factor of 0"}},
      {"a vertex beyond the mesh", [](J& j) { j["steps"][2]["probe"]["vertex"] = 8; }, {"/steps/2/probe/vertex: 8 is out of range [0, 7]"}},
      {"a style that does not exist", [](J& j) { j["steps"][1]["views"]["world"]["style"] = "toon"; },
       {"/steps/1/views/world/style: \"toon\" is not flat, shaded, wire, hidden-line or hidden-removed"}},
      {"an orbit for the camera view", [](J& j) { j["steps"][1]["views"]["camera"] = {{"orbit", J::object()}}; },
       {"/steps/1/views/camera/orbit: unknown key"}},
      {"a pitch beyond 89 degrees", [](J& j) { j["steps"][1]["views"]["world"]["orbit"] = {{"pitch_deg", 90}}; },
       {"/steps/1/views/world/orbit/pitch_deg: 90 is out of range"}},
      {"an overlay that does not exist", [](J& j) { j["steps"][1]["overlays"] = {{"grid", true}}; },
       {"/steps/1/overlays/grid: unknown key", "vertex_names"}},
      {"a tab that does not exist", [](J& j) { j["steps"][1]["tab"] = "lights"; }, {"/steps/1/tab: \"lights\" is not camera, scene"}},
      {"a morph beyond DC", [](J& j) { j["steps"][1]["morph"] = 5; }, {"/steps/1/morph: 5 is out of range [0, 4]"}},
      {"a highlight of nothing vplab knows", [](J& j) { j["steps"][1]["highlight"] = {{{"teapot", 1}}}; },
       {"/steps/1/highlight/0/teapot: unknown key; a highlight names one of"}},
      {"a matrix entry out of the matrix", [](J& j) { j["steps"][1]["highlight"] = {{{"matrix", "npcFromVrc"}, {"column", 4}}}; },
       {"/steps/1/highlight/0/column: 4 is out of range [0, 3]"}},
      {"a user plane the scene lacks", [](J& j) { j["steps"][1]["highlight"] = {{{"plane", "user1"}}}; },
       {"/steps/1/highlight/0/plane: \"user1\" is not left, right, bottom, top, back or front"}},
      {"a step-through past the six planes", [](J& j) { j["steps"][1]["step_through"] = {{"object", "cube"}, {"face", 0}, {"plane", 7}}; },
       {"/steps/1/step_through/plane: 7 is out of range [0, 6]"}},
      {"a face beyond the mesh", [](J& j) { j["steps"][1]["step_through"] = {{"object", "cube"}, {"face", 6}}; },
       {"/steps/1/step_through/face: 6 is out of range [0, 5]"}},
      {"a selection the scene lacks", [](J& j) { j["steps"][2]["select"] = "teapot"; },
       {"/steps/2/select: the scene has no object named \"teapot\""}},
      {"free is not a boolean", [](J& j) { j["steps"][2]["free"] = "yes"; }, {"/steps/2/free: must be true or false, not string"}},
      {"a cited value the caption does not say", [](J& j) { j["steps"][1]["cites"] = {"6.44"}; },
       {"/steps/1/cites/0: \"6.44\" is not in the step's caption"}},
      {"a cited value that is no text", [](J& j) { j["steps"][1]["cites"] = {34}; }, {"/steps/1/cites/0: must be a string"}},
      {"too many cited values", [](J& j) { j["steps"][1]["cites"] = J::array(); for (int i = 0; i < 17; ++i) j["steps"][1]["cites"].push_back("a"); },
       {"/steps/1/cites: at most 16 values, not 17"}},
  };
  for (const BadLesson& c : cases) {
    SCOPED_TRACE(c.what);
    J j = threeSteps();
    c.edit(j);
    try {
      parse(j);
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      for (const std::string& part : c.message) EXPECT_THAT(e.what(), HasSubstr(part));
    }
  }
}

TEST(Lesson, LimitsAreCheckedBeforeAnythingIsBuiltForThem) {
  // Each limit alone, lowered below what the three steps need.
  auto message = [](const J& j, const std::function<void(LessonLimits&)>& lower) -> std::string {
    LessonContext small = context();
    lower(small.lessonLimits);
    try {
      parse(j, small);
    } catch (const Error& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_THAT(message(threeSteps(), [](LessonLimits& l) { l.steps = 2; }),
              HasSubstr("/steps: a lesson may have at most 2 steps, not 3"));
  EXPECT_THAT(message(threeSteps(), [](LessonLimits& l) { l.captionBytes = 20; }),
              HasSubstr("/steps/1/caption: is 39 bytes long; a caption may have at most 20"));
  EXPECT_THAT(message(threeSteps(), [](LessonLimits& l) { l.highlights = 2; }),
              HasSubstr("/steps/1/highlight: a step may highlight at most 2 things, not 3"));
  J scenes = threeSteps();
  scenes["steps"][2]["scene"] = "parallel";
  scenes["steps"][2].erase("objects");
  scenes["steps"][2].erase("probe");
  scenes["steps"][2].erase("select");
  EXPECT_THAT(message(scenes, [](LessonLimits& l) { l.scenes = 1; }),
              HasSubstr("/steps/2/scene: a lesson may show at most 1 different scenes"));
  EXPECT_EQ(message(scenes, [](LessonLimits&) {}), "no error");
}

TEST(Lesson, HostileFilesEndInClearErrors) {
  test::TempDir dir;
  // Deep nesting is refused before the tree is built, a key given twice is an error.
  std::string deep = "{\"title\": \"x\", \"language\": \"en\", \"steps\": " + std::string(5000, '[') + std::string(5000, ']') + "}";
  EXPECT_THROW(parseLesson(deep, "deep.json", ".", context()), Error);
  try {
    parseLesson(R"({"title": "a", "title": "b", "language": "en", "steps": []})", "twice.json", ".", context());
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("twice.json"));
    EXPECT_THAT(e.what(), HasSubstr("title"));
  }
  // A special file and a file beyond the size are not read.
  EXPECT_THROW(loadLesson("/dev/zero", context()), Error);
  LessonContext tiny = context();
  tiny.lessonLimits.fileBytes = 10;
  const auto big = dir.write("big.json", threeSteps().dump());
  try {
    loadLesson(big, tiny);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("big.json"));
  }
  try {
    loadLesson(dir.path / "missing.json", context());
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("missing.json"));
  }
}

}  // namespace
}  // namespace vplab

namespace vplab {
namespace {

TEST(Lesson, TheStepThroughGoesOnThroughTheEnabledUserPlanes) {
  // clip-planes.json has two user planes, both enabled: the passes are the six, then those two.
  auto step = [](int plane, bool secondEnabled) {
    J j{{"title", "Planes"},
        {"language", "en"},
        {"steps", {{{"caption", "x"}, {"scene", "clip-planes"}, {"step_through", {{"object", "cube"}, {"face", 0}, {"plane", plane}}}}}}};
    if (!secondEnabled) j["steps"][0]["clip_planes"] = {{{"normal", {1, 0, 0}}, {"point", {0, 0, 0}}}, {{"normal", {0, 1, 0}}, {"point", {0, 0, 0}}, {"enabled", false}}};
    return parse(j).steps[0].state.stepThrough->plane;
  };
  EXPECT_EQ(step(8, true), 8);
  EXPECT_THROW(step(9, true), Error);
  EXPECT_EQ(step(7, false), 7);
  EXPECT_THROW(step(8, false), Error);
}

}  // namespace
}  // namespace vplab
