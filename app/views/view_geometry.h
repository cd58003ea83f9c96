// Geometry the views draw, shared by the GL views (app/views/*_view.cpp) and their SVG export
// (app/export/svg.cpp), so the picture and the vector drawing are built from one description.
#pragma once

#include "app/views/labels.h"
#include "app/views/theme.h"
#include "base/language.h"
#include "pipeline/pipeline.h"

#include <glm/glm.hpp>

#include <array>
#include <string>
#include <vector>

namespace vplab::geometry {

/// Corner i of the unit cube: x = bit 0, y = bit 1, z = bit 2 (z = 1 front, 0 back).
inline Vec3 cubeCorner(int i) { return Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1); }

/// A point of NPC taken back to WC through the inverse of the camera's npcFromWc (divided by w).
Vec3 wcOfNpc(const Mat4& wcFromNpc, const Vec3& npc);

/// The view volume's corners in WC: the unit cube's corners taken back from NPC (exact for every
/// projection). Corner i as cubeCorner(i).
std::array<Vec3, 8> viewVolumeCorners(const Mat4& wcFromNpc);

/// The four cube corners lying on a clip plane (ClipPlane 0 … 5), in order around the face.
std::array<int, 4> cubeFaceRing(int plane);

/// A square of half-size `halfSize` on a user clip plane, around its point (the world view's
/// translucent quad).
std::array<Vec3, 4> clipPlaneSquare(const UserClipPlane& plane, double halfSize);
/// The half-size of those squares for a camera: 0.6 of the window's larger side.
double clipPlaneSquareSize(const Camera& camera);

/// How far the NPC view's faded parts reach beyond the cube: half its size on every side.
inline constexpr double kFadedMargin = 0.5;
/// The boundary coordinates of the cube grown by m on every side: x + m·w, (1 + m)·w − x, …
Boundary grownBoundary(const Vec4& p, double m);

/// The NPC view's faded polygon: face f as it was, clipped to the cube grown by half its size on
/// every side (which also keeps w > 0), then divided. The same Sutherland–Hodgman kernel with other
/// boundary values: x + m·w ≥ 0, (1 + m)·w − x ≥ 0, …
std::vector<Vec3> fadedNpcPolygon(const ObjectRun& o, size_t f, ClipScratch& scratch);
/// The same into `out` (cleared first), without allocating once `out` has grown.
void fadedNpcPolygon(const ObjectRun& o, size_t f, ClipScratch& scratch, std::vector<Vec3>& out);
/// Whether face f lies inside that grown cube with every corner in front of the eye (w > 0): its
/// faded polygon is then the face itself, divided by w (most faded faces are).
bool fadedFaceWhole(const ObjectRun& o, size_t f);

/// A label at a point of the view's space.
struct AnchoredLabel {
  Vec3 at;
  std::string text;
  glm::vec4 color;
  std::string shortText{};  // where the text finds no room (labels.h)
  int priority = 0;
};
/// The NPC cube's axis length and its labels (axes, 0 and 1 ticks, the front and back faces).
inline constexpr double kNpcAxisLength = 1.18;
std::vector<AnchoredLabel> npcCubeLabels(const theme::Palette& pal, Language lang);

/// A named point in WC with its object's colour.
struct NamedPoint {
  Vec3 at;
  std::string name;
  glm::vec4 color;
};
/// The vertices of the scene's visible polygon objects in WC, named P1 … Pn in their order (one
/// polygon: P1 …; several: each object's name first, "quad.P1").
std::vector<NamedPoint> polygonVertexNames(const Scene& scene);

}  // namespace vplab::geometry
