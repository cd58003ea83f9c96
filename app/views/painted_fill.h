// Filled faces without a depth buffer (the SVG backend): the painter's algorithm (Foley et al. 15.5,
// "depth sort"). Each face of a Fill is projected and clipped as GL would (app/views/projection.h:
// the view volume, the user clip planes, Fill::volume), coloured once as the shaders colour it
// (flat: its colour; lit: shaders/scene.frag's Blinn–Phong, lecture notes 13.5, evaluated once,
// at the centroid of the face's clipped corners, with the face's normal there), and the faces are
// sorted back to front by the mean depth of their clipped corners. Unlike the depth buffer this cannot show
// faces that intersect or overlap cyclically, and a lit face is one colour where GL interpolates across it.
//
// No GL.
#pragma once

#include <vector>

#include "app/views/projection.h"

namespace vplab::draw {

struct PaintedPolygon {
  std::vector<PixelPoint> points;  // the view's pixels, convex when the face is
  glm::vec4 color;                 // as the fragment shader writes it, alpha included
  double depth = 0;                // the mean NPC z of the face's clipped corners (larger is nearer)
};

/// The number of faces a fill draws (its meshes' faces and its polygons), before any clipping: what
/// an export checks against its limit before building anything.
size_t faceCount(const Fill& fill);

/// The fill's faces in `list`'s pixels, back to front (stable: equal depths keep their order).
/// Fill::volume: the inside part of each face is exact (the pipeline's clipper against the other
/// camera's six boundary forms); the outside part is exact too, as up to six disjoint pieces (the
/// part outside plane 0, the part inside 0 and outside 1, …), which meet along seams an
/// anti-aliased SVG renderer may show faintly.
std::vector<PaintedPolygon> paintedPolygons(const Fill& fill, const DisplayList& list);

/// shaders/scene.frag's colour of a point `at` with normal `normal` (batch space) of a face seen
/// from the side `seen` (unit or not) points to, for an observer whose eye is `eye` (w = 1: a point;
/// w = 0: the direction to the viewer).
glm::vec3 litColor(const Fill& fill, const glm::vec3& color, const Vec3& at, Vec3 normal, const Vec3& seen,
                   const Vec4& eye);

}  // namespace vplab::draw
