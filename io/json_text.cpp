#include "io/json_text.h"

#include "base/error.h"

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

void appendPrettyJson(const Json& j, int indent, size_t inlineWidth, int level, std::string& out) {
  if (indent < 0) {
    out += j.dump();
    return;
  }
  write(j, indent, inlineWidth, level, out);
}

JsonStreamWriter::JsonStreamWriter(std::ostream& out, int indent, size_t inlineWidth)
    : out_(out), indent_(indent), inlineWidth_(inlineWidth) {}

void JsonStreamWriter::element() {
  if (open_.empty() || !open_.back().array) return;  // the top, or after a key
  Open& o = open_.back();
  if (indent_ < 0) {
    if (o.entries) buffer_ += ',';
  } else {
    buffer_ += o.entries ? ",\n" : "\n";
    buffer_.append(size_t(indent_) * open_.size(), ' ');
  }
  ++o.entries;
}

void JsonStreamWriter::beginObject() {
  element();
  buffer_ += '{';
  open_.push_back({false, 0});
}

void JsonStreamWriter::beginArray() {
  element();
  buffer_ += '[';
  open_.push_back({true, 0});
}

void JsonStreamWriter::end() {
  const Open o = open_.back();
  open_.pop_back();
  if (o.entries && indent_ >= 0) {
    buffer_ += '\n';
    buffer_.append(size_t(indent_) * open_.size(), ' ');
  }
  buffer_ += o.array ? ']' : '}';
  flushIfFull();
}

void JsonStreamWriter::key(std::string_view key) {
  Open& o = open_.back();
  if (indent_ < 0) {
    if (o.entries) buffer_ += ',';
    buffer_ += Json(key).dump() + ":";
  } else {
    buffer_ += o.entries ? ",\n" : "\n";
    buffer_.append(size_t(indent_) * open_.size(), ' ');
    buffer_ += Json(key).dump() + ": ";
  }
  ++o.entries;
}

void JsonStreamWriter::value(const Json& j) {
  element();
  appendPrettyJson(j, indent_, inlineWidth_, int(open_.size()), buffer_);
  flushIfFull();
}

void JsonStreamWriter::flushIfFull() {
  if (buffer_.size() < (1u << 16)) return;
  out_.write(buffer_.data(), std::streamsize(buffer_.size()));
  buffer_.clear();
  if (!out_) throw Error("writing the JSON text failed");
}

void JsonStreamWriter::finish(std::string_view tail) {
  buffer_ += tail;
  out_.write(buffer_.data(), std::streamsize(buffer_.size()));
  buffer_.clear();
  out_.flush();
  if (!out_) throw Error("writing the JSON text failed");
}

std::string prettyJson(const Json& j, int indent, size_t inlineWidth) {
  if (indent < 0) return j.dump();
  std::string out;
  write(j, indent, inlineWidth, 0, out);
  return out;
}

}  // namespace vplab
