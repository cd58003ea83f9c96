#include "course/assignment.h"

#include "course/mistake_models.h"
#include "io/json_read.h"
#include "io/limits.h"
#include "base/error.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <set>

namespace vplab {

using Json = nlohmann::ordered_json;

namespace {

constexpr size_t kMaxItems = 10000;

struct Reader {
  std::string source;
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw Error(source + ": " + (path.empty() ? "/" : path) + ": " + what);
  }
  void onlyKeys(const Json& j, const std::string& path, std::initializer_list<const char*> keys) const {
    if (!j.is_object()) fail(path, "an object expected");
    for (const auto& [key, value] : j.items()) {
      bool known = false;
      std::string list;
      for (const char* k : keys) known |= key == k, list += (list.empty() ? "" : ", ") + std::string(k);
      if (!known) fail(path + "/" + key, "unknown key (known here: " + list + ")");
    }
  }
  std::string text(const Json& j, const std::string& path) const {
    if (!j.is_string()) fail(path, "a string expected");
    return j.get<std::string>();
  }
  double number(const Json& j, const std::string& path, double lo, double hi) const {
    if (!j.is_number() || !(j.get<double>() >= lo && j.get<double>() <= hi))
      fail(path, j.dump() + " where a number from " + format(lo) + " to " + format(hi) + " is expected");
    return j.get<double>();
  }
  std::vector<std::string> mistakeKeys(const Json& j, const std::string& path) const {
    if (!j.is_array() || j.size() > mistakeModels().size()) fail(path, "a list of mistake keys expected");
    std::vector<std::string> keys;
    for (size_t i = 0; i < j.size(); ++i) {
      const std::string key = text(j[i], path + "/" + std::to_string(i));
      std::string known;
      bool found = false;
      for (const MistakeModel& m : mistakeModels()) found |= m.key == key, known += (known.empty() ? "" : ", ") + std::string(m.key);
      if (!found) fail(path + "/" + std::to_string(i), "\"" + key + "\" is no mistake model (known: " + known + ")");
      keys.push_back(key);
    }
    return keys;
  }
};

bool isPointer(std::string_view p) {
  if (p.empty() || p[0] != '/' || p.back() == '/') return false;
  return p.find("//") == std::string_view::npos;
}

}  // namespace

Assignment parseAssignment(std::string_view text, std::string_view source) {
  const Json j = parseCheckedJson(text, source, kDefaultLimits.jsonDepth);
  const Reader r{std::string(source)};
  r.onlyKeys(j, "", {"vplab_assignment", "title", "scene", "tolerance", "row_vector_form", "pass_mark", "items"});
  if (!j.contains("vplab_assignment") || j["vplab_assignment"] != 1)
    r.fail("/vplab_assignment", "missing or not 1 (the format's version: this file is not a vplab assignment)");
  Assignment a;
  if (j.contains("title")) a.title = r.text(j["title"], "/title");
  if (j.contains("scene")) a.scene = r.text(j["scene"], "/scene");
  if (j.contains("tolerance")) a.tolerance = r.number(j["tolerance"], "/tolerance", 0, 0.5);
  if (j.contains("row_vector_form")) {
    const std::string form = r.text(j["row_vector_form"], "/row_vector_form");
    if (form != "accepted" && form != "wrong")
      r.fail("/row_vector_form", "\"" + form + "\" where \"accepted\" or \"wrong\" is expected");
    a.rowVectorFormAccepted = form == "accepted";
  }
  if (!j.contains("items") || !j["items"].is_array() || j["items"].empty())
    r.fail("/items", "a list of at least one item expected (an assignment that asks for nothing grades nothing)");
  if (j["items"].size() > kMaxItems)
    r.fail("/items", std::to_string(j["items"].size()) + " items exceed the limit of " + std::to_string(kMaxItems));
  std::set<std::string> paths;
  for (size_t i = 0; i < j["items"].size(); ++i) {
    const std::string at = "/items/" + std::to_string(i);
    const Json& item = j["items"][i];
    r.onlyKeys(item, at, {"path", "title", "points", "required", "no_follow_through_after"});
    if (!item.contains("path")) r.fail(at, "missing required key \"path\"");
    AssignmentItem it;
    it.path = r.text(item["path"], at + "/path");
    if (!isPointer(it.path)) r.fail(at + "/path", "\"" + it.path + "\" is not a JSON pointer into the answer (\"/camera/n\")");
    if (!paths.insert(it.path).second) r.fail(at + "/path", "\"" + it.path + "\" is given twice");
    it.title = item.contains("title") ? r.text(item["title"], at + "/title") : it.path;
    if (item.contains("points")) it.points = r.number(item["points"], at + "/points", 0, 1000);
    if (item.contains("required")) {
      if (!item["required"].is_boolean()) r.fail(at + "/required", "true or false expected");
      it.required = item["required"].get<bool>();
    }
    if (item.contains("no_follow_through_after")) it.noFollowThroughAfter = r.mistakeKeys(item["no_follow_through_after"], at + "/no_follow_through_after");
    a.items.push_back(std::move(it));
  }
  if (j.contains("pass_mark")) {
    double total = 0;
    for (const AssignmentItem& i : a.items) total += i.points;
    a.passMark = r.number(j["pass_mark"], "/pass_mark", 0, total);
  }
  return a;
}

std::string assignmentJson(const Assignment& a) {
  Json items = Json::array();
  for (const AssignmentItem& i : a.items) {
    Json item = {{"path", i.path}, {"title", i.title}, {"points", i.points}};
    if (!i.required) item["required"] = false;
    if (!i.noFollowThroughAfter.empty()) item["no_follow_through_after"] = i.noFollowThroughAfter;
    items.push_back(item);
  }
  Json j = {{"vplab_assignment", 1},
                  {"title", a.title},
                  {"scene", a.scene.generic_string()},
                  {"tolerance", a.tolerance},
                  {"row_vector_form", a.rowVectorFormAccepted ? "accepted" : "wrong"},
                  {"items", items}};
  if (a.passMark) j["pass_mark"] = *a.passMark;
  return j.dump(2) + "\n";
}

bool isWithin(std::string_view path, std::string_view item) {
  return path.size() >= item.size() && path.substr(0, item.size()) == item &&
         (path.size() == item.size() || path[item.size()] == '/');
}

}  // namespace vplab
