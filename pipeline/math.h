// Vectors and matrices of the CPU pipeline: double precision, column vectors (p' = M · p), as GLM.
//
// The seeds write points as row vectors (p' = p · M); their matrices are the transposes of ours
// (docs/conventions.md, "Notation"). `matrixFromRows` lets code write a matrix as it looks on paper, in the
// column-vector form, inside a `// clang-format off` block.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <string>

namespace vplab {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
using Vec4 = glm::dvec4;
using Mat3 = glm::dmat3;
using Mat4 = glm::dmat4;

/// A 4 × 4 matrix from its rows, as printed on paper (GLM stores columns; this transposes).
constexpr Mat4 matrixFromRows(double m00, double m01, double m02, double m03,
                              double m10, double m11, double m12, double m13,
                              double m20, double m21, double m22, double m23,
                              double m30, double m31, double m32, double m33) {
  return Mat4(m00, m10, m20, m30,   // column 0
              m01, m11, m21, m31,   // column 1
              m02, m12, m22, m32,   // column 2
              m03, m13, m23, m33);  // column 3
}

/// Row r of M (r = 0..3).
inline Vec4 row(const Mat4& m, int r) { return {m[0][r], m[1][r], m[2][r], m[3][r]}; }

/// The matrix as 4 rows, the order the dump and the matrix panel print it in.
inline std::array<std::array<double, 4>, 4> rowsOf(const Mat4& m) {
  std::array<std::array<double, 4>, 4> rows{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) rows[r][c] = m[c][r];
  return rows;
}

/// M · p for an affine transform (bottom row 0 0 0 1): the w component is not computed.
inline Vec3 transformAffine(const Mat4& m, const Vec3& p) {
  return Vec3(m[0]) * p.x + Vec3(m[1]) * p.y + Vec3(m[2]) * p.z + Vec3(m[3]);
}

inline bool isFinite(double v) { return std::isfinite(v); }
inline bool isFinite(const Vec3& v) { return isFinite(v.x) && isFinite(v.y) && isFinite(v.z); }
inline bool isFinite(const Vec4& v) { return isFinite(Vec3(v)) && isFinite(v.w); }
bool isFinite(const Mat4& m);

/// "(x, y, z)" with up to 6 significant digits, for error messages that name the values.
std::string format(const Vec3& v);
std::string format(double v);

constexpr double kPi = 3.14159265358979323846;
constexpr double radians(double deg) { return deg * (kPi / 180.0); }

}  // namespace vplab
