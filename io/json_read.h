// Reading JSON that an attacker may have written (scene files, student answers, recovery files):
// nlohmann's parser behind a SAX builder that checks what the finished tree could no longer show.
#pragma once

#include <nlohmann/json.hpp>

#include <string_view>

namespace vplab {

/// The JSON tree of `text`. Nesting deeper than `maxDepth` objects and arrays is refused before the
/// tree is built (whatever walks a deep tree would overflow its stack), a key given twice in one
/// object is an error (not silently last-wins), and a number beyond a double's range is an error.
/// Throws vplab::Error "SOURCE:LINE:COL: JSON syntax error …" for a syntax error and
/// "SOURCE: /json/path: what is wrong" for the others.
nlohmann::ordered_json parseCheckedJson(std::string_view text, std::string_view source, int maxDepth);

/// Line and column (both from 1) of byte `byte` (from 1, as nlohmann counts) of `text`.
std::pair<int, int> lineAndColumn(std::string_view text, size_t byte);

}  // namespace vplab
