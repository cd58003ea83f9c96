#include "app/practice/practice_marks.h"

#include "pipeline/clipping.h"

#include <cmath>
#include <string>

namespace vplab {

using Json = nlohmann::ordered_json;

namespace {

const std::string kPolygon = "/objects/0/polygons/0";

/// The numbers of the item at `path`, row by row, when every one of them is given and readable.
std::optional<std::vector<double>> numbersAt(const Practice& p, const std::string& path) {
  for (const ItemFields& f : p.fields) {
    if (f.item.path != path) continue;
    if (f.texts.empty()) return std::nullopt;
    std::vector<double> v;
    for (const std::string& t : f.texts) {
      const std::string n = normalizedField(t);
      const auto x = n.empty() ? std::nullopt : answerNumber(Json(n));
      if (!x || !std::isfinite(*x)) return std::nullopt;
      v.push_back(*x);
    }
    return v;
  }
  return std::nullopt;
}

std::optional<Vec3> vec3At(const Practice& p, const std::string& path) {
  const auto v = numbersAt(p, path);
  if (!v || v->size() != 3) return std::nullopt;
  return Vec3((*v)[0], (*v)[1], (*v)[2]);
}

std::optional<Vec4> vec4At(const Practice& p, const std::string& path) {
  const auto v = numbersAt(p, path);
  if (!v || v->size() != 4) return std::nullopt;
  return Vec4((*v)[0], (*v)[1], (*v)[2], (*v)[3]);
}

/// A matrix as written on paper (rows), into GLM's columns; transposed when given in row-vector form.
std::optional<Mat4> matrixAt(const Practice& p, const std::string& path, bool rowVectorForm) {
  const auto v = numbersAt(p, path);
  if (!v || v->size() != 16) return std::nullopt;
  Mat4 m(1.0);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = (*v)[size_t(r * 4 + c)];
  return rowVectorForm ? glm::transpose(m) : m;
}

/// A homogeneous point divided by its w: nullopt at (or next to) w = 0, where it has no place.
std::optional<Vec3> divided(const Vec4& h) {
  if (!(std::abs(h.w) > 1e-12)) return std::nullopt;
  return Vec3(h) / h.w;
}

/// The vertices of a polygon item, each of `size` numbers.
std::vector<std::vector<double>> verticesAt(const Practice& p, const std::string& path) {
  std::vector<std::vector<double>> out;
  for (const ItemFields& f : p.fields) {
    if (f.item.path != path || f.kind != FieldKind::polygon) continue;
    for (int r = 0; r < f.rows; ++r) {
      std::vector<double> v;
      for (int c = 0; c < f.columns; ++c) {
        const std::string& t = f.text(r, c);
        const std::string n = normalizedField(t);
      const auto x = n.empty() ? std::nullopt : answerNumber(Json(n));
        if (!x || !std::isfinite(*x)) return {};
        v.push_back(*x);
      }
      out.push_back(std::move(v));
    }
  }
  return out;
}

}  // namespace

Highlights::Student practiceMarks(const Practice& p, std::optional<int> pass, bool rowVectorForm) {
  Highlights::Student s;
  const PipelineRun& run = p.solution.run;
  // P1 where the student put it, in each space the views show.
  if (const auto wc = vec3At(p, kPolygon + "/wc/0")) s.pointsWc.push_back(*wc);
  if (const auto vrc = vec3At(p, kPolygon + "/vrc/0")) s.pointsWc.push_back(Vec3(run.wcFromVrc * Vec4(*vrc, 1.0)));
  if (const auto h = vec4At(p, kPolygon + "/npc_h/0"))
    if (const auto npc = divided(*h)) s.pointsNpc.push_back(*npc);
  if (const auto npc = vec3At(p, kPolygon + "/npc/0")) s.pointsNpc.push_back(*npc);
  if (const auto dc = vec3At(p, kPolygon + "/dc/0")) s.pointsDc.push_back(*dc);
  if (p.reveal == Reveal::values) {
    s.labWc.push_back(p.solution.point.wc);
    if (p.solution.point.outcode == 0) {  // outside the view volume P1 has no place in NPC and DC
      s.labNpc.push_back(p.solution.point.npc);
      s.labDc.push_back(p.solution.point.dc);
    }
  }
  // The polygon placed by their modeling matrix.
  if (const auto wcFromMc = matrixAt(p, "/objects/0/wc_from_mc", rowVectorForm))
    for (const Vec3& v : p.exercise.scene.objects[0].vertices) s.polygonWc.push_back(Vec3(*wcFromMc * Vec4(v, 1.0)));
  // The view volume their orientation and mapping make: the NPC cube taken back through their
  // matrices (the lab's for the one they did not give).
  const auto vrcFromWc = matrixAt(p, "/matrices/vrc_from_wc", rowVectorForm);
  const auto npcFromVrc = matrixAt(p, "/matrices/npc_from_vrc", rowVectorForm);
  if (vrcFromWc || npcFromVrc) {
    const Mat4 npcFromWc = npcFromVrc.value_or(run.npcFromVrc) * vrcFromWc.value_or(run.vrcFromWc);
    if (std::abs(glm::determinant(npcFromWc)) > 1e-12) {
      const Mat4 wcFromNpc = glm::inverse(npcFromWc);
      for (int i = 0; i < 8; ++i) {
        const Vec3 c(i & 1, (i >> 1) & 1, (i >> 2) & 1);
        const auto corner = divided(wcFromNpc * Vec4(c, 1.0));
        if (!corner) {
          s.volumeWc.clear();
          break;
        }
        s.volumeWc.push_back(*corner);
      }
    }
  }
  // Their polygon after the pass shown (or their last one), divided by their w.
  for (int k = kPlaneCount; k >= 1; --k) {
    if (pass && *pass >= 1 && k != *pass) continue;
    const auto vertices = verticesAt(p, kPolygon + "/clip_steps/" + std::to_string(k - 1) + "/polygon");
    if (vertices.empty()) continue;
    for (const auto& v : vertices) {
      const auto npc = divided(Vec4(v[0], v[1], v[2], v[3]));
      if (!npc) {
        s.polygonNpc.clear();
        break;
      }
      s.polygonNpc.push_back(*npc);
    }
    break;
  }
  for (const auto& v : verticesAt(p, kPolygon + "/clipped_dc")) s.polygonDc.push_back(Vec3(v[0], v[1], v[2]));
  return s;
}

}  // namespace vplab
