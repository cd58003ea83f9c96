#include "course/follow_through.h"

#include "course/grading.h"
#include "pipeline/camera.h"
#include "pipeline/clipping.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vplab {

using Json = nlohmann::ordered_json;

namespace {

const Json* at(const Json& j, const std::string& pointer) {
  const Json::json_pointer p(pointer);
  return j.contains(p) ? &j[p] : nullptr;
}

// The student's numbers at `pointer`: exactly n of them (fractions as strings too), else nullopt.
std::optional<std::vector<double>> numbers(const Json& answer, const std::string& pointer, size_t n) {
  const Json* j = at(answer, pointer);
  if (!j || !j->is_array() || j->size() != n) return std::nullopt;
  std::vector<double> out;
  for (const Json& e : *j) {
    const std::optional<double> x = answerNumber(e);
    if (!x) return std::nullopt;
    out.push_back(*x);
  }
  return out;
}

std::optional<Vec3> vec3(const Json& answer, const std::string& pointer) {
  const auto v = numbers(answer, pointer, 3);
  return v ? std::optional<Vec3>(Vec3((*v)[0], (*v)[1], (*v)[2])) : std::nullopt;
}

std::optional<Vec4> vec4(const Json& answer, const std::string& pointer) {
  const auto v = numbers(answer, pointer, 4);
  return v ? std::optional<Vec4>(Vec4((*v)[0], (*v)[1], (*v)[2], (*v)[3])) : std::nullopt;
}

// A matrix as the answer writes it: 4 rows (column vectors, p' = M · p).
std::optional<Mat4> matrix(const Json& answer, const std::string& pointer) {
  Mat4 m(1.0);
  for (int r = 0; r < 4; ++r) {
    const auto row = numbers(answer, pointer + "/" + std::to_string(r), 4);
    if (!row) return std::nullopt;
    for (int c = 0; c < 4; ++c) m[c][r] = (*row)[size_t(c)];
  }
  return m;
}

std::optional<std::vector<Vec4>> polygon(const Json& answer, const std::string& pointer) {
  const Json* j = at(answer, pointer);
  if (!j || !j->is_array()) return std::nullopt;
  std::vector<Vec4> out;
  for (size_t i = 0; i < j->size(); ++i) {
    const auto p = vec4(answer, pointer + "/" + std::to_string(i));
    if (!p) return std::nullopt;
    out.push_back(*p);
  }
  return out;
}

Json json(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }
Json json(const Vec4& v) { return Json::array({v.x, v.y, v.z, v.w}); }
Json json(const Mat4& m) {
  Json rows = Json::array();
  for (int r = 0; r < 4; ++r) rows.push_back(json(row(m, r)));
  return rows;
}

// One Sutherland–Hodgman pass with the pipeline's kernel.
std::vector<Vec4> clippedBy(const std::vector<Vec4>& in, int plane) {
  std::vector<ClipVertex> input, output;
  for (size_t i = 0; i < in.size(); ++i) input.push_back({in[i], clipValues(boundaryCoordinates(in[i])), uint32_t(i)});
  clipPolygonAgainstPlane(input, plane, output);
  std::vector<Vec4> out;
  for (const ClipVertex& v : output) out.push_back(v.p);
  return out;
}

// Whether a vertex of the polygon lies outside the plane: a pass of Sutherland–Hodgman then has work.
// A vertex that an earlier pass put on a plane lies on it up to rounding (a boundary value of
// −4e-16): on the plane within 1e-9 · max(1, |w|) is not outside.
bool needsCut(const std::vector<Vec4>& polygon, int plane) {
  for (const Vec4& p : polygon)
    if (boundaryCoordinates(p)[size_t(plane)] < -1e-9 * std::max(1.0, std::abs(p.w))) return true;
  return false;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

std::optional<Json> followingValue(const std::string& path, const Json& answer, const Json& reference, const Scene& scene) {
  const std::string poly = "/objects/0/polygons/0";
  const Camera& camera = scene.camera;
  if (path == poly + "/wc/0") {
    const auto wcFromMc = matrix(answer, "/objects/0/wc_from_mc");
    const auto mc = vec3(reference, poly + "/mc/0");
    if (wcFromMc && mc) return json(Vec3(*wcFromMc * Vec4(*mc, 1.0)));
  } else if (path == "/camera/u") {
    if (const auto n = vec3(answer, "/camera/n"); n && glm::length(glm::cross(camera.vup, *n)) > 0)
      return json(glm::normalize(glm::cross(camera.vup, *n)));
  } else if (path == "/camera/v") {
    const auto n = vec3(answer, "/camera/n"), u = vec3(answer, "/camera/u");
    if (n && u) return json(glm::cross(*n, *u));
  } else if (path == "/matrices/vrc_from_wc") {
    const auto u = vec3(answer, "/camera/u"), v = vec3(answer, "/camera/v"), n = vec3(answer, "/camera/n");
    if (u && v && n) {
      const VrcAxes axes{*u, *v, *n, 0, 0, 0};
      return json(vrcFromWc(axes, camera.vrp));
    }
  } else if (path == poly + "/vrc/0") {
    const auto m = matrix(answer, "/matrices/vrc_from_wc");
    const auto wc = vec3(answer, poly + "/wc/0");
    if (m && wc) return json(Vec3(*m * Vec4(*wc, 1.0)));
  } else if (path == poly + "/npc_h/0") {
    const auto m = matrix(answer, "/matrices/npc_from_vrc");
    const auto vrc = vec3(answer, poly + "/vrc/0");
    if (m && vrc) return json(*m * Vec4(*vrc, 1.0));
  } else if (path == poly + "/boundary/0") {
    if (const auto h = vec4(answer, poly + "/npc_h/0")) {
      const Boundary bc = boundaryCoordinates(*h);
      return Json(std::vector<double>(bc.begin(), bc.end()));
    }
  } else if (path == poly + "/outcodes/0") {
    if (const auto bc = numbers(answer, poly + "/boundary/0", kPlaneCount)) {
      Boundary b{};
      for (int i = 0; i < kPlaneCount; ++i) b[size_t(i)] = (*bc)[size_t(i)];
      return Json(int(outcodeOf(b)));
    }
  } else if (path == poly + "/npc/0") {
    if (const auto h = vec4(answer, poly + "/npc_h/0")) return json(divideByW(*h));
  } else if (path == poly + "/dc/0") {
    const auto m = matrix(answer, "/matrices/dc_from_npc");
    const auto npc = vec3(answer, poly + "/npc/0");
    if (m && npc) return json(Vec3(*m * Vec4(*npc, 1.0)));
  } else if (path.rfind(poly + "/clip_steps/", 0) == 0 && endsWith(path, "/polygon")) {
    const std::string index = path.substr(poly.size() + 12, path.size() - poly.size() - 12 - 8);
    if (index.size() != 1 || index[0] < '0' || index[0] >= '0' + kPlaneCount) return std::nullopt;
    const int plane = index[0] - '0';
    const auto previousIn = [&](const Json& j) {
      return plane == 0 ? polygon(reference, poly + "/npc_h")
                        : polygon(j, poly + "/clip_steps/" + std::to_string(plane - 1) + "/polygon");
    };
    const auto previous = previousIn(answer), keyPrevious = previousIn(reference);
    // Folgefehler, not an easier exercise: a pass whose plane cuts the key's polygon earns credit
    // only when it had a cut to make on the student's own polygon too (a polygon copied into every
    // pass, already inside, made every later pass's work vanish).
    if (previous && keyPrevious && needsCut(*keyPrevious, plane) && !needsCut(*previous, plane)) return std::nullopt;
    if (previous) {
      Json out = Json::array();
      for (const Vec4& p : clippedBy(*previous, plane)) out.push_back(json(p));
      return out;
    }
  } else if (path == poly + "/clipped_dc") {
    const auto m = matrix(answer, "/matrices/dc_from_npc");
    const auto last = polygon(answer, poly + "/clip_steps/5/polygon");
    if (m && last) {
      Json out = Json::array();
      if (last->size() >= 3)
        for (const Vec4& p : *last) out.push_back(json(Vec3(*m * Vec4(divideByW(p), 1.0))));
      return out;
    }
  }
  return std::nullopt;
}

}  // namespace vplab
