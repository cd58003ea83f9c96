// Parts of the scene format (io/scene_io.h) that other formats write the same way: a lesson's step
// changes the camera, moves an object and replaces the clip planes with the scene's own keys
// (app/lessons/lesson.h).
#pragma once

#include "io/json_read.h"
#include "pipeline/scene.h"

#include <string>
#include <vector>

namespace vplab {

/// A "camera" object (the scene format's keys). Without `base` its required keys must all be given
/// (a scene); with it, any may be, each replacing the base's (a lesson's step). The camera must be
/// valid, else "SOURCE: PATH: invalid camera: …" (cameraError's reason).
Camera readCamera(const JsonReader& r, const nlohmann::ordered_json& j, const std::string& path, const Camera* base = nullptr);

/// An object's "translate", "rotate" and "scale" keys in `j` (others are the caller's to allow).
ModelTransform readTransform(const JsonReader& r, const nlohmann::ordered_json& j, const std::string& path);

/// A "clip_planes" array: at most kMaxUserPlanes planes, each {"normal", "point", "enabled"} in WC.
std::vector<UserClipPlane> readClipPlanes(const JsonReader& r, const nlohmann::ordered_json& j, const std::string& path);

}  // namespace vplab
