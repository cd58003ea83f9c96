// Stage 3, view mapping VRC → homogeneous NPC (lecture notes 14, 15.2.3–15.2.4; docs/conventions.md stage 3).
//
// The view volume maps onto the unit cube 0 ≤ x, y, z ≤ 1 with front → z = 1, back → z = 0,
// left → x = 0, bottom → y = 0. Perspective results have w ≠ 1: clip first (stage 4), then divide.
#pragma once

#include "pipeline/camera.h"

namespace vplab {

/// npcFromVrc for the camera's projection. Throws vplab::Error for an invalid camera.
Mat4 npcFromVrc(const Camera& camera);

/// The same for a frame already derived from the camera (no validation).
Mat4 npcFromVrc(const Camera& camera, const VrcAxes& frame);

/// Perspective with the centre of projection at VRC (0, 0, VPD): the lecture notes' shear into a regular
/// 45° pyramid and its scaling into the cube, folded into one matrix; w' = ze = VPD − z.
Mat4 perspectiveNpcFromVrc(const ViewWindow& w, double vpd, double front, double back);

/// Parallel projection along −N, sheared by the oblique angle first (d = 0: orthographic).
Mat4 parallelNpcFromVrc(const ViewWindow& w, double front, double back, const ObliqueParams& ob);

/// The oblique shear alone (lecture notes 14.3.2): x_s = x + z·d·cos φ, y_s = y − z·d·sin φ, z_s = z.
Mat4 obliqueShear(const ObliqueParams& ob);

/// NPC z after the division, for a VRC depth z on the axis: dmin·(dmax − ze)/((dmax − dmin)·ze)
/// for perspective (not linear: equal steps crowd near the back plane, lecture notes 15.2.4), (z − B)/(F − B)
/// for parallel projections.
double npcDepthOfVrcZ(const Camera& camera, const VrcAxes& frame, double vrcZ);

/// The smallest VRC depth difference a depth buffer of `bits` bits can tell apart at VRC z: one step
/// 1/(2^bits − 1) of window depth (= 1 − NPC z) divided by how fast NPC z changes with VRC z. For
/// perspective that is (2^bits − 1)⁻¹ · (dmax − dmin)·ze² / (dmin·dmax), growing with the square of
/// the distance from the eye ze (lecture notes 15.2.4); for parallel projections it is constant, (F − B) / (2^bits − 1).
double depthResolution(const Camera& camera, const VrcAxes& frame, double vrcZ, int bits);

}  // namespace vplab
