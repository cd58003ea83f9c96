#include "pipeline/math.h"

#include <cstdio>

namespace vplab {

bool isFinite(const Mat4& m) {
  for (int c = 0; c < 4; ++c)
    if (!isFinite(m[c])) return false;
  return true;
}

std::string format(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string format(const Vec3& v) {
  return "(" + format(v.x) + ", " + format(v.y) + ", " + format(v.z) + ")";
}

}  // namespace vplab
