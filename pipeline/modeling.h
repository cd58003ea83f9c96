// Stage 1, modeling MC → WC (lecture notes 13.1–13.5, 15.2.1; docs/conventions.md stage 1).
//
// wcFromMc = T(translate) · R_k · … · R_1 · S(scale): scale first, then the rotations in the order
// listed (the first listed acts first), then the translation.
#pragma once

#include "pipeline/math.h"

#include <optional>
#include <vector>

namespace vplab {

/// A rotation by `deg` degrees, right-handed, about `axis` through the origin or through `through`.
struct Rotation {
  Vec3 axis{0, 0, 1};
  double deg = 0;
  std::optional<Vec3> through;  // a point on the axis, in the coordinates the rotation acts in
  bool operator==(const Rotation&) const = default;
};

struct ModelTransform {
  Vec3 translate{0, 0, 0};
  std::vector<Rotation> rotations;  // the first listed acts first
  Vec3 scale{1, 1, 1};
  bool operator==(const ModelTransform&) const = default;
};

/// T(t) (lecture notes 13.1).
Mat4 translation(const Vec3& t);
/// S(s) about the origin (lecture notes 13.2).
Mat4 scaling(const Vec3& s);
/// T(Z) · S · T(−Z): scaling with the fixed point Z (lecture notes 13.2).
Mat4 scalingAbout(const Vec3& s, const Vec3& fixedPoint);
/// Rotation about the x, y or z axis (lecture notes 13.3, in column-vector form).
Mat4 rotationX(double deg);
Mat4 rotationY(double deg);
Mat4 rotationZ(double deg);
/// Rotation about an axis direction through the origin. The seed composes it from rotating the
/// axis into z, Rz, and undoing; this is the same matrix in closed (Rodrigues) form.
Mat4 rotationAbout(const Vec3& axis, double deg);
/// Rotation about the line through `point` along `axis`: T(point) · R · T(−point) (lecture notes 13.3).
Mat4 rotationAboutLine(const Vec3& axis, double deg, const Vec3& point);
Mat4 rotation(const Rotation& r);

/// Stage 1 matrix of an object. Throws vplab::Error for a zero or non-finite axis or scale.
Mat4 wcFromMc(const ModelTransform& m);

/// Change of basis (lecture notes 13.4): the matrix taking coordinates in frame B (axes x, y, z and origin
/// given in A) to coordinates in A. Its columns are B's axes and origin.
Mat4 aFromB(const Vec3& xAxis, const Vec3& yAxis, const Vec3& zAxis, const Vec3& origin);

/// Normals map with the inverse transpose of the upper 3 × 3 (lecture notes 13.5).
Mat3 normalMatrix(const Mat4& m);

}  // namespace vplab
