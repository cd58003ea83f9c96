#include "app/document/autosave.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/document/atomic_file.h"
#include "base/error.h"
#include "io/scene_io.h"

namespace vplab {

namespace {

constexpr double kNever = 1e9;
// Scenes are small (meshes stay in their OBJ files); this bounds what a start reads at worst.
constexpr std::uintmax_t kMaxRecoveryBytes = 64ull << 20;

std::string localTime() {
  const std::time_t now = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
  return buf;
}

/// Whether process `pid` still runs vplab (then its file is its live autosave, not a leftover).
bool vplabRunning(long pid) {
  if (pid <= 0 || pid == long(::getpid())) return pid == long(::getpid());
  if (::kill(pid_t(pid), 0) != 0 && errno != EPERM) return false;
  std::ifstream comm("/proc/" + std::to_string(pid) + "/comm");
  std::string name;
  std::getline(comm, name);
  return !comm || name.find("vplab") != std::string::npos;  // unknown: assume it is
}

std::string readText(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw Error(file.string() + ": not a regular file");
  const auto size = std::filesystem::file_size(file, ec);
  if (ec || size > kMaxRecoveryBytes)
    throw Error(file.string() + ": " +
                (ec ? ec.message() : "larger than " + std::to_string(kMaxRecoveryBytes) + " bytes"));
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw Error(file.string() + ": cannot read the recovery file");
  return text.str();
}

/// A camera's numbers as they are, valid or not (a scene file's reader would refuse an invalid one).
nlohmann::ordered_json cameraNumbers(const Camera& c) {
  auto vec = [](const Vec3& v) { return nlohmann::ordered_json::array({v.x, v.y, v.z}); };
  return {{"vrp", vec(c.vrp)},
          {"prp", vec(c.prp)},
          {"vup", vec(c.vup)},
          {"window", {c.window.xmin, c.window.xmax, c.window.ymin, c.window.ymax}},
          {"front", c.front},
          {"back", c.back},
          {"projection", std::string(toString(c.projection))},
          {"oblique", {c.oblique.d, c.oblique.phiDeg}}};
}

/// A field's number read back: finite (a field never holds NaN), else it throws.
double finiteNumber(const nlohmann::json& v) {
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw std::range_error("not finite");
  return d;
}

/// Three finite numbers read back, else it throws.
Vec3 finiteVec3(const nlohmann::json& v) {
  if (!v.is_array() || v.size() != 3) throw std::range_error("not 3 numbers");
  return Vec3(finiteNumber(v[0]), finiteNumber(v[1]), finiteNumber(v[2]));
}

/// A transform's numbers as they are, valid or not (a scale of 0, a rotation about the zero vector).
nlohmann::ordered_json transformNumbers(const ModelTransform& t) {
  auto vec = [](const Vec3& v) { return nlohmann::ordered_json::array({v.x, v.y, v.z}); };
  nlohmann::ordered_json rotations = nlohmann::ordered_json::array();
  for (const Rotation& r : t.rotations) {
    nlohmann::ordered_json rj{{"axis", vec(r.axis)}, {"deg", r.deg}};
    if (r.through) rj["through"] = vec(*r.through);
    rotations.push_back(rj);
  }
  return {{"translate", vec(t.translate)}, {"rotate", rotations}, {"scale", vec(t.scale)}};
}

/// transformNumbers read back, at most kMaxRotations rotations and each number finite; nothing for
/// anything else.
std::optional<ModelTransform> transformFromNumbers(const nlohmann::json& j) {
  constexpr size_t kMaxRotations = 64;
  try {
    ModelTransform t;
    t.translate = finiteVec3(j.at("translate"));
    t.scale = finiteVec3(j.at("scale"));
    const auto& rotations = j.at("rotate");
    if (!rotations.is_array() || rotations.size() > kMaxRotations) return std::nullopt;
    for (const auto& r : rotations) {
      Rotation rotation{finiteVec3(r.at("axis")), finiteNumber(r.at("deg")), std::nullopt};
      if (r.contains("through")) rotation.through = finiteVec3(r.at("through"));
      t.rotations.push_back(rotation);
    }
    return t;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

/// cameraNumbers read back; nothing for anything else (each number finite: a field never holds NaN).
std::optional<Camera> cameraFromNumbers(const nlohmann::json& j) {
  try {
    Camera c;
    c.vrp = finiteVec3(j.at("vrp"));
    c.prp = finiteVec3(j.at("prp"));
    c.vup = finiteVec3(j.at("vup"));
    const auto& w = j.at("window");
    if (w.size() != 4) return std::nullopt;
    c.window = {finiteNumber(w[0]), finiteNumber(w[1]), finiteNumber(w[2]), finiteNumber(w[3])};
    c.front = finiteNumber(j.at("front"));
    c.back = finiteNumber(j.at("back"));
    const std::optional<Projection> p = fromString<Projection>(j.at("projection").get<std::string>());
    if (!p) return std::nullopt;
    c.projection = *p;
    const auto& o = j.at("oblique");
    if (o.size() != 2) return std::nullopt;
    c.oblique = {finiteNumber(o[0]), finiteNumber(o[1])};
    return c;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::filesystem::path Autosave::defaultDirectory() {
  if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state == '/')
    return std::filesystem::path(state) / "vplab";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".local/state/vplab";
  return {};
}

Autosave::Autosave(std::filesystem::path directory, double delaySeconds)
    : directory_(std::move(directory)), delay_(delaySeconds) {
  if (!directory_.empty()) file_ = directory_ / ("recovery-" + std::to_string(::getpid()) + ".json");
}

void Autosave::update(const Document& doc, double now, const RecoveryView& view) {
  if (file_.empty()) return;
  if (!doc.dirty()) {
    if (savedRevision_ != 0) removeFile();
    pending_ = false;
    seenRevision_ = doc.revision();
    return;
  }
  if (doc.revision() != seenRevision_ || (view != writtenView_ && !pending_)) {  // a change: wait until it is `delay` old
    seenRevision_ = doc.revision();
    changedAt_ = now;
    pending_ = seenRevision_ != savedRevision_ || view != writtenView_;
  }
  if (pending_ && now - changedAt_ >= delay_) write(doc, view);
}

double Autosave::dueIn(double now) const {
  return pending_ ? std::max(0.0, changedAt_ + delay_ - now) : kNever;
}

bool Autosave::writeNow(const Document& doc, const RecoveryView& view) {
  if (file_.empty()) return false;
  if (doc.dirty() && (pending_ || savedRevision_ != doc.revision() || view != writtenView_)) write(doc, view);
  return doc.dirty() && savedRevision_ == doc.revision();
}

void Autosave::write(const Document& doc, const RecoveryView& view) {
  pending_ = false;
  try {
    std::error_code ec;
    std::filesystem::create_directories(directory_, ec);
    if (ec) throw Error(directory_.string() + ": cannot create the autosave directory: " + ec.message());
    nlohmann::ordered_json j;
    j["scene_path"] = doc.path().empty() ? std::string() : std::filesystem::absolute(doc.path()).string();
    j["saved_at"] = localTime();
    // The scene the views showed: a scene file holds only valid cameras; the typed one beside it.
    j["scene"] = nlohmann::ordered_json::parse(sceneToJson(doc.shown()));
    if (!view.lesson.empty()) j["lesson"] = {{"file", std::filesystem::absolute(view.lesson).string()}, {"step", view.step}};
    if (!view.views.empty()) j["views"] = view.views;
    if (doc.scene().camera != doc.shown().camera) j["edited_camera"] = cameraNumbers(doc.scene().camera);
    if (doc.scene().objects.size() == doc.shown().objects.size())
      for (size_t i = 0; i < doc.scene().objects.size(); ++i)
        if (doc.scene().objects[i].transform != doc.shown().objects[i].transform)
          j["edited_transforms"].push_back({{"object", i}, {"transform", transformNumbers(doc.scene().objects[i].transform)}});
    writeFileAtomically(file_, j.dump(2) + "\n");
    savedRevision_ = doc.revision();
    writtenView_ = view;
    error_.clear();
  } catch (const std::exception& e) {
    error_ = std::string("autosave failed: ") + e.what();
  }
}

void Autosave::removeFile() {
  if (file_.empty()) return;
  std::error_code ignored;
  std::filesystem::remove(file_, ignored);
  savedRevision_ = 0;
}

std::optional<Recovery> Autosave::read(const std::filesystem::path& file) {
  try {
    const auto j = nlohmann::json::parse(readText(file));
    return Recovery{file, j.at("scene_path").get<std::string>(), j.at("saved_at").get<std::string>()};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::vector<Recovery> Autosave::findAll(const std::filesystem::path& directory) {
  std::vector<std::pair<std::filesystem::file_time_type, Recovery>> found;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(directory, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("recovery-", 0) != 0 || entry.path().extension() != ".json") continue;
    const std::string digits = name.substr(9, name.size() - 9 - 5);
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9)
      continue;
    if (vplabRunning(std::stol(digits))) continue;
    std::error_code e;
    const auto time = entry.last_write_time(e);
    if (e) continue;
    if (std::optional<Recovery> r = read(entry.path())) found.emplace_back(time, std::move(*r));
  }
  std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Recovery> newestFirst;
  for (auto& [time, r] : found) newestFirst.push_back(std::move(r));
  return newestFirst;
}

std::optional<Recovery> Autosave::find(const std::filesystem::path& directory) {
  std::vector<Recovery> all = findAll(directory);
  if (all.empty()) return std::nullopt;
  return std::move(all.front());
}

RecoveryView Autosave::loadView(const Recovery& recovery) {
  RecoveryView view;
  try {
    const auto j = nlohmann::json::parse(readText(recovery.file));
    if (j.contains("lesson") && j["lesson"].is_object()) {
      view.lesson = j["lesson"].at("file").get<std::string>();
      view.step = j["lesson"].at("step").get<size_t>();
    }
    if (j.contains("views") && j["views"].is_string()) view.views = j["views"].get<std::string>();
    if (j.contains("edited_camera")) view.editedCamera = cameraFromNumbers(j["edited_camera"]);
    if (j.contains("edited_transforms") && j["edited_transforms"].is_array())
      for (const auto& e : j["edited_transforms"]) {
        if (!e.is_object() || !e.contains("object") || !e["object"].is_number_unsigned() || !e.contains("transform")) continue;
        if (auto t = transformFromNumbers(e["transform"])) view.editedTransforms.emplace_back(e["object"].get<size_t>(), *t);
      }
  } catch (const std::exception&) {
    // What can be read of it was read; the scene is load()'s.
  }
  return view;
}

Scene Autosave::load(const Recovery& recovery) {
  const std::string source = recovery.file.string();
  try {
    const auto j = nlohmann::json::parse(readText(recovery.file));
    const std::filesystem::path baseDir =
        recovery.scenePath.empty() ? std::filesystem::path() : recovery.scenePath.parent_path();
    Scene scene = parseScene(j.at("scene").dump(2), source + ": /scene", baseDir);
    scene.path = recovery.scenePath;
    return scene;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(source + ": not a vplab recovery file: " + e.what());
  }
}

void Autosave::discard(const Recovery& recovery) {
  std::error_code ignored;
  std::filesystem::remove(recovery.file, ignored);
}

}  // namespace vplab
