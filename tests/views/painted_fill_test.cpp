#include "app/views/painted_fill.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/hand_made_lists.h"

namespace vplab::draw {
namespace {

using lists::square;

double area(const std::vector<PixelPoint>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i)
    a += p[i].x * p[(i + 1) % p.size()].y - p[(i + 1) % p.size()].x * p[i].y;
  return std::abs(a) / 2;
}

TEST(PaintedFill, FacesComeBackToFront) {
  const DisplayList list = lists::wcList();
  Fill f;
  f.polygons.push_back(square(1, 0.2, {1, 0, 0}));   // near, listed first
  f.polygons.push_back(square(-1, 0.5, {0, 0, 1}));  // far
  const auto faces = paintedPolygons(f, list);
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_EQ(faces[0].color, glm::vec4(0, 0, 1, 1));  // the far one first
  EXPECT_EQ(faces[1].color, glm::vec4(1, 0, 0, 1));
  EXPECT_LT(faces[0].depth, faces[1].depth);
  EXPECT_EQ(faceCount(f), 2u);
}

TEST(PaintedFill, FlatIsTheColourAndAlpha) {
  const DisplayList list = lists::wcList();
  Fill f;
  f.alpha = 0.4f;
  MeshInstance m{std::make_shared<Mesh>(), Mat4(1.0), {0.2f, 0.5f, 0.8f, 1.f}};
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0, 0.5, 0}};
  mesh->addFace({0, 1, 2});
  m.mesh = mesh;
  f.meshes.push_back(m);
  const auto faces = paintedPolygons(f, list);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(faces[0].color, glm::vec4(0.2f, 0.5f, 0.8f, 0.4f));
  // Its pixels: width 1 of the window's 2 is 200 px, height 1 of 1.5 is 200 px: area 200·200 / 2.
  EXPECT_NEAR(area(faces[0].points), 20000, 1e-6);
}

TEST(PaintedFill, LitIsBlinnPhongOfTheShader) {
  // A face at z = 0 facing +z, a white light on the axis at z = 5 and the eye at z = 5 (the default
  // camera's PRP): at the centroid n·l = 1 and n·h = 1, so colour = ambient·c + c + 0.3, clamped.
  Fill f;
  f.lit = true;
  f.ambient = 0.25f;
  f.lights = {Light{{0, 0, 5}, {1, 1, 1}}};
  const glm::vec3 c(0.2f, 0.4f, 0.1f);
  const glm::vec3 got = litColor(f, c, Vec3(0), Vec3(0, 0, 2), Vec3(0, 0, 1), Vec4(0, 0, 5, 1));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], std::min(1.0, 1.25 * c[i] + 0.3), 1e-6);
  // Seen from behind it is lit from the side it is seen from: the same colour.
  const glm::vec3 back = litColor(f, c, Vec3(0), Vec3(0, 0, -2), Vec3(0, 0, -1), Vec4(0, 0, 5, 1));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(back[i], got[i], 1e-6);
  // A light behind the face: ambient only.
  f.lights = {Light{{0, 0, -5}, {1, 1, 1}}};
  const glm::vec3 dark = litColor(f, c, Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1), Vec4(0, 0, 5, 1));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(dark[i], 0.25 * c[i], 1e-6);
  // At 45°: diffuse cos 45°, the half vector between l and the eye direction.
  f.lights = {Light{{5, 0, 5}, {1, 1, 1}}};
  const glm::vec3 oblique = litColor(f, c, Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1), Vec4(0, 0, 1, 0));
  const double d = std::sqrt(0.5), h = std::cos(M_PI / 8);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(oblique[i], std::min(1.0, 0.25 * c[i] + d * c[i] + 0.3 * std::pow(h, 48)), 1e-6);
}

TEST(PaintedFill, TheVolumeSplitsEachFaceIntoInsideAndOutside) {
  const DisplayList list = lists::wcList();
  // "The other camera": a parallel box x, y, z ∈ [0, 1] of WC is its unit cube (npcFromSpace = 1).
  Fill inside, outside;
  inside.polygons.push_back(square(0.5, 0.5, {1, 1, 1}));  // x, y ∈ [−0.5, 0.5] at z = 0.5
  inside.volume = {VolumeTest::Keep::inside, Mat4(1.0)};
  outside = inside;
  outside.volume.keep = VolumeTest::Keep::outside;
  double in = 0, out = 0;
  for (const auto& p : paintedPolygons(inside, list)) in += area(p.points);
  for (const auto& p : paintedPolygons(outside, list)) out += area(p.points);
  Fill all = inside;
  all.volume.keep = VolumeTest::Keep::all;
  const double whole = area(paintedPolygons(all, list)[0].points);
  EXPECT_NEAR(in, whole / 4, 1e-6);  // the quarter with x, y ≥ 0
  EXPECT_NEAR(out, 3 * whole / 4, 1e-6);
  EXPECT_GT(paintedPolygons(outside, list).size(), 1u);  // in pieces
}

TEST(PaintedFill, UserClipPlanesCutTheFaces) {
  const DisplayList list = lists::wcList();
  Fill f;
  f.polygons.push_back(square(0, 0.5, {1, 1, 1}));
  const double whole = area(paintedPolygons(f, list)[0].points);
  f.clipPlanes = {Vec4(0, -1, 0, 0)};  // y ≤ 0 kept
  const auto faces = paintedPolygons(f, list);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_NEAR(area(faces[0].points), whole / 2, 1e-6);
  for (const PixelPoint& p : faces[0].points) EXPECT_GE(p.y, 150 - 1e-9);  // the lower half (y down)
}

}  // namespace
}  // namespace vplab::draw
