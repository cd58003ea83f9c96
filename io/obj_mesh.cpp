#include "io/obj_mesh.h"
#include "io/build_mesh.h"

#include "base/error.h"
#include "io/read_file.h"

// TINYOBJLOADER_USE_DOUBLE comes with the tinyobjloader_double target.
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <limits>
#include <string>

namespace vplab {

namespace {

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

bool parseNumber(std::string_view s, double& v) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
#if defined(__cpp_lib_to_chars)
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(v);
#else
  // The browser build's libc++ (LLVM 14) has no from_chars for double: strtod, given only what
  // from_chars takes (no sign but '-', no whitespace, no hexadecimal), reads the same numbers.
  if (s.empty() || !(s[0] == '-' || s[0] == '.' || std::isdigit(static_cast<unsigned char>(s[0])))) return false;
  if (s.find_first_of("xX") != std::string_view::npos || (s[0] == '-' && s.size() > 1 && s[1] == '+')) return false;
  const std::string text(s);
  char* end = nullptr;
  errno = 0;
  v = std::strtod(text.c_str(), &end);
  return errno != ERANGE && end == text.c_str() + text.size() && std::isfinite(v);
#endif
}

bool parseIndex(std::string_view s, long& v) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size();
}

// The lines of an OBJ text as tinyobjloader's safeGetline splits them: at LF, at CR, and at CR LF.
// (A CR alone ends a line there too: "#\rf 1 2 4" is a comment and a face.)
struct Lines {
  std::string_view text;
  size_t pos = 0;
  bool next(std::string_view& line) {
    if (pos >= text.size()) return false;
    const size_t end = std::min(text.find_first_of("\r\n", pos), text.size());
    line = text.substr(pos, end - pos);
    pos = end + 1;
    if (end < text.size() && text[end] == '\r' && pos < text.size() && text[pos] == '\n') ++pos;
    return true;
  }
};

// Checks what tinyobjloader lets through: every number parses and is finite, every face has at
// least three corners and every index refers to an element defined before it (1-based, or
// negative: relative to the end); and counts faces, vertices and corners against the limits.
// Throws with "name:line: ...". Returns the size tinyobjloader's result must have.
MeshSize checkObjText(std::string_view text, std::string_view name, const Limits& limits, const MeshSize& used) {
  size_t counts[3] = {0, 0, 0};  // v, vt, vn defined so far
  MeshSize size;
  size_t lineNo = 0;
  auto fail = [&](const std::string& what) {
    throw Error(std::string(name) + ":" + std::to_string(lineNo) + ": " + what);
  };
  auto checkSize = [&] {
    try {
      checkMeshSize(size, used, limits);
    } catch (const Error& e) {
      fail(e.what());
    }
  };
  if (const size_t nul = text.find('\0'); nul != std::string_view::npos) {
    Lines lines{text.substr(0, nul)};
    for (std::string_view l; lines.next(l);) ++lineNo;
    lineNo = std::max<size_t>(lineNo, 1);
    fail("a NUL byte: this is not a text OBJ file");
  }
  Lines lines{text};
  for (std::string_view raw; lines.next(raw);) {
    ++lineNo;
    if (const size_t hash = raw.find('#'); hash != std::string::npos) raw = raw.substr(0, hash);  // "f 1 2 3  # top"
    const auto t = tokens(raw);
    if (t.empty()) continue;
    const std::string_view kw = t[0];
    if (kw == "v" || kw == "vn" || kw == "vt") {
      const size_t need = kw == "vt" ? 1 : 3;
      if (t.size() - 1 < need)
        fail("'" + std::string(kw) + "' needs " + std::to_string(need) + " numbers, found " +
             std::to_string(t.size() - 1));
      for (size_t i = 1; i < t.size(); ++i) {
        double v;
        if (!parseNumber(t[i], v))
          fail("'" + std::string(t[i]) + "' is not a finite number in a '" + std::string(kw) + "' line");
      }
      // Normals and texture coordinates are bounded by the vertex limit as well: a file cannot make
      // tinyobjloader store more of them than of vertices.
      const int which = kw == "v" ? 0 : kw == "vt" ? 1 : 2;
      if (++counts[which] > limits.vertices && which > 0)
        fail("more than " + std::to_string(limits.vertices) + " '" + std::string(kw) +
             "' lines: the limit is " + std::to_string(limits.vertices) + " per scene");
      if (which == 0) {
        size.vertices = counts[0];
        checkSize();
      }
    } else if (kw == "f") {
      if (t.size() < 4) fail("a face needs at least 3 vertices, found " + std::to_string(t.size() - 1));
      if (t.size() - 1 > size_t(limits.faceCorners))  // tinyobjloader counts face corners in an unsigned char
        fail("a face has " + std::to_string(t.size() - 1) + " vertices; at most " +
             std::to_string(limits.faceCorners) + " are supported");
      for (size_t i = 1; i < t.size(); ++i) {
        std::string_view corner = t[i];
        for (int part = 0; part < 3 && !corner.empty(); ++part) {
          const size_t slash = corner.find('/');
          const std::string_view ref = corner.substr(0, slash);
          corner = slash == std::string_view::npos ? std::string_view{} : corner.substr(slash + 1);
          if (ref.empty() && part > 0) continue;  // "1//3": no texture coordinate
          long index = 0;
          static constexpr const char* what[] = {"vertex", "texture coordinate", "normal"};
          if (!parseIndex(ref, index) || index == 0)
            fail("'" + std::string(t[i]) + "' is not a valid face corner (indices start at 1)");
          const long n = long(counts[part]);
          if (index > n || index < -n)
            fail(std::string(what[part]) + " index " + std::to_string(index) + " in '" +
                 std::string(t[i]) + "' is out of range: " + std::to_string(n) + " defined so far");
        }
      }
      ++size.faces;
      size.corners += t.size() - 1;
      checkSize();
    }
  }
  if (size.faces == 0) throw Error(std::string(name) + ": the OBJ file has no faces ('f' lines)");
  return size;
}

// Builds the mesh from what tinyobjloader returned, trusting none of it: every count and every
// index is checked against the arrays it refers to, and the sizes must not exceed what the text check
// counted against the limits.
Mesh toMesh(const tinyobj::ObjReader& reader, std::string_view name, const MeshSize& expected) {
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  auto fail = [&](const std::string& what) {
    throw Error(std::string(name) + ": " + what + " (the OBJ reader disagrees with the file's check)");
  };
  const size_t vertexCount = attrib.vertices.size() / 3, normalCount = attrib.normals.size() / 3;
  if (attrib.vertices.size() % 3 || vertexCount > expected.vertices)
    fail(std::to_string(attrib.vertices.size()) + " vertex coordinates returned for " +
         std::to_string(expected.vertices) + " vertices");
  size_t faces = 0, corners = 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    faces += shape.mesh.num_face_vertices.size();
    size_t shapeCorners = 0;
    for (const unsigned char n : shape.mesh.num_face_vertices) shapeCorners += n;
    corners += shapeCorners;
    if (shape.mesh.indices.size() != shapeCorners)
      fail("shape \"" + shape.name + "\" has " + std::to_string(shape.mesh.indices.size()) +
           " indices for the corners of its faces, which count differently");
  }
  if (faces > expected.faces || corners > expected.corners)
    fail(std::to_string(faces) + " faces with " + std::to_string(corners) + " corners returned for " +
         std::to_string(expected.faces) + " faces with " + std::to_string(expected.corners) + " corners");

  Mesh mesh;
  mesh.positions.reserve(vertexCount);
  for (size_t i = 0; i < vertexCount; ++i)
    mesh.positions.push_back({attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]});
  mesh.indices.reserve(corners);
  mesh.faceStart.reserve(faces + 1);
  // The normals the corners name, each once, in the order first named ("vn" lines no face names are
  // left out); then one a vertex where every vertex's corners agree (normalPerVertexWherePossible).
  bool allNormals = true;
  constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> kept(normalCount, kNone);  // the mesh's normal of each "vn"
  std::vector<uint32_t> face;
  size_t f = 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    size_t offset = 0;
    for (const unsigned char n : shape.mesh.num_face_vertices) {
      ++f;
      if (n < 3) fail("face " + std::to_string(f) + " has " + std::to_string(n) + " vertices, not at least 3");
      face.clear();
      for (size_t k = 0; k < n; ++k) {
        const tinyobj::index_t& idx = shape.mesh.indices[offset + k];
        if (idx.vertex_index < 0 || size_t(idx.vertex_index) >= vertexCount)
          fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(idx.vertex_index + 1) + " of " +
               std::to_string(vertexCount));
        face.push_back(uint32_t(idx.vertex_index));
        if (idx.normal_index < 0) {
          allNormals = false;
        } else if (size_t(idx.normal_index) >= normalCount) {
          fail("face " + std::to_string(f) + " refers to normal " + std::to_string(idx.normal_index + 1) + " of " +
               std::to_string(normalCount));
        } else if (allNormals) {
          uint32_t& n = kept[size_t(idx.normal_index)];
          if (n == kNone) {
            const size_t j = 3 * size_t(idx.normal_index);
            n = uint32_t(mesh.normals.size());
            mesh.normals.push_back({attrib.normals[j], attrib.normals[j + 1], attrib.normals[j + 2]});
          }
          mesh.normalIndices.push_back(n);
        }
      }
      mesh.addFace(face);
      offset += n;
    }
  }
  if (!allNormals || mesh.indices.empty()) {
    std::vector<Vec3>().swap(mesh.normals);
    std::vector<uint32_t>().swap(mesh.normalIndices);
  }
  normalPerVertexWherePossible(mesh);
  return mesh;
}

}  // namespace

Mesh parseObj(std::string_view text, std::string_view name, const Limits& limits, const MeshSize& used) {
  const MeshSize size = checkObjText(text, name, limits, used);
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(std::string(text), "", config))
    throw Error(std::string(name) + ": " + reader.Error());
  return toMesh(reader, name, size);
}

Mesh loadObj(const std::filesystem::path& file, const Limits& limits, const MeshSize& used) {
  return parseObj(readRegularFile(file, limits.objFileBytes, "OBJ file"), file.string(), limits, used);
}

}  // namespace vplab
