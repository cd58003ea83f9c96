// Reading JSON that an attacker may have written (scene files, student answers, recovery files):
// nlohmann's parser behind a SAX builder that checks what the finished tree could no longer show,
// and the reader of its values at their JSON paths.
#pragma once

#include "pipeline/math.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string>
#include <string_view>

namespace vplab {

/// The JSON tree of `text`. Nesting deeper than `maxDepth` objects and arrays is refused before the
/// tree is built (whatever walks a deep tree would overflow its stack), a key given twice in one
/// object is an error (not silently last-wins), and a number beyond a double's range is an error.
/// Throws vplab::Error "SOURCE:LINE:COL: JSON syntax error …" for a syntax error and
/// "SOURCE: /json/path: what is wrong" for the others.
nlohmann::ordered_json parseCheckedJson(std::string_view text, std::string_view source, int maxDepth);

/// Reads the values of a checked tree at their JSON paths, failing with vplab::Error
/// "SOURCE: /json/path: what is wrong" (a wrong type, a number out of range, an unknown key with
/// the keys allowed there): the one set of rules behind every file format vplab reads.
struct JsonReader {
  using Json = nlohmann::ordered_json;
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  std::string source;

  [[noreturn]] void fail(const std::string& path, const std::string& message) const;
  /// `j` is an object whose keys are all in `allowed`.
  void object(const Json& j, const std::string& path, std::initializer_list<std::string_view> allowed) const;
  const Json& required(const Json& j, const std::string& path, const char* key) const;
  double number(const Json& j, const std::string& path, double lo = -kInf, double hi = kInf) const;
  int integer(const Json& j, const std::string& path, int lo, int hi) const;
  Vec3 vec3(const Json& j, const std::string& path, double lo = -kInf, double hi = kInf) const;
  Vec3 color(const Json& j, const std::string& path) const { return vec3(j, path, 0.0, 1.0); }
  std::string string(const Json& j, const std::string& path) const;
  bool boolean(const Json& j, const std::string& path) const;
  const Json& array(const Json& j, const std::string& path) const;
};

/// Line and column (both from 1) of byte `byte` (from 1, as nlohmann counts) of `text`.
std::pair<int, int> lineAndColumn(std::string_view text, size_t byte);

}  // namespace vplab
