// SceneLoader with a remote builder (the page's loader worker, app/document/loader.h): the file is read
// here and its text handed on; the meshes that come back make the scene, parsed again here; an
// answer to a cancelled or replaced request is dropped; errors end the load and keep the open
// scene. The "worker" in these tests is the same parseScene the page's worker runs.
#include "app/document/loader.h"

#include "io/build_mesh.h"
#include "io/scene_io.h"
#include "tests/support/files.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace vplab {
namespace {

using testing::HasSubstr;

const std::filesystem::path kData = VPLAB_TEST_DATA;

/// scene_mesh.json with its sphere at 512 segments (130 000 faces): over what is read at once.
std::filesystem::path largeScene(const test::TempDir& dir) {
  std::string text = test::readFile(kData / "scene_mesh.json");
  const std::string small = "\"segments\": 8", large = "\"segments\": 512";
  text.replace(text.find(small), small.size(), large);
  const std::string box = "\"box_quads_normals.obj\"";
  text.replace(text.find(box), box.size(), "\"" + (kData / "box_quads_normals.obj").string() + "\"");
  return dir.write("large.json", text);
}

/// An OBJ grid of n × n squares, two triangles each.
std::string gridObj(int n) {
  std::string obj;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) obj += "v " + std::to_string(x) + " " + std::to_string(y) + " 0\n";
  auto at = [n](int x, int y) { return std::to_string(y * (n + 1) + x + 1); };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      obj += "f " + at(x, y) + " " + at(x + 1, y) + " " + at(x + 1, y + 1) + "\n";
      obj += "f " + at(x, y) + " " + at(x + 1, y + 1) + " " + at(x, y + 1) + "\n";
    }
  return obj;
}

struct Request {
  uint64_t id;
  std::string text, source;
  std::filesystem::path baseDir;
};

struct RemoteLoader {
  SceneLoader loader;
  std::vector<Request> sent;
  RemoteLoader() {
    loader.useRemote([this](uint64_t id, const std::string& text, const std::string& source, const std::filesystem::path& baseDir) {
      sent.push_back({id, text, source, baseDir});
    });
  }
  /// Answers request `r` as the page's worker does.
  void answer(const Request& r) {
    BuiltMeshes meshes;
    std::string error;
    try {
      for (const SceneObject& o : parseScene(r.text, r.source, r.baseDir).objects) meshes.push_back(o.mesh);
    } catch (const std::exception& e) {
      error = e.what();
    }
    loader.deliver(r.id, std::move(meshes), std::move(error));
  }
};

// A small scene is read at once, as before: the worker's start would cost more than its reading.
TEST(SceneLoaderRemote, ASmallSceneIsReadAtOnce) {
  RemoteLoader r;
  const std::filesystem::path file = kData / "scene_mesh.json";
  r.loader.start(file);
  EXPECT_TRUE(r.sent.empty());
  std::optional<SceneLoader::Loaded> loaded = r.loader.poll();
  ASSERT_TRUE(loaded && loaded->scene) << (loaded ? loaded->error : "nothing");
  EXPECT_EQ(sceneToJson(*loaded->scene), sceneToJson(loadScene(file)));
  EXPECT_EQ(loaded->scene->path, file);
}

TEST(SceneLoaderRemote, TheWorkersMeshesMakeTheScene) {
  RemoteLoader r;
  ASSERT_TRUE(r.loader.remote());
  const test::TempDir dir;
  const std::filesystem::path file = largeScene(dir);
  r.loader.start(file);
  EXPECT_TRUE(r.loader.busy());
  ASSERT_EQ(r.sent.size(), 1u);
  EXPECT_EQ(r.sent[0].source, file.string());
  EXPECT_EQ(r.sent[0].baseDir, dir.path);
  EXPECT_FALSE(r.loader.poll()) << "done before the worker answered";
  r.answer(r.sent[0]);
  std::optional<SceneLoader::Loaded> loaded = r.loader.poll();
  ASSERT_TRUE(loaded && loaded->scene) << (loaded ? loaded->error : "nothing");
  EXPECT_FALSE(r.loader.busy());
  EXPECT_EQ(loaded->scene->path, file);
  EXPECT_EQ(sceneToJson(*loaded->scene), sceneToJson(loadScene(file)));
  ASSERT_TRUE(loaded->scene->objects[0].mesh);
  EXPECT_EQ(loaded->scene->objects[1].mesh->faceCount(), loadScene(file).objects[1].mesh->faceCount());
  EXPECT_GT(loaded->scene->objects[1].mesh->faceCount(), 50'000u);
}

TEST(SceneLoaderRemote, AnAnswerToACancelledOrReplacedRequestIsDropped) {
  RemoteLoader r;
  const test::TempDir dir;
  const std::filesystem::path file = largeScene(dir);
  r.loader.start(file);
  r.loader.cancel();
  EXPECT_FALSE(r.loader.busy());
  r.answer(r.sent[0]);
  EXPECT_FALSE(r.loader.poll());
  EXPECT_FALSE(r.loader.busy());

  r.loader.start(file);
  r.loader.start(file);  // replaces the first
  ASSERT_EQ(r.sent.size(), 3u);
  r.answer(r.sent[1]);
  EXPECT_FALSE(r.loader.poll()) << "the replaced request's answer was taken";
  r.answer(r.sent[2]);
  EXPECT_TRUE(r.loader.poll());
}

TEST(SceneLoaderRemote, ErrorsEndTheLoad) {
  RemoteLoader r;
  r.loader.start(kData / "no-such-scene.json");  // read here: never sent
  EXPECT_TRUE(r.sent.empty());
  std::optional<SceneLoader::Loaded> loaded = r.loader.poll();
  ASSERT_TRUE(loaded);
  EXPECT_FALSE(loaded->scene);
  EXPECT_THAT(loaded->error, HasSubstr("no-such-scene.json"));

  const test::TempDir dir;
  const std::filesystem::path file = largeScene(dir);
  r.loader.start(file);
  r.loader.deliver(r.sent.back().id, {}, "the page's loader stopped (out of memory)");
  loaded = r.loader.poll();
  ASSERT_TRUE(loaded);
  EXPECT_EQ(loaded->error, "the page's loader stopped (out of memory)");

  // Meshes that do not fit the text (a worker of another version, say): an error, not a scene.
  r.loader.start(file);
  r.loader.deliver(r.sent.back().id, {}, "");
  loaded = r.loader.poll();
  ASSERT_TRUE(loaded);
  EXPECT_FALSE(loaded->scene);
  EXPECT_THAT(loaded->error, HasSubstr("/objects/0: no mesh was built for it"));
}

// "+ OBJ mesh…": a small OBJ is built at once, a large one (65 000 triangles, 2 MiB) by the worker.
TEST(SceneLoaderRemote, AnObjectsMeshComesBackForIt) {
  RemoteLoader r;
  SceneObject small;
  small.name = "box";
  small.shape = Shape::mesh;
  small.file = "box_quads_normals.obj";
  r.loader.startObject(small, kData);
  EXPECT_TRUE(r.sent.empty());
  std::optional<SceneLoader::Loaded> box = r.loader.poll();
  ASSERT_TRUE(box && box->object && box->object->mesh) << (box ? box->error : "nothing");

  const test::TempDir dir;
  dir.write("grid.obj", gridObj(180));
  SceneObject o;
  o.name = "grid";
  o.shape = Shape::mesh;
  o.file = "grid.obj";
  o.color = Vec3(0.1, 0.2, 0.3);
  r.loader.startObject(o, dir.path);
  ASSERT_EQ(r.sent.size(), 1u);
  EXPECT_EQ(r.sent[0].baseDir, dir.path);
  r.answer(r.sent[0]);
  std::optional<SceneLoader::Loaded> loaded = r.loader.poll();
  ASSERT_TRUE(loaded && loaded->object) << (loaded ? loaded->error : "nothing");
  EXPECT_EQ(loaded->object->name, "grid");
  EXPECT_EQ(loaded->object->color, Vec3(0.1, 0.2, 0.3));
  ASSERT_TRUE(loaded->object->mesh);
  SceneObject direct = o;
  buildMesh(direct, dir.path);
  EXPECT_EQ(direct.mesh->faceCount(), 2u * 180 * 180);
  EXPECT_EQ(loaded->object->mesh->indices, direct.mesh->indices);
}

}  // namespace
}  // namespace vplab
