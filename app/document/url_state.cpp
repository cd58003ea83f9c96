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

/// What a link's value is shown as in a problem: control characters as '?', at most 60 characters.
std::string shownValue(std::string_view s) {
  constexpr size_t kShown = 60;
  std::string out(s.substr(0, kShown));
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return out + (s.size() > kShown ? "…" : "");
}

/// Reads one fragment's parts into `s`, each problem into s.problems (the part left out).
struct LinkReader {
  UrlState& s;

  void problem(std::string_view key, std::string_view value, text::Text why, std::string detail = {}) {
    s.problems.push_back({shownValue(key), shownValue(value), why, std::move(detail)});
  }

  /// `count` finite numbers separated by commas (what encodeUrlState writes); nullopt, said, otherwise.
  std::optional<std::vector<double>> numbers(std::string_view key, std::string_view value, size_t count) {
    std::vector<double> out;
    size_t start = 0;
    for (;;) {
      const size_t comma = value.find(',', start);
      const std::string part(value.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
      char* end = nullptr;
      const double v = part.empty() ? NAN : std::strtod(part.c_str(), &end);
      if (part.empty() || end != part.c_str() + part.size() || !std::isfinite(v)) {
        badCount(key, value, count);
        return std::nullopt;
      }
      out.push_back(v);
      if (comma == std::string_view::npos || out.size() > count) break;
      start = comma + 1;
    }
    if (out.size() != count) {
      badCount(key, value, count);
      return std::nullopt;
    }
    return out;
  }
  void badCount(std::string_view key, std::string_view value, size_t count) {
    if (count == 1) problem(key, value, "a finite number expected");
    else problem(key, value, "{1} finite numbers separated by commas expected", std::to_string(count));
  }

  std::optional<Style> style(std::string_view key, std::string_view value) {
    if (auto st = fromString<Style>(value)) return *st;
    problem(key, value, "not a style (flat, shaded, wire, hidden-line or hidden-removed)");
    return std::nullopt;
  }

  std::optional<Orbit> orbit(std::string_view key, std::string_view value) {
    const auto v = numbers(key, value, 7);
    if (!v) return std::nullopt;
    const std::vector<double>& n = *v;
    Orbit o{{n[0], n[1], n[2]}, n[3], n[4], n[5], n[6]};
    if (std::abs(o.pitchDeg) > 89 || o.distance <= 0 || o.fovDeg <= 0 || o.fovDeg >= 180) {
      problem(key, value, "no observer: pitch from -89 to 89 degrees, distance > 0, a field of view from 0 to 180 degrees");
      return std::nullopt;
    }
    return o;
  }

  std::optional<Vec3> vec3(std::string_view key, std::string_view value) {
    const auto v = numbers(key, value, 3);
    if (!v) return std::nullopt;
    return Vec3((*v)[0], (*v)[1], (*v)[2]);
  }

  void embed(std::string_view value) {
    std::vector<ViewKind> views;
    size_t at = 0;
    while (at <= value.size()) {
      const size_t comma = std::min(value.find(',', at), value.size());
      const std::string_view name = value.substr(at, comma - at);
      const auto kind = fromString<ViewKind>(name);
      if (!kind || (*kind != ViewKind::camera && *kind != ViewKind::world && *kind != ViewKind::npc))
        return problem("embed", value, "\"{1}\" is not one of the views camera, world and npc", shownValue(name));
      if (std::find(views.begin(), views.end(), *kind) != views.end())
        return problem("embed", value, "names the view \"{1}\" twice", shownValue(name));
      views.push_back(*kind);
      at = comma + 1;
    }
    s.embed = std::move(views);
  }

  /// One part KEY=VALUE.
  void part(std::string_view key, std::string_view value, std::optional<ExerciseTopic>& topic,
            std::optional<uint64_t>& seed, std::optional<std::string>& studentId);
};

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

void LinkReader::part(std::string_view key, std::string_view value, std::optional<ExerciseTopic>& topic,
                      std::optional<uint64_t>& seed, std::optional<std::string>& studentId) {
  CameraLink& c = s.camera;
  if (key == "embed") {
    embed(value);
  } else if (key == "exercise") {
    if (const auto t = fromString<ExerciseTopic>(value)) topic = *t;
    else problem(key, value, "not a topic of the exercises (orientation, mapping, clipping or pipeline)");
  } else if (key == "seed") {
    if (const auto n = exerciseSeedFrom(value)) seed = *n;
    else problem(key, value, "not an exercise's number (0 to 999999999999999999)");
  } else if (key == "id") {
    if (!value.empty() && validStudentId(value)) studentId = std::string(value);
    else problem(key, value, "not a student's id (at most 64 letters, digits, '.', '-' or '@')");
  } else if (key == "reveal") {
    if (const auto r = fromString<Reveal>(value)) s.reveal = *r;
    else problem(key, value, "not values, stages or none");
  } else if (key == "lesson") {
    if (isBundledLessonName(value)) s.lesson = std::string(value);
    else problem(key, value, "not the name of a bundled lesson (letters, digits, - and _, then .de, .en or nothing)");
  } else if (key == "step") {
    char* end = nullptr;
    const std::string text(value);
    const double n = text.empty() ? NAN : std::strtod(text.c_str(), &end);
    if (!text.empty() && end == text.c_str() + text.size() && n == std::floor(n) && n >= 1 && n <= 10000) s.step = size_t(n);
    else problem(key, value, "not a step's number (1, 2, …)");
  } else if (key == "scene") {
    if (isBundledSceneName(value)) s.scene = std::string(value);
    else problem(key, value, "not the name of a bundled scene (letters, digits, - and _)");
  } else if (key == "vrp") {
    c.vrp = vec3(key, value);
  } else if (key == "prp") {
    c.prp = vec3(key, value);
  } else if (key == "vup") {
    c.vup = vec3(key, value);
  } else if (key == "window") {
    if (const auto v = numbers(key, value, 4)) c.window = ViewWindow{(*v)[0], (*v)[1], (*v)[2], (*v)[3]};
  } else if (key == "front") {
    if (const auto v = numbers(key, value, 1)) c.front = (*v)[0];
  } else if (key == "back") {
    if (const auto v = numbers(key, value, 1)) c.back = (*v)[0];
  } else if (key == "projection") {
    if (const auto p = fromString<Projection>(value)) c.projection = *p;
    else problem(key, value, "not perspective, parallel or oblique");
  } else if (key == "oblique") {
    if (const auto v = numbers(key, value, 2)) c.oblique = ObliqueParams{(*v)[0], (*v)[1]};
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
    if (const auto st = fromString<ClipStrategy>(value)) s.strategy = *st;
    else problem(key, value, "not npc, wc or divide-first");
  } else {
    problem(key, value, "not a key vplab knows");
  }
}

UrlState decodeUrlState(std::string_view fragment) {
  if (!fragment.empty() && fragment.front() == '#') fragment.remove_prefix(1);
  UrlState s;
  LinkReader r{s};
  if (fragment.size() > kMaxUrlStateLength) {
    r.problem("", "", "the link is {1} characters long: too long to be read", std::to_string(fragment.size()));
    return s;
  }
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
    if (eq == std::string_view::npos) {
      r.problem(part, "", "not KEY=VALUE");
      continue;
    }
    r.part(part.substr(0, eq), part.substr(eq + 1), exerciseTopic, exerciseSeed, studentId);
  }
  // An exercise is named by its topic and seed; its projection is the exercise's, not a camera's, and
  // it is its own scene: what else the link gives is left out, said.
  if (exerciseTopic && !exerciseSeed) r.problem("exercise", toString(*exerciseTopic), "an exercise needs its seed=N");
  if (!exerciseTopic && (exerciseSeed || studentId || s.reveal))
    r.problem(exerciseSeed ? "seed" : studentId ? "id" : "reveal", "", "a part of an exercise, but the link gives no exercise=TOPIC");
  if (exerciseTopic && exerciseSeed) {
    ExerciseRef ref;
    ref.spec = {*exerciseSeed, *exerciseTopic, s.camera.projection.value_or(Projection::perspective)};
    ref.studentId = studentId.value_or("");
    s.exercise = ref;
    s.camera.projection.reset();
    if (!s.camera.empty() || !s.lesson.empty() || !s.scene.empty()) {
      r.problem(!s.lesson.empty() ? "lesson" : !s.scene.empty() ? "scene" : "", "",
                "left out: an exercise is its own scene, without another scene, lesson or camera");
      s.camera = {};
      s.lesson.clear();
      s.scene.clear();
    }
  } else if (!exerciseTopic) {
    s.reveal.reset();
  }
  if (s.step > 0 && s.lesson.empty()) {
    r.problem("step", std::to_string(s.step), "a step without lesson=NAME");
    s.step = 0;
  }
  return s;
}

std::string LinkProblem::said(Language lang) const {
  const std::string reason = text::fill(lang, why, {detail});
  if (key.empty()) return reason;
  return key + (value.empty() ? "" : "=\"" + value + "\"") + ": " + reason;
}

std::string saidTogether(const std::vector<LinkProblem>& problems, Language lang) {
  std::string out;
  for (const LinkProblem& p : problems) out += (out.empty() ? "" : "; ") + p.said(lang);
  return out;
}

Camera CameraLink::over(const Camera& base) const {
  const Camera c = applied(base);
  if (auto e = cameraError(c)) throw Error("the link's camera is not valid: " + *e);
  return c;
}

Camera CameraLink::applied(const Camera& base) const {
  Camera c = base;
  if (vrp) c.vrp = *vrp;
  if (prp) c.prp = *prp;
  if (vup) c.vup = *vup;
  if (window) c.window = *window;
  if (front) c.front = *front;
  if (back) c.back = *back;
  if (projection) c.projection = *projection;
  if (oblique) c.oblique = *oblique;
  return c;
}

CameraLink cameraLinkOf(const Camera& c) {
  CameraLink l{c.vrp, c.prp, c.vup, c.window, c.front, c.back, c.projection, std::nullopt};
  if (c.projection == Projection::oblique) l.oblique = c.oblique;
  return l;
}

}  // namespace vplab
