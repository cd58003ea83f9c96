#include "io/dump.h"

#include "base/error.h"
#include "io/json_text.h"

#include <sstream>

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
         {"bounding_box_test", run.options.boundingBoxTest}};
  for (const auto& field : kStatsFields) j[std::string(field.key)] = s.*field.member;
  Json operations = Json::object();
  for (const auto& field : kOperationFields) operations[std::string(field.key)] = s.operations.*field.member;
  j["operations"] = operations;
  return j;
}

}  // namespace

std::optional<std::string> nonFiniteError(const PipelineRun& run) {
  const Mat4 matrices[] = {run.vrcFromWc, run.npcFromVrc, run.dcFromNpc};
  const char* names[] = {"vrc_from_wc", "npc_from_vrc", "dc_from_npc"};
  for (int i = 0; i < 3; ++i)
    if (!isFinite(matrices[i])) return std::string("the matrix ") + names[i] + " is not finite";
  for (size_t i = 0; i < run.objects.size(); ++i) {
    const ObjectRun& o = run.objects[i];
    const std::string object = "object \"" + o.name + "\" (/objects/" +
                               std::to_string(i < run.sceneIndex.size() ? run.sceneIndex[i] : i) + ")";
    auto bad = [&](size_t v, const char* stage, const std::string& value) {
      return object + ": vertex " + std::to_string(v) + " in " + stage + " is " + value +
             ", not finite: the scene's coordinates or scale factors are too large";
    };
    if (!isFinite(o.wcFromMc)) return object + ": its modeling matrix wc_from_mc is not finite";
    for (size_t v = 0; v < o.vertexCount(); ++v) {
      const uint32_t u = uint32_t(v);
      if (!isFinite(o.mesh->positions[v])) return bad(v, "MC", format(o.mesh->positions[v]));
      if (!isFinite(o.wc(u))) return bad(v, "WC", format(o.wc(u)));
      if (!isFinite(o.vrc(u))) return bad(v, "VRC", format(o.vrc(u)));
      if (!isFinite(o.npcH[v])) return bad(v, "homogeneous NPC", format(o.npcH[v]));
    }
    for (size_t f = 0; f < o.faceCount(); ++f)
      for (uint32_t ref : o.clippedFace(f))
        if (!isFinite(o.clippedDc(ref))) return bad(ref, "DC", format(o.clippedDc(ref)));
  }
  return std::nullopt;
}

void writeDump(std::ostream& out, const PipelineRun& run, int indent) {
  if (auto e = nonFiniteError(run)) throw Error(*e);
  JsonStreamWriter w(out, indent);
  w.beginObject();
  w.key("camera");
  w.value({{"u", toJson(run.vrc.u)}, {"v", toJson(run.vrc.v)}, {"n", toJson(run.vrc.n)},
           {"vpd", run.vrc.vpd}, {"dmin", run.vrc.dmin}, {"dmax", run.vrc.dmax},
           {"projection", std::string(toString(run.camera.projection))}});
  w.key("device");
  w.value({{"width", run.device.width}, {"height", run.device.height}});
  w.key("matrices");
  w.value({{"vrc_from_wc", toJson(run.vrcFromWc)},
           {"npc_from_vrc", toJson(run.npcFromVrc)},
           {"dc_from_npc", toJson(run.dcFromNpc)}});
  w.key("objects");
  w.beginArray();
  for (const ObjectRun& o : run.objects) {
    w.beginObject();
    w.key("name");
    w.value(o.name);
    w.key("wc_from_mc");
    w.value(toJson(o.wcFromMc));
    w.key("polygons");
    w.beginArray();
    for (size_t f = 0; f < o.faceCount(); ++f) w.value(polygonJson(o, f));
    w.end();
    w.end();
  }
  w.end();
  w.key("stats");
  w.value(statsJson(run));
  w.end();
  w.finish("\n");
}

std::string dumpJson(const PipelineRun& run, int indent) {
  std::ostringstream out;
  writeDump(out, run, indent);
  return std::move(out).str();
}

}  // namespace vplab
