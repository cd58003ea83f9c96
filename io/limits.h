// Resource limits for what a scene or OBJ file may ask for (docs/reliability.md). A file is input
// an attacker may have written: every size it implies is checked against these limits BEFORE the
// memory for it is allocated, and exceeding one is an error naming the limit and the value.
//
// The defaults leave room for the bundled 1M-triangle scene (a sphere with n = 1024: 524 288 faces
// on 523 266 vertices) four times over, and keep the worst case a file can ask for to about 2 GB
// (a pipeline run costs about 0.5 kB per face with its dump streamed).
#pragma once

#include "pipeline/primitives.h"

#include <cstddef>
#include <cstdint>

namespace vplab {

struct Limits {
  std::uintmax_t sceneFileBytes = std::uintmax_t(8) << 20;  // 8 MiB: the bundled scenes are < 4 kB
  std::uintmax_t objFileBytes = std::uintmax_t(256) << 20;  // 256 MiB: ~3M triangles with normals
  int jsonDepth = 32;                    // nesting of JSON objects and arrays (a scene needs 5)
  int segments = kMaxSegments;           // of a sphere or cylinder (2048)
  std::size_t faces = std::size_t(1) << 21;     // 2 097 152 per scene, after tessellation
  std::size_t vertices = std::size_t(1) << 21;  // 2 097 152 per scene, after tessellation
  std::size_t corners = std::size_t(1) << 23;   // 8 388 608 face corners per scene (a quad has 4)
  int faceCorners = 255;                 // of one OBJ face (tinyobjloader counts them in a byte)
};

/// The limits of the command line and the viewer.
inline constexpr Limits kDefaultLimits{};

/// Images `vplab render` and the viewer write: each side, and the pixels of the whole picture.
inline constexpr int kMaxImageSide = 16384;
inline constexpr std::int64_t kMaxImagePixels = std::int64_t(1) << 25;  // 33.5 Mpx: 8K UHD; 128 MiB as RGBA

/// What is left of a scene's budget while its objects are built (checked before each mesh is).
struct MeshBudget {
  std::size_t faces, vertices, corners;
  static MeshBudget of(const Limits& l) { return {l.faces, l.vertices, l.corners}; }
};

}  // namespace vplab
