// `vplab dump` (dump.h): the JSON contract other tools rely on. Parsed with nlohmann::json; every
// contract key is present, values are the run's (doubles survive the text bit for bit, nlohmann
// writes the shortest round-trip form), and matrices are 4 rows for column vectors.
#include "io/dump.h"

#include "pipeline/view_mapping.h"
#include "tests/support/test_util.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace vplab {
namespace {

using Json = nlohmann::json;

Scene dumpScene() {
  return test::sceneWith(test::checkCamera(),
                         {test::shapeObject("crossing cube", Shape::cube, {{0.9, 0.1, 0}, {{{0, 1, 0}, 20, {}}}, {0.8, 0.8, 0.8}}),
                          test::polygonObject("triangle", {{-0.5, -0.5, 0}, {0, 0.5, 0.5}, {-0.8, 0.2, -1}}),
                          test::shapeObject("far away", Shape::tetrahedron, {{0, 0, -20}, {}, {1, 1, 1}})});
}

void expectVec(const Json& j, const Vec3& v) {
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 3u);
  EXPECT_EQ(j[0].get<double>(), v.x);
  EXPECT_EQ(j[1].get<double>(), v.y);
  EXPECT_EQ(j[2].get<double>(), v.z);
}

void expectMatrix(const Json& j, const Mat4& m) {
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 4u);
  for (int r = 0; r < 4; ++r) {
    ASSERT_EQ(j[r].size(), 4u);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(j[r][c].get<double>(), m[c][r]) << "row " << r << " col " << c;  // row-major
  }
}

// Every number finite, no null (nlohmann writes NaN and infinity as null).
void expectNoNullOrNaN(const Json& j, const std::string& path = "") {
  ASSERT_FALSE(j.is_null()) << path;
  if (j.is_number()) {
    EXPECT_TRUE(std::isfinite(j.get<double>())) << path;
  }
  if (j.is_array())
    for (size_t i = 0; i < j.size(); ++i) expectNoNullOrNaN(j[i], path + "/" + std::to_string(i));
  if (j.is_object())
    for (const auto& [k, v] : j.items()) expectNoNullOrNaN(v, path + "/" + k);
}

TEST(Dump, ContractKeysAndValues) {
  const Scene scene = dumpScene();
  const PipelineRun run = runPipeline(scene);
  const Json j = Json::parse(dumpJson(run));
  expectNoNullOrNaN(j);

  const Json& cam = j.at("camera");
  expectVec(cam.at("u"), run.vrc.u);
  expectVec(cam.at("v"), run.vrc.v);
  expectVec(cam.at("n"), run.vrc.n);
  EXPECT_EQ(cam.at("vpd").get<double>(), 5);
  EXPECT_EQ(cam.at("dmin").get<double>(), 3);
  EXPECT_EQ(cam.at("dmax").get<double>(), 7);
  EXPECT_EQ(cam.at("projection"), "perspective");
  EXPECT_EQ(j.at("device").at("width"), 320);
  EXPECT_EQ(j.at("device").at("height"), 240);

  const Json& mats = j.at("matrices");
  expectMatrix(mats.at("vrc_from_wc"), vrcFromWc(scene.camera));
  expectMatrix(mats.at("npc_from_vrc"), npcFromVrc(scene.camera));
  expectMatrix(mats.at("dc_from_npc"), dcFromNpc(scene.device));

  ASSERT_EQ(j.at("objects").size(), run.objects.size());
  for (size_t k = 0; k < run.objects.size(); ++k) {
    const ObjectRun& o = run.objects[k];
    const Json& jo = j["objects"][k];
    SCOPED_TRACE(o.name);
    EXPECT_EQ(jo.at("name"), o.name);
    expectMatrix(jo.at("wc_from_mc"), o.wcFromMc);
    ASSERT_EQ(jo.at("polygons").size(), o.faceCount());
    for (size_t f = 0; f < o.faceCount(); ++f) {
      const Json& p = jo["polygons"][f];
      const auto face = o.mesh->face(f);
      for (const char* key : {"mc", "wc", "vrc", "npc_h", "outcodes"}) ASSERT_EQ(p.at(key).size(), face.size()) << key;
      for (size_t i = 0; i < face.size(); ++i) {
        expectVec(p["mc"][i], o.mesh->positions[face[i]]);
        expectVec(p["wc"][i], o.wc(face[i]));
        expectVec(p["vrc"][i], o.vrc(face[i]));
        ASSERT_EQ(p["npc_h"][i].size(), 4u);
        for (int c = 0; c < 4; ++c) EXPECT_EQ(p["npc_h"][i][c].get<double>(), o.npcH[face[i]][c]);
        EXPECT_EQ(p["outcodes"][i].get<int>(), o.outcodes[face[i]]);
      }
      EXPECT_EQ(p.at("fate"), std::string(toString(o.fate[f])));
      const auto clipped = o.clippedFace(f);
      ASSERT_EQ(p.at("clipped_dc").size(), clipped.size());
      for (size_t i = 0; i < clipped.size(); ++i) expectVec(p["clipped_dc"][i], o.clippedDc(clipped[i]));
    }
  }

  const Json& st = j.at("stats");
  EXPECT_EQ(st.at("strategy"), "npc");
  EXPECT_EQ(st.at("wrong_on_purpose"), false);
  EXPECT_EQ(st.at("bounding_box_test"), false);
  EXPECT_EQ(st.at("objects").get<uint64_t>(), run.stats.objects);
  EXPECT_EQ(st.at("vertices").get<uint64_t>(), run.stats.vertices);
  EXPECT_EQ(st.at("vertices_transformed").get<uint64_t>(), run.stats.verticesTransformed);
  EXPECT_EQ(st.at("vertices_classified").get<uint64_t>(), run.stats.verticesClassified);
  EXPECT_EQ(st.at("polygons").get<uint64_t>(), run.stats.polygons);
  EXPECT_EQ(st.at("polygons_trivially_accepted").get<uint64_t>(), run.stats.polygonsTriviallyAccepted);
  EXPECT_EQ(st.at("polygons_trivially_rejected").get<uint64_t>(), run.stats.polygonsTriviallyRejected);
  EXPECT_EQ(st.at("polygons_clipped").get<uint64_t>(), run.stats.polygonsClipped);
  EXPECT_EQ(st.at("polygons_clipped_away").get<uint64_t>(), run.stats.polygonsClippedAway);
  EXPECT_EQ(st.at("vertices_created").get<uint64_t>(), run.stats.verticesCreated);
  EXPECT_EQ(st.at("vertices_output").get<uint64_t>(), run.stats.verticesOutput);
  EXPECT_EQ(st.at("objects_accepted_by_box").get<uint64_t>(), 0u);
  EXPECT_EQ(st.at("objects_rejected_by_box").get<uint64_t>(), 0u);
  EXPECT_EQ(st.at("polygons_decided_by_box").get<uint64_t>(), 0u);
  EXPECT_EQ(st.at("operations").at("multiplications").get<uint64_t>(), run.stats.operations.multiplications);
  EXPECT_EQ(st.at("operations").at("divisions").get<uint64_t>(), run.stats.operations.divisions);
  EXPECT_GT(run.stats.polygonsClipped, 0u);  // the scene exercises clipping
  EXPECT_GT(run.stats.polygonsTriviallyRejected, 0u);
}

// The dump alone is enough to recompute the stages: with the rows as printed and column vectors,
// npc_h = npc_from_vrc · (vrc, 1) and vrc = vrc_from_wc · (wc, 1). Relative 1e-12: a 4-term dot
// product recomputed in the same order as GLM up to the summation order.
TEST(Dump, MatricesAreRowsForColumnVectors) {
  const Json j = Json::parse(dumpJson(runPipeline(dumpScene())));
  auto apply = [](const Json& rows, const Json& p3) {
    double out[4];
    for (int r = 0; r < 4; ++r) {
      out[r] = rows[r][3].get<double>();
      for (int c = 0; c < 3; ++c) out[r] += rows[r][c].get<double>() * p3[c].get<double>();
    }
    return Vec4(out[0], out[1], out[2], out[3]);
  };
  int checked = 0;
  for (const Json& o : j["objects"]) {
    for (const Json& p : o["polygons"]) {
      for (size_t i = 0; i < p["mc"].size(); ++i) {
        const Vec4 wc = apply(o["wc_from_mc"], p["mc"][i]);
        const Vec4 vrc = apply(j["matrices"]["vrc_from_wc"], p["wc"][i]);
        const Vec4 npc = apply(j["matrices"]["npc_from_vrc"], p["vrc"][i]);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(wc[c], p["wc"][i][c].get<double>(), 1e-12 * (1 + std::abs(wc[c])));
          EXPECT_NEAR(vrc[c], p["vrc"][i][c].get<double>(), 1e-12 * (1 + std::abs(vrc[c])));
        }
        EXPECT_EQ(wc.w, 1);
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(npc[c], p["npc_h"][i][c].get<double>(), 1e-12 * (1 + std::abs(npc[c])));
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 20);
}

TEST(Dump, IndentAndOptions) {
  const PipelineRun run = runPipeline(dumpScene(), {ClipStrategy::divideFirst, true});
  const std::string compact = dumpJson(run, -1);
  const std::string pretty = dumpJson(run, 4);
  EXPECT_EQ(compact.find('\n'), compact.size() - 1);  // one line and the final newline
  EXPECT_NE(pretty.find("\n    \"camera\""), std::string::npos);
  const Json a = Json::parse(compact), b = Json::parse(pretty);
  EXPECT_EQ(a, b);
  EXPECT_EQ(a["stats"]["strategy"], "divide-first");
  EXPECT_EQ(a["stats"]["wrong_on_purpose"], true);
  EXPECT_EQ(a["stats"]["bounding_box_test"], true);
  EXPECT_EQ(a["stats"]["objects_rejected_by_box"].get<int>(), 1);  // the far tetrahedron
  expectNoNullOrNaN(a);
}

TEST(Dump, EmptySceneAndRandomScenesHaveNoNaN) {
  const Json empty = Json::parse(dumpJson(runPipeline(test::sceneWith(test::checkCamera(), {}))));
  EXPECT_TRUE(empty.at("objects").empty());
  EXPECT_EQ(empty.at("stats").at("polygons"), 0);
  test::Rng rng(12);
  for (int k = 0; k < 10; ++k) {
    const Camera c = test::randomCamera(rng, Projection(k % 3));
    for (ClipStrategy s : {ClipStrategy::npc, ClipStrategy::wc, ClipStrategy::divideFirst})
      expectNoNullOrNaN(Json::parse(dumpJson(runPipeline(test::randomPolygonScene(rng, c, 8, true), {s}))));
  }
}

}  // namespace
}  // namespace vplab
