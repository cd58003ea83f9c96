#include "pipeline/scene.h"

#include "base/error.h"
#include "pipeline/primitives.h"

namespace vplab {

std::shared_ptr<const Mesh> primitiveMesh(const SceneObject& o) {
  switch (o.shape) {
    case Shape::cube: return std::make_shared<const Mesh>(cube());
    case Shape::tetrahedron: return std::make_shared<const Mesh>(tetrahedron());
    case Shape::cylinder: return std::make_shared<const Mesh>(cylinder(o.segments));
    case Shape::sphere: return std::make_shared<const Mesh>(sphere(o.segments));
    case Shape::polygon:
      for (const Vec3& v : o.vertices)
        if (!isFinite(v)) throw Error("polygon vertex " + format(v) + " is not finite");
      return std::make_shared<const Mesh>(polygon(o.vertices));
    case Shape::mesh: break;
  }
  throw Error("object \"" + o.name + "\" is a mesh read from a file, not a primitive");
}

std::optional<std::string> sceneError(const Scene& scene) {
  if (auto e = cameraError(scene.camera)) return "camera: " + *e;
  for (const SceneObject& o : scene.objects) {
    if (!o.mesh) return "object \"" + o.name + "\" has no mesh";
    try {
      wcFromMc(o.transform);
    } catch (const Error& e) {
      return "object \"" + o.name + "\": " + e.what();
    }
  }
  return std::nullopt;
}

const std::string& titleIn(const Scene& scene, Language lang) {
  return lang == Language::de && !scene.titleDe.empty() ? scene.titleDe : scene.title;
}

const std::string& captionIn(const Scene& scene, Language lang) {
  return lang == Language::de && !scene.captionDe.empty() ? scene.captionDe : scene.caption;
}

const std::string& nameIn(const SceneObject& object, Language lang) {
  return lang == Language::de && !object.nameDe.empty() ? object.nameDe : object.name;
}

Scene defaultScene() {
  // The lecture scene: the lecture notes' cube and tetrahedron with a cylinder and a sphere (lecture notes, chapter 16), seen
  // in perspective; the tetrahedron crosses the window's right and bottom edges and the sphere its
  // right and top edges (its farthest point, VRC z = -3.14, stays in front of B = -3.2), so every
  // view shows clipping.
  Scene s;
  s.title = "Default lecture scene";
  s.caption = "Cube, tetrahedron, cylinder and sphere (lecture notes, chapter 16) in perspective: the tetrahedron crosses the "
              "window's right and bottom edges and the sphere its right and top edges, so every view shows clipping.";
  s.titleDe = "Standard-Vorlesungsszene";
  s.captionDe = "Würfel, Tetraeder, Zylinder und Kugel (Skript, Kapitel 16) in Zentralprojektion: das Tetraeder ragt über "
                "den rechten und unteren Fensterrand, die Kugel über den rechten und oberen, so zeigt jede Ansicht Clipping.";
  s.camera = {.vrp = {0, 0, 0}, .prp = {3.0, 2.4, 7.5}, .vup = {0, 1, 0}, .window = {-2.4, 2.4, -1.8, 1.8},
              .front = 3.0, .back = -3.2, .projection = Projection::perspective};
  s.device = {640, 480};
  s.background = {0.11, 0.12, 0.15};
  s.lights = {{{6, 8, 9}, {1, 1, 1}}};

  auto add = [&](std::string name, std::string nameDe, Shape shape, Vec3 color, ModelTransform t, int segments = 32) {
    SceneObject o;
    o.name = std::move(name);
    o.nameDe = std::move(nameDe);
    o.shape = shape;
    o.color = color;
    o.transform = std::move(t);
    o.segments = segments;
    o.mesh = primitiveMesh(o);
    s.objects.push_back(std::move(o));
  };
  add("cube", "Würfel", Shape::cube, {0.86, 0.33, 0.27}, {{0, 0, 0}, {{{0, 1, 0}, 30, {}}}, {1.3, 1.3, 1.3}});
  add("tetrahedron", "Tetraeder", Shape::tetrahedron, {0.25, 0.55, 0.9}, {{2.2, -0.9, 1.1}, {}, {1.5, 1.5, 1.5}});
  add("cylinder", "Zylinder", Shape::cylinder, {0.62, 0.45, 0.85}, {{-2.3, 0.3, -0.5}, {{{1, 0, 0}, 90, {}}}, {0.5, 0.5, 1.0}}, 24);
  add("sphere", "Kugel", Shape::sphere, {0.93, 0.75, 0.3}, {{1.4, 1.0, -3.4}, {}, {0.9, 0.9, 0.9}}, 24);
  return s;
}

}  // namespace vplab
