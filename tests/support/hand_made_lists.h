// Hand-made display lists for the GL-free helpers' tests: a 400 × 300 view of WC through the
// pipeline's default camera (eye at (0, 0, 5) looking down −z, window ±1 × ±0.75 at z = 0, front
// plane z = 2, back plane z = −2), so WC (0, 0, 0) is the view's centre pixel (200, 150).
#pragma once

#include "app/views/display_list.h"

namespace vplab::draw::lists {

inline DisplayList wcList(int width = 400, int height = 300) {
  DisplayList list;
  list.width = width;
  list.height = height;
  list.observer = {Space::wc, viewCameraOf(Camera{})};
  return list;
}

/// A square of half-size `half` around the z axis at depth z, in one colour.
inline PolygonSet square(double z, double half, const glm::vec3& color) {
  PolygonSet s;
  s.color = color;
  const Vec3 q[4] = {{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
  s.add(q);
  return s;
}

}  // namespace vplab::draw::lists
