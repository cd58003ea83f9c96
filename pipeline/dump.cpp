#include "pipeline/dump.h"

#include "pipeline/json_text.h"

namespace vplab {

namespace {

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

}  // namespace

std::string dumpJson(const PipelineRun& run, int indent) {
  Json j;
  j["camera"] = {{"u", toJson(run.frame.u)}, {"v", toJson(run.frame.v)}, {"n", toJson(run.frame.n)},
                 {"vpd", run.frame.vpd}, {"dmin", run.frame.dmin}, {"dmax", run.frame.dmax},
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

}  // namespace vplab
