#include "pipeline/modeling.h"

#include "base/error.h"

namespace vplab {

Mat4 translation(const Vec3& t) {
  // clang-format off
  return matrixFromRows(
      1, 0, 0, t.x,
      0, 1, 0, t.y,
      0, 0, 1, t.z,
      0, 0, 0, 1);
  // clang-format on
}

Mat4 scaling(const Vec3& s) {
  // clang-format off
  return matrixFromRows(
      s.x, 0,   0,   0,
      0,   s.y, 0,   0,
      0,   0,   s.z, 0,
      0,   0,   0,   1);
  // clang-format on
}

Mat4 scalingAbout(const Vec3& s, const Vec3& fixedPoint) {
  return translation(fixedPoint) * scaling(s) * translation(-fixedPoint);
}

Mat4 rotationX(double deg) {
  const double c = std::cos(radians(deg)), s = std::sin(radians(deg));
  // clang-format off
  return matrixFromRows(
      1, 0,  0, 0,
      0, c, -s, 0,
      0, s,  c, 0,
      0, 0,  0, 1);
  // clang-format on
}

Mat4 rotationY(double deg) {
  const double c = std::cos(radians(deg)), s = std::sin(radians(deg));
  // clang-format off
  return matrixFromRows(
       c, 0, s, 0,
       0, 1, 0, 0,
      -s, 0, c, 0,
       0, 0, 0, 1);
  // clang-format on
}

Mat4 rotationZ(double deg) {
  const double c = std::cos(radians(deg)), s = std::sin(radians(deg));
  // clang-format off
  return matrixFromRows(
      c, -s, 0, 0,
      s,  c, 0, 0,
      0,  0, 1, 0,
      0,  0, 0, 1);
  // clang-format on
}

Mat4 rotationAbout(const Vec3& axis, double deg) {
  const double len = glm::length(axis);
  if (!isFinite(axis) || !(len > 1e-12) || !isFinite(deg))
    throw Error("a rotation needs a finite, non-zero axis and a finite angle, but axis = " +
                format(axis) + ", deg = " + format(deg));
  const Vec3 a = axis / len;
  const double c = std::cos(radians(deg)), s = std::sin(radians(deg)), t = 1 - c;
  // clang-format off
  return matrixFromRows(
      t*a.x*a.x + c,     t*a.x*a.y - s*a.z, t*a.x*a.z + s*a.y, 0,
      t*a.x*a.y + s*a.z, t*a.y*a.y + c,     t*a.y*a.z - s*a.x, 0,
      t*a.x*a.z - s*a.y, t*a.y*a.z + s*a.x, t*a.z*a.z + c,     0,
      0,                 0,                 0,                 1);
  // clang-format on
}

Mat4 rotationAboutLine(const Vec3& axis, double deg, const Vec3& point) {
  if (!isFinite(point)) throw Error("the point a rotation axis passes through must be finite, "
                                    "but it is " + format(point));
  return translation(point) * rotationAbout(axis, deg) * translation(-point);
}

Mat4 rotation(const Rotation& r) {
  return r.through ? rotationAboutLine(r.axis, r.deg, *r.through) : rotationAbout(r.axis, r.deg);
}

Mat4 wcFromMc(const ModelTransform& m) {
  if (!isFinite(m.translate)) throw Error("translate " + format(m.translate) + " must be finite");
  if (!isFinite(m.scale) || m.scale.x == 0 || m.scale.y == 0 || m.scale.z == 0)
    throw Error("scale " + format(m.scale) + " must be finite and non-zero in every axis");
  Mat4 rotations(1.0);
  for (const Rotation& r : m.rotations) rotations = rotation(r) * rotations;  // first acts first
  return translation(m.translate) * rotations * scaling(m.scale);
}

Mat4 aFromB(const Vec3& x, const Vec3& y, const Vec3& z, const Vec3& o) {
  // clang-format off
  return matrixFromRows(
      x.x, y.x, z.x, o.x,
      x.y, y.y, z.y, o.y,
      x.z, y.z, z.z, o.z,
      0,   0,   0,   1);
  // clang-format on
}

Mat3 normalMatrix(const Mat4& m) { return glm::transpose(glm::inverse(Mat3(m))); }

}  // namespace vplab
