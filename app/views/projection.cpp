#include "app/views/projection.h"

#include <cmath>
#include <string>

#include "pipeline/device_mapping.h"
#include "base/error.h"

namespace vplab::draw {

PixelPoint mix(const PixelPoint& a, const PixelPoint& b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
}
double distancePx(const PixelPoint& a, const PixelPoint& b) { return std::hypot(b.x - a.x, b.y - a.y); }

namespace {

// Blinn's boundary coordinates BC0..BC5 (x, w − x, y, w − y, z, w − z) as forms on homogeneous NPC.
constexpr int kFrontForm = kFront;  // BC5 = w − z: the front plane, GL's near plane
const Vec4 kCubeForms[kPlaneCount] = {Vec4(1, 0, 0, 0),  Vec4(-1, 0, 0, 1), Vec4(0, 1, 0, 0),
                                      Vec4(0, -1, 0, 1), Vec4(0, 0, 1, 0),  Vec4(0, 0, -1, 1)};

// The view's pixels as NPC: the inverse of the device mapping x_px = W·x, y_px = H·(1 − y), at the
// depth of the middle of the cube (overlays in pixels are never depth tested).
Mat4 npcFromPixels(int width, int height) {
  // clang-format off
  return glm::transpose(Mat4(1.0 / width, 0,            0, 0,
                             0,          -1.0 / height, 0, 1,
                             0,           0,            0, 0.5,
                             0,           0,            0, 1));
  // clang-format on
}

}  // namespace

ViewProjection::ViewProjection(const DisplayList& list, Space space, std::span<const Vec4> clipPlanes)
    : width_(list.width), height_(list.height) {
  if (width_ < 1 || height_ < 1)
    throw Error("display list: the size " + std::to_string(width_) + " x " + std::to_string(height_) +
                " is not at least 1 x 1 pixels");
  if (space == Space::pixels)
    npcFromSpace_ = npcFromPixels(width_, height_);
  else if (space == list.observer.space)
    npcFromSpace_ = list.observer.camera.npcFromWc();
  else
    throw Error("display list: a batch in " + std::string(toString(space)) + " in a view that looks at " +
                std::string(toString(list.observer.space)));
  if (clipPlanes.size() > size_t(kMaxUserPlanes))
    throw Error("display list: " + std::to_string(clipPlanes.size()) + " user clip planes, at most " +
                std::to_string(kMaxUserPlanes));
  spaceFromNpc_ = glm::inverse(npcFromSpace_);
  spaceFromNpcT_ = glm::transpose(spaceFromNpc_);
  forms_.assign(std::begin(kCubeForms), std::end(kCubeForms));
  for (const Vec4& p : clipPlanes) forms_.push_back(formInNpc(p));
}

PixelPoint ViewProjection::pixel(const Vec4& h) const {
  const Vec3 npc = divideByW(h);
  return {width_ * npc.x, height_ * (1.0 - npc.y), npc.z};
}

std::optional<PixelSegment> ViewProjection::segment(const Vec4& a, const Vec4& b) const {
  const EdgeRange r = clipEdgeByForms(a, b, forms_);
  if (!r.visible || !(r.t1 > r.t0)) return std::nullopt;
  const double fa = glm::dot(kCubeForms[kFrontForm], a), fb = glm::dot(kCubeForms[kFrontForm], b);
  const double tNear = fa < 0 ? fa / (fa - fb) : 0.0;
  const PixelPoint origin = pixel(glm::mix(a, b, tNear));
  const PixelPoint p0 = pixel(glm::mix(a, b, r.t0)), p1 = pixel(glm::mix(a, b, r.t1));
  return PixelSegment{p0, p1, distancePx(origin, p0)};
}

std::vector<Vec4> ViewProjection::clip(std::span<const Vec4> npcH, std::span<const Vec4> extraForms) const {
  std::vector<Vec4> clipped = clipPolygonByForms(npcH, forms_, scratch_);
  if (!extraForms.empty() && clipped.size() >= 3) {
    if (extraForms.size() > size_t(kMaxClipPlanes))
      throw Error("display list: " + std::to_string(extraForms.size()) + " extra clip forms, at most " +
                  std::to_string(kMaxClipPlanes));
    clipped = clipPolygonByForms(clipped, extraForms, scratch_);
  }
  if (clipped.size() < 3) clipped.clear();
  return clipped;
}

std::vector<PixelPoint> ViewProjection::polygon(std::span<const Vec4> npcH,
                                                std::span<const Vec4> extraForms) const {
  std::vector<PixelPoint> out;
  for (const Vec4& h : clip(npcH, extraForms)) out.push_back(pixel(h));
  return out;
}

std::optional<PixelPoint> ViewProjection::point(const Vec3& p) const {
  const Vec4 h = npcH(p);
  if (!(h.w > 0) || h.z > h.w || h.z < 0) return std::nullopt;
  return pixel(h);
}

}  // namespace vplab::draw
