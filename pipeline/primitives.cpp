#include "pipeline/primitives.h"

#include "base/error.h"

#include <algorithm>

namespace vplab {

Mesh cube() {
  Mesh m;
  // Vertex i has x = +0.5 when bit 0 is set, y when bit 1, z when bit 2.
  for (int i = 0; i < 8; ++i) m.positions.push_back({i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5});
  m.addFace({1, 3, 7, 5});  // +x
  m.addFace({0, 4, 6, 2});  // −x
  m.addFace({2, 6, 7, 3});  // +y
  m.addFace({0, 1, 5, 4});  // −y
  m.addFace({4, 5, 7, 6});  // +z
  m.addFace({0, 2, 3, 1});  // −z
  return m;
}

Mesh tetrahedron() {
  // Alternate corners of a cube of edge 1/√2 have edge length 1 and their centroid at its centre.
  const double a = 1.0 / (2.0 * std::sqrt(2.0));
  Mesh m;
  m.positions = {{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}};
  m.addFace({0, 2, 3});
  m.addFace({0, 3, 1});
  m.addFace({0, 1, 2});
  m.addFace({1, 3, 2});
  return m;
}

MeshSize cylinderSize(int n) {
  const size_t k = size_t(std::max(n, 0));
  return {k + 2, 2 * k, 4 * k + 2 * k};  // n side quads and two n-gon caps
}

MeshSize sphereSize(int n) {
  const size_t k = size_t(std::max(n, 4));
  // n triangles at each pole, n(n/2 − 2) quads; the poles and n/2 − 1 circles of n vertices
  return {2 * k + k * (k / 2 - 2), 2 + (k / 2 - 1) * k, 6 * k + 4 * k * (k / 2 - 2)};
}

Mesh cylinder(int n) {
  if (n < 3 || n > kMaxSegments)
    throw Error("a cylinder needs 3 to " + std::to_string(kMaxSegments) + " segments, not " + std::to_string(n));
  const double delta = 2 * kPi / n;  // lecture notes 16.2.1: δ = 2π/n, φ = k·δ
  Mesh m;
  for (int k = 0; k < n; ++k) m.positions.push_back({std::cos(k * delta), std::sin(k * delta), 1.0});
  for (int k = 0; k < n; ++k) m.positions.push_back({std::cos(k * delta), std::sin(k * delta), -1.0});
  auto top = [](int k) { return uint32_t(k); };
  auto bottom = [n](int k) { return uint32_t(n + k); };
  // Normals: the n radial directions (a side's top and bottom corners share theirs), then +z and −z
  // for the caps: a rim vertex has two, so the corners index them.
  for (int k = 0; k < n; ++k) m.normals.push_back({std::cos(k * delta), std::sin(k * delta), 0.0});
  const uint32_t up = uint32_t(n), down = uint32_t(n + 1);
  m.normals.push_back({0, 0, 1});
  m.normals.push_back({0, 0, -1});
  for (int k = 0; k < n; ++k) {
    const int k1 = (k + 1) % n;
    // The seed lists top(φ), top(φ+δ), bottom(φ+δ), bottom(φ): clockwise from outside. Reversed.
    const uint32_t q[4] = {top(k), bottom(k), bottom(k1), top(k1)};
    m.addFace(q);
    m.normalIndices.insert(m.normalIndices.end(), {uint32_t(k), uint32_t(k), uint32_t(k1), uint32_t(k1)});
  }
  std::vector<uint32_t> cap;
  for (int k = 0; k < n; ++k) cap.push_back(top(k));  // counter-clockwise seen from +z
  m.addFace(cap);
  m.normalIndices.insert(m.normalIndices.end(), size_t(n), up);
  cap.clear();
  for (int k = n - 1; k >= 0; --k) cap.push_back(bottom(k));  // counter-clockwise seen from −z
  m.addFace(cap);
  m.normalIndices.insert(m.normalIndices.end(), size_t(n), down);
  return m;
}

Mesh sphere(int n) {
  if (n < 4 || n % 2 != 0 || n > kMaxSegments)
    throw Error("a sphere needs an even number of segments from 4 to " + std::to_string(kMaxSegments) +
                ", not " + std::to_string(n));
  const double delta = 2 * kPi / n;  // lecture notes 16.2.2: θ = l·δ from the north pole, φ = k·δ
  const int rings = n / 2 - 1;       // latitude circles l = 1 .. n/2 − 1
  auto point = [](double theta, double phi) {
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  };
  Mesh m;
  m.positions.push_back({0, 0, 1});  // north pole, index 0
  for (int l = 1; l <= rings; ++l)
    for (int k = 0; k < n; ++k) m.positions.push_back(point(l * delta, k * delta));
  m.positions.push_back({0, 0, -1});  // south pole
  const uint32_t south = uint32_t(m.positions.size() - 1);
  auto at = [n](int l, int k) { return uint32_t(1 + (l - 1) * n + (k % n)); };
  for (int k = 0; k < n; ++k) m.addFace({0, at(1, k), at(1, k + 1)});
  for (int l = 1; l < rings; ++l)
    for (int k = 0; k < n; ++k) m.addFace({at(l, k), at(l + 1, k), at(l + 1, k + 1), at(l, k + 1)});
  for (int k = 0; k < n; ++k) m.addFace({south, at(rings, k + 1), at(rings, k)});
  m.normals = m.positions;  // one a vertex: the radius ⟂ the surface
  return m;
}

Mesh polygon(const std::vector<Vec3>& vertices) {
  if (vertices.size() < 3)
    throw Error("a polygon needs at least 3 vertices, not " + std::to_string(vertices.size()));
  Mesh m;
  m.positions = vertices;
  std::vector<uint32_t> face(vertices.size());
  for (size_t i = 0; i < face.size(); ++i) face[i] = uint32_t(i);
  m.addFace(face);
  return m;
}

}  // namespace vplab
