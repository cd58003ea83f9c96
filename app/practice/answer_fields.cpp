#include "app/practice/answer_fields.h"

#include "base/error.h"
#include "course/grading.h"

#include <algorithm>
#include <cstdio>

namespace vplab {

using Json = nlohmann::ordered_json;

namespace {

bool endsWith(std::string_view s, std::string_view end) {
  return s.size() >= end.size() && s.substr(s.size() - end.size()) == end;
}

/// The item's kind by where it sits in the answer format and what the key holds there.
FieldKind kindOf(const std::string& path, const Json& value) {
  if (path.find("/outcodes/") != std::string::npos) return FieldKind::outcode;
  if (endsWith(path, "/polygon") || endsWith(path, "/clipped_dc")) return FieldKind::polygon;
  if (value.is_array() && !value.empty() && value[0].is_array()) return FieldKind::matrix;
  if (value.is_array()) return FieldKind::vector;
  return FieldKind::number;
}

/// A JSON number as a student would have typed it: the shortest text that reads back the same.
std::string numberText(double v) {
  char buf[64];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

/// A kept value's text: a string as it was typed, a number as printed; nullopt for anything else.
std::optional<std::string> textOf(const Json& j) {
  if (j.is_string()) return normalizedField(j.get<std::string>());
  if (j.is_number_integer()) return std::to_string(j.get<int64_t>());
  if (j.is_number()) return numberText(j.get<double>());
  return std::nullopt;
}

}  // namespace

bool ItemFields::answered() const {
  return std::any_of(texts.begin(), texts.end(), [](const std::string& t) { return !normalizedField(t).empty(); });
}

void ItemFields::setRows(int n) {
  if (kind != FieldKind::polygon) return;
  rows = std::clamp(n, 0, kMaxPolygonVertices);
  texts.resize(size_t(rows * columns));
}

std::string ItemFields::path(int row, int column) const {
  switch (kind) {
    case FieldKind::number:
    case FieldKind::outcode: return item.path;
    case FieldKind::vector: return item.path + "/" + std::to_string(column);
    default: return item.path + "/" + std::to_string(row) + "/" + std::to_string(column);
  }
}

std::vector<ItemFields> answerFields(const Assignment& assignment, const Json& key) {
  std::vector<ItemFields> fields;
  for (const AssignmentItem& item : assignment.items) {
    const Json::json_pointer at(item.path);
    if (!key.contains(at)) throw Error("the exercise's key has no value at " + item.path);
    const Json& value = key[at];
    ItemFields f;
    f.item = item;
    f.kind = kindOf(item.path, value);
    switch (f.kind) {
      case FieldKind::vector: f.columns = int(value.size()); break;
      case FieldKind::matrix:
        f.rows = int(value.size());
        f.columns = int(value[0].size());
        break;
      case FieldKind::polygon:
        // The vertex size of the answer format: homogeneous NPC after a pass, DC for the clipped polygon.
        f.columns = endsWith(item.path, "/clipped_dc") ? 3 : 4;
        f.rows = 0;
        break;
      default: break;
    }
    f.texts.assign(size_t(f.rows * f.columns), "");
    fields.push_back(std::move(f));
  }
  return fields;
}

std::string normalizedField(std::string_view typed) {
  std::string t;
  for (size_t i = 0; i < typed.size(); ++i) {
    const std::string_view rest = typed.substr(i);
    if (rest.starts_with("\u2212") || rest.starts_with("\u2013")) {  // − and –: a minus as typography writes it
      t += '-';
      i += 2;
    } else if (typed[i] != ' ' && typed[i] != '\t' && typed[i] != '\n' && typed[i] != '\r') {
      t += typed[i];
    }
  }
  if (t.size() > kMaxFieldText) t.resize(kMaxFieldText);
  return t;
}

bool readableField(FieldKind kind, std::string_view text) {
  if (text.empty()) return true;
  if (kind == FieldKind::outcode) {
    if (text.size() == 6 && text.find_first_not_of("01") == std::string_view::npos) return true;
    if (text.size() <= 2 && text.find_first_not_of("0123456789") == std::string_view::npos) return std::stoi(std::string(text)) <= 63;
    return false;
  }
  return answerNumber(Json(std::string(text))).has_value();
}

Json answerOfFields(const std::vector<ItemFields>& fields, const Json& answerTemplate) {
  Json answer = answerTemplate;
  auto value = [](const std::string& typed) {
    const std::string text = normalizedField(typed);
    return text.empty() ? Json(nullptr) : Json(text);
  };
  for (const ItemFields& f : fields) {
    Json v;
    switch (f.kind) {
      case FieldKind::number:
      case FieldKind::outcode: v = value(f.texts[0]); break;
      case FieldKind::vector:
        v = Json::array();
        for (int c = 0; c < f.columns; ++c) v.push_back(value(f.text(0, c)));
        break;
      case FieldKind::matrix:
      case FieldKind::polygon:
        // A polygon not begun is not answered (null as a whole, as in the template); a begun one is
        // its vertices, a vertex's empty fields null.
        if (f.kind == FieldKind::polygon && !f.answered()) break;
        v = Json::array();
        for (int r = 0; r < f.rows; ++r) {
          Json row = Json::array();
          for (int c = 0; c < f.columns; ++c) row.push_back(value(f.text(r, c)));
          v.push_back(std::move(row));
        }
        break;
    }
    answer[Json::json_pointer(f.item.path)] = std::move(v);
  }
  return answer;
}

size_t fillFields(std::vector<ItemFields>& fields, const Json& answer) {
  size_t filled = 0;
  auto put = [&](std::string& into, const Json& j) {
    if (const auto t = textOf(j)) {
      into = *t;
      filled += !t->empty();
    }
  };
  for (ItemFields& f : fields) {
    const Json::json_pointer at(f.item.path);
    if (!answer.is_object() || !answer.contains(at)) continue;
    const Json& v = answer[at];
    switch (f.kind) {
      case FieldKind::number:
      case FieldKind::outcode: put(f.texts[0], v); break;
      case FieldKind::vector:
        if (v.is_array() && int(v.size()) == f.columns)
          for (int c = 0; c < f.columns; ++c) put(f.text(0, c), v[size_t(c)]);
        break;
      case FieldKind::matrix:
      case FieldKind::polygon:
        if (!v.is_array() || (f.kind == FieldKind::matrix && int(v.size()) != f.rows)) break;
        if (f.kind == FieldKind::polygon) f.setRows(int(v.size()));
        for (int r = 0; r < f.rows; ++r)
          if (v[size_t(r)].is_array() && int(v[size_t(r)].size()) == f.columns)
            for (int c = 0; c < f.columns; ++c) put(f.text(r, c), v[size_t(r)][size_t(c)]);
        break;
    }
  }
  return filled;
}

}  // namespace vplab
