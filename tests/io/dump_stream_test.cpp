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

// ---------------------------------------------------------------- the former dumpJson, verbatim

using Json = nlohmann::ordered_json;

Json toJson(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }
Json toJson(const Vec4& v) { return Json::array({v.x, v.y, v.z, v.w}); }
Json toJson(const Mat4& m) {
  Json rows = Json::array();
  for (const auto& r : rowsOf(m)) rows.push_back(Json::array({r[0], r[1], r[2], r[3]}));
  return rows;
}

Json polygonJson(const ObjectRun& o, size_t f) {
  Json mc = Json::array(), wc = Json::array(), vrc = Json::array(), npcH = Json::array(), codes = Json::array();
  for (uint32_t v : o.mesh->face(f)) {
    mc.push_back(toJson(o.mesh->positions[v]));
    wc.push_back(toJson(o.wc(v)));
    vrc.push_back(toJson(o.vrc(v)));
    npcH.push_back(toJson(o.npcH[v]));
    codes.push_back(o.outcodes[v]);
  }
  Json dc = Json::array();
  for (uint32_t ref : o.clippedFace(f)) dc.push_back(toJson(o.clippedDc(ref)));
  return Json{{"mc", mc}, {"wc", wc}, {"vrc", vrc}, {"npc_h", npcH}, {"outcodes", codes},
              {"fate", std::string(toString(o.fate[f]))}, {"clipped_dc", dc}};
}

Json statsJson(const PipelineRun& run) {
  const PipelineStats& s = run.stats;
  Json j{{"strategy", std::string(toString(run.options.strategy))},
         {"wrong_on_purpose", !isCorrect(run.options.strategy)},
         {"bounding_box_test", run.options.boundingBoxTest},
         {"objects", s.objects},
         {"vertices", s.vertices},
         {"vertices_transformed", s.verticesTransformed},
         {"vertices_classified", s.verticesClassified},
         {"polygons", s.polygons},
         {"polygons_trivially_accepted", s.polygonsTriviallyAccepted},
         {"polygons_trivially_rejected", s.polygonsTriviallyRejected},
         {"polygons_clipped", s.polygonsClipped},
         {"polygons_clipped_away", s.polygonsClippedAway},
         {"vertices_created", s.verticesCreated},
         {"vertices_output", s.verticesOutput},
         {"objects_box_tested", s.objectsBoxTested},
         {"objects_accepted_by_box", s.objectsAcceptedByBox},
         {"objects_rejected_by_box", s.objectsRejectedByBox},
         {"polygons_decided_by_box", s.polygonsDecidedByBox}};
  j["operations"] = {{"multiplications", s.operations.multiplications},
                     {"additions", s.operations.additions},
                     {"divisions", s.operations.divisions},
                     {"comparisons", s.operations.comparisons}};
  return j;
}

std::string formerDumpJson(const PipelineRun& run, int indent) {
  Json j;
  j["camera"] = {{"u", toJson(run.vrc.u)}, {"v", toJson(run.vrc.v)}, {"n", toJson(run.vrc.n)},
                 {"vpd", run.vrc.vpd}, {"dmin", run.vrc.dmin}, {"dmax", run.vrc.dmax},
                 {"projection", std::string(toString(run.camera.projection))}};
  j["device"] = {{"width", run.device.width}, {"height", run.device.height}};
  j["matrices"] = {{"vrc_from_wc", toJson(run.vrcFromWc)},
                   {"npc_from_vrc", toJson(run.npcFromVrc)},
                   {"dc_from_npc", toJson(run.dcFromNpc)}};
  j["objects"] = Json::array();
  for (const ObjectRun& o : run.objects) {
    Json polygons = Json::array();
    for (size_t f = 0; f < o.faceCount(); ++f) polygons.push_back(polygonJson(o, f));
    j["objects"].push_back({{"name", o.name}, {"wc_from_mc", toJson(o.wcFromMc)}, {"polygons", polygons}});
  }
  j["stats"] = statsJson(run);
  return prettyJson(j, indent) + "\n";
}

// ---------------------------------------------------------------- the comparison

TEST(DumpStream, StreamedTextEqualsTheFormerTextOnEveryBundledScene) {
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
        const std::string expected = formerDumpJson(run, indent);
        std::ostringstream streamed;
        writeDump(streamed, run, indent);
        ASSERT_EQ(streamed.str(), expected);
        EXPECT_EQ(dumpJson(run, indent), expected);
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
