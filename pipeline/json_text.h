// JSON text for people: objects one key per line, short arrays of numbers on one line
// ([x, y, z] rather than one number per line), as the scene files in assets/ are written.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace vplab {

/// `indent` spaces per level; arrays of scalars (and arrays of such arrays up to `inlineWidth`
/// characters) stay on one line. indent < 0: everything on one line.
std::string prettyJson(const nlohmann::ordered_json& j, int indent = 2, size_t inlineWidth = 100);

}  // namespace vplab
