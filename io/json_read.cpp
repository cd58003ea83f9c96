#include "io/json_read.h"

#include "base/error.h"

#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace vplab {

namespace {

using Json = nlohmann::ordered_json;

/// Builds the JSON tree (nlohmann's DOM builder behind its SAX interface) while checking what the
/// tree itself cannot show: nesting deeper than the limit is refused before it is built (a deep
/// tree would overflow the stack of whatever walks it), a key given twice in one object is an error
/// (not silently last-wins), and every error knows the JSON path it happened at.
class CheckedJsonBuilder {
 public:
  CheckedJsonBuilder(Json& root, int maxDepth) : dom_(root, false), maxDepth_(maxDepth) {}

  std::string error;       // "/json/path: what is wrong", or the parser's message for a syntax error
  bool syntaxError = false;  // an error of the parser (errorByte says where), not of ours
  size_t errorByte = 0;

  bool null() { return value() && dom_.null(); }
  bool boolean(bool b) { return value() && dom_.boolean(b); }
  bool number_integer(Json::number_integer_t n) { return value() && dom_.number_integer(n); }
  bool number_unsigned(Json::number_unsigned_t n) { return value() && dom_.number_unsigned(n); }
  bool number_float(Json::number_float_t n, const std::string& s) { return value() && dom_.number_float(n, s); }
  bool string(std::string& s) { return value() && dom_.string(s); }
  bool binary(Json::binary_t& b) { return value() && dom_.binary(b); }
  bool start_object(std::size_t n) { return open(false) && dom_.start_object(n); }
  bool start_array(std::size_t n) { return open(true) && dom_.start_array(n); }
  bool end_object() { levels_.pop_back(); return dom_.end_object(); }
  bool end_array() { levels_.pop_back(); return dom_.end_array(); }
  bool key(std::string& k) {
    Level& l = levels_.back();
    l.key = k;
    if (!l.keys.insert(k).second) return fail("the key \"" + k + "\" is given twice in this object");
    return dom_.key(k);
  }
  bool parse_error(std::size_t byte, const std::string& token, const nlohmann::detail::exception& e) {
    syntaxError = true;
    errorByte = byte;
    std::string what = e.what();
    if (e.id == 406) {  // out_of_range.406: a number beyond the range of a double
      error = path() + ": the number " + token + " is out of range: a number must be finite (at most about 1.8e308)";
    } else {
      if (auto p = what.find("syntax error"); p != std::string::npos) what = what.substr(p);
      else if (auto q = what.find("] "); q != std::string::npos) what = what.substr(q + 2);  // "[json.exception…] "
      error = "JSON " + what;
    }
    return false;
  }

  /// The path of the value being read: "/objects/0/translate/1".
  std::string path() const {
    std::string p;
    for (const Level& l : levels_) {
      if (l.array) {
        if (l.count) p += "/" + std::to_string(l.count - 1);
      } else if (!l.key.empty() || !l.keys.empty()) {
        p += "/";
        for (char c : l.key) p += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
      }
    }
    return p.empty() ? "/" : p;
  }

 private:
  struct Level {
    bool array;
    size_t count = 0;          // arrays: values started so far
    std::string key;           // objects: the current key
    std::set<std::string> keys;  // objects: the keys seen
  };

  bool fail(const std::string& what) {
    error = path() + ": " + what;
    return false;
  }
  bool value() {
    if (!levels_.empty() && levels_.back().array) ++levels_.back().count;
    return true;
  }
  bool open(bool array) {
    value();
    if (int(levels_.size()) >= maxDepth_)
      return fail("objects and arrays nested deeper than " + std::to_string(maxDepth_) + " levels (the limit)");
    levels_.push_back(Level{array, 0, {}, {}});
    return true;
  }

  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  int maxDepth_;
  std::vector<Level> levels_;
};

}  // namespace

std::pair<int, int> lineAndColumn(std::string_view text, size_t byte) {
  int line = 1, col = 1;
  for (size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') { ++line; col = 1; } else { ++col; }
  }
  return {line, col};
}

Json parseCheckedJson(std::string_view text, std::string_view source, int maxDepth) {
  Json j;
  CheckedJsonBuilder builder(j, maxDepth);
  if (!Json::sax_parse(text.begin(), text.end(), &builder)) {
    if (!builder.syntaxError) throw Error(std::string(source) + ": " + builder.error);
    const auto [line, col] = lineAndColumn(text, builder.errorByte);
    throw Error(std::string(source) + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " + builder.error);
  }
  return j;
}

// ---------------------------------------------------------------- JsonReader

void JsonReader::fail(const std::string& path, const std::string& message) const {
  throw Error(source + ": " + (path.empty() ? "/" : path) + ": " + message);
}

void JsonReader::object(const Json& j, const std::string& path, std::initializer_list<std::string_view> allowed) const {
  if (!j.is_object()) fail(path, std::string("must be an object, not ") + j.type_name());
  for (const auto& [key, value] : j.items()) {
    bool ok = false;
    for (std::string_view a : allowed) ok = ok || key == a;
    if (ok) continue;
    std::string list;
    for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    fail(path + "/" + key, "unknown key; allowed here: " + list);
  }
}

const JsonReader::Json& JsonReader::required(const Json& j, const std::string& path, const char* key) const {
  auto it = j.find(key);
  if (it == j.end()) fail(path, std::string("missing required key \"") + key + "\"");
  return *it;
}

double JsonReader::number(const Json& j, const std::string& path, double lo, double hi) const {
  if (!j.is_number()) fail(path, std::string("must be a number, not ") + j.type_name());
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(path, "must be finite");
  if (v < lo || v > hi) fail(path, format(v) + " is out of range [" + format(lo) + ", " + format(hi) + "]");
  return v;
}

int JsonReader::integer(const Json& j, const std::string& path, int lo, int hi) const {
  auto range = [&] { return " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]"; };
  if (!j.is_number_integer()) fail(path, std::string("must be an integer, not ") + j.type_name());
  if (j.is_number_unsigned() && j.get<uint64_t>() > uint64_t(std::numeric_limits<long long>::max()))
    fail(path, std::to_string(j.get<uint64_t>()) + range());  // would wrap around as a signed number
  const auto v = j.get<long long>();
  if (v < lo || v > hi) fail(path, std::to_string(v) + range());
  return int(v);
}

Vec3 JsonReader::vec3(const Json& j, const std::string& path, double lo, double hi) const {
  if (!j.is_array() || j.size() != 3)
    fail(path, std::string("must be an array of 3 numbers, not ") +
                   (j.is_array() ? "an array of " + std::to_string(j.size()) : std::string(j.type_name())));
  return {number(j[0], path + "/0", lo, hi), number(j[1], path + "/1", lo, hi), number(j[2], path + "/2", lo, hi)};
}

std::string JsonReader::string(const Json& j, const std::string& path) const {
  if (!j.is_string()) fail(path, std::string("must be a string, not ") + j.type_name());
  return j.get<std::string>();
}

bool JsonReader::boolean(const Json& j, const std::string& path) const {
  if (!j.is_boolean()) fail(path, std::string("must be true or false, not ") + j.type_name());
  return j.get<bool>();
}

const JsonReader::Json& JsonReader::array(const Json& j, const std::string& path) const {
  if (!j.is_array()) fail(path, std::string("must be an array, not ") + j.type_name());
  return j;
}

}  // namespace vplab
