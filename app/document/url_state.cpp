#include "app/document/url_state.h"

#include "base/error.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace vplab {

namespace {

std::string join(std::initializer_list<double> values) {
  std::string s;
  for (double v : values) s += (s.empty() ? "" : ",") + shortestNumber(v);
  return s;
}

/// Letters, digits and - . _ ~ stay; everything else is %XX (a scene name is checked to be plain anyway).
std::string quoteForError(std::string_view s) {
  constexpr size_t kShown = 60;
  std::string out(s.substr(0, kShown));
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return "\"" + out + (s.size() > kShown ? "…" : "") + "\"";
}

/// `count` finite numbers separated by commas (what encodeUrlState writes), or an error naming the key.
std::vector<double> numbers(std::string_view key, std::string_view value, size_t count) {
  std::vector<double> out;
  size_t start = 0;
  while (out.size() <= count) {
    const size_t comma = value.find(',', start);
    const std::string part(value.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    char* end = nullptr;
    const double v = part.empty() ? NAN : std::strtod(part.c_str(), &end);
    if (part.empty() || end != part.c_str() + part.size() || !std::isfinite(v))
      throw Error("the link's " + std::string(key) + "=" + quoteForError(value) + " is not " + std::to_string(count) +
                  " finite number" + (count > 1 ? "s separated by commas" : ""));
    out.push_back(v);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (out.size() != count)
    throw Error("the link's " + std::string(key) + "=" + quoteForError(value) + " has " +
                (out.size() > count ? "more than " : "") + std::to_string(out.size() > count ? count : out.size()) +
                " numbers, " + std::to_string(count) + " expected");
  return out;
}

Style style(std::string_view key, std::string_view value) {
  if (auto s = fromString<Style>(value)) return *s;
  throw Error("the link's " + std::string(key) + "=" + quoteForError(value) +
              " is not a style (flat, shaded, wire, hidden-line or hidden-removed)");
}

Orbit orbit(std::string_view key, std::string_view value) {
  const std::vector<double> v = numbers(key, value, 7);
  Orbit o{{v[0], v[1], v[2]}, v[3], v[4], v[5], v[6]};
  if (std::abs(o.pitchDeg) > 89 || o.distance <= 0 || o.fovDeg <= 0 || o.fovDeg >= 180)
    throw Error("the link's " + std::string(key) + "=" + quoteForError(value) +
                " is no observer: pitch from -89 to 89 degrees, distance > 0 and a field of view from 0 to 180 degrees");
  return o;
}

std::string orbitText(const Orbit& o) {
  return join({o.target.x, o.target.y, o.target.z, o.yawDeg, o.pitchDeg, o.distance, o.fovDeg});
}

}  // namespace

std::string shortestNumber(double v) {
  if (v == 0) return "0";  // and -0
  char buf[400];
  // Plain decimals for the numbers a camera has (40, not 4e+01); exponents only for the very large
  // and the very small.
  const bool plain = std::abs(v) >= 1e-6 && std::abs(v) < 1e15;
  for (int digits = plain ? 0 : 1; digits <= (plain ? 21 : 17); ++digits) {
    std::snprintf(buf, sizeof buf, plain ? "%.*f" : "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) return buf;
  }
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string encodeUrlState(const UrlState& s) {
  std::vector<std::string> parts;
  if (!s.embed.empty()) {
    std::string views;
    for (ViewKind v : s.embed) views += (views.empty() ? "" : ",") + std::string(toString(v));
    parts.push_back("embed=" + views);
  }
  if (s.exercise) {
    parts.push_back("exercise=" + std::string(toString(s.exercise->spec.topic)));
    parts.push_back("seed=" + std::to_string(s.exercise->spec.seed));
    if (!s.exercise->studentId.empty()) parts.push_back("id=" + s.exercise->studentId);
    if (s.exercise->spec.projection != Projection::perspective)
      parts.push_back("projection=" + std::string(toString(s.exercise->spec.projection)));
    if (s.reveal) parts.push_back("reveal=" + std::string(toString(*s.reveal)));
  }
  if (!s.lesson.empty()) parts.push_back("lesson=" + s.lesson);
  if (s.step > 0) parts.push_back("step=" + std::to_string(s.step));
  if (!s.scene.empty()) parts.push_back("scene=" + s.scene);
  const CameraLink& c = s.camera;
  if (c.vrp) parts.push_back("vrp=" + join({c.vrp->x, c.vrp->y, c.vrp->z}));
  if (c.prp) parts.push_back("prp=" + join({c.prp->x, c.prp->y, c.prp->z}));
  if (c.vup) parts.push_back("vup=" + join({c.vup->x, c.vup->y, c.vup->z}));
  if (c.window) parts.push_back("window=" + join({c.window->xmin, c.window->xmax, c.window->ymin, c.window->ymax}));
  if (c.front) parts.push_back("front=" + shortestNumber(*c.front));
  if (c.back) parts.push_back("back=" + shortestNumber(*c.back));
  if (c.projection) parts.push_back("projection=" + std::string(toString(*c.projection)));
  if (c.oblique) parts.push_back("oblique=" + join({c.oblique->d, c.oblique->phiDeg}));
  if (s.cameraStyle) parts.push_back("camera-style=" + std::string(toString(*s.cameraStyle)));
  if (s.worldStyle) parts.push_back("world-style=" + std::string(toString(*s.worldStyle)));
  if (s.npcStyle) parts.push_back("npc-style=" + std::string(toString(*s.npcStyle)));
  if (s.worldOrbit) parts.push_back("world=" + orbitText(*s.worldOrbit));
  if (s.npcOrbit) parts.push_back("npc=" + orbitText(*s.npcOrbit));
  if (s.strategy) parts.push_back("strategy=" + std::string(toString(*s.strategy)));
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : "&") + p;
  return out;
}

bool isBundledSceneName(std::string_view s) {
  if (s.empty() || s.size() > 100) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_')) return false;
  return true;
}

bool isBundledLessonName(std::string_view s) {
  const size_t dot = s.find('.');
  if (dot == std::string_view::npos) return isBundledSceneName(s);
  const std::string_view language = s.substr(dot + 1);
  return isBundledSceneName(s.substr(0, dot)) && (language == "de" || language == "en");
}

UrlState decodeUrlState(std::string_view fragment) {
  if (!fragment.empty() && fragment.front() == '#') fragment.remove_prefix(1);
  if (fragment.size() > kMaxUrlStateLength)
    throw Error("the link's state is " + std::to_string(fragment.size()) + " characters long; at most " +
                std::to_string(kMaxUrlStateLength) + " are read");
  UrlState s;
  CameraLink& c = s.camera;
  std::optional<ExerciseTopic> exerciseTopic;
  std::optional<uint64_t> exerciseSeed;
  std::optional<std::string> studentId;
  size_t start = 0;
  while (start < fragment.size()) {
    const size_t amp = fragment.find('&', start);
    const std::string_view part = fragment.substr(start, amp == std::string_view::npos ? std::string_view::npos : amp - start);
    start = amp == std::string_view::npos ? fragment.size() : amp + 1;
    if (part.empty()) continue;
    const size_t eq = part.find('=');
    if (eq == std::string_view::npos) throw Error("the link's " + quoteForError(part) + " is not KEY=VALUE");
    const std::string_view key = part.substr(0, eq), value = part.substr(eq + 1);
    auto vec3 = [&] {
      const auto v = numbers(key, value, 3);
      return Vec3(v[0], v[1], v[2]);
    };
    if (key == "embed") {
      size_t at = 0;
      while (at <= value.size()) {
        const size_t comma = std::min(value.find(',', at), value.size());
        const std::string_view name = value.substr(at, comma - at);
        const auto kind = fromString<ViewKind>(name);
        if (!kind || (*kind != ViewKind::camera && *kind != ViewKind::world && *kind != ViewKind::npc))
          throw Error("the link's embed=" + quoteForError(value) + " names " + quoteForError(name) +
                      ", not one of the views camera, world and npc");
        if (std::find(s.embed.begin(), s.embed.end(), *kind) != s.embed.end())
          throw Error("the link's embed=" + quoteForError(value) + " names " + quoteForError(name) + " twice");
        s.embed.push_back(*kind);
        at = comma + 1;
      }
    } else if (key == "exercise") {
      const auto topic = fromString<ExerciseTopic>(value);
      if (!topic)
        throw Error("the link's exercise=" + quoteForError(value) + " is not a topic of the exercises (orientation, mapping, clipping or pipeline)");
      exerciseTopic = *topic;
    } else if (key == "seed") {
      const auto seed = exerciseSeedFrom(value);
      if (!seed) throw Error("the link's seed=" + quoteForError(value) + " is not an exercise's number (0 to 999999999999999999)");
      exerciseSeed = *seed;
    } else if (key == "id") {
      if (value.empty() || !validStudentId(value))
        throw Error("the link's id=" + quoteForError(value) + " is not a student's id (at most 64 letters, digits, '.', '-' or '@')");
      studentId = std::string(value);
    } else if (key == "reveal") {
      const auto reveal = fromString<Reveal>(value);
      if (!reveal) throw Error("the link's reveal=" + quoteForError(value) + " is not values, stages or none");
      s.reveal = *reveal;
    } else if (key == "lesson") {
      if (!isBundledLessonName(value))
        throw Error("the link's lesson=" + quoteForError(value) +
                    " is not the name of a bundled lesson (letters, digits, - and _, then .de or .en or nothing)");
      s.lesson = std::string(value);
    } else if (key == "step") {
      const double n = numbers(key, value, 1)[0];
      if (n != std::floor(n) || n < 1 || n > 10000)
        throw Error("the link's step=" + quoteForError(value) + " is not a step's number (1, 2, …)");
      s.step = size_t(n);
    } else if (key == "scene") {
      if (!isBundledSceneName(value))
        throw Error("the link's scene=" + quoteForError(value) + " is not the name of a bundled scene (letters, digits, - and _)");
      s.scene = std::string(value);
    } else if (key == "vrp") {
      c.vrp = vec3();
    } else if (key == "prp") {
      c.prp = vec3();
    } else if (key == "vup") {
      c.vup = vec3();
    } else if (key == "window") {
      const auto v = numbers(key, value, 4);
      c.window = ViewWindow{v[0], v[1], v[2], v[3]};
    } else if (key == "front") {
      c.front = numbers(key, value, 1)[0];
    } else if (key == "back") {
      c.back = numbers(key, value, 1)[0];
    } else if (key == "projection") {
      const auto p = fromString<Projection>(value);
      if (!p) throw Error("the link's projection=" + quoteForError(value) + " is not perspective, parallel or oblique");
      c.projection = *p;
    } else if (key == "oblique") {
      const auto v = numbers(key, value, 2);
      c.oblique = ObliqueParams{v[0], v[1]};
    } else if (key == "camera-style") {
      s.cameraStyle = style(key, value);
    } else if (key == "world-style") {
      s.worldStyle = style(key, value);
    } else if (key == "npc-style") {
      s.npcStyle = style(key, value);
    } else if (key == "world") {
      s.worldOrbit = orbit(key, value);
    } else if (key == "npc") {
      s.npcOrbit = orbit(key, value);
    } else if (key == "strategy") {
      const auto st = fromString<ClipStrategy>(value);
      if (!st) throw Error("the link's strategy=" + quoteForError(value) + " is not npc, wc or divide-first");
      s.strategy = *st;
    } else {
      throw Error("the link's " + quoteForError(key) + " is not a key vplab knows (embed, lesson, step, scene, vrp, prp, "
                  "vup, window, front, back, projection, oblique, camera-style, world-style, npc-style, world, npc, strategy, "
                  "exercise, seed, id, reveal)");
    }
  }
  // An exercise is named by its topic and seed; its projection is the exercise's, not a camera's.
  if (exerciseTopic || exerciseSeed || studentId || s.reveal) {
    if (!exerciseTopic) throw Error("the link gives an exercise's seed, id or reveal but no exercise=TOPIC");
    if (!exerciseSeed) throw Error("the link's exercise=" + std::string(toString(*exerciseTopic)) + " needs its seed=N");
    ExerciseRef ref;
    ref.spec = {*exerciseSeed, *exerciseTopic, c.projection.value_or(Projection::perspective)};
    ref.studentId = studentId.value_or("");
    s.exercise = ref;
    c.projection.reset();
    if (!c.empty() || !s.lesson.empty() || !s.scene.empty())
      throw Error("the link names an exercise and a scene, lesson or camera: an exercise is its own scene");
  }
  return s;
}

Camera CameraLink::over(const Camera& base) const {
  Camera c = base;
  if (vrp) c.vrp = *vrp;
  if (prp) c.prp = *prp;
  if (vup) c.vup = *vup;
  if (window) c.window = *window;
  if (front) c.front = *front;
  if (back) c.back = *back;
  if (projection) c.projection = *projection;
  if (oblique) c.oblique = *oblique;
  if (auto e = cameraError(c)) throw Error("the link's camera is not valid: " + *e);
  return c;
}

CameraLink cameraLinkOf(const Camera& c) {
  CameraLink l{c.vrp, c.prp, c.vup, c.window, c.front, c.back, c.projection, std::nullopt};
  if (c.projection == Projection::oblique) l.oblique = c.oblique;
  return l;
}

}  // namespace vplab
