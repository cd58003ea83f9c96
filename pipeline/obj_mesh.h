// Meshes from Wavefront OBJ files, read with tinyobjloader after a line-by-line check of our own,
// because tinyobjloader accepts "v 1 x 0" and out-of-range face indices silently.
#pragma once

#include "pipeline/mesh.h"

#include <filesystem>
#include <string_view>

namespace vplab {

/// Loads an OBJ file: positions, faces (any size ≥ 3) and, when every corner of the file has one,
/// the normals. Throws vplab::Error naming the file and line of the first problem.
Mesh loadObj(const std::filesystem::path& file);

/// The same check and parse for OBJ text already in memory; `name` is used in messages.
Mesh parseObj(std::string_view text, std::string_view name);

}  // namespace vplab
