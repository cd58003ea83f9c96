#include "pipeline/json_text.h"

namespace vplab {

namespace {

using Json = nlohmann::ordered_json;

bool isScalarArray(const Json& j) {
  if (!j.is_array()) return false;
  for (const Json& e : j)
    if (e.is_structured()) return false;
  return true;
}

void write(const Json& j, int indent, size_t inlineWidth, int level, std::string& out) {
  const std::string pad(size_t(indent * (level + 1)), ' '), closePad(size_t(indent * level), ' ');
  if (j.is_object() && !j.empty()) {
    out += "{\n";
    size_t i = 0;
    for (const auto& [key, value] : j.items()) {
      out += pad + Json(key).dump() + ": ";
      write(value, indent, inlineWidth, level + 1, out);
      out += ++i < j.size() ? ",\n" : "\n";
    }
    out += closePad + "}";
    return;
  }
  if (j.is_array() && !j.empty()) {
    bool flat = isScalarArray(j);
    if (!flat) {
      flat = true;
      for (const Json& e : j) flat = flat && isScalarArray(e);
      flat = flat && j.dump().size() <= inlineWidth;
    }
    if (flat) {
      std::string line = "[";
      for (size_t i = 0; i < j.size(); ++i) {
        if (i) line += ", ";
        if (j[i].is_array()) {
          line += "[";
          for (size_t k = 0; k < j[i].size(); ++k) line += (k ? ", " : "") + j[i][k].dump();
          line += "]";
        } else {
          line += j[i].dump();
        }
      }
      out += line + "]";
      return;
    }
    out += "[\n";
    for (size_t i = 0; i < j.size(); ++i) {
      out += pad;
      write(j[i], indent, inlineWidth, level + 1, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += closePad + "]";
    return;
  }
  out += j.dump();
}

}  // namespace

std::string prettyJson(const Json& j, int indent, size_t inlineWidth) {
  if (indent < 0) return j.dump();
  std::string out;
  write(j, indent, inlineWidth, 0, out);
  return out;
}

}  // namespace vplab
