// Scene files (scene_io.h): loading, every kind of bad input with the JSON path (or file:line:col)
// in the message, and the save/load round trip.
#include "io/scene_io.h"

#include "pipeline/pipeline.h"
#include "pipeline/view_mapping.h"
#include "tests/support/test_util.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <limits>
#include <fstream>

namespace vplab {
namespace {

namespace fs = std::filesystem;
using test::errorOf;
using test::readFile;
using test::TempDir;
using testing::HasSubstr;

const std::string kData = VPLAB_TEST_DATA;

// A minimal valid scene as JSON, edited by the cases below.
nlohmann::json minimalScene() {
  return nlohmann::json::parse(R"({
    "camera": {"vrp": [0, 0, 0], "prp": [0, 0, 5], "vup": [0, 1, 0],
               "window": {"xmin": -1, "xmax": 1, "ymin": -0.75, "ymax": 0.75},
               "front": 2, "back": -2},
    "objects": [{"shape": "cube"}]
  })");
}

TEST(SceneIo, MinimalSceneGetsTheDefaults) {
  const Scene s = parseScene(minimalScene().dump(), "min.json", kData);
  const Camera c = test::checkCamera();
  EXPECT_EQ(s.camera.vrp, c.vrp);
  EXPECT_EQ(s.camera.prp, c.prp);
  EXPECT_EQ(s.camera.projection, Projection::perspective);  // the default
  EXPECT_EQ(s.device.width, Device{}.width);
  EXPECT_EQ(s.device.height, Device{}.height);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].name, "cube 0");  // shape and index when unnamed
  EXPECT_EQ(s.objects[0].shape, Shape::cube);
  ASSERT_TRUE(s.objects[0].mesh);
  EXPECT_EQ(s.objects[0].mesh->vertexCount(), 8u);
  EXPECT_TRUE(s.lights.empty());
}

TEST(SceneIo, LoadSceneWithMeshFile) {
  const Scene s = loadScene(kData + "/scene_mesh.json");
  EXPECT_EQ(s.path, fs::path(kData + "/scene_mesh.json"));
  EXPECT_EQ(s.camera.prp, Vec3(3, 2.5, 4));
  EXPECT_EQ(s.device.width, 320);
  EXPECT_EQ(s.background, Vec3(0.1, 0.2, 0.3));
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].color, Vec3(1, 0.9, 0.8));
  ASSERT_EQ(s.objects.size(), 3u);
  const SceneObject& box = s.objects[0];
  EXPECT_EQ(box.shape, Shape::mesh);
  EXPECT_EQ(box.file, "box_quads_normals.obj");  // kept relative, as written
  ASSERT_TRUE(box.mesh);
  EXPECT_EQ(box.mesh->faceCount(), 6u);
  ASSERT_EQ(box.transform.rotations.size(), 1u);
  EXPECT_EQ(box.transform.rotations[0].through, Vec3(0.5));
  EXPECT_EQ(box.transform.scale, Vec3(1));
  const SceneObject& ball = s.objects[1];
  EXPECT_EQ(ball.segments, 8);
  EXPECT_EQ(ball.mesh->vertexCount(), 2u + 3u * 8u);
  EXPECT_EQ(ball.transform.scale, Vec3(0.5, 0.5, 0.25));
  EXPECT_EQ(s.objects[2].name, "cube 2");
  EXPECT_FALSE(s.objects[2].visible);
  // And it runs: the invisible object is skipped.
  const PipelineRun run = runPipeline(s);
  EXPECT_EQ(run.objects.size(), 2u);
  EXPECT_EQ(run.sceneIndex, (std::vector<size_t>{0, 1}));
}

// A scene that carries its mesh (issue 24: a scene saved in the page named an OBJ by its in-page
// path): the OBJ text in "obj" instead of a "file"; read as strictly as an OBJ file, one of the
// two, written back as it was read. carryingItsMeshes reads every OBJ file into its object.
TEST(SceneIo, AMeshCarriedInTheScene) {
  nlohmann::json j = minimalScene();
  j["objects"][0] = {{"shape", "mesh"}, {"name", "tri"}, {"obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}};
  const Scene s = parseScene(j.dump(), "carried.json", "/nowhere");
  ASSERT_TRUE(s.objects[0].mesh);
  EXPECT_EQ(s.objects[0].mesh->faceCount(), 1u);
  EXPECT_TRUE(s.objects[0].file.empty());
  const Scene again = parseScene(sceneToJson(s), "again.json", "/nowhere");
  ASSERT_TRUE(again.objects[0].obj);
  EXPECT_EQ(*again.objects[0].obj, *s.objects[0].obj);

  j["objects"][0]["obj"] = "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
  EXPECT_THAT(errorOf([&] { parseScene(j.dump(), "bad.json", "/nowhere"); }),
              testing::AllOf(HasSubstr("bad.json: /objects/0"), HasSubstr("tri (its OBJ in the scene)"), HasSubstr(":3")));
  j["objects"][0]["file"] = "x.obj";
  EXPECT_THAT(errorOf([&] { parseScene(j.dump(), "both.json", "/nowhere"); }),
              HasSubstr("a mesh takes \"file\" (an OBJ file) or \"obj\" (the OBJ text), not both"));
  j["objects"][0].erase("file");
  j["objects"][0].erase("obj");
  EXPECT_THAT(errorOf([&] { parseScene(j.dump(), "neither.json", "/nowhere"); }), HasSubstr("/objects/0: a mesh needs \"file\" (an OBJ file) or \"obj\" (the OBJ text)"));
  j["objects"][0] = {{"shape", "cube"}, {"obj", "v 0 0 0"}};
  EXPECT_THAT(errorOf([&] { parseScene(j.dump(), "cube.json", "/nowhere"); }), HasSubstr("/objects/0/obj: is only for mesh"));
}

TEST(SceneIo, CarryingItsMeshesReadsEachObjFile) {
  const Scene s = loadScene(kData + "/scene_mesh.json");  // box_quads_normals.obj beside it
  const Scene carried = carryingItsMeshes(s);
  ASSERT_TRUE(carried.objects[0].obj);
  EXPECT_TRUE(carried.objects[0].file.empty());
  EXPECT_EQ(*carried.objects[0].obj, readFile(kData + "/box_quads_normals.obj"));
  EXPECT_EQ(s.objects[0].file, "box_quads_normals.obj") << "the scene itself keeps its file";
  // Opened elsewhere (no OBJ beside it), the same mesh.
  const Scene opened = parseScene(sceneToJson(carried), "elsewhere.json", "/nowhere");
  ASSERT_TRUE(opened.objects[0].mesh);
  EXPECT_EQ(opened.objects[0].mesh->positions, s.objects[0].mesh->positions);
  EXPECT_EQ(opened.objects[0].mesh->faceCount(), s.objects[0].mesh->faceCount());
  // A missing OBJ is named; so is a scene that would be larger than a scene file may be.
  Scene lost = s;
  lost.objects[0].file = "gone.obj";
  EXPECT_THAT(errorOf([&] { carryingItsMeshes(lost); }), HasSubstr("gone.obj"));
  Limits small;
  small.sceneFileBytes = 1024;
  EXPECT_THAT(errorOf([&] { carryingItsMeshes(s, small); }),
              HasSubstr("more than a scene file may be (1 kB): keep the OBJ files beside the scene"));
}

TEST(SceneIo, SyntaxErrorNamesFileLineAndColumn) {
  // The stray comma is on line 3, column 18.
  const std::string text = "{\n  \"camera\": {\n    \"vrp\": [0, 0,, 0]\n  }\n}\n";
  EXPECT_THAT(errorOf([&] { parseScene(text, "broken.json", "."); }), HasSubstr("broken.json:3:18: JSON syntax error"));
  EXPECT_THAT(errorOf([&] { parseScene("", "empty.json", "."); }), HasSubstr("empty.json:1:1: JSON syntax error"));
  EXPECT_THAT(errorOf([&] { parseScene("{\"objects\": []", "eof.json", "."); }), HasSubstr("eof.json:1:"));
}

struct BadScene {
  const char* what;
  std::function<void(nlohmann::json&)> edit;
  std::vector<std::string> parts;  // each must appear in the message
};

TEST(SceneIo, BadScenesNameTheJsonPath) {
  using J = nlohmann::json;
  const std::vector<BadScene> cases = {
      {"top-level unknown key", [](J& j) { j["colour"] = 1; }, {"bad.json: /colour: unknown key", "camera, device"}},
      {"unknown key in an object", [](J& j) { j["objects"][0]["colour"] = {1, 0, 0}; },
       {"bad.json: /objects/0/colour: unknown key", "color"}},
      {"unknown key in the window", [](J& j) { j["camera"]["window"]["xmn"] = 0; }, {"/camera/window/xmn: unknown key"}},
      {"unknown key in a rotation", [](J& j) { j["objects"][0]["rotate"] = {{{"axis", {0, 1, 0}}, {"angle", 3}}}; },
       {"/objects/0/rotate/0/angle: unknown key"}},
      {"unknown key in a light", [](J& j) { j["lights"] = {{{"position", {1, 2, 3}}, {"intensity", 2}}}; },
       {"/lights/0/intensity: unknown key"}},
      {"not an object", [](J& j) { j = J::array(); }, {"bad.json: /: must be an object, not array"}},
      {"a German name that is no text", [](J& j) { j["objects"][0]["name_de"] = 3; }, {"bad.json: /objects/0/name_de: "}},
      {"a German title that is no text", [](J& j) { j["title_de"] = J::array(); }, {"bad.json: /title_de: "}},
      {"vrp a string", [](J& j) { j["camera"]["vrp"] = "origin"; }, {"/camera/vrp: must be an array of 3 numbers, not string"}},
      {"vrp of 2", [](J& j) { j["camera"]["vrp"] = {0, 0}; }, {"/camera/vrp: must be an array of 3 numbers, not an array of 2"}},
      {"vup element a bool", [](J& j) { j["camera"]["vup"][1] = true; }, {"/camera/vup/1: must be a number, not boolean"}},
      {"front a string", [](J& j) { j["camera"]["front"] = "2"; }, {"/camera/front: must be a number, not string"}},
      {"projection unknown", [](J& j) { j["camera"]["projection"] = "fisheye"; },
       {"/camera/projection: \"fisheye\" is not one of perspective, parallel, oblique"}},
      {"projection a number", [](J& j) { j["camera"]["projection"] = 1; }, {"/camera/projection: must be a string"}},
      {"visible a number", [](J& j) { j["objects"][0]["visible"] = 1; }, {"/objects/0/visible: must be true or false, not number"}},
      {"segments not an integer", [](J& j) { j["objects"][0] = {{"shape", "sphere"}, {"segments", 8.5}}; },
       {"/objects/0/segments: must be an integer"}},
      {"objects not an array", [](J& j) { j["objects"] = {{"shape", "cube"}}; }, {"/objects: must be an array, not object"}},
      {"name a number", [](J& j) { j["objects"][0]["name"] = 3; }, {"/objects/0/name: must be a string"}},
      {"shape unknown", [](J& j) { j["objects"][0]["shape"] = "torus"; }, {"/objects/0/shape: \"torus\" is not one of"}},
      {"missing camera", [](J& j) { j.erase("camera"); }, {"bad.json: /: missing required key \"camera\""}},
      {"missing objects", [](J& j) { j.erase("objects"); }, {"bad.json: /: missing required key \"objects\""}},
      {"missing vrp", [](J& j) { j["camera"].erase("vrp"); }, {"/camera: missing required key \"vrp\""}},
      {"missing window ymax", [](J& j) { j["camera"]["window"].erase("ymax"); }, {"/camera/window: missing required key \"ymax\""}},
      {"missing shape", [](J& j) { j["objects"][0].erase("shape"); }, {"/objects/0: missing required key \"shape\""}},
      {"missing polygon vertices", [](J& j) { j["objects"][0] = {{"shape", "polygon"}}; },
       {"/objects/0: missing required key \"vertices\""}},
      {"missing mesh file", [](J& j) { j["objects"][0] = {{"shape", "mesh"}}; }, {"/objects/0: a mesh needs \"file\" (an OBJ file) or \"obj\" (the OBJ text)"}},
      {"missing device height", [](J& j) { j["device"] = {{"width", 10}}; }, {"/device: missing required key \"height\""}},
      {"missing rotation deg", [](J& j) { j["objects"][0]["rotate"] = {{{"axis", {0, 1, 0}}}}; },
       {"/objects/0/rotate/0: missing required key \"deg\""}},
      {"colour above 1", [](J& j) { j["objects"][0]["color"] = {1.5, 0, 0}; }, {"/objects/0/color/0: 1.5 is out of range [0, 1]"}},
      {"background below 0", [](J& j) { j["background"] = {0, -0.1, 0}; }, {"/background/1: -0.1 is out of range [0, 1]"}},
      {"device width 0", [](J& j) { j["device"] = {{"width", 0}, {"height", 10}}; }, {"/device/width: 0 is out of range [1, 16384]"}},
      {"device height huge", [](J& j) { j["device"] = {{"width", 10}, {"height", 100000}}; }, {"/device/height: 100000 is out of range"}},
      {"sphere with odd segments", [](J& j) { j["objects"][0] = {{"shape", "sphere"}, {"segments", 7}}; },
       {"/objects/0/segments: a sphere needs an even number of segments, not 7"}},
      {"sphere with 2 segments", [](J& j) { j["objects"][0] = {{"shape", "sphere"}, {"segments", 2}}; },
       {"/objects/0/segments: 2 is out of range [4, 2048]"}},
      {"cylinder with 2 segments", [](J& j) { j["objects"][0] = {{"shape", "cylinder"}, {"segments", 2}}; },
       {"/objects/0/segments: 2 is out of range [3, 2048]"}},
      {"segments on a cube", [](J& j) { j["objects"][0]["segments"] = 8; },
       {"/objects/0/segments: is only for cylinder and sphere, not for a cube"}},
      {"vertices on a sphere", [](J& j) { j["objects"][0] = {{"shape", "sphere"}, {"vertices", J::array()}}; },
       {"/objects/0/vertices: is only for polygon"}},
      {"file on a cube", [](J& j) { j["objects"][0]["file"] = "x.obj"; }, {"/objects/0/file: is only for mesh"}},
      {"polygon of 2", [](J& j) { j["objects"][0] = {{"shape", "polygon"}, {"vertices", {{0, 0, 0}, {1, 0, 0}}}}; },
       {"/objects/0/vertices: a polygon needs at least 3 vertices, not 2"}},
      {"polygon vertex of 2", [](J& j) { j["objects"][0] = {{"shape", "polygon"}, {"vertices", {{0, 0, 0}, {1, 0, 0}, {1, 1}}}}; },
       {"/objects/0/vertices/2: must be an array of 3 numbers"}},
      {"scale 0", [](J& j) { j["objects"][0]["scale"] = 0; }, {"/objects/0/scale: a scale factor of 0 flattens the object"}},
      {"scale with a 0", [](J& j) { j["objects"][0]["scale"] = {1, 0, 1}; }, {"/objects/0/scale: a scale factor of 0"}},
      {"zero rotation axis", [](J& j) { j["objects"][0]["rotate"] = {{{"axis", {0, 0, 0}}, {"deg", 3}}}; },
       {"/objects/0/rotate/0/axis: the rotation axis must not be the zero vector"}},
      {"oblique d negative", [](J& j) { j["camera"]["oblique"] = {{"d", -1}, {"phi_deg", 30}}; },
       {"/camera/oblique/d: -1 is out of range"}},
      {"missing mesh file on disk", [](J& j) { j["objects"][0] = {{"shape", "mesh"}, {"file", "nope.obj"}}; },
       {"bad.json: /objects/0: ", "nope.obj: cannot open the OBJ file"}},
      {"bad OBJ on disk", [](J& j) { j["objects"][0] = {{"shape", "mesh"}, {"file", "bad_vertex.obj"}}; },
       {"bad.json: /objects/0: ", "bad_vertex.obj:5: 'zero' is not a finite number"}},
      {"invalid camera PRP = VRP", [](J& j) { j["camera"]["prp"] = {0, 0, 0}; },
       {"bad.json: /camera: invalid camera: PRP (0, 0, 0) equals VRP (0, 0, 0)"}},
      {"invalid camera F >= VPD", [](J& j) { j["camera"]["front"] = 5; }, {"/camera: invalid camera: ", "F < VPD"}},
      {"invalid camera window", [](J& j) { j["camera"]["window"]["xmin"] = 2; }, {"/camera: invalid camera: ", "xmin = 2, xmax = 1"}},
      {"invalid camera VUP parallel", [](J& j) { j["camera"]["vup"] = {0, 0, 1}; }, {"/camera: invalid camera: VUP (0, 0, 1) is parallel"}},
  };
  for (const BadScene& c : cases) {
    SCOPED_TRACE(c.what);
    nlohmann::json j = minimalScene();
    c.edit(j);
    const std::string message = errorOf([&] { parseScene(j.dump(2), "bad.json", kData); });
    for (const std::string& part : c.parts) EXPECT_THAT(message, HasSubstr(part));
  }
}

TEST(SceneIo, LoadSceneErrorsNameTheFile) {
  EXPECT_THAT(errorOf([] { loadScene(kData + "/missing.json"); }),
              HasSubstr(kData + "/missing.json: cannot open the scene file"));
  TempDir dir;
  std::ofstream(dir.path / "bad.json") << "{\n  \"camera\": 1\n}\n";
  EXPECT_THAT(errorOf([&] { loadScene(dir.path / "bad.json"); }),
              HasSubstr((dir.path / "bad.json").string() + ": /camera: must be an object, not number"));
}

// Field by field: what a scene file holds.
void expectSameScene(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.title, b.title);
  EXPECT_EQ(a.caption, b.caption);
  EXPECT_EQ(a.titleDe, b.titleDe);
  EXPECT_EQ(a.captionDe, b.captionDe);
  EXPECT_EQ(a.camera.vrp, b.camera.vrp);
  EXPECT_EQ(a.camera.prp, b.camera.prp);
  EXPECT_EQ(a.camera.vup, b.camera.vup);
  EXPECT_EQ(a.camera.window.xmin, b.camera.window.xmin);
  EXPECT_EQ(a.camera.window.xmax, b.camera.window.xmax);
  EXPECT_EQ(a.camera.window.ymin, b.camera.window.ymin);
  EXPECT_EQ(a.camera.window.ymax, b.camera.window.ymax);
  EXPECT_EQ(a.camera.front, b.camera.front);
  EXPECT_EQ(a.camera.back, b.camera.back);
  EXPECT_EQ(a.camera.projection, b.camera.projection);
  if (a.camera.projection == Projection::oblique) {
    EXPECT_EQ(a.camera.oblique.d, b.camera.oblique.d);
    EXPECT_EQ(a.camera.oblique.phiDeg, b.camera.oblique.phiDeg);
  }
  EXPECT_EQ(a.device.width, b.device.width);
  EXPECT_EQ(a.device.height, b.device.height);
  EXPECT_EQ(a.background, b.background);
  ASSERT_EQ(a.lights.size(), b.lights.size());
  for (size_t i = 0; i < a.lights.size(); ++i) {
    EXPECT_EQ(a.lights[i].position, b.lights[i].position);
    EXPECT_EQ(a.lights[i].color, b.lights[i].color);
  }
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (size_t i = 0; i < a.objects.size(); ++i) {
    const SceneObject &x = a.objects[i], &y = b.objects[i];
    SCOPED_TRACE(x.name);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.nameDe, y.nameDe);
    EXPECT_EQ(x.shape, y.shape);
    if (x.shape == Shape::sphere || x.shape == Shape::cylinder) {
      EXPECT_EQ(x.segments, y.segments);
    }
    EXPECT_EQ(x.vertices, y.vertices);
    EXPECT_EQ(x.file, y.file);
    EXPECT_EQ(x.color, y.color);
    EXPECT_EQ(x.visible, y.visible);
    EXPECT_EQ(x.transform.translate, y.transform.translate);
    EXPECT_EQ(x.transform.scale, y.transform.scale);
    ASSERT_EQ(x.transform.rotations.size(), y.transform.rotations.size());
    for (size_t r = 0; r < x.transform.rotations.size(); ++r) {
      EXPECT_EQ(x.transform.rotations[r].axis, y.transform.rotations[r].axis);
      EXPECT_EQ(x.transform.rotations[r].deg, y.transform.rotations[r].deg);
      EXPECT_EQ(x.transform.rotations[r].through, y.transform.rotations[r].through);
    }
    ASSERT_TRUE(x.mesh && y.mesh);
    EXPECT_EQ(x.mesh->positions, y.mesh->positions);
    EXPECT_EQ(x.mesh->indices, y.mesh->indices);
  }
}

Scene richScene() {
  Scene s = loadScene(kData + "/scene_mesh.json");
  s.camera.projection = Projection::oblique;
  s.camera.oblique = {0.7, -33.3};
  s.camera.window = {-1.0 / 3, 0.1, -0.2, 1e-7};  // values without short decimal forms
  s.background = {0.1, 0.2, 1.0 / 3};
  s.lights.push_back({{-1, 2.5, 1e10}, {0, 0, 0}});
  s.objects.push_back(test::polygonObject("tri", {{0, 0, 0}, {1.0 / 7, 0, 0}, {0, 1, -2.5}}));
  ModelTransform t;
  t.translate = {1, 2, 3};
  t.rotations = {{{0, 0, 1}, 33.3, {}}, {{1, 1, 0}, -10, Vec3(0.1, 0.2, 0.3)}};
  t.scale = {2, 2, 2};
  s.objects.push_back(test::shapeObject("can", Shape::cylinder, t, 9));
  s.objects.back().color = {0, 1, 0.123456789012345};
  s.objects.back().nameDe = "Dose";
  s.title = "Rich \"scene\"";
  s.titleDe = "Reiche „Szene“";
  s.captionDe = "Jedes Feld des Formats.";
  s.caption = "Every field of the format, with values that need all 17 digits: ü, ∞.";
  return s;
}

TEST(SceneIo, RoundTripKeepsEverything) {
  const Scene s = richScene();
  const std::string text = sceneToJson(s);
  const Scene back = parseScene(text, "round.json", kData);
  expectSameScene(s, back);
  EXPECT_EQ(sceneToJson(back), text);  // stable
  // The written text is the documented format: 2-space indentation, a trailing newline.
  EXPECT_EQ(text.substr(0, 5), "{\n  \"");
  EXPECT_NE(text.find("\n  \"camera\": {\n    \"vrp\": ["), std::string::npos);
  EXPECT_EQ(text.back(), '\n');
  // The default lecture scene too.
  const Scene d = defaultScene();
  expectSameScene(d, parseScene(sceneToJson(d), "default.json", kData));
}

// Every scene shipped in assets/scenes loads, has a valid camera, runs through every strategy
// without NaN, and survives the save/load round trip; default.json is the built-in default scene.
TEST(SceneIo, ShippedScenesLoadAndRun) {
  const fs::path dir = fs::path(VPLAB_ASSETS) / "scenes";
  int scenes = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    ++scenes;
    Scene s;
    ASSERT_EQ(errorOf([&] { s = loadScene(entry.path()); }), "<no exception thrown>");
    EXPECT_EQ(cameraError(s.camera), std::nullopt);
    for (ClipStrategy strategy : {ClipStrategy::npc, ClipStrategy::wc, ClipStrategy::divideFirst}) {
      const PipelineRun run = runPipeline(s, {strategy, false, true});
      for (const ObjectRun& o : run.objects) {
        for (const Vec4& p : o.npcH) ASSERT_TRUE(isFinite(p));
        for (size_t f = 0; f < o.faceCount(); ++f)
          for (uint32_t ref : o.clippedFace(f)) ASSERT_TRUE(isFinite(o.clippedDc(ref)));
      }
    }
    expectSameScene(s, parseScene(sceneToJson(s), "again", entry.path().parent_path()));
  }
  EXPECT_GT(scenes, 0);
  // A link names the built-in scene "default", i.e. this file (Viewer::urlState): it must be there.
  ASSERT_TRUE(fs::exists(dir / "default.json"));
  Scene fromFile = loadScene(dir / "default.json");
  Scene builtIn = defaultScene();
  fromFile.title = builtIn.title;  // presentation only
  fromFile.caption = builtIn.caption;
  fromFile.titleDe = builtIn.titleDe;
  fromFile.captionDe = builtIn.captionDe;
  expectSameScene(builtIn, fromFile);
}

// German throughout (issue 37): every shipped scene has its title, caption and each object's name in
// German too, and the German differs from the English where it is a sentence (not copied over).
TEST(SceneIo, ShippedScenesSpeakGerman) {
  for (const auto& entry : fs::directory_iterator(fs::path(VPLAB_ASSETS) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().filename().string());
    const Scene s = loadScene(entry.path());
    EXPECT_FALSE(s.titleDe.empty());
    EXPECT_FALSE(s.captionDe.empty());
    EXPECT_NE(s.captionDe, s.caption);
    for (const SceneObject& o : s.objects) EXPECT_FALSE(o.nameDe.empty()) << o.name;
    EXPECT_EQ(titleIn(s, Language::de), s.titleDe);
    EXPECT_EQ(titleIn(s, Language::en), s.title);
  }
}

TEST(SceneIo, SaveSceneWritesAtomically) {
  TempDir dir;
  Scene s = richScene();
  // Mesh files resolve relative to the scene file: make the reference absolute for the copy.
  s.objects[0].file = kData + "/box_quads_normals.obj";
  const fs::path file = dir.path / "scene.json";
  std::ofstream(file) << "old contents";
  saveScene(s, file);
  EXPECT_EQ(readFile(file), sceneToJson(s));
  // Only the target remains: the temporary file was renamed over it.
  std::vector<fs::path> entries;
  for (const auto& e : fs::directory_iterator(dir.path)) entries.push_back(e.path().filename());
  EXPECT_EQ(entries, std::vector<fs::path>{"scene.json"});
  const Scene back = loadScene(file);
  expectSameScene(s, back);
  EXPECT_EQ(back.path, file);

  // A target that cannot be replaced (a non-empty directory): an error naming the file, nothing
  // else changed and no temporary file left behind.
  const fs::path blocked = dir.path / "blocked.json";
  fs::create_directories(blocked / "inside");
  EXPECT_THAT(errorOf([&] { saveScene(s, blocked); }), HasSubstr(blocked.string() + ": cannot replace the scene file"));
  EXPECT_TRUE(fs::is_directory(blocked / "inside"));
  EXPECT_FALSE(fs::exists(blocked.string() + ".tmp"));
  // A directory that does not exist.
  const fs::path nowhere = dir.path / "no" / "such" / "dir.json";
  EXPECT_THAT(errorOf([&] { saveScene(s, nowhere); }), HasSubstr(nowhere.string() + ": cannot write the scene file"));
  EXPECT_EQ(readFile(file), sceneToJson(s));  // the earlier file is untouched
}

// User clip planes (DGL wiki, glClipPlane) in scene files.
TEST(SceneIo, UserClipPlanesAreReadAndWritten) {
  const std::string base = R"({"camera": {"vrp": [0,0,0], "prp": [0,0,5], "vup": [0,1,0],
      "window": {"xmin": -1, "xmax": 1, "ymin": -1, "ymax": 1}, "front": 2, "back": -2}, "objects": [],
      "clip_planes": )";
  const Scene s = parseScene(base + R"([{"normal": [1,0,0], "point": [0.5,0,0]},
                                        {"normal": [0,1,0], "point": [0,0,0], "enabled": false}]})",
                             "planes.json", {});
  ASSERT_EQ(s.clipPlanes.size(), 2u);
  EXPECT_EQ(s.clipPlanes[0].coefficients(), Vec4(1, 0, 0, -0.5));
  EXPECT_FALSE(s.clipPlanes[1].enabled);
  EXPECT_EQ(parseScene(sceneToJson(s), "again", {}).clipPlanes, s.clipPlanes) << "round trip";
  auto error = [&](const std::string& planes) {
    return test::errorOf([&] { parseScene(base + planes + "}", "planes.json", {}); });
  };
  EXPECT_THAT(error(R"([{"normal": [0,0,0], "point": [0,0,0]}])"), HasSubstr("/clip_planes/0/normal"));
  EXPECT_THAT(error(R"([{"point": [0,0,0]}])"), HasSubstr("missing required key \"normal\""));
  EXPECT_THAT(error(R"([{"normal": [1,0,0], "point": [0,0,0], "side": 1}])"), HasSubstr("/clip_planes/0/side"));
  std::string seven = "[";
  for (int i = 0; i < 7; ++i) seven += std::string(i ? "," : "") + R"({"normal": [1,0,0], "point": [0,0,0]})";
  EXPECT_THAT(error(seven + "]"), HasSubstr("at most 6 user clip planes"));
}

// The page's way (app/document/loader.h): a worker parses the scene and builds its meshes; the page
// parses the same text again with them. The scene is the same, its meshes the very ones handed in;
// a wrong number of meshes, a malformed mesh or one over the limits is an error naming the object.
TEST(SceneIo, ParsesWithMeshesBuiltElsewhere) {
  const std::string text = readFile(kData + "/scene_mesh.json");
  const Scene built = parseScene(text, "scene_mesh.json", kData);
  ASSERT_GE(built.objects.size(), 2u);
  BuiltMeshes meshes;
  for (const SceneObject& o : built.objects) meshes.push_back(o.mesh);
  const Scene again = parseScene(text, "scene_mesh.json", kData, kDefaultLimits, &meshes);
  ASSERT_EQ(again.objects.size(), built.objects.size());
  for (size_t i = 0; i < again.objects.size(); ++i) EXPECT_EQ(again.objects[i].mesh, meshes[i]);
  EXPECT_EQ(sceneToJson(again), sceneToJson(built));

  BuiltMeshes fewer(meshes.begin(), meshes.end() - 1);
  EXPECT_THAT(errorOf([&] { parseScene(text, "scene_mesh.json", kData, kDefaultLimits, &fewer); }),
              HasSubstr("/objects/" + std::to_string(meshes.size() - 1) + ": no mesh was built for it"));
  auto broken = std::make_shared<Mesh>(*meshes[0]);
  broken->indices[1] = uint32_t(broken->positions.size());
  BuiltMeshes bad = meshes;
  bad[0] = broken;
  EXPECT_THAT(errorOf([&] { parseScene(text, "scene_mesh.json", kData, kDefaultLimits, &bad); }),
              HasSubstr("/objects/0: index 1 names vertex " + std::to_string(broken->positions.size()) + " of " +
                        std::to_string(broken->positions.size())));
  auto nan = std::make_shared<Mesh>(*meshes[0]);
  nan->positions[0].y = std::numeric_limits<double>::quiet_NaN();
  bad[0] = nan;
  EXPECT_THAT(errorOf([&] { parseScene(text, "scene_mesh.json", kData, kDefaultLimits, &bad); }),
              HasSubstr("/objects/0: vertex 0 is not finite"));
  Limits small;
  small.vertices = meshes[0]->vertexCount() - 1;
  EXPECT_THAT(errorOf([&] { parseScene(text, "scene_mesh.json", kData, small, &meshes); }), HasSubstr("/objects/0: "));
}

}  // namespace
}  // namespace vplab
