// Stage 5, device mapping NPC → DC (lecture notes 15.2.5; docs/conventions.md stage 5) and the constant that hands
// homogeneous NPC to OpenGL's clip space (docs/conventions.md "The GLSL path with the same matrices").
#include "pipeline/device_mapping.h"

#include "pipeline/clipping.h"

#include <gtest/gtest.h>

namespace vplab {
namespace {

Vec3 dcOf(const Device& d, const Vec3& npc) { return Vec3(dcFromNpc(d) * Vec4(npc, 1.0)); }

// DC has its origin top-left and y down: NPC (0, 0, *) → (0, H), (1, 1, *) → (W, 0); z unchanged.
// Every value is a small integer times W or H: exact.
TEST(DeviceMapping, CubeCornersLandOnScreenCorners) {
  for (const Device d : {Device{320, 240}, Device{1, 1}, Device{1920, 1080}, Device{7, 4096}}) {
    const double W = d.width, H = d.height;
    for (double z : {0.0, 0.3, 1.0}) {
      EXPECT_EQ(dcOf(d, {0, 0, z}), Vec3(0, H, z));
      EXPECT_EQ(dcOf(d, {1, 1, z}), Vec3(W, 0, z));
      EXPECT_EQ(dcOf(d, {1, 0, z}), Vec3(W, H, z));
      EXPECT_EQ(dcOf(d, {0, 1, z}), Vec3(0, 0, z));
      EXPECT_EQ(dcOf(d, {0.5, 0.5, z}), Vec3(W / 2, H / 2, z));
    }
    const Vec4 h = dcFromNpc(d) * Vec4(0.25, 0.75, 0.5, 1);
    EXPECT_EQ(h.w, 1);  // affine: no division needed after the NPC one
    EXPECT_DOUBLE_EQ(d.aspect(), W / H);
  }
}

// glClipFromNpc maps the NPC inside-test 0 ≤ x, y, z ≤ w onto GL's −w ≤ x, y, z ≤ w, front z = w onto
// the near plane z_c = −w; its inverse is x = (x_c + w)/2, y likewise, z = (w − z_c)/2.
TEST(DeviceMapping, GlClipFromNpc) {
  const Mat4 m = glClipFromNpc();
  for (double w : {1.0, 0.25, 7.0}) {
    for (int i = 0; i < 8; ++i) {
      const Vec4 npc((i & 1) * w, (i & 2 ? 1 : 0) * w, (i & 4 ? 1 : 0) * w, w);
      const Vec4 c = m * npc;
      EXPECT_EQ(c.x, i & 1 ? w : -w);
      EXPECT_EQ(c.y, i & 2 ? w : -w);
      EXPECT_EQ(c.z, i & 4 ? -w : w);  // front (z = w) → near plane z_c = −w
      EXPECT_EQ(c.w, w);
      const Vec4 back((c.x + c.w) / 2, (c.y + c.w) / 2, (c.w - c.z) / 2, c.w);
      EXPECT_EQ(back, npc);
    }
  }
  // Inside in NPC ⇔ inside in GL clip space, for points on either side of every plane.
  for (double x : {-0.1, 0.0, 0.5, 1.0, 1.1})
    for (double z : {-0.1, 0.0, 0.5, 1.0, 1.1}) {
      const Vec4 npc(x * 2, 0.5 * 2, z * 2, 2);
      const Vec4 c = m * npc;
      const bool glInside = -c.w <= c.x && c.x <= c.w && -c.w <= c.y && c.y <= c.w && -c.w <= c.z && c.z <= c.w;
      EXPECT_EQ(glInside, outcodeOf(boundaryCoordinates(npc)) == 0) << x << " " << z;
    }
}

}  // namespace
}  // namespace vplab
