// Parts of the scene format (io/scene_io.h) that other formats write the same way: a lesson's step
// moves an object and replaces the clip planes with the scene's own keys (app/core/lesson.h).
#pragma once

#include "io/json_read.h"
#include "pipeline/scene.h"

#include <string>
#include <vector>

namespace vplab {

/// An object's "translate", "rotate" and "scale" keys in `j` (others are the caller's to allow).
ModelTransform readTransform(const JsonReader& r, const nlohmann::ordered_json& j, const std::string& path);

/// A "clip_planes" array: at most kMaxUserPlanes planes, each {"normal", "point", "enabled"} in WC.
std::vector<UserClipPlane> readClipPlanes(const JsonReader& r, const nlohmann::ordered_json& j, const std::string& path);

}  // namespace vplab
