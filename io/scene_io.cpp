// Index: 0 parsing (io/json_read.h: the tree and the reading helpers)  2 reading the sections  3 writing
#include "io/scene_io.h"
#include "io/scene_parts.h"
#include "io/build_mesh.h"

#include "base/error.h"
#include "io/json_read.h"
#include "io/json_text.h"
#include "pipeline/clipping.h"
#include "pipeline/primitives.h"
#include "io/read_file.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace vplab {

namespace {

using Json = nlohmann::ordered_json;
using Reader = JsonReader;

// ---------------------------------------------------------------- 0 parsing

// ---------------------------------------------------------------- 2 reading the sections

SceneObject readObject(const Reader& r, const Json& j, const std::string& path, size_t index,
                       const std::filesystem::path& baseDir, const Limits& limits, const MeshSize& used,
                       const BuiltMeshes* built) {
  r.object(j, path, {"name", "name_de", "shape", "segments", "vertices", "file", "obj", "color", "visible", "translate", "rotate", "scale"});
  SceneObject o;
  const std::string s = r.string(r.required(j, path, "shape"), path + "/shape");
  const auto shape = fromString<Shape>(s);
  if (!shape) r.fail(path + "/shape", "\"" + s + "\" is not one of cube, tetrahedron, cylinder, sphere, polygon, mesh");
  o.shape = *shape;
  o.name = j.contains("name") ? r.string(j["name"], path + "/name") : std::string(s) + " " + std::to_string(index);
  if (j.contains("name_de")) o.nameDe = r.string(j["name_de"], path + "/name_de");
  auto onlyFor = [&](const char* key, bool allowed, const char* shapes) {
    if (j.contains(key) && !allowed) r.fail(path + "/" + key, std::string("is only for ") + shapes + ", not for a " + s);
  };
  onlyFor("segments", o.shape == Shape::cylinder || o.shape == Shape::sphere, "cylinder and sphere");
  onlyFor("vertices", o.shape == Shape::polygon, "polygon");
  onlyFor("file", o.shape == Shape::mesh, "mesh");
  onlyFor("obj", o.shape == Shape::mesh, "mesh");
  if (auto it = j.find("segments"); it != j.end()) {
    const int lo = o.shape == Shape::sphere ? 4 : 3;
    o.segments = r.integer(*it, path + "/segments", lo, std::min(kMaxSegments, limits.segments));
    if (o.shape == Shape::sphere && o.segments % 2)
      r.fail(path + "/segments", "a sphere needs an even number of segments, not " + std::to_string(o.segments));
  }
  if (o.shape == Shape::polygon) {
    const std::string vp = path + "/vertices";
    const Json& v = r.array(r.required(j, path, "vertices"), vp);
    if (v.size() < 3) r.fail(vp, "a polygon needs at least 3 vertices, not " + std::to_string(v.size()));
    for (size_t i = 0; i < v.size(); ++i) o.vertices.push_back(r.vec3(v[i], vp + "/" + std::to_string(i)));
  }
  if (o.shape == Shape::mesh) {
    // The OBJ in a file beside the scene, or carried in the scene as text: one of the two.
    if (j.contains("file") && j.contains("obj"))
      r.fail(path, "a mesh takes \"file\" (an OBJ file) or \"obj\" (the OBJ text), not both");
    if (!j.contains("file") && !j.contains("obj"))
      r.fail(path, "a mesh needs \"file\" (an OBJ file) or \"obj\" (the OBJ text)");
    if (j.contains("file")) o.file = r.string(j["file"], path + "/file");
    else o.obj = std::make_shared<const std::string>(r.string(j["obj"], path + "/obj"));
  }
  if (auto it = j.find("color"); it != j.end()) o.color = r.color(*it, path + "/color");
  if (auto it = j.find("visible"); it != j.end()) o.visible = r.boolean(*it, path + "/visible");
  o.transform = readTransform(r, j, path);
  try {
    if (built) {
      if (index >= built->size() || !(*built)[index]) throw Error("no mesh was built for it");
      const Mesh& m = *(*built)[index];
      checkMeshSize({m.faceCount(), m.vertexCount(), m.indices.size()}, used, limits);
      checkWellFormed(m);
      o.mesh = (*built)[index];
    } else {
      buildMesh(o, baseDir, limits, used);
    }
  } catch (const Error& e) {
    r.fail(path, e.what());
  }
  return o;
}

// ---------------------------------------------------------------- 3 writing

Json toJson(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

Json toJson(const SceneObject& o) {
  Json j;
  j["name"] = o.name;
  if (!o.nameDe.empty()) j["name_de"] = o.nameDe;
  j["shape"] = std::string(toString(o.shape));
  if (o.shape == Shape::cylinder || o.shape == Shape::sphere) j["segments"] = o.segments;
  if (o.shape == Shape::polygon) {
    j["vertices"] = Json::array();
    for (const Vec3& v : o.vertices) j["vertices"].push_back(toJson(v));
  }
  if (o.shape == Shape::mesh) {
    if (o.obj) j["obj"] = *o.obj;
    else j["file"] = o.file;
  }
  j["color"] = toJson(o.color);
  if (!o.visible) j["visible"] = false;
  j["translate"] = toJson(o.transform.translate);
  if (!o.transform.rotations.empty()) {
    j["rotate"] = Json::array();
    for (const Rotation& r : o.transform.rotations) {
      Json rj{{"axis", toJson(r.axis)}, {"deg", r.deg}};
      if (r.through) rj["through"] = toJson(*r.through);
      j["rotate"].push_back(rj);
    }
  }
  const Vec3& s = o.transform.scale;
  j["scale"] = s.x == s.y && s.y == s.z ? Json(s.x) : toJson(s);
  return j;
}

}  // namespace

// ---------------------------------------------------------------- 2 the parts other formats reuse (io/scene_parts.h)

Camera readCamera(const JsonReader& r, const nlohmann::ordered_json& j, const std::string& path, const Camera* base) {
  r.object(j, path, {"vrp", "prp", "vup", "window", "front", "back", "projection", "oblique"});
  Camera c = base ? *base : Camera{};
  // A key given replaces the base's; without a base the scene format's keys are required.
  auto part = [&](const char* key) -> const Json* {
    if (auto it = j.find(key); it != j.end()) return &*it;
    if (!base) r.required(j, path, key);  // fails naming the key
    return nullptr;
  };
  if (const Json* v = part("vrp")) c.vrp = r.vec3(*v, path + "/vrp");
  if (const Json* v = part("prp")) c.prp = r.vec3(*v, path + "/prp");
  if (const Json* v = part("vup")) c.vup = r.vec3(*v, path + "/vup");
  if (const Json* w = part("window")) {
    const std::string wp = path + "/window";
    r.object(*w, wp, {"xmin", "xmax", "ymin", "ymax"});
    c.window.xmin = r.number(r.required(*w, wp, "xmin"), wp + "/xmin");
    c.window.xmax = r.number(r.required(*w, wp, "xmax"), wp + "/xmax");
    c.window.ymin = r.number(r.required(*w, wp, "ymin"), wp + "/ymin");
    c.window.ymax = r.number(r.required(*w, wp, "ymax"), wp + "/ymax");
  }
  if (const Json* v = part("front")) c.front = r.number(*v, path + "/front");
  if (const Json* v = part("back")) c.back = r.number(*v, path + "/back");
  if (auto it = j.find("projection"); it != j.end()) {
    const std::string s = r.string(*it, path + "/projection");
    const auto p = fromString<Projection>(s);
    if (!p) r.fail(path + "/projection", "\"" + s + "\" is not one of perspective, parallel, oblique");
    c.projection = *p;
  }
  if (auto it = j.find("oblique"); it != j.end()) {
    const std::string op = path + "/oblique";
    r.object(*it, op, {"d", "phi_deg"});
    c.oblique.d = r.number(r.required(*it, op, "d"), op + "/d", 0.0, 1e6);
    c.oblique.phiDeg = r.number(r.required(*it, op, "phi_deg"), op + "/phi_deg", -360.0, 360.0);
  }
  if (auto e = cameraError(c)) r.fail(path, "invalid camera: " + *e);
  return c;
}

ModelTransform readTransform(const JsonReader& r, const nlohmann::ordered_json& j, const std::string& path) {
  ModelTransform t;
  if (auto it = j.find("translate"); it != j.end()) t.translate = r.vec3(*it, path + "/translate");
  if (auto it = j.find("scale"); it != j.end()) {
    const std::string sp = path + "/scale";
    t.scale = it->is_array() ? r.vec3(*it, sp) : Vec3(r.number(*it, sp));
    if (t.scale.x == 0 || t.scale.y == 0 || t.scale.z == 0) r.fail(sp, "a scale factor of 0 flattens the object");
  }
  if (auto it = j.find("rotate"); it != j.end()) {
    const std::string rp = path + "/rotate";
    for (size_t i = 0; i < r.array(*it, rp).size(); ++i) {
      const std::string ip = rp + "/" + std::to_string(i);
      const Json& rj = (*it)[i];
      r.object(rj, ip, {"axis", "deg", "through"});
      Rotation rot;
      rot.axis = r.vec3(r.required(rj, ip, "axis"), ip + "/axis");
      if (glm::length(rot.axis) < 1e-12) r.fail(ip + "/axis", "the rotation axis must not be the zero vector");
      rot.deg = r.number(r.required(rj, ip, "deg"), ip + "/deg");
      if (auto th = rj.find("through"); th != rj.end()) rot.through = r.vec3(*th, ip + "/through");
      t.rotations.push_back(rot);
    }
  }
  return t;
}

std::vector<UserClipPlane> readClipPlanes(const JsonReader& r, const nlohmann::ordered_json& j, const std::string& path) {
  if (r.array(j, path).size() > kMaxUserPlanes)
    r.fail(path, "at most " + std::to_string(kMaxUserPlanes) + " user clip planes, not " + std::to_string(j.size()));
  std::vector<UserClipPlane> planes;
  for (size_t i = 0; i < j.size(); ++i) {
    const std::string cp = path + "/" + std::to_string(i);
    const Json& pj = j[i];
    r.object(pj, cp, {"normal", "point", "enabled"});
    UserClipPlane plane;
    plane.normal = r.vec3(r.required(pj, cp, "normal"), cp + "/normal");
    if (glm::length(plane.normal) < 1e-12) r.fail(cp + "/normal", "the plane's normal must not be the zero vector");
    plane.point = r.vec3(r.required(pj, cp, "point"), cp + "/point");
    if (auto e = pj.find("enabled"); e != pj.end()) plane.enabled = r.boolean(*e, cp + "/enabled");
    planes.push_back(plane);
  }
  return planes;
}

Scene parseScene(std::string_view text, std::string_view source, const std::filesystem::path& baseDir,
                 const Limits& limits, const BuiltMeshes* built) {
  const Reader r{std::string(source)};
  const Json j = parseCheckedJson(text, source, limits.jsonDepth);
  r.object(j, "", {"title", "title_de", "caption", "caption_de", "camera", "device", "background", "lights", "clip_planes", "objects"});
  Scene scene;
  if (auto it = j.find("title"); it != j.end()) scene.title = r.string(*it, "/title");
  if (auto it = j.find("caption"); it != j.end()) scene.caption = r.string(*it, "/caption");
  if (auto it = j.find("title_de"); it != j.end()) scene.titleDe = r.string(*it, "/title_de");
  if (auto it = j.find("caption_de"); it != j.end()) scene.captionDe = r.string(*it, "/caption_de");
  scene.camera = readCamera(r, r.required(j, "", "camera"), "/camera");
  if (auto it = j.find("device"); it != j.end()) {
    r.object(*it, "/device", {"width", "height"});
    scene.device.width = r.integer(r.required(*it, "/device", "width"), "/device/width", 1, 16384);
    scene.device.height = r.integer(r.required(*it, "/device", "height"), "/device/height", 1, 16384);
  }
  if (auto it = j.find("background"); it != j.end()) scene.background = r.color(*it, "/background");
  if (auto it = j.find("lights"); it != j.end()) {
    for (size_t i = 0; i < r.array(*it, "/lights").size(); ++i) {
      const std::string lp = "/lights/" + std::to_string(i);
      r.object((*it)[i], lp, {"position", "color"});
      Light light;
      light.position = r.vec3(r.required((*it)[i], lp, "position"), lp + "/position");
      if (auto c = (*it)[i].find("color"); c != (*it)[i].end()) light.color = r.color(*c, lp + "/color");
      scene.lights.push_back(light);
    }
  }
  if (auto it = j.find("clip_planes"); it != j.end()) scene.clipPlanes = readClipPlanes(r, *it, "/clip_planes");
  const Json& objects = r.array(r.required(j, "", "objects"), "/objects");
  MeshSize used;  // the scene's faces, vertices and corners so far, against limits
  for (size_t i = 0; i < objects.size(); ++i) {
    scene.objects.push_back(readObject(r, objects[i], "/objects/" + std::to_string(i), i, baseDir, limits, used, built));
    const Mesh& m = *scene.objects.back().mesh;
    used.faces += m.faceCount();
    used.vertices += m.vertexCount();
    used.corners += m.indices.size();
  }
  return scene;
}

Scene loadScene(const std::filesystem::path& file, const Limits& limits) {
  Scene scene = parseScene(readRegularFile(file, limits.sceneFileBytes, "scene file"), file.string(),
                           file.parent_path(), limits);
  scene.path = file;
  return scene;
}

namespace {
std::string sizeText(std::uintmax_t bytes) {
  return bytes >= (std::uintmax_t(1) << 20) ? std::to_string(bytes >> 20) + " MiB" : std::to_string((bytes + 1023) >> 10) + " kB";
}
}  // namespace

Scene carryingItsMeshes(Scene scene, const Limits& limits) {
  for (SceneObject& o : scene.objects) {
    if (o.shape != Shape::mesh || o.obj) continue;
    const std::filesystem::path file(o.file);
    const std::filesystem::path p = file.is_absolute() || scene.path.empty() ? file : scene.path.parent_path() / file;
    o.obj = std::make_shared<const std::string>(readRegularFile(p, limits.objFileBytes, "OBJ file"));
    o.file.clear();
  }
  if (const size_t bytes = sceneToJson(scene).size(); bytes > limits.sceneFileBytes)
    throw Error("the scene with its meshes would be " + sizeText(bytes) + ", more than a scene file may be (" +
                sizeText(limits.sceneFileBytes) + "): keep the OBJ files beside the scene");
  return scene;
}

std::string sceneToJson(const Scene& scene) {
  const Camera& c = scene.camera;
  Json j;
  if (!scene.title.empty()) j["title"] = scene.title;
  if (!scene.caption.empty()) j["caption"] = scene.caption;
  if (!scene.titleDe.empty()) j["title_de"] = scene.titleDe;
  if (!scene.captionDe.empty()) j["caption_de"] = scene.captionDe;
  j["camera"] = {{"vrp", toJson(c.vrp)},
                 {"prp", toJson(c.prp)},
                 {"vup", toJson(c.vup)},
                 {"window", {{"xmin", c.window.xmin}, {"xmax", c.window.xmax}, {"ymin", c.window.ymin}, {"ymax", c.window.ymax}}},
                 {"front", c.front},
                 {"back", c.back},
                 {"projection", std::string(toString(c.projection))}};
  if (c.projection == Projection::oblique) j["camera"]["oblique"] = {{"d", c.oblique.d}, {"phi_deg", c.oblique.phiDeg}};
  j["device"] = {{"width", scene.device.width}, {"height", scene.device.height}};
  j["background"] = toJson(scene.background);
  if (!scene.lights.empty()) {
    j["lights"] = Json::array();
    for (const Light& l : scene.lights) j["lights"].push_back({{"position", toJson(l.position)}, {"color", toJson(l.color)}});
  }
  if (!scene.clipPlanes.empty()) {
    j["clip_planes"] = Json::array();
    for (const UserClipPlane& p : scene.clipPlanes) {
      Json pj{{"normal", toJson(p.normal)}, {"point", toJson(p.point)}};
      if (!p.enabled) pj["enabled"] = false;
      j["clip_planes"].push_back(pj);
    }
  }
  j["objects"] = Json::array();
  for (const SceneObject& o : scene.objects) j["objects"].push_back(toJson(o));
  return prettyJson(j) + "\n";
}

void saveScene(const Scene& scene, const std::filesystem::path& file) {
  const std::string text = sceneToJson(scene);
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(file.string() + ": cannot write the scene file");
    out << text;
    if (!out.flush()) {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);  // leave no partial temporary file behind
      throw Error(file.string() + ": writing the scene file failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);  // the target is unchanged; so is the directory
    throw Error(file.string() + ": cannot replace the scene file: " + ec.message());
  }
}

}  // namespace vplab
