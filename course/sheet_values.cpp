#include "course/sheet_values.h"

#include "course/mistake_models.h"
#include "pipeline/clipping.h"

namespace vplab {

using Json = nlohmann::ordered_json;

namespace {

Vec4 vec4Of(const Json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>(), j[3].get<double>()}; }
Json jsonOf(const Vec4& v) { return Json::array({v.x, v.y, v.z, v.w}); }
Json jsonOf(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

Mat4 matrixOf(const Json& rows, bool transposed) {
  Mat4 m(1.0);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = (transposed ? rows[c][r] : rows[r][c]).get<double>();  // glm: [column][row]
  return m;
}

// Sutherland–Hodgman plane by plane with the pipeline's own kernel (clipPolygonAgainstPlane): the
// polygon after each of the cube's six passes.
Json clipStepsOf(const Json& npcH) {
  std::vector<ClipVertex> in, out;
  for (size_t i = 0; i < npcH.size(); ++i) {
    const Vec4 p = vec4Of(npcH[i]);
    in.push_back({p, clipValues(boundaryCoordinates(p)), uint32_t(i)});
  }
  Json steps = Json::array();
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    clipPolygonAgainstPlane(in, plane, out);
    Json polygon = Json::array();
    for (const ClipVertex& v : out) polygon.push_back(jsonOf(v.p));
    steps.push_back({{"plane", planeName(plane)}, {"polygon", polygon}});
    std::swap(in, out);
  }
  return steps;
}

}  // namespace

void addSheetValues(Json& dump, bool matricesTransposed, bool dividedFirst) {
  const Mat4 dcFromNpc = matrixOf(dump["matrices"]["dc_from_npc"], matricesTransposed);
  for (Json& object : dump["objects"])
    for (Json& polygon : object["polygons"]) {
      Json boundary = Json::array(), npc = Json::array(), dc = Json::array(), divided = Json::array();
      Json outcodes = Json::array();
      for (const Json& p : polygon["npc_h"]) {
        const Vec4 h = vec4Of(p);
        const Vec3 n = divideByW(h);
        // Dividing first, the clipper sees (x/w, y/w, z/w, 1): a point behind the eye (w < 0) flips.
        const Vec4 clipped = dividedFirst ? Vec4(n, 1.0) : h;
        const Boundary bc = boundaryCoordinates(clipped);
        boundary.push_back(Json(std::vector<double>(bc.begin(), bc.end())));
        outcodes.push_back(int(outcodeOf(bc)));
        divided.push_back(jsonOf(clipped));
        npc.push_back(jsonOf(n));
        dc.push_back(jsonOf(Vec3(dcFromNpc * Vec4(n, 1.0))));
      }
      polygon["boundary"] = boundary;
      if (dividedFirst) polygon["outcodes"] = outcodes;
      polygon["npc"] = npc;
      polygon["dc"] = dc;
      polygon["clip_steps"] = clipStepsOf(divided);
    }
}

Json referenceAnswer(const Scene& scene) {
  Json answer = referenceDump(scene);
  addSheetValues(answer);
  return answer;
}

}  // namespace vplab
