// The tests' own Sutherland–Hodgman clipper in homogeneous NPC (issue 38's answers made independently
// of the code under test: follow_through_test.cpp, tests/app/commands/class_of_300_test.cpp). Written from the
// lecture notes 15.3 and Blinn & Newell's boundary coordinates, sharing nothing with pipeline/.
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace vplab::test {

using P4 = std::array<double, 4>;  // homogeneous NPC (x, y, z, w)
using Polygon = std::vector<P4>;

/// Boundary coordinate of plane k (left, right, bottom, top, back, front): ≥ 0 inside (0 ≤ x, y, z ≤ w).
inline double boundary(const P4& p, int k) {
  switch (k) {
    case 0: return p[0];
    case 1: return p[3] - p[0];
    case 2: return p[1];
    case 3: return p[3] - p[1];
    case 4: return p[2];
    default: return p[3] - p[2];
  }
}

/// One Sutherland–Hodgman pass: each edge a → b (from the last vertex to the first, then on around)
/// keeps b if inside and adds the crossing where it leaves or enters (t = BC(a) / (BC(a) − BC(b))).
inline Polygon clipPass(const Polygon& in, int k) {
  Polygon out;
  for (size_t i = 0; i < in.size(); ++i) {
    const P4& a = in[(i + in.size() - 1) % in.size()];
    const P4& b = in[i];
    const double ba = boundary(a, k), bb = boundary(b, k);
    if ((ba >= 0) != (bb >= 0)) {
      const double t = ba / (ba - bb);
      P4 c;
      for (size_t j = 0; j < 4; ++j) c[j] = a[j] + t * (b[j] - a[j]);
      out.push_back(c);
    }
    if (bb >= 0) out.push_back(b);
  }
  return out;
}

/// Whether plane k cuts the polygon: a vertex an earlier pass put on a plane is on it up to rounding
/// (−4e-16), not outside.
inline bool needsCut(const Polygon& p, int k) {
  for (const P4& v : p)
    if (boundary(v, k) < -1e-9 * std::max(1.0, std::abs(v[3]))) return true;
  return false;
}

inline nlohmann::ordered_json jsonOf(const P4& v) { return nlohmann::ordered_json::array({v[0], v[1], v[2], v[3]}); }
inline nlohmann::ordered_json jsonOf(const Polygon& p) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const P4& v : p) out.push_back(jsonOf(v));
  return out;
}

}  // namespace vplab::test
