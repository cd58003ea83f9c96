// How a display list's batch reaches its view's pixels, on the CPU (the SVG backend; lecture notes
// 15.3 and 15.4, docs/conventions.md stages 4 and 5). A batch in the observer's space goes through
// the observer's synthetic camera to homogeneous NPC, is clipped there, before the division, by the
// pipeline's own clipper (pipeline/clipping.h: Blinn & Newell's boundary coordinates, as linear
// forms, with the batch's user clip planes as further forms), divided, and device-mapped to the
// view's pixels (origin top-left, y down). A batch in Space::pixels is already there: it is taken
// into NPC by the inverse of that device mapping so that one path serves both.
//
// No GL: this is what GL's clipper and viewport do for the GL backend.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "app/views/display_list.h"
#include "pipeline/clipping.h"

namespace vplab::draw {

/// A point of a view's pixels (x right, y down) with the observer's NPC z: 1 at its front plane, 0 at
/// its back plane, so larger is nearer (GL's window depth is 1 − z).
struct PixelPoint {
  double x = 0, y = 0, z = 0;
};
PixelPoint mix(const PixelPoint& a, const PixelPoint& b, double t);
double distancePx(const PixelPoint& a, const PixelPoint& b);  // in the view's plane, z ignored

/// A segment's part inside the view volume, in pixels, with the dash phase GL gives its start: the
/// dashes are measured from the segment's start after cutting it at the observer's front plane
/// (GL's near plane), and the rest of the clipping does not move them.
struct PixelSegment {
  PixelPoint a, b;
  double dashOrigin = 0;  // px from the dash origin to a
};

class ViewProjection {
 public:
  /// The projection of the batches of `list` in `space` with the user clip planes `clipPlanes`
  /// (linear forms on the space's homogeneous points, p · x ≥ 0 kept). Throws vplab::Error when
  /// `space` is neither the list's observer space nor pixels, or the list has no pixels.
  ViewProjection(const DisplayList& list, Space space, std::span<const Vec4> clipPlanes = {});

  /// The observer's homogeneous NPC of a point of the batch's space.
  Vec4 npcH(const Vec3& p) const { return npcFromSpace_ * Vec4(p, 1.0); }
  Vec4 npcH(const Vec4& p) const { return npcFromSpace_ * p; }
  /// A form on the space's homogeneous points as the same form on the observer's homogeneous NPC.
  Vec4 formInNpc(const Vec4& spaceForm) const { return spaceFromNpcT_ * spaceForm; }
  /// The device mapping of a point of homogeneous NPC with w > 0 (after the division).
  PixelPoint pixel(const Vec4& npcH) const;

  std::optional<PixelSegment> segment(const Vec4& aNpcH, const Vec4& bNpcH) const;
  std::optional<PixelSegment> segment(const Vec3& a, const Vec3& b) const {
    return segment(npcH(a), npcH(b));
  }
  /// A polygon given in homogeneous NPC, clipped to the volume, the user planes and `extraForms`
  /// (forms on homogeneous NPC), still in homogeneous NPC; empty when fewer than three vertices remain.
  std::vector<Vec4> clip(std::span<const Vec4> npcH, std::span<const Vec4> extraForms = {}) const;
  /// The same, in pixels.
  std::vector<PixelPoint> polygon(std::span<const Vec4> npcH, std::span<const Vec4> extraForms = {}) const;
  /// The point of the batch's space a point of homogeneous NPC is (after the division).
  Vec3 spaceOf(const Vec4& npcH) const { return divideByW(spaceFromNpc_ * npcH); }
  /// A marker's centre, when its point lies in front of the eye between the front and back planes.
  std::optional<PixelPoint> point(const Vec3& p) const;

 private:
  Mat4 npcFromSpace_{1.0};
  Mat4 spaceFromNpc_{1.0};
  Mat4 spaceFromNpcT_{1.0};  // its transpose: takes forms along
  int width_ = 0, height_ = 0;
  std::vector<Vec4> forms_;  // BC0..BC5 of the cube, then the user planes, on homogeneous NPC
  mutable ClipScratch scratch_;
};

}  // namespace vplab::draw
