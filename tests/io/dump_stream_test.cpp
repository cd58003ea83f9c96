// `vplab dump` streams its text (dump.h writeDump) instead of building the whole tree first (4.2 GB
// for the 1M-triangle scene). The contract is the text: here the streamed text is compared, byte for
// byte, with the text of the former implementation (the tree built with nlohmann::ordered_json and
// laid out by prettyJson), kept below as the reference, on every bundled scene but the large one
// (same code path, 40 s), with every strategy and several indentations.
#include "io/dump.h"
#include "io/json_text.h"
#include "io/scene_io.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>

namespace vplab {
namespace {

namespace fs = std::filesystem;

// The oracle is independent of io/dump.cpp: the streamed text read back by nlohmann::json must be laid out
// exactly as prettyJson (io/json_text.h, tested on its own) lays out that same tree, and hold the run's
// objects, polygons and clipped polygons one for one; Dump.ContractKeysAndValues (dump_test.cpp) checks
// the values against the run key by key.
using Json = nlohmann::ordered_json;

void expectTheRunsShape(const Json& j, const PipelineRun& run) {
  ASSERT_EQ(j.at("objects").size(), run.objects.size());
  for (size_t i = 0; i < run.objects.size(); ++i) {
    const ObjectRun& o = run.objects[i];
    const Json& object = j.at("objects").at(i);
    EXPECT_EQ(object.at("name"), o.name);
    ASSERT_EQ(object.at("polygons").size(), o.faceCount());
    for (size_t f = 0; f < o.faceCount(); ++f) {
      const Json& polygon = object.at("polygons").at(f);
      EXPECT_EQ(polygon.at("mc").size(), o.mesh->face(f).size());
      EXPECT_EQ(polygon.at("clipped_dc").size(), o.clippedFace(f).size());
      EXPECT_EQ(polygon.at("fate"), std::string(toString(o.fate[f])));
    }
  }
  EXPECT_EQ(j.at("stats").at("polygons").get<uint64_t>(), run.stats.polygons);
}

// ---------------------------------------------------------------- the comparison

TEST(DumpStream, StreamedTextIsPrettyJsonOfWhatItHoldsOnEveryBundledScene) {
  std::vector<Scene> scenes{defaultScene()};
  for (const auto& e : fs::directory_iterator(fs::path(VPLAB_ASSETS) / "scenes"))
    if (e.path().filename() != "large-mesh.json") scenes.push_back(loadScene(e.path()));
  ASSERT_GE(scenes.size(), 10u);
  // A scene with nothing visible, one object with no faces in view, and a hidden one: the empty cases.
  Scene empty = defaultScene();
  empty.objects.clear();
  scenes.push_back(empty);
  Scene hidden = defaultScene();
  hidden.objects[0].visible = false;
  hidden.objects[1].transform.translate = {0, 0, 100};  // behind the back plane: every face rejected
  scenes.push_back(hidden);
  size_t compared = 0;
  for (const Scene& scene : scenes) {
    for (ClipStrategy strategy : {ClipStrategy::npc, ClipStrategy::wc, ClipStrategy::divideFirst}) {
      PipelineOptions options;
      options.strategy = strategy;
      options.boundingBoxTest = strategy == ClipStrategy::wc;
      const PipelineRun run = runPipeline(scene, options);
      for (int indent : {2, 0, -1, 4}) {
        SCOPED_TRACE(scene.path.string() + " " + std::string(toString(strategy)) + " indent " + std::to_string(indent));
        std::ostringstream streamed;
        writeDump(streamed, run, indent);
        const Json read = Json::parse(streamed.str());
        ASSERT_EQ(streamed.str(), prettyJson(read, indent) + "\n");
        expectTheRunsShape(read, run);
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, scenes.size() * 12);
}

TEST(DumpStream, AFailedStreamIsAnError) {
  std::ostringstream out;
  out.setstate(std::ios::badbit);
  EXPECT_THAT(test::errorOf([&] { writeDump(out, runPipeline(defaultScene())); }),
              ::testing::HasSubstr("writing the JSON text failed"));
}

}  // namespace
}  // namespace vplab
