// Stage 5, device mapping NPC → DC (lecture notes 15.2.5), and the constant that hands homogeneous NPC to
// OpenGL's clip space (docs/conventions.md, "The GLSL path with the same matrices").
#pragma once

#include "pipeline/math.h"

namespace vplab {

/// A device of W × H pixels; DC has its origin top-left and y down.
struct Device {
  int width = 640;
  int height = 480;
  double aspect() const { return double(width) / double(height); }
  bool operator==(const Device&) const = default;
};

/// x_dc = W·x, y_dc = H·(1 − y), z_dc = z (1 at the front plane, 0 at the back).
Mat4 dcFromNpc(const Device& device);

/// x_c = 2x − w, y_c = 2y − w, z_c = w − 2z, w_c = w: the NPC cube with front z = w becomes GL's
/// clip volume with the near plane z_c = −w, without changing what is inside.
Mat4 glClipFromNpc();

}  // namespace vplab
