// Hostile input (issue "Hardening"): what an attacker's scene or OBJ file gets is a vplab::Error
// naming the file, the place (JSON path or line), the value and the limit or what was expected;
// never an out-of-range read, an allocation beyond the limits (io/limits.h), a stack overflow
// or a dump with nulls in it. Each case here failed before the fix it tests (crashed, allocated
// without bound, was accepted, or gave a message without the place).
#include "io/dump.h"
#include "io/obj_mesh.h"
#include "pipeline/primitives.h"
#include "io/read_file.h"
#include "io/scene_io.h"
#include "tests/support/test_util.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace vplab {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;
using test::errorOf;
using test::TempDir;

const std::string kCamera = R"("camera": {"vrp": [0, 0, 0], "prp": [0, 0, 5], "vup": [0, 1, 0],
  "window": {"xmin": -1, "xmax": 1, "ymin": -1, "ymax": 1}, "front": 2, "back": -2})";

std::string sceneWithObjects(const std::string& objects) { return "{" + kCamera + ",\n\"objects\": [" + objects + "]}"; }

// ---------------------------------------------------------------- 1 OBJ: what the loader returned

// The issue's file: a CR alone inside a comment ends the line for tinyobjloader, so "f 1 2 4" is a
// face to it. Our check read the line as one comment; the face's index 4 (of 3 vertices) then read
// past the end of the positions (a heap-buffer-overflow under ASan, SIGSEGV in Release).
TEST(Hardening, CarriageReturnInACommentEndsTheLineAsForTheLoader) {
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n#\rf 1 2 4\n";
  EXPECT_THAT(errorOf([&] { parseObj(text, "m.obj"); }),
              HasSubstr("m.obj:6: vertex index 4 in '4' is out of range: 3 defined so far"));
  // CR LF is one line end, CR alone is one too: the same faces either way.
  const Mesh crlf = parseObj("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n", "crlf.obj");
  const Mesh cr = parseObj("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r", "cr.obj");
  EXPECT_EQ(crlf.faceCount(), 1u);
  EXPECT_EQ(cr.faceCount(), 1u);
  EXPECT_EQ(cr.indices, crlf.indices);
}

TEST(Hardening, ObjThroughASceneNamesSceneObjectAndLine) {
  TempDir dir;
  dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n#\rf 1 2 4\n");
  const fs::path scene = dir.write("m.json", sceneWithObjects(R"({"shape": "mesh", "file": "m.obj"})"));
  EXPECT_THAT(errorOf([&] { loadScene(scene); }),
              AllOf(HasSubstr("m.json: /objects/0: "), HasSubstr("m.obj:6: vertex index 4")));
}

TEST(Hardening, ObjWithANulByteIsNotText) {
  EXPECT_THAT(errorOf([] { parseObj(std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\0f 1 2 9\n", 34), "nul.obj"); }),
              HasSubstr("nul.obj:4: a NUL byte"));
}

TEST(Hardening, ObjCountsAreCheckedAgainstTheLimitsWhileReading) {
  Limits small;
  small.faces = 2;
  small.vertices = 4;
  small.corners = 7;
  const std::string v4 = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  EXPECT_THAT(errorOf([&] { parseObj(v4 + "v 1 1 1\nf 1 2 3\n", "v.obj", small); }),
              HasSubstr("v.obj:5: 5 vertices exceed the limit of 4 vertices per scene"));
  EXPECT_THAT(errorOf([&] { parseObj(v4 + "f 1 2 3\nf 1 2 4\nf 2 3 4\n", "f.obj", small); }),
              HasSubstr("f.obj:7: 3 faces exceed the limit of 2 faces per scene"));
  EXPECT_THAT(errorOf([&] { parseObj(v4 + "f 1 2 3 4\nf 1 2 4 3\n", "c.obj", small); }),
              HasSubstr("c.obj:6: 8 face corners exceed the limit of 7 face corners per scene"));
  EXPECT_THAT(errorOf([&] { parseObj(v4 + "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nf 1 2 3\n", "n.obj", small); }),
              HasSubstr("n.obj:9: more than 4 'vn' lines"));
  // What earlier objects of the scene took counts too.
  EXPECT_THAT(errorOf([&] { parseObj(v4 + "f 1 2 3\n", "u.obj", small, MeshSize{2, 0, 0}); }),
              HasSubstr("1 faces (after 2 in earlier objects) exceed the limit of 2 faces"));
}

// ---------------------------------------------------------------- 2 limits before allocating

TEST(Hardening, SphereSegmentsBeyondTheLimitAreRefused) {
  // 4096 segments: 8.4M faces; vplab dump grew to 24 GB before the kernel killed it.
  EXPECT_THAT(errorOf([] { parseScene(sceneWithObjects(R"({"shape": "sphere", "segments": 4096})"), "s.json", "."); }),
              HasSubstr("s.json: /objects/0/segments: 4096 is out of range [4, 2048]"));
  EXPECT_EQ(kMaxSegments, kDefaultLimits.segments);
}

TEST(Hardening, SceneBudgetIsCheckedBeforeEachMeshIsBuilt) {
  // The sizes are known before the meshes are built: the formulas agree with the meshes.
  for (int n : {3, 4, 17, 64}) {
    const Mesh c = cylinder(n);
    EXPECT_EQ(cylinderSize(n).faces, c.faceCount());
    EXPECT_EQ(cylinderSize(n).vertices, c.vertexCount());
    EXPECT_EQ(cylinderSize(n).corners, c.indices.size());
  }
  for (int n : {4, 6, 32, 100}) {
    const Mesh s = sphere(n);
    EXPECT_EQ(sphereSize(n).faces, s.faceCount());
    EXPECT_EQ(sphereSize(n).vertices, s.vertexCount());
    EXPECT_EQ(sphereSize(n).corners, s.indices.size());
  }
  // The largest sphere fills the default budget (2048² / 2 = 2 097 152 faces); one cube more does not fit.
  EXPECT_EQ(sphereSize(kDefaultLimits.segments).faces, kDefaultLimits.faces);
  EXPECT_LE(sphereSize(kDefaultLimits.segments).corners, kDefaultLimits.corners);
  Limits small;
  small.faces = 100;
  EXPECT_THAT(errorOf([&] { parseScene(sceneWithObjects(R"({"shape": "sphere", "segments": 2048})"), "s.json", ".", small); }),
              HasSubstr("s.json: /objects/0: 2097152 faces exceed the limit of 100 faces per scene"));
  small.faces = 130;
  EXPECT_THAT(errorOf([&] {
                parseScene(sceneWithObjects(R"({"shape": "sphere", "segments": 16}, {"shape": "cube"})"), "s.json", ".", small);
              }),
              HasSubstr("s.json: /objects/1: 6 faces (after 128 in earlier objects) exceed the limit of 130 faces per scene"));
  small.faces = 1000;
  small.vertices = 3;
  EXPECT_THAT(errorOf([&] {
                parseScene(sceneWithObjects(R"({"shape": "polygon", "vertices": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]]})"),
                           "p.json", ".", small);
              }),
              HasSubstr("p.json: /objects/0: 4 vertices exceed the limit of 3 vertices per scene"));
}

TEST(Hardening, OnlyRegularFilesAreRead) {
  TempDir dir;
  const fs::path fifo = dir.path / "fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // Before: /dev/zero and a FIFO grew memory without bound (or blocked); a directory said "no faces".
  EXPECT_THAT(errorOf([] { loadScene("/dev/zero"); }),
              HasSubstr("/dev/zero: is a character device; a scene file must be a regular file"));
  EXPECT_THAT(errorOf([&] { loadScene(fifo); }), HasSubstr("fifo: is a FIFO (named pipe); a scene file must be a regular file"));
  EXPECT_THAT(errorOf([&] { loadScene(dir.path); }), HasSubstr(": is a directory; a scene file must be a regular file"));
  EXPECT_THAT(errorOf([] { loadObj("/dev/zero"); }), HasSubstr("/dev/zero: is a character device; an OBJ file must be a regular file"));
  EXPECT_THAT(errorOf([&] { loadObj(fifo); }), HasSubstr("fifo: is a FIFO (named pipe); an OBJ file must be a regular file"));
  EXPECT_THAT(errorOf([&] { loadObj(dir.path); }), HasSubstr(": is a directory; an OBJ file must be a regular file"));
  const fs::path scene = dir.write("dev.json", sceneWithObjects(R"({"shape": "mesh", "file": "/dev/zero"})"));
  EXPECT_THAT(errorOf([&] { loadScene(scene); }), AllOf(HasSubstr("dev.json: /objects/0: /dev/zero: is a character device")));
}

TEST(Hardening, FileSizesAreLimited) {
  TempDir dir;
  // 8 MiB and one byte of a valid scene (spaces after it).
  const std::string scene = sceneWithObjects(R"({"shape": "cube"})");
  const fs::path big = dir.write("big.json", scene + std::string((8u << 20) + 1 - scene.size(), ' '));
  EXPECT_THAT(errorOf([&] { loadScene(big); }),
              HasSubstr("big.json: the scene file has 8388609 bytes; the limit is 8 MiB (8388608 bytes)"));
  EXPECT_EQ(errorOf([&] { fs::resize_file(big, 8u << 20); loadScene(big); }), "<no exception thrown>");
  Limits small;
  small.objFileBytes = 40;
  const fs::path obj = dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# a comment that makes it long\n");
  EXPECT_THAT(errorOf([&] { loadObj(obj, small); }), HasSubstr("m.obj: the OBJ file has 63 bytes; the limit is 40 bytes"));
  EXPECT_EQ(formatBytes(256u << 20), "256 MiB (268435456 bytes)");
}

// ---------------------------------------------------------------- 3 nesting

TEST(Hardening, DeepNestingIsRefusedBeforeTheTreeIsBuilt) {
  // 10 000 levels overflowed the stack under ASan; now the parse stops at level 33.
  const std::string deep = std::string(10000, '[') + std::string(10000, ']');
  EXPECT_THAT(errorOf([&] { parseScene(deep, "deep.json", "."); }),
              AllOf(HasSubstr("deep.json: /0/0/0/"), HasSubstr("objects and arrays nested deeper than 32 levels (the limit)")));
  const std::string deepInObject = "{" + kCamera + R"(, "objects": [{"shape": "cube", "name": )" +
                                   std::string(40, '[') + std::string(40, ']') + "}]}";
  EXPECT_THAT(errorOf([&] { parseScene(deepInObject, "d.json", "."); }),
              HasSubstr("d.json: /objects/0/name/0/0/"));
  // The bundled scenes need 5 levels; 32 leave room for tools that write more.
  EXPECT_EQ(errorOf([&] { parseScene(sceneWithObjects(R"({"shape": "cube", "rotate": [{"axis": [0, 1, 0], "deg": 3}]})"), "ok.json", "."); }),
            "<no exception thrown>");
}

// ---------------------------------------------------------------- 5 messages that name the place

TEST(Hardening, NumberBeyondADoubleNamesFileLineAndPath) {
  // Before: "unexpected error" (nlohmann's out_of_range.406) without file, line or path.
  const std::string text = "{" + kCamera + ",\n\"objects\": [{\"shape\": \"cube\",\n \"scale\": 1e309}]}";
  EXPECT_THAT(errorOf([&] { parseScene(text, "big.json", "."); }),
              HasSubstr("big.json:4:15: /objects/0/scale: the number 1e309 is out of range: a number must be finite"));
}

TEST(Hardening, DuplicateKeysAreErrors) {
  // Before: the last one won, silently.
  EXPECT_THAT(errorOf([] { parseScene("{" + kCamera + R"(, "objects": [], "objects": []})", "dup.json", "."); }),
              HasSubstr("dup.json: /objects: the key \"objects\" is given twice in this object"));
  EXPECT_THAT(errorOf([] {
                parseScene(sceneWithObjects(R"({"shape": "cube", "translate": [0, 0, 0], "translate": [1, 1, 1]})"), "dup.json", ".");
              }),
              HasSubstr("dup.json: /objects/0/translate: the key \"translate\" is given twice"));
  // The same key in two objects is fine.
  EXPECT_EQ(errorOf([] { parseScene(sceneWithObjects(R"({"shape": "cube"}, {"shape": "cube"})"), "ok.json", "."); }),
            "<no exception thrown>");
}

TEST(Hardening, IntegersBeyondInt64AreOutOfRangeNotMinusOne) {
  const std::string text = "{" + kCamera + R"(, "device": {"width": 18446744073709551615, "height": 4}, "objects": []})";
  EXPECT_THAT(errorOf([&] { parseScene(text, "u.json", "."); }),
              HasSubstr("u.json: /device/width: 18446744073709551615 is out of range [1, 16384]"));
  const std::string segments = sceneWithObjects(R"({"shape": "sphere", "segments": 9223372036854775808})");
  EXPECT_THAT(errorOf([&] { parseScene(segments, "s.json", "."); }),
              HasSubstr("s.json: /objects/0/segments: 9223372036854775808 is out of range [4, 2048]"));
}

TEST(Hardening, NonFiniteResultsAreAnErrorNotNulls) {
  // A translation of 1e308 is a finite number, but the products overflow: dump printed nulls, exit 0.
  const Scene s = parseScene(sceneWithObjects(R"({"name": "far", "shape": "cube", "translate": [1e308, 0, 0]})"), "t.json", ".");
  const PipelineRun run = runPipeline(s);
  const std::string message = errorOf([&] { dumpJson(run); });
  EXPECT_THAT(message, HasSubstr("object \"far\" (/objects/0): vertex 0 in homogeneous NPC is (inf"));
  EXPECT_THAT(message, HasSubstr("not finite"));
  EXPECT_TRUE(nonFiniteError(run).has_value());
  // At 1e300 everything is still finite: no error.
  const Scene near = parseScene(sceneWithObjects(R"({"shape": "cube", "translate": [1e300, 0, 0]})"), "t.json", ".");
  EXPECT_EQ(nonFiniteError(runPipeline(near)), std::nullopt);
}

}  // namespace
}  // namespace vplab
