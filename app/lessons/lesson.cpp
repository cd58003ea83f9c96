// Index: 1 the parts of a step (camera, objects, views, overlays, marks)  2 a step over the previous
//        3 the lesson  4 the bundled lessons
#include "app/lessons/lesson.h"

#include "app/document/assets.h"
#include "app/lessons/lesson_framing.h"
#include "app/lessons/tabs.h"
#include "io/json_read.h"
#include "io/read_file.h"
#include "io/scene_io.h"
#include "io/scene_parts.h"
#include "base/error.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <map>
#include <utility>

namespace vplab {

namespace {

using Json = nlohmann::ordered_json;

/// "a, b or c" for a message listing the allowed words.
template <class Names>
std::string wordList(const Names& names) {
  std::string out;
  const size_t n = std::size(names);
  size_t i = 0;
  for (const auto& name : names) {
    out += (i == 0 ? "" : i + 1 == n ? " or " : ", ") + std::string(name);
    ++i;
  }
  return out;
}

/// The index of `word` in `names`, or a failure naming the allowed words.
template <class Names>
size_t oneOf(const JsonReader& r, const Json& j, const std::string& path, const Names& names) {
  const std::string word = r.string(j, path);
  size_t i = 0;
  for (const auto& name : names) {
    if (word == name) return i;
    ++i;
  }
  r.fail(path, "\"" + word + "\" is not " + wordList(names));
}

// ---------------------------------------------------------------- 1 the parts of a step

/// The scene's object named `name`: exactly one must be.
size_t objectNamed(const JsonReader& r, const Scene& scene, const std::string& name, const std::string& path) {
  std::optional<size_t> found;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    if (scene.objects[i].name != name) continue;
    if (found) r.fail(path, "the scene has more than one object named \"" + name + "\"");
    found = i;
  }
  if (!found) {
    std::vector<std::string> names;
    for (const SceneObject& o : scene.objects) names.push_back("\"" + o.name + "\"");
    r.fail(path, "the scene has no object named \"" + name + "\"; it has " + (names.empty() ? "none" : wordList(names)));
  }
  return *found;
}

/// "objects": {"NAME": {"visible", "translate", "rotate", "scale"}}; a transform's part that is given
/// replaces the object's, the others stay.
void changeObjects(const JsonReader& r, const Json& j, const std::string& path, Scene& scene) {
  if (!j.is_object()) r.fail(path, std::string("must be an object of objects by name, not ") + j.type_name());
  for (const auto& [name, change] : j.items()) {
    const std::string op = path + "/" + name;
    SceneObject& o = scene.objects[objectNamed(r, scene, name, op)];
    r.object(change, op, {"visible", "translate", "rotate", "scale"});
    if (auto it = change.find("visible"); it != change.end()) o.visible = r.boolean(*it, op + "/visible");
    const ModelTransform t = readTransform(r, change, op);
    if (change.contains("translate")) o.transform.translate = t.translate;
    if (change.contains("rotate")) o.transform.rotations = t.rotations;
    if (change.contains("scale")) o.transform.scale = t.scale;
  }
}

Orbit changedOrbit(const JsonReader& r, const Json& j, const std::string& path, Orbit o) {
  r.object(j, path, {"target", "yaw_deg", "pitch_deg", "distance", "fov_deg"});
  if (auto it = j.find("target"); it != j.end()) o.target = r.vec3(*it, path + "/target");
  if (auto it = j.find("yaw_deg"); it != j.end()) o.yawDeg = r.number(*it, path + "/yaw_deg", -3600, 3600);
  if (auto it = j.find("pitch_deg"); it != j.end()) o.pitchDeg = r.number(*it, path + "/pitch_deg", -89, 89);
  if (auto it = j.find("distance"); it != j.end()) o.distance = r.number(*it, path + "/distance", 1e-6, 1e6);
  if (auto it = j.find("fov_deg"); it != j.end()) o.fovDeg = r.number(*it, path + "/fov_deg", 1, 170);
  return o;
}

/// "views": {"camera"|"world"|"npc"|"morph": {"style", "orbit"}}; the camera view has no orbit (it
/// is the scene's camera).
void changeViews(const JsonReader& r, const Json& j, const std::string& path, DisplaySettings& d) {
  r.object(j, path, {"camera", "world", "npc", "morph"});
  const std::pair<const char*, ViewSettings*> views[] = {{"camera", &d.camera}, {"world", &d.world}, {"npc", &d.npc}, {"morph", &d.morph}};
  for (const auto& [name, view] : views) {
    auto it = j.find(name);
    if (it == j.end()) continue;
    const std::string vp = path + "/" + name;
    if (view == &d.camera) r.object(*it, vp, {"style"});
    else r.object(*it, vp, {"style", "orbit"});
    if (auto s = it->find("style"); s != it->end()) {
      constexpr std::array names = {"flat", "shaded", "wire", "hidden-line", "hidden-removed"};
      view->style = allOf<Style>()[oneOf(r, *s, vp + "/style", names)];
    }
    if (auto o = it->find("orbit"); o != it->end()) view->orbit = changedOrbit(r, *o, vp + "/orbit", view->orbit);
  }
}

void changeOverlays(const JsonReader& r, const Json& j, const std::string& path, OverlaySettings& o) {
  const std::pair<const char*, bool*> overlays[] = {
      {"frustum", &o.frustum},       {"view_plane", &o.viewPlane},       {"camera_axes", &o.cameraAxes},
      {"labels", &o.labels},         {"fade_outside", &o.fadeOutside},   {"new_edges", &o.newEdges},
      {"cube", &o.cube},             {"cpu_polygons", &o.cpuPolygons},   {"difference", &o.difference},
      {"vanishing_points", &o.vanishingPoints}, {"vertex_names", &o.vertexNames}};
  if (!j.is_object()) r.fail(path, std::string("must be an object, not ") + j.type_name());
  for (const auto& item : j.items()) {
    const std::string& key = item.key();
    const Json& value = item.value();
    auto it = std::find_if(std::begin(overlays), std::end(overlays), [&](const auto& p) { return key == p.first; });
    if (it == std::end(overlays)) {
      std::vector<std::string> names;
      for (const auto& p : overlays) names.push_back(p.first);
      r.fail(path + "/" + key, "unknown key; allowed here: " + wordList(names));
    }
    *it->second = r.boolean(value, path + "/" + key);
  }
}

/// {"object": NAME, "vertex": k}: a vertex of the step's scene.
Probe vertexOf(const JsonReader& r, const Json& j, const std::string& path, const Scene& scene) {
  r.object(j, path, {"object", "vertex"});
  const std::string name = r.string(r.required(j, path, "object"), path + "/object");
  const size_t object = objectNamed(r, scene, name, path + "/object");
  const size_t count = scene.objects[object].mesh ? scene.objects[object].mesh->vertexCount() : 0;
  if (count == 0) r.fail(path + "/object", "\"" + name + "\" has no vertices");
  const int vertex = r.integer(r.required(j, path, "vertex"), path + "/vertex", 0, int(std::min<size_t>(count - 1, 1u << 30)));
  return {object, uint32_t(vertex)};
}

LessonStepThrough stepThroughOf(const JsonReader& r, const Json& j, const std::string& path, const Scene& scene) {
  r.object(j, path, {"object", "face", "plane"});
  const std::string name = r.string(r.required(j, path, "object"), path + "/object");
  const size_t object = objectNamed(r, scene, name, path + "/object");
  const size_t faces = scene.objects[object].mesh ? scene.objects[object].mesh->faceCount() : 0;
  if (faces == 0) r.fail(path + "/object", "\"" + name + "\" has no faces");
  LessonStepThrough s;
  s.object = object;
  s.face = r.integer(r.required(j, path, "face"), path + "/face", 0, int(std::min<size_t>(faces - 1, 1u << 30)));
  const int userPlanes = int(std::count_if(scene.clipPlanes.begin(), scene.clipPlanes.end(), [](const UserClipPlane& p) { return p.enabled; }));
  if (auto it = j.find("plane"); it != j.end()) s.plane = r.integer(*it, path + "/plane", 0, 6 + userPlanes);
  return s;
}

LessonHighlight highlightOf(const JsonReader& r, const Json& j, const std::string& path, const Scene& scene) {
  if (!j.is_object() || j.empty())
    r.fail(path, "must be an object naming a handle, matrix, vertex, plane or axis");
  LessonHighlight h;
  const std::string kind = j.begin().key();
  if (kind == "handle") {
    r.object(j, path, {"handle"});
    constexpr std::array names = {"vrp", "prp", "xmin", "xmax", "ymin", "ymax", "front", "back"};
    h.kind = LessonHighlight::Kind::handle;
    h.handle = kHandles[oneOf(r, j["handle"], path + "/handle", names)];
  } else if (kind == "matrix") {
    r.object(j, path, {"matrix", "row", "column"});
    h.kind = LessonHighlight::Kind::matrix;
    h.matrix = kLessonMatrices[oneOf(r, j["matrix"], path + "/matrix", kLessonMatrices)];
    if (auto it = j.find("row"); it != j.end()) h.row = r.integer(*it, path + "/row", 0, 3);
    if (auto it = j.find("column"); it != j.end()) h.column = r.integer(*it, path + "/column", 0, 3);
  } else if (kind == "vertex") {
    r.object(j, path, {"vertex"});
    h.kind = LessonHighlight::Kind::vertex;
    h.vertex = vertexOf(r, j["vertex"], path + "/vertex", scene);
  } else if (kind == "plane") {
    r.object(j, path, {"plane"});
    h.kind = LessonHighlight::Kind::plane;
    std::vector<std::string> names(std::begin(kLessonPlanes), std::end(kLessonPlanes));
    for (size_t k = 0; k < scene.clipPlanes.size(); ++k) names.push_back("user" + std::to_string(k + 1));
    h.plane = int(oneOf(r, j["plane"], path + "/plane", names));
  } else if (kind == "axis") {
    r.object(j, path, {"axis"});
    constexpr std::array names = {"u", "v", "n"};
    h.kind = LessonHighlight::Kind::axis;
    h.axis = int(oneOf(r, j["axis"], path + "/axis", names));
  } else {
    r.fail(path + "/" + kind, "unknown key; a highlight names one of handle, matrix, vertex, plane, axis");
  }
  return h;
}

// ---------------------------------------------------------------- 2 a step over the previous

/// Loads each scene a lesson names once.
struct SceneCache {
  const LessonContext& context;
  std::filesystem::path baseDir;
  std::map<std::filesystem::path, Scene> scenes;

  const Scene& get(const JsonReader& r, const std::filesystem::path& file, const std::string& path) {
    if (auto it = scenes.find(file); it != scenes.end()) return it->second;
    if (scenes.size() >= context.lessonLimits.scenes)
      r.fail(path, "a lesson may show at most " + std::to_string(context.lessonLimits.scenes) + " different scenes");
    try {
      return scenes.emplace(file, loadScene(file, context.limits)).first->second;
    } catch (const Error& e) {
      r.fail(path, e.what());
    }
  }
};

LessonStep readStep(const JsonReader& r, const Json& j, const std::string& path, const LessonState* previous,
                    SceneCache& scenes) {
  r.object(j, path, {"caption", "section", "scene", "scene_file", "camera", "objects", "clip_planes", "views",
                     "overlays", "strategy", "bounding_box", "morph", "select", "tab", "probe", "step_through",
                     "highlight", "free", "cites"});
  const LessonContext& context = scenes.context;
  LessonStep step;
  step.caption = r.string(r.required(j, path, "caption"), path + "/caption");
  if (step.caption.size() > context.lessonLimits.captionBytes)
    r.fail(path + "/caption", "is " + std::to_string(step.caption.size()) + " bytes long; a caption may have at most " +
                                  std::to_string(context.lessonLimits.captionBytes));
  if (auto it = j.find("section"); it != j.end()) step.section = r.string(*it, path + "/section");
  if (auto it = j.find("free"); it != j.end()) step.free = r.boolean(*it, path + "/free");
  if (auto it = j.find("cites"); it != j.end()) {
    const Json& cites = r.array(*it, path + "/cites");
    if (cites.size() > context.lessonLimits.cites)
      r.fail(path + "/cites", "at most " + std::to_string(context.lessonLimits.cites) + " values, not " +
                                  std::to_string(cites.size()));
    for (size_t i = 0; i < cites.size(); ++i) {
      const std::string where = path + "/cites/" + std::to_string(i);
      const std::string value = r.string(cites[i], where);
      // A cited value is one the caption says (so a reader can find it in both).
      if (value.empty() || step.caption.find(value) == std::string::npos)
        r.fail(where, "\"" + value + "\" is not in the step's caption");
      step.cites.push_back(value);
    }
  }

  // The scene: a new one starts from a fresh document's views; otherwise the previous step's state.
  LessonState& s = step.state;
  if (j.contains("scene") && j.contains("scene_file")) r.fail(path, "a step takes \"scene\" or \"scene_file\", not both");
  std::optional<std::filesystem::path> file;
  if (auto it = j.find("scene"); it != j.end()) {
    const std::string name = r.string(*it, path + "/scene");
    if (!isBundledSceneName(name)) r.fail(path + "/scene", "\"" + name + "\" is not the name of a bundled scene (letters, digits, - and _)");
    file = context.scenesDirectory / (name + ".json");
  } else if (auto f = j.find("scene_file"); f != j.end()) {
    const std::filesystem::path p(r.string(*f, path + "/scene_file"));
    file = p.is_absolute() ? p : scenes.baseDir / p;
  }
  if (file) {
    const std::string key = j.contains("scene") ? "/scene" : "/scene_file";
    s.scene = scenes.get(r, *file, path + key);
    s.display = context.fresh;
    s.display.world.orbit = defaultWorldOrbit(s.scene, context.worldAspect);
  } else if (previous) {
    s.scene = previous->scene;
    s.display = previous->display;
    s.strategy = previous->strategy;
    s.boundingBoxTest = previous->boundingBoxTest;
    s.morphShown = previous->morphShown;
    s.selected = previous->selected;
    s.tab = previous->tab;
  } else {
    r.fail(path, "the first step must name a \"scene\" (a bundled one) or a \"scene_file\"");
  }

  if (auto it = j.find("camera"); it != j.end()) s.scene.camera = readCamera(r, *it, path + "/camera", &s.scene.camera);
  if (auto it = j.find("objects"); it != j.end()) changeObjects(r, *it, path + "/objects", s.scene);
  if (auto it = j.find("clip_planes"); it != j.end()) s.scene.clipPlanes = readClipPlanes(r, *it, path + "/clip_planes");
  if (auto it = j.find("views"); it != j.end()) changeViews(r, *it, path + "/views", s.display);
  if (auto it = j.find("overlays"); it != j.end()) changeOverlays(r, *it, path + "/overlays", s.display.overlays);
  if (auto it = j.find("strategy"); it != j.end()) {
    constexpr std::array names = {"npc", "wc", "divide-first"};
    s.strategy = allOf<ClipStrategy>()[oneOf(r, *it, path + "/strategy", names)];
  }
  if (auto it = j.find("bounding_box"); it != j.end()) s.boundingBoxTest = r.boolean(*it, path + "/bounding_box");
  if (auto it = j.find("morph"); it != j.end()) {
    s.display.morphing.t = r.number(*it, path + "/morph", 0, 4);
    s.morphShown = true;
  }
  if (auto it = j.find("select"); it != j.end())
    s.selected = objectNamed(r, s.scene, r.string(*it, path + "/select"), path + "/select");
  if (auto it = j.find("tab"); it != j.end()) s.tab = kTabNames[oneOf(r, *it, path + "/tab", kTabNames)];
  if (auto it = j.find("probe"); it != j.end()) s.probe = vertexOf(r, *it, path + "/probe", s.scene);
  if (auto it = j.find("step_through"); it != j.end()) s.stepThrough = stepThroughOf(r, *it, path + "/step_through", s.scene);
  if (auto it = j.find("highlight"); it != j.end()) {
    const std::string hp = path + "/highlight";
    if (r.array(*it, hp).size() > context.lessonLimits.highlights)
      r.fail(hp, "a step may highlight at most " + std::to_string(context.lessonLimits.highlights) + " things, not " +
                     std::to_string(it->size()));
    for (size_t i = 0; i < it->size(); ++i) s.highlights.push_back(highlightOf(r, (*it)[i], hp + "/" + std::to_string(i), s.scene));
  }
  return step;
}

}  // namespace

// ---------------------------------------------------------------- 3 the lesson

Lesson parseLesson(std::string_view text, std::string_view source, const std::filesystem::path& baseDir,
                   const LessonContext& context) {
  const JsonReader r{std::string(source)};
  const Json j = parseCheckedJson(text, source, context.limits.jsonDepth);
  r.object(j, "", {"title", "language", "steps"});
  Lesson lesson;
  lesson.title = r.string(r.required(j, "", "title"), "/title");
  constexpr std::array languages = {"en", "de"};
  lesson.language = oneOf(r, r.required(j, "", "language"), "/language", languages) == 0 ? Language::en : Language::de;
  const Json& steps = r.array(r.required(j, "", "steps"), "/steps");
  if (steps.empty()) r.fail("/steps", "a lesson needs at least one step");
  if (steps.size() > context.lessonLimits.steps)
    r.fail("/steps", "a lesson may have at most " + std::to_string(context.lessonLimits.steps) + " steps, not " +
                         std::to_string(steps.size()));
  SceneCache scenes{context, baseDir, {}};
  lesson.steps.reserve(steps.size());
  for (size_t i = 0; i < steps.size(); ++i) {
    const LessonState* previous = i == 0 ? nullptr : &lesson.steps.back().state;
    lesson.steps.push_back(readStep(r, steps[i], "/steps/" + std::to_string(i), previous, scenes));
  }
  // Then each step's object framed in the view that shows it: after the chain, so the next step
  // starts from the views as written, not from the zoom (lesson_framing.h).
  for (size_t i = 0; i < steps.size(); ++i) {
    auto ownOrbit = [&](const char* view) {
      const Json& step = steps[i];
      return step.contains("views") && step["views"].contains(view) && step["views"][view].contains("orbit");
    };
    frameStepObjects(lesson.steps[i].state, context.worldAspect, ownOrbit("world"), ownOrbit("npc"));
  }
  return lesson;
}

Lesson loadLesson(const std::filesystem::path& file, const LessonContext& context) {
  Lesson lesson = parseLesson(readRegularFile(file, context.lessonLimits.fileBytes, "lesson file"), file.string(),
                              file.parent_path(), context);
  lesson.file = file;
  return lesson;
}

// ---------------------------------------------------------------- 4 the bundled lessons

std::vector<LessonFileInfo> listBundledLessons(Language language) {
  namespace fs = std::filesystem;
  std::vector<LessonFileInfo> lessons;
  const fs::path dir = assetsDirectory();
  if (dir.empty()) return lessons;
  const std::string suffix = language == Language::de ? ".de.json" : ".en.json";
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir / "lessons", ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() <= suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
    LessonFileInfo info{e.path(), name.substr(0, name.size() - suffix.size())};
    // Only the title is read here; the lesson is read (and checked) when chosen.
    std::ifstream in(e.path());
    const auto j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_object() && j.contains("title") && j["title"].is_string()) info.title = j["title"].get<std::string>();
    lessons.push_back(std::move(info));
  }
  std::sort(lessons.begin(), lessons.end(),
            [](const LessonFileInfo& a, const LessonFileInfo& b) { return a.file.filename() < b.file.filename(); });
  return lessons;
}

std::filesystem::path bundledLessonFile(std::string_view name, Language language) {
  if (!isBundledLessonName(name)) return {};
  const size_t dot = name.find('.');
  const std::string_view stem = name.substr(0, dot);
  const std::string_view lang = dot != std::string_view::npos ? name.substr(dot + 1) : language == Language::de ? "de" : "en";
  const std::filesystem::path assets = assetsDirectory();
  if (assets.empty()) return {};
  const std::filesystem::path file = assets / "lessons" / (std::string(stem) + "." + std::string(lang) + ".json");
  std::error_code ec;
  return std::filesystem::is_regular_file(file, ec) ? file : std::filesystem::path();
}

}  // namespace vplab
