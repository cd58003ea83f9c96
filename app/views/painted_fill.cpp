#include "app/views/painted_fill.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace vplab::draw {

namespace {

// Newell's normal of a polygon (robust for non-planar and concave faces; pipeline/mesh.h's rule).
Vec3 newellNormal(std::span<const Vec3> p) {
  Vec3 n(0);
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec3 &a = p[i], &b = p[(i + 1) % p.size()];
    n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return n;
}

// The six forms of Blinn's test "inside the other camera's volume" (scene.frag's volumeMode) as forms
// on the observer's homogeneous NPC: BC_k(V·X) = (Vᵀ·bc_k)·X for the batch's point X.
std::array<Vec4, kPlaneCount> volumeForms(const ViewProjection& proj, const Mat4& npcFromSpace) {
  const Vec4 cube[kPlaneCount] = {Vec4(1, 0, 0, 0),  Vec4(-1, 0, 0, 1), Vec4(0, 1, 0, 0),
                                  Vec4(0, -1, 0, 1), Vec4(0, 0, 1, 0),  Vec4(0, 0, -1, 1)};
  std::array<Vec4, kPlaneCount> out;
  for (int k = 0; k < kPlaneCount; ++k)
    out[size_t(k)] = proj.formInNpc(glm::transpose(npcFromSpace) * cube[k]);
  return out;
}

class Painter {
 public:
  Painter(const Fill& fill, const DisplayList& list)
      : fill_(fill), eye_(list.observer.camera.eyeWc), proj_(list, fill.space, fill.clipPlanes) {
    if (fill.volume.keep != VolumeTest::Keep::all) volume_ = volumeForms(proj_, fill.volume.npcFromSpace);
  }

  // One face: `space` its corners in the batch's space (after the division), `npcH` the observer's
  // homogeneous NPC of them; `normal` its normal for lighting.
  void face(std::span<const Vec3> space, std::span<const Vec4> npcH, const Vec3& normal,
            const glm::vec4& color) {
    pieces_.clear();
    if (fill_.volume.keep == VolumeTest::Keep::all) {
      pieces_.push_back(proj_.clip(npcH));
    } else if (fill_.volume.keep == VolumeTest::Keep::inside) {
      pieces_.push_back(proj_.clip(npcH, volume_));
    } else {  // outside: outside plane k and inside planes 0 … k − 1, disjoint, together the complement
      std::vector<Vec4> forms;
      for (int k = 0; k < kPlaneCount; ++k) {
        forms.push_back(-volume_[size_t(k)]);
        pieces_.push_back(proj_.clip(npcH, forms));
        forms.back() = volume_[size_t(k)];
      }
    }
    // The depth to sort by, and the point to light: the centroid of what is drawn of the face (a
    // face reaching behind the eye is lit where it is seen, as the fragments light it).
    double z = 0;
    Vec3 at(0);
    size_t n = 0;
    for (const auto& piece : pieces_)
      for (const Vec4& h : piece) {
        z += h.z / h.w;
        at += proj_.spaceOf(h);
        ++n;
      }
    if (n == 0) return;
    glm::vec4 c(glm::vec3(color), color.a * fill_.alpha);
    if (fill_.lit)
      c = glm::vec4(litColor(fill_, glm::vec3(color), at / double(n), normal, newellNormal(space), eye_),
                    c.a);
    for (const auto& piece : pieces_) {
      if (piece.size() < 3) continue;
      PaintedPolygon p{{}, c, z / double(n)};
      for (const Vec4& h : piece) p.points.push_back(proj_.pixel(h));
      out_.push_back(std::move(p));
    }
  }

  std::vector<PaintedPolygon> take() {
    std::stable_sort(out_.begin(), out_.end(),
                     [](const PaintedPolygon& a, const PaintedPolygon& b) { return a.depth < b.depth; });
    return std::move(out_);
  }
  const ViewProjection& projection() const { return proj_; }

 private:
  const Fill& fill_;
  Vec4 eye_;
  ViewProjection proj_;
  std::array<Vec4, kPlaneCount> volume_{};
  std::vector<std::vector<Vec4>> pieces_;
  std::vector<PaintedPolygon> out_;
};

}  // namespace

size_t faceCount(const Fill& fill) {
  size_t n = 0;
  for (const MeshInstance& m : fill.meshes)
    if (m.mesh) n += m.mesh->faceCount();
  for (const PolygonSet& s : fill.polygons) n += s.polygonCount();
  return n;
}

glm::vec3 litColor(const Fill& fill, const glm::vec3& color, const Vec3& at, Vec3 normal, const Vec3& seen,
                   const Vec4& eye) {
  const double len = glm::length(normal);
  Vec3 n = len > 0 ? normal / len : Vec3(0);
  const Vec3 toEyeRaw = eye.w == 0 ? Vec3(eye) : Vec3(eye) - at;
  const Vec3 toEye = glm::length(toEyeRaw) > 0 ? glm::normalize(toEyeRaw) : Vec3(0);
  if (glm::dot(seen, toEye) < 0) n = -n;  // polygons are lit from the side they are seen from
  Vec3 c = double(fill.ambient) * Vec3(color);
  for (const Light& light : fill.lights) {
    const Vec3 l = glm::normalize(light.position - at);
    const double diffuse = std::max(glm::dot(n, l), 0.0);
    const Vec3 half = l + toEye;
    const double h = glm::length(half) > 0 ? std::max(glm::dot(n, glm::normalize(half)), 0.0) : 0.0;
    const double specular = diffuse > 0 ? std::pow(h, 48.0) : 0.0;
    c += light.color * (diffuse * Vec3(color) + 0.3 * specular);
  }
  return glm::vec3(glm::min(c, Vec3(1.0)));
}

std::vector<PaintedPolygon> paintedPolygons(const Fill& fill, const DisplayList& list) {
  Painter painter(fill, list);
  const ViewProjection& proj = painter.projection();
  std::vector<Vec3> space;
  std::vector<Vec4> npcH;
  for (const MeshInstance& m : fill.meshes) {
    if (!m.mesh) continue;
    const Mesh& mesh = *m.mesh;
    const glm::dmat3 normalFromMc = glm::transpose(glm::inverse(glm::dmat3(m.spaceFromMc)));
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
      space.clear();
      npcH.clear();
      for (uint32_t v : mesh.face(f)) {
        const Vec4 h = m.spaceFromMc * Vec4(mesh.positions[v], 1.0);
        space.push_back(divideByW(h));
        npcH.push_back(proj.npcH(h));
      }
      Vec3 normal = newellNormal(space);
      if (mesh.smooth()) {  // the interpolated corner normals at the centroid
        Vec3 sum(0);
        for (uint32_t i = mesh.faceStart[f]; i < mesh.faceStart[f + 1]; ++i) sum += mesh.cornerNormal(i);
        normal = normalFromMc * sum;
      }
      painter.face(space, npcH, normal, m.color);
    }
  }
  std::vector<Vec3> scratch;  // a polygon worked out from the run (PolygonSet::npcOf)
  for (const PolygonSet& s : fill.polygons)
    for (size_t i = 0; i < s.polygonCount(); ++i) {
      const std::span<const Vec3> p = s.polygon(i, scratch);
      npcH.clear();
      for (const Vec3& q : p) npcH.push_back(proj.npcH(q));
      painter.face(p, npcH, newellNormal(p), glm::vec4(s.color, 1.f));
    }
  return painter.take();
}

}  // namespace vplab::draw
