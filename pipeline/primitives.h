// The primitives of lecture notes chapter 16 in MC, faces counter-clockwise seen from outside.
#pragma once

#include "pipeline/mesh.h"

namespace vplab {

/// Edge length 1, centred at the origin: 8 vertices (±0.5, ±0.5, ±0.5), 6 quads (lecture notes 16.1.1).
Mesh cube();
/// Edge length 1, centroid at the origin, 4 triangles (lecture notes 16.1.1).
Mesh tetrahedron();
/// Radius 1, axis z, z = ±1: n side quads and two n-gon caps (lecture notes 16.2.1); n ≥ 3.
/// Side corners carry the radial normal (smooth shading), cap corners ±z.
Mesh cylinder(int n);
/// Radius 1, n even ≥ 4: n/2 meridians 2π/n apart, n/2 − 1 latitude circles, n triangles at
/// each pole and n(n/2 − 2) quads between (lecture notes 16.2.2). Normals are the position vectors.
Mesh sphere(int n);
/// One polygon through the given vertices, in the given order (at least 3).
Mesh polygon(const std::vector<Vec3>& vertices);

/// The most segments a cylinder or sphere may have (a file may be limited to fewer: io/limits.h).
inline constexpr int kMaxSegments = 2048;

/// The sizes cylinder(n) and sphere(n) will have (n checked by them, not here).
MeshSize cylinderSize(int n);
MeshSize sphereSize(int n);

}  // namespace vplab
