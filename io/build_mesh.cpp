#include "io/build_mesh.h"

#include "io/obj_mesh.h"
#include "pipeline/error.h"
#include "pipeline/primitives.h"

#include <algorithm>
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
