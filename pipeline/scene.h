// A scene: the synthetic camera, the device, and objects built from primitives in MC, each placed in
// WC by its modeling transform (lecture notes 15.2.1). Plain data; scene_io.h reads and writes it as JSON.
#pragma once

#include "pipeline/camera.h"
#include "base/enum_table.h"
#include "base/language.h"
#include "pipeline/device_mapping.h"
#include "pipeline/mesh.h"
#include "pipeline/modeling.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace vplab {

enum class Shape { cube, tetrahedron, cylinder, sphere, polygon, mesh };
/// The scene format's "shape".
inline constexpr EnumTable<Shape, 6> kShapeNames = {{{Shape::cube, "cube"},         {Shape::tetrahedron, "tetrahedron"},
                                                     {Shape::cylinder, "cylinder"}, {Shape::sphere, "sphere"},
                                                     {Shape::polygon, "polygon"},   {Shape::mesh, "mesh"}}};
constexpr const auto& namesOf(Shape) { return kShapeNames; }

struct SceneObject {
  std::string name;              // its name in files, lessons and links (the scene format's "name")
  std::string nameDe;            // shown in a German viewer ("name_de"); empty: the name
  Shape shape = Shape::cube;
  int segments = 32;             // cylinder and sphere
  std::vector<Vec3> vertices;    // polygon, MC
  std::string file;              // mesh: an OBJ file, relative to the scene file
  /// mesh: or the OBJ text itself, carried by the scene (one file for the page's meshes); shared,
  /// as the mesh is, so that undo steps do not copy it. Null: none.
  std::shared_ptr<const std::string> obj;
  Vec3 color{0.8, 0.8, 0.8};     // 0..1
  ModelTransform transform;      // MC → WC
  bool visible = true;
  std::shared_ptr<const Mesh> mesh;  // built from the fields above by buildMesh
  bool operator==(const SceneObject&) const = default;  // meshes compare by identity
};

/// A point light in WC for the shaded style.
struct Light {
  Vec3 position{5, 5, 5};
  Vec3 color{1, 1, 1};
  bool operator==(const Light&) const = default;
};

/// A user clip plane in WC (DGL wiki, glClipPlane): the half-space n·(x − point) ≥ 0 is kept.
struct UserClipPlane {
  Vec3 normal{1, 0, 0};
  Vec3 point{0, 0, 0};
  bool enabled = true;
  /// (a, b, c, d) with a·x + b·y + c·z + d ≥ 0 inside: (n, −n·point).
  Vec4 coefficients() const { return {normal, -glm::dot(normal, point)}; }
  bool operator==(const UserClipPlane&) const = default;
};

struct Scene {
  std::string title;    // a preset's name, shown in the viewer's menu and title
  std::string caption;  // one or two sentences on the idea the scene shows
  std::string titleDe, captionDe;  // the same in German ("title_de", "caption_de"); empty: the above
  Camera camera;
  Device device;
  Vec3 background{0.12, 0.12, 0.14};
  std::vector<SceneObject> objects;
  std::vector<Light> lights;       // empty: one light at the eye
  std::vector<UserClipPlane> clipPlanes;  // at most 6 (kMaxUserPlanes)
  std::filesystem::path path;      // where it was loaded from; empty for the built-in scene
  bool operator==(const Scene&) const = default;
};

/// The MC mesh of a primitive object (every shape but Shape::mesh, whose faces are read from a file
/// by io/build_mesh.h). Throws vplab::Error naming the value for a shape's invalid parameters. The
/// size is not checked against a file's limits here: io's buildMesh does that before calling this.
std::shared_ptr<const Mesh> primitiveMesh(const SceneObject& object);

/// Why the scene cannot be run (an invalid camera, an object's invalid transform, a missing mesh),
/// naming the values; nullopt when it can.
std::optional<std::string> sceneError(const Scene& scene);

/// The words a viewer shows in `lang` (docs/formats.md "Scene format": a scene speaks the lecture's German
/// beside its own language): the German ones when asked for and given, else those as written.
const std::string& titleIn(const Scene& scene, Language lang);
const std::string& captionIn(const Scene& scene, Language lang);
const std::string& nameIn(const SceneObject& object, Language lang);

/// The built-in default lecture scene (also assets/scenes/default.json).
Scene defaultScene();

}  // namespace vplab
