// Meshes from Wavefront OBJ files, read with tinyobjloader after a line-by-line check of our own,
// because tinyobjloader accepts "v 1 x 0" and out-of-range face indices silently. The check splits
// lines as tinyobjloader does (LF, CR or CR LF) and counts what the file defines against the limits
// before tinyobjloader allocates anything; what tinyobjloader returns is then validated again, index
// by index, so a disagreement between the two readers is an error and never an out-of-range read.
#pragma once

#include "io/limits.h"
#include "pipeline/mesh.h"

#include <filesystem>
#include <string_view>

namespace vplab {

/// Loads an OBJ file: positions, faces (any size ≥ 3) and, when every corner of the file has one,
/// the normals. Throws vplab::Error naming the file and line of the first problem.
/// `used` is what earlier objects of the scene took of `limits` (faces, vertices, corners).
Mesh loadObj(const std::filesystem::path& file, const Limits& limits = kDefaultLimits, const MeshSize& used = {});

/// The same check and parse for OBJ text already in memory; `name` is used in messages.
Mesh parseObj(std::string_view text, std::string_view name, const Limits& limits = kDefaultLimits,
              const MeshSize& used = {});

}  // namespace vplab
