// Scene files (JSON), a contract other tools rely on (docs/formats.md "Scene format"):
//
//   { "title": "…", "caption": "…",                      (optional: a preset's name and idea)
//     "camera": { "vrp": [x,y,z], "prp": [x,y,z], "vup": [x,y,z],
//                 "window": {"xmin": a, "xmax": b, "ymin": c, "ymax": d},
//                 "front": F, "back": B,
//                 "projection": "perspective" | "parallel" | "oblique",
//                 "oblique": {"d": 0.5, "phi_deg": 50} },
//     "device": {"width": W, "height": H},
//     "background": [r,g,b],
//     "lights": [ {"position": [x,y,z], "color": [r,g,b]} ],
//     "clip_planes": [ {"normal": [a,b,c], "point": [x,y,z], "enabled": true} ],   (at most 6, WC)
//     "objects": [ { "name": .., "shape": "cube" | "tetrahedron" | "cylinder" | "sphere" | "polygon" | "mesh",
//                    "segments": n, "vertices": [[x,y,z], ...],
//                    "file": "meshes/bunny.obj" or "obj": "v 0 0 0\nv 1 0 0\n…\nf 1 2 3\n" (a mesh: one of the two),
//                    "color": [r,g,b], "visible": true,
//                    "translate": [x,y,z],
//                    "rotate": [ {"axis": [x,y,z], "deg": a, "through": [x,y,z]} ],
//                    "scale": s or [sx,sy,sz] } ] }
//
// Unknown keys, keys given twice, wrong types, missing required keys, out-of-range values and nesting
// deeper than Limits::jsonDepth are errors that name the JSON path (and the line, for syntax errors
// and numbers beyond a double); the camera must be valid (camera.h).
#pragma once

#include "io/limits.h"
#include "pipeline/scene.h"

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

/// Reads a scene file and builds its meshes (OBJ files relative to the scene file).
/// Throws vplab::Error "FILE: /json/path: what is wrong".
/// Only regular files are read; the file, its JSON and its meshes must stay within `limits`
/// (io/limits.h), checked before the memory for them is allocated.
Scene loadScene(const std::filesystem::path& file, const Limits& limits = kDefaultLimits);

/// Meshes built elsewhere from the same scene text, one per object in order: the page builds a
/// large scene's meshes in a Web Worker (docs/measured.md "Large scenes in the page") and reads the text
/// again on its own thread with them.
using BuiltMeshes = std::vector<std::shared_ptr<const Mesh>>;

/// The same for JSON text; `source` names it in messages, `baseDir` resolves mesh files. With
/// `built`, each object takes its mesh from there (checked against the limits and for being well
/// formed, as if built here) instead of building it.
Scene parseScene(std::string_view json, std::string_view source, const std::filesystem::path& baseDir,
                 const Limits& limits = kDefaultLimits, const BuiltMeshes* built = nullptr);

/// The scene as JSON text in the format above (2-space indentation).
std::string sceneToJson(const Scene& scene);

/// The scene as one file that carries its meshes: each mesh object's OBJ file (relative to the
/// scene's path) read into its `obj` text, so the scene opens anywhere (a scene saved in the page
/// names no in-page file). Throws vplab::Error naming the file when an OBJ cannot be read, or the
/// size when the scene with its meshes would exceed `limits.sceneFileBytes` (then keep the OBJ
/// beside the scene).
Scene carryingItsMeshes(Scene scene, const Limits& limits = kDefaultLimits);

/// Writes the scene atomically (a temporary file renamed over the target). Throws vplab::Error.
void saveScene(const Scene& scene, const std::filesystem::path& file);

}  // namespace vplab
