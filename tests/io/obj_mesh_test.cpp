// Meshes from Wavefront OBJ (obj_mesh.h): a valid file with quads and normals, and every bad input
// with a message that names the file and the line.
#include "io/obj_mesh.h"
#include "io/build_mesh.h"

#include "pipeline/pipeline.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <cmath>
#include <gtest/gtest.h>

namespace vplab {
namespace {

using test::errorOf;
using testing::HasSubstr;

const std::string kData = VPLAB_TEST_DATA;

TEST(ObjMesh, QuadsWithNormalsLoad) {
  const Mesh m = loadObj(kData + "/box_quads_normals.obj");
  EXPECT_EQ(m.vertexCount(), 8u);
  ASSERT_EQ(m.faceCount(), 6u);
  for (size_t f = 0; f < 6; ++f) EXPECT_EQ(m.face(f).size(), 4u) << f;  // not triangulated
  // Six "vn" lines, one a face: each vertex has three, so the 24 corners index them.
  ASSERT_EQ(m.normals.size(), 6u);
  ASSERT_EQ(m.normalIndices.size(), 24u);
  EXPECT_EQ(m.positions[0], Vec3(0, 0, 0));
  EXPECT_EQ(m.positions[6], Vec3(1, 1, 1));
  // Indices are 0-based in the mesh (1-based in the file): the first face is "1 4 3 2".
  const auto f0 = m.face(0);
  EXPECT_EQ(std::vector<uint32_t>(f0.begin(), f0.end()), (std::vector<uint32_t>{0, 3, 2, 1}));
  // The file's normals per corner; each agrees with the face's own (Newell) normal, so the faces
  // are counter-clockwise seen from outside, and outward from the box centre.
  for (size_t f = 0; f < 6; ++f) {
    const Vec3 n = glm::normalize(faceNormal(m, f));
    for (uint32_t k = m.faceStart[f]; k < m.faceStart[f + 1]; ++k) EXPECT_EQ(m.cornerNormal(k), n) << f;
    Vec3 c(0);
    for (uint32_t i : m.face(f)) c += m.positions[i] / 4.0;
    EXPECT_GT(glm::dot(n, c - Vec3(0.5)), 0) << f;
  }
  EXPECT_EQ(m.cornerNormal(0), Vec3(0, 0, -1));
}

TEST(ObjMesh, ParseObjFromText) {
  // Negative (relative) indices, CRLF line ends, tabs, comments, a pentagon, "v/vt" corners.
  const std::string text =
      "# comment\r\n"
      "v 0 0 0\r\n"
      "v\t1 0 0\r\n"
      "v 1 1 0\r\n"
      "v 0.5 1.5 0\r\n"
      "v -0.5 1 0 1.0\r\n"  // an optional w
      "vt 0 0\r\n"
      "f -5 -4 -3 -2 -1\r\n"
      "f 1/1 2/1 3/1\r\n";
  const Mesh m = parseObj(text, "memory.obj");
  EXPECT_EQ(m.vertexCount(), 5u);
  ASSERT_EQ(m.faceCount(), 2u);
  EXPECT_EQ(m.face(0).size(), 5u);
  EXPECT_EQ(m.face(0)[0], 0u);
  EXPECT_EQ(m.face(0)[4], 4u);
  EXPECT_FALSE(m.smooth());  // no normals in the file: flat shading
  EXPECT_TRUE(m.normalIndices.empty());
  EXPECT_EQ(m.positions[4], Vec3(-0.5, 1, 0));
}

// Normals are kept indexed as the file has them, each "vn" the faces name once; when every vertex's
// corners name one normal, the mesh keeps one a vertex and no indices (an exported smooth sphere).
TEST(ObjMesh, NormalsStayIndexedOrBecomeOneAVertex) {
  const std::string quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n";
  // A vertex normal each (vn 2 ... 5 for v 1 ... 4, vn 1 unused, v 5 in no face): one a vertex.
  Mesh m = parseObj(quad + "vn 9 9 9\nvn 0 0 1\nvn 0 0.5 0.75\nvn 0.5 0 0.75\nvn 0 -0.5 0.75\n"
                           "f 1//2 2//3 3//4\nf 1//2 3//4 4//5\n", "smooth.obj");
  EXPECT_TRUE(m.normalIndices.empty());
  ASSERT_EQ(m.normals.size(), m.positions.size());
  EXPECT_EQ(m.cornerNormal(0), Vec3(0, 0, 1));
  // tinyobjloader's own number parser: 0.75 comes out an ulp or so above.
  EXPECT_NEAR(glm::length(m.cornerNormal(4) - Vec3(0.5, 0, 0.75)), 0, 1e-15) << "v 3 in the second face";
  EXPECT_EQ(m.normals[4], Vec3(0, 0, 1)) << "a vertex no face uses: +z";
  EXPECT_NO_THROW(checkWellFormed(m));
  // Vertex 1 with two normals: indexed, the unused "vn 9 9 9" left out.
  m = parseObj(quad + "vn 9 9 9\nvn 0 0 1\nvn 1 0 0\nf 1//2 2//2 3//2\nf 1//3 3//3 4//3\n", "creased.obj");
  ASSERT_EQ(m.normals.size(), 2u);
  ASSERT_EQ(m.normalIndices.size(), 6u);
  EXPECT_EQ(m.cornerNormal(0), Vec3(0, 0, 1));
  EXPECT_EQ(m.cornerNormal(3), Vec3(1, 0, 0));
  EXPECT_NO_THROW(checkWellFormed(m));
}

// A mesh made elsewhere (the page's loader worker) is checked before use: normal indices that do not
// match the corners or name no normal, per-vertex normals of the wrong count, non-finite normals.
TEST(ObjMesh, IllFormedNormalsAreRefusedWithTheValues) {
  const Mesh good = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvn 1 0 0\n"
                              "f 1//1 2//1 3//1\nf 1//2 3//2 4//2\n", "creased.obj");
  ASSERT_EQ(good.normalIndices.size(), 6u);
  ASSERT_NO_THROW(checkWellFormed(good));
  Mesh m = good;
  m.normalIndices.pop_back();
  EXPECT_THAT(errorOf([&] { checkWellFormed(m); }), HasSubstr("5 normal indices for 6 corners"));
  m = good;
  m.normalIndices[1] = 7;
  EXPECT_THAT(errorOf([&] { checkWellFormed(m); }), HasSubstr("corner 1 names normal 7 of 2"));
  m = good;
  m.normalIndices.clear();  // one a vertex, but two normals for four vertices
  EXPECT_THAT(errorOf([&] { checkWellFormed(m); }), HasSubstr("2 normals, one a vertex, for 4 vertices"));
  m = good;
  m.normals[1].y = std::nan("");
  EXPECT_THAT(errorOf([&] { checkWellFormed(m); }), HasSubstr("normal 1 is not finite"));
}

// When only some corners carry a normal, none are used (flat shading) rather than a misaligned list.
TEST(ObjMesh, PartialNormalsAreDropped) {
  const Mesh m = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\n"
                          "f 1//1 2//1 3//1\nf 1 2 4\n",
                          "partial.obj");
  EXPECT_EQ(m.faceCount(), 2u);
  EXPECT_FALSE(m.smooth());  // a face without normals: the whole mesh flat
  EXPECT_TRUE(m.normalIndices.empty());
}

struct BadObj {
  const char* what;
  std::string text;
  std::vector<std::string> parts;  // each must appear in the message
};

TEST(ObjMesh, BadInputsNameFileAndLine) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";  // lines 1–3
  const std::vector<BadObj> cases = {
      {"non-numeric coordinate", "v 0 0 0\nv 1 x 0\n", {"bad.obj:2:", "'x' is not a finite number in a 'v' line"}},
      {"NaN", tri + "v nan 0 0\nf 1 2 3\n", {"bad.obj:4:", "'nan' is not a finite number"}},
      {"infinity", tri + "v 0 inf 0\nf 1 2 3\n", {"bad.obj:4:", "'inf'"}},
      {"overflow", tri + "v 0 1e999 0\nf 1 2 3\n", {"bad.obj:4:", "'1e999'"}},
      {"two coordinates", "v 1 2\n", {"bad.obj:1:", "'v' needs 3 numbers, found 2"}},
      {"normal with a word", tri + "vn 0 0 one\n", {"bad.obj:4:", "'one'", "'vn' line"}},
      {"index out of range", tri + "f 1 2 4\n", {"bad.obj:4:", "vertex index 4 in '4' is out of range: 3 defined so far"}},
      {"negative index out of range", tri + "f -1 -2 -4\n", {"bad.obj:4:", "vertex index -4"}},
      {"index used before its vertex", "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n", {"bad.obj:3:", "index 3", "2 defined so far"}},
      {"index 0", tri + "f 0 1 2\n", {"bad.obj:4:", "'0' is not a valid face corner (indices start at 1)"}},
      {"index not a number", tri + "f 1 2 three\n", {"bad.obj:4:", "'three' is not a valid face corner"}},
      {"face with 2 vertices", tri + "\n# two\nf 1 2\n", {"bad.obj:6:", "a face needs at least 3 vertices, found 2"}},
      {"normal index out of range", tri + "vn 0 0 1\nf 1//1 2//1 3//2\n", {"bad.obj:5:", "normal index 2 in '3//2'"}},
      {"texture index out of range", tri + "f 1/1 2/1 3/1\n", {"bad.obj:4:", "texture coordinate index 1"}},
      {"no faces", tri, {"bad.obj: the OBJ file has no faces"}},
      {"empty file", "", {"bad.obj: the OBJ file has no faces"}},
  };
  for (const BadObj& c : cases) {
    SCOPED_TRACE(c.what);
    const std::string message = errorOf([&] { parseObj(c.text, "bad.obj"); });
    for (const std::string& part : c.parts) EXPECT_THAT(message, HasSubstr(part));
  }
}

TEST(ObjMesh, BadFilesNameThePathAndLine) {
  EXPECT_THAT(errorOf([] { loadObj(kData + "/bad_vertex.obj"); }),
              HasSubstr(kData + "/bad_vertex.obj:5: 'zero' is not a finite number"));
  EXPECT_THAT(errorOf([] { loadObj(kData + "/no_faces.obj"); }),
              HasSubstr(kData + "/no_faces.obj: the OBJ file has no faces"));
  EXPECT_THAT(errorOf([] { loadObj(kData + "/does_not_exist.obj"); }),
              HasSubstr(kData + "/does_not_exist.obj: cannot open the OBJ file"));
  EXPECT_THAT(errorOf([] { loadObj(kData); }), HasSubstr(kData));  // a directory: no crash, an error
}

// A loaded mesh goes through the pipeline without NaN.
TEST(ObjMesh, LoadedMeshRunsThroughThePipeline) {
  SceneObject o;
  o.name = "box";
  o.shape = Shape::mesh;
  o.file = "box_quads_normals.obj";
  buildMesh(o, kData);
  Camera c = test::checkCamera();
  c.vrp = {0.5, 0.5, 0.5};
  c.prp = {0.5, 0.5, 3};
  const PipelineRun run = runPipeline(test::sceneWith(c, {o}));
  ASSERT_EQ(run.objects.size(), 1u);
  const ObjectRun& r = run.objects[0];
  EXPECT_EQ(r.faceCount(), 6u);
  for (size_t f = 0; f < r.faceCount(); ++f) {
    EXPECT_NE(r.fate[f], Fate::rejected);
    for (uint32_t ref : r.clippedFace(f)) EXPECT_TRUE(isFinite(r.clippedDc(ref)));
  }
}

}  // namespace
}  // namespace vplab
