// Stage 4, clipping in homogeneous coordinates (lecture notes 15.3, 15.2.4; Hill 7.4 and the DGL wiki; docs/conventions.md).
//
// Blinn & Newell, "Clipping using homogeneous coordinates" (SIGGRAPH 1978), as retold by Hill 7.4:
// a point (x, y, z, w) of homogeneous NPC is inside when 0 ≤ x ≤ w, 0 ≤ y ≤ w, 0 ≤ z ≤ w. Its six
// boundary coordinates BC0..BC5 are x, w − x, y, w − y, z, w − z; the 6-bit outcode has bit i set
// when BCi < 0 (Cohen–Sutherland in 3D). Both are computed once per vertex and reused by every edge
// and polygon the vertex belongs to. Boundary coordinates are linear in the point, so a vertex
// created on an edge gets its own by the same interpolation, never by recomputation.
//
// Clip before dividing: a point behind the eye has w < 0 and fails x ≤ w or 0 ≤ x by itself, while
// after the division x/w flips sign and can land inside the cube (Hill 7.4 and the DGL wiki).
#pragma once

#include "pipeline/math.h"

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace vplab {

enum ClipPlane : int { kLeft = 0, kRight, kBottom, kTop, kBack, kFront, kPlaneCount };
/// User clip planes (DGL wiki, glClipPlane) follow the cube's six: planes 6 … 11. Each is a linear
/// form of the homogeneous point too, so the same clipper handles them.
inline constexpr int kMaxUserPlanes = 6;
inline constexpr int kMaxClipPlanes = kPlaneCount + kMaxUserPlanes;
std::string_view planeName(int plane);         // "left", "right", …, "user plane 1", …
std::string_view planeInequality(int plane);   // "x ≥ 0", "x ≤ w", …, "a·x + b·y + c·z + d ≥ 0", as the lecture notes write them

using Outcode = uint16_t;  // bits 0–5: the cube's planes; bits 6–11: user planes
using Boundary = std::array<double, kPlaneCount>;       // BC0..BC5
using ClipValues = std::array<double, kMaxClipPlanes>;  // the cube's BCs, then the user planes' values

/// Blinn's boundary coordinates of a point in homogeneous NPC.
inline Boundary boundaryCoordinates(const Vec4& p) {
  return {p.x, p.w - p.x, p.y, p.w - p.y, p.z, p.w - p.z};
}

/// The outcode of a point in homogeneous NPC: outcodeOf(boundaryCoordinates(p)) bit for bit,
/// without the array in between (the vertex pass's hot loop).
inline Outcode outcodeOf(const Vec4& p) {
  return Outcode((p.x < 0) | (p.w - p.x < 0) << 1 | (p.y < 0) << 2 | (p.w - p.y < 0) << 3 | (p.z < 0) << 4 |
                 (p.w - p.z < 0) << 5);
}

/// Bit i set when BCi < 0: a point exactly on a plane is inside.
inline Outcode outcodeOf(const Boundary& bc) {
  Outcode code = 0;
  for (int i = 0; i < kPlaneCount; ++i) code |= Outcode(bc[i] < 0) << i;
  return code;
}

/// The boundary values of a point for every plane: the cube's six BCs, then `user` (the user
/// planes' values; planes without a value count as inside).
ClipValues clipValues(const Boundary& cube, std::span<const double> user = {});

/// Bit i set when value i < 0, for the cube's and the user planes' values.
inline Outcode outcodeOf(const ClipValues& v) {
  Outcode code = 0;
  for (int i = 0; i < kMaxClipPlanes; ++i) code |= Outcode(v[size_t(i)] < 0) << i;
  return code;
}

/// A vertex while a polygon is being clipped: its position, its boundary values (for the NPC
/// strategy Blinn's BCs; for the WC strategy the six frustum plane equations, equal in exact
/// arithmetic; then the user planes'), and where it came from.
struct ClipVertex {
  Vec4 p;                 // homogeneous NPC (WC strategy: WC with w = 1)
  ClipValues bc;
  uint32_t source;        // index of the mesh vertex, or kCreated
  uint16_t onPlanes = 0;  // bit i: the vertex was created on plane i (new edges lie on such planes)
  static constexpr uint32_t kCreated = 0xffffffffu;
};

/// One Sutherland–Hodgman pass: the part of the closed polygon `in` with bc[plane] ≥ 0, appended to
/// `out` (cleared first). Each intersection is computed from the inside endpoint towards the outside
/// one, t = BC(in) / (BC(in) − BC(out)), interpolating all four coordinates and the boundary values,
/// so two polygons sharing an edge get the same new vertex. The new vertex lies exactly on the plane.
void clipPolygonAgainstPlane(std::span<const ClipVertex> in, int plane, std::vector<ClipVertex>& out);

/// Scratch buffers for clipPolygon; sized once, reused for every polygon (no heap allocation per
/// polygon once they have grown to the largest face).
struct ClipScratch {
  std::vector<ClipVertex> a, b;
};

/// Sutherland–Hodgman against every plane whose bit is set in `planes` (the OR of the polygon's
/// outcodes: no other plane can cut it). Returns the clipped polygon (inside `scratch`), empty when
/// fewer than 3 vertices remain. `polygon` is taken from scratch.a, filled by the caller.
std::span<const ClipVertex> clipPolygon(Outcode planes, ClipScratch& scratch);

/// The visible part [t0, t1] of the edge P(t) = (1 − t)·P0 + t·P1, 0 ≤ t ≤ 1, from the boundary
/// values of its endpoints (parametric clipping, Liang–Barsky in homogeneous form).
struct EdgeRange {
  double t0 = 0, t1 = 1;
  bool visible = true;
};
EdgeRange clipEdge(const ClipValues& bc0, const ClipValues& bc1, Outcode planes);
inline EdgeRange clipEdge(const Boundary& bc0, const Boundary& bc1, Outcode planes) {
  return clipEdge(clipValues(bc0), clipValues(bc1), planes);
}

/// The same kernels for any planes given as linear forms on homogeneous points (inside where
/// dot(form, p) ≥ 0, at most kMaxClipPlanes of them): another camera's view volume, a grown cube.
std::vector<Vec4> clipPolygonByForms(std::span<const Vec4> polygon, std::span<const Vec4> forms, ClipScratch& scratch);
EdgeRange clipEdgeByForms(const Vec4& a, const Vec4& b, std::span<const Vec4> forms);

/// Linear interpolation of two clip vertices (all four coordinates and the boundary values).
ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t);

/// The perspective division (x/w, y/w, z/w), only ever applied after clipping, where w > 0. Kept
/// finite for the divide-first demonstration, which also divides points with w ≤ 0: a point in the
/// eye plane (|w| < 1e-12) is divided by 1e-12 with w's sign instead of by 0.
inline Vec3 divideByW(const Vec4& p) {
  constexpr double kTiny = 1e-12;
  const double w = std::abs(p.w) < kTiny ? std::copysign(kTiny, p.w) : p.w;
  return Vec3(p) / w;
}

/// Puts a homogeneous NPC point exactly onto the cube's planes in `onPlanes` (x = 0, x = w, …),
/// removing the rounding of the interpolation so clipped output never lies a few ulps outside the
/// cube. (User planes are not axis planes: their vertices keep the interpolated coordinates.)
/// Inline: a call made the clipper write the point's coordinates one by one to memory and read them
/// back at once as pairs, which waits for the writes (store forwarding fails).
inline void snapToPlanes(Vec4& p, uint16_t onPlanes) {
  if (onPlanes & 1u << kLeft) p.x = 0;
  if (onPlanes & 1u << kRight) p.x = p.w;
  if (onPlanes & 1u << kBottom) p.y = 0;
  if (onPlanes & 1u << kTop) p.y = p.w;
  if (onPlanes & 1u << kBack) p.z = 0;
  if (onPlanes & 1u << kFront) p.z = p.w;
}

}  // namespace vplab
