#include "pipeline/device_mapping.h"

namespace vplab {

Mat4 dcFromNpc(const Device& device) {
  const double W = device.width;
  const double H = device.height;
  // clang-format off
  return matrixFromRows(
      W, 0,  0, 0,
      0, -H, 0, H,
      0, 0,  1, 0,
      0, 0,  0, 1);
  // clang-format on
}

Mat4 glClipFromNpc() {
  // clang-format off
  return matrixFromRows(
      2, 0, 0,  -1,
      0, 2, 0,  -1,
      0, 0, -2, 1,
      0, 0, 0,  1);
  // clang-format on
}

}  // namespace vplab
