// JSON text for people: objects one key per line, short arrays of numbers on one line
// ([x, y, z] rather than one number per line), as the scene files in assets/ are written.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

/// `indent` spaces per level; arrays of scalars (and arrays of such arrays up to `inlineWidth`
/// characters) stay on one line. indent < 0: everything on one line.
std::string prettyJson(const nlohmann::ordered_json& j, int indent = 2, size_t inlineWidth = 100);

/// Appends j as prettyJson lays it out at nesting `level` (0: the top).
void appendPrettyJson(const nlohmann::ordered_json& j, int indent, size_t inlineWidth, int level, std::string& out);

/// Writes JSON text exactly as prettyJson lays out the whole tree, but a piece at a time, so a large
/// document never exists in memory: the caller opens and closes the large objects and arrays (of
/// objects: prettyJson never puts those on one line) and gives the small values as trees.
class JsonStreamWriter {
 public:
  JsonStreamWriter(std::ostream& out, int indent, size_t inlineWidth = 100);
  void beginObject();
  void beginArray();  // only for arrays of objects
  void end();
  void key(std::string_view key);                 // in an object: the key of the next value
  void value(const nlohmann::ordered_json& j);    // a whole value (in an array: the next element)
  /// Ends the text with `tail` and flushes. Throws vplab::Error when the stream failed.
  void finish(std::string_view tail = "\n");

 private:
  void element();  // in an array: the separator and indentation before the next element
  void flushIfFull();
  struct Open {
    bool array;
    size_t entries;
  };
  std::ostream& out_;
  int indent_;
  size_t inlineWidth_;
  std::vector<Open> open_;
  std::string buffer_;
};

}  // namespace vplab
