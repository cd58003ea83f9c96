#include "io/build_mesh.h"

#include "io/obj_mesh.h"
#include "base/error.h"
#include "pipeline/primitives.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace vplab {

void checkMeshSize(const MeshSize& size, const MeshSize& used, const Limits& limits) {
  auto check = [](size_t n, size_t before, size_t limit, const char* what) {
    if (n > limit - std::min(before, limit))
      throw Error(std::to_string(n) + " " + what + (before ? " (after " + std::to_string(before) + " in earlier objects)" : "") +
                  " exceed the limit of " + std::to_string(limit) + " " + what + " per scene");
  };
  check(size.faces, used.faces, limits.faces, "faces");
  check(size.vertices, used.vertices, limits.vertices, "vertices");
  check(size.corners, used.corners, limits.corners, "face corners");
}

namespace {

/// The size primitiveMesh(o) will have, known before it is built.
MeshSize primitiveSize(const SceneObject& o, const Limits& limits) {
  auto segmentsWithin = [&] {
    if (o.segments > limits.segments)
      throw Error(std::to_string(o.segments) + " segments exceed the limit of " + std::to_string(limits.segments));
  };
  switch (o.shape) {
    case Shape::cube: return {6, 8, 24};
    case Shape::tetrahedron: return {4, 4, 12};
    case Shape::cylinder: segmentsWithin(); return cylinderSize(o.segments);
    case Shape::sphere: segmentsWithin(); return sphereSize(o.segments);
    case Shape::polygon: return {1, o.vertices.size(), o.vertices.size()};
    case Shape::mesh: break;
  }
  return {};
}

}  // namespace

void checkWellFormed(const Mesh& mesh) {
  if (mesh.faceStart.empty() || mesh.faceStart.front() != 0 || mesh.faceStart.back() != mesh.indices.size())
    throw Error("its face list does not cover its " + std::to_string(mesh.indices.size()) + " indices");
  for (size_t f = 0; f + 1 < mesh.faceStart.size(); ++f)
    if (mesh.faceStart[f + 1] < mesh.faceStart[f]) throw Error("face " + std::to_string(f) + " ends before it starts");
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.positions.size())
      throw Error("index " + std::to_string(i) + " names vertex " + std::to_string(mesh.indices[i]) + " of " +
                  std::to_string(mesh.positions.size()));
  if (!mesh.normalIndices.empty()) {
    if (mesh.normalIndices.size() != mesh.indices.size())
      throw Error(std::to_string(mesh.normalIndices.size()) + " normal indices for " +
                  std::to_string(mesh.indices.size()) + " corners");
    for (size_t c = 0; c < mesh.normalIndices.size(); ++c)
      if (mesh.normalIndices[c] >= mesh.normals.size())
        throw Error("corner " + std::to_string(c) + " names normal " + std::to_string(mesh.normalIndices[c]) + " of " +
                    std::to_string(mesh.normals.size()));
  } else if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) {
    throw Error(std::to_string(mesh.normals.size()) + " normals, one a vertex, for " +
                std::to_string(mesh.positions.size()) + " vertices");
  }
  auto finite = [](const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (!finite(mesh.positions[v])) throw Error("vertex " + std::to_string(v) + " is not finite");
  for (size_t n = 0; n < mesh.normals.size(); ++n)
    if (!finite(mesh.normals[n])) throw Error("normal " + std::to_string(n) + " is not finite");
}

void buildMesh(SceneObject& o, const std::filesystem::path& baseDir, const Limits& limits, const MeshSize& used) {
  if (o.shape != Shape::mesh) {
    // Primitives are sized before they are built, so a scene cannot ask for more than the limits allow.
    checkMeshSize(primitiveSize(o, limits), used, limits);
    o.mesh = primitiveMesh(o);
    return;
  }
  if (o.obj) {  // carried by the scene
    o.mesh = std::make_shared<Mesh>(parseObj(*o.obj, o.name + " (its OBJ in the scene)", limits, used));
    return;
  }
  if (o.file.empty()) throw Error("a mesh object needs a file");
  const std::filesystem::path file(o.file);
  const std::filesystem::path p = file.is_absolute() ? file : baseDir / file;
  o.mesh = std::make_shared<Mesh>(loadObj(p, limits, used));
}

}  // namespace vplab
