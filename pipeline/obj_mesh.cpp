#include "pipeline/obj_mesh.h"

#include "pipeline/error.h"

// TINYOBJLOADER_USE_DOUBLE comes with the tinyobjloader_double target.
#include <tiny_obj_loader.h>

#include <charconv>
#include <fstream>
#include <sstream>

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
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(v);
}

bool parseIndex(std::string_view s, long& v) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size();
}

// Checks what tinyobjloader lets through: every number parses and is finite, every face has at
// least three corners and every index refers to an element defined before it (1-based, or
// negative: relative to the end). Throws with "name:line: ...".
void checkObjText(std::string_view text, std::string_view name) {
  size_t counts[3] = {0, 0, 0};  // v, vt, vn defined so far
  size_t faces = 0;
  size_t lineNo = 0;
  auto fail = [&](const std::string& what) {
    throw Error(std::string(name) + ":" + std::to_string(lineNo) + ": " + what);
  };
  std::istringstream in{std::string(text)};
  std::string raw;
  while (std::getline(in, raw)) {
    ++lineNo;
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    if (const size_t hash = raw.find('#'); hash != std::string::npos) raw.resize(hash);  // "f 1 2 3  # top"
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
      ++counts[kw == "v" ? 0 : kw == "vt" ? 1 : 2];
    } else if (kw == "f") {
      if (t.size() < 4) fail("a face needs at least 3 vertices, found " + std::to_string(t.size() - 1));
      if (t.size() - 1 > 255)  // tinyobjloader counts face corners in an unsigned char
        fail("a face has " + std::to_string(t.size() - 1) + " vertices; at most 255 are supported");
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
      ++faces;
    }
  }
  if (faces == 0) throw Error(std::string(name) + ": the OBJ file has no faces ('f' lines)");
}

Mesh toMesh(const tinyobj::ObjReader& reader) {
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  Mesh mesh;
  mesh.positions.reserve(attrib.vertices.size() / 3);
  for (size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
    mesh.positions.push_back({attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]});
  bool allNormals = true;
  std::vector<Vec3> normals;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    size_t offset = 0;
    for (const unsigned char n : shape.mesh.num_face_vertices) {
      std::vector<uint32_t> face;
      for (size_t k = 0; k < n; ++k) {
        const tinyobj::index_t& idx = shape.mesh.indices[offset + k];
        face.push_back(uint32_t(idx.vertex_index));
        if (idx.normal_index < 0) {
          allNormals = false;
        } else {
          const size_t j = 3 * size_t(idx.normal_index);
          normals.push_back({attrib.normals[j], attrib.normals[j + 1], attrib.normals[j + 2]});
        }
      }
      mesh.addFace(face);
      offset += n;
    }
  }
  if (allNormals) mesh.cornerNormals = std::move(normals);
  return mesh;
}

}  // namespace

Mesh parseObj(std::string_view text, std::string_view name) {
  checkObjText(text, name);
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(std::string(text), "", config))
    throw Error(std::string(name) + ": " + reader.Error());
  return toMesh(reader);
}

Mesh loadObj(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(file.string() + ": cannot open the OBJ file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseObj(text.str(), file.string());
}

}  // namespace vplab
