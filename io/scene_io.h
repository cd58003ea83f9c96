// Scene files (JSON), a contract other tools rely on (README "Scene format"):
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
//                    "segments": n, "vertices": [[x,y,z], ...], "file": "meshes/bunny.obj",
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
#include <string>
#include <string_view>

namespace vplab {

/// Reads a scene file and builds its meshes (OBJ files relative to the scene file).
/// Throws vplab::Error "FILE: /json/path: what is wrong".
/// Only regular files are read; the file, its JSON and its meshes must stay within `limits`
/// (io/limits.h), checked before the memory for them is allocated.
Scene loadScene(const std::filesystem::path& file, const Limits& limits = kDefaultLimits);

/// The same for JSON text; `source` names it in messages, `baseDir` resolves mesh files.
Scene parseScene(std::string_view json, std::string_view source, const std::filesystem::path& baseDir,
                 const Limits& limits = kDefaultLimits);

/// The scene as JSON text in the format above (2-space indentation).
std::string sceneToJson(const Scene& scene);

/// Writes the scene atomically (a temporary file renamed over the target). Throws vplab::Error.
void saveScene(const Scene& scene, const std::filesystem::path& file);

}  // namespace vplab
