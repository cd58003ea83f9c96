// Meshes from Wavefront OBJ (obj_mesh.h): a valid file with quads and normals, and every bad input
// with a message that names the file and the line.
#include "io/obj_mesh.h"
#include "io/build_mesh.h"

#include "pipeline/pipeline.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
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
  ASSERT_EQ(m.cornerNormals.size(), 24u);
  EXPECT_EQ(m.positions[0], Vec3(0, 0, 0));
  EXPECT_EQ(m.positions[6], Vec3(1, 1, 1));
  // Indices are 0-based in the mesh (1-based in the file): the first face is "1 4 3 2".
  const auto f0 = m.face(0);
  EXPECT_EQ(std::vector<uint32_t>(f0.begin(), f0.end()), (std::vector<uint32_t>{0, 3, 2, 1}));
  // The file's normals per corner; each agrees with the face's own (Newell) normal, so the faces
  // are counter-clockwise seen from outside, and outward from the box centre.
  for (size_t f = 0; f < 6; ++f) {
    const Vec3 n = glm::normalize(faceNormal(m, f));
    for (uint32_t k = m.faceStart[f]; k < m.faceStart[f + 1]; ++k) EXPECT_EQ(m.cornerNormals[k], n) << f;
    Vec3 c(0);
    for (uint32_t i : m.face(f)) c += m.positions[i] / 4.0;
    EXPECT_GT(glm::dot(n, c - Vec3(0.5)), 0) << f;
  }
  EXPECT_EQ(m.cornerNormals[0], Vec3(0, 0, -1));
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
  EXPECT_TRUE(m.cornerNormals.empty());  // no normals in the file: flat shading
  EXPECT_EQ(m.positions[4], Vec3(-0.5, 1, 0));
}

// When only some corners carry a normal, none are used (flat shading) rather than a misaligned list.
TEST(ObjMesh, PartialNormalsAreDropped) {
  const Mesh m = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\n"
                          "f 1//1 2//1 3//1\nf 1 2 4\n",
                          "partial.obj");
  EXPECT_EQ(m.faceCount(), 2u);
  EXPECT_TRUE(m.cornerNormals.empty());
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
