// Building a scene object's mesh from what a file asked for: a primitive, or faces read from an OBJ
// file. A file is input an attacker may have written (docs/reliability.md), so every size is checked
// against the limits (io/limits.h) before the memory for it is allocated.
#pragma once

#include "io/limits.h"
#include "pipeline/scene.h"

#include <filesystem>

namespace vplab {

/// Throws vplab::Error naming the limit and the value when a mesh of `size` does not fit in what is
/// left of the scene's budget (`used` of `limits` already taken by earlier objects).
void checkMeshSize(const MeshSize& size, const MeshSize& used, const Limits& limits);

/// Throws vplab::Error saying what is wrong when `mesh` is not well formed: a face start out of
/// order or past the indices, an index past the vertices, corner normals not one per index, a
/// coordinate not finite. For meshes that come from elsewhere (the page's loader worker).
void checkWellFormed(const Mesh& mesh);

/// Builds the object's MC mesh from its shape (OBJ files relative to baseDir). Throws vplab::Error,
/// before allocating, when the mesh would exceed what `used` (earlier objects) leaves of `limits`.
void buildMesh(SceneObject& object, const std::filesystem::path& baseDir, const Limits& limits = kDefaultLimits,
               const MeshSize& used = {});

}  // namespace vplab
