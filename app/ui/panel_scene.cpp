// The scene panel: the objects (lecture notes, chapter 16) and their modeling transforms (lecture notes 13, 15.2.1).
#include "app/ui/panels.h"
#include "app/ui/widgets.h"

#include "pipeline/clipping.h"
#include "base/error.h"
#include "io/obj_mesh.h"
#include "io/build_mesh.h"

#include <imgui_stdlib.h>

namespace vplab::ui {

void addObject(ViewerState& s, Shape shape, std::string file) {
  Scene& scene = s.doc.scene();
  SceneObject o;
  o.shape = shape;
  o.name = std::string(toString(shape)) + " " + std::to_string(scene.objects.size());
  o.file = std::move(file);
  o.segments = 24;
  o.color = {0.75, 0.75, 0.78};
  if (shape == Shape::polygon) o.vertices = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  o.transform.translate = scene.camera.vrp;  // where the camera looks
  if (shape == Shape::mesh) {  // read on the viewer's worker thread (app/document/loader.h)
    s.objectToLoad = std::move(o);
    return;
  }
  try {
    buildMesh(o, scene.path.empty() ? std::filesystem::path{} : scene.path.parent_path());
  } catch (const Error& e) {
    s.status = e.what();
    s.statusIsError = true;
    return;
  }
  scene.objects.push_back(std::move(o));
  s.selectedObject = int(scene.objects.size()) - 1;
}

namespace {

void transformEditor(ViewerState& s, SceneObject& o) {
  ModelTransform& t = o.transform;
  dragVec3(s, tr(s, "translate"), "object.translate", t.translate);
  tooltip(s, "T(translate), applied last: wcFromMc = T · R_k ⋯ R_1 · S.");
  bool uniform = t.scale.x == t.scale.y && t.scale.y == t.scale.z;
  if (uniform) {
    double k = t.scale.x;
    if (dragDouble(s, tr(s, "scale"), "object.scale", k, 0.01f)) t.scale = Vec3(k == 0 ? 1e-3 : k);
  } else {
    dragVec3(s, tr(s, "scale"), "object.scale", t.scale, 0.01f);
  }
  tooltip(s, "S(scale), applied first. 0 is refused: it would flatten the object.");
  for (size_t i = 0; i < t.rotations.size(); ++i) {
    ImGui::PushID(int(i));
    Rotation& r = t.rotations[i];
    ImGui::TextUnformatted(tr(s, "rotation {1}", {std::to_string(i + 1)}).c_str());
    ImGui::SameLine();
    const bool remove = ImGui::SmallButton(tr(s, "remove"));
    dragVec3(s, tr(s, "axis"), "object.rotation.axis", r.axis, 0.01f);
    dragDouble(s, tr(s, "deg"), "object.rotation.deg", r.deg, 0.5f, 0, 0, "%.1f");
    bool through = r.through.has_value();
    if (checkbox(tr(s, "axis through a point"), &through))
      r.through = through ? std::optional<Vec3>(t.translate) : std::nullopt;
    tooltip(s, "Rotate about the line through this point (lecture notes 13.3: translate, rotate, translate back).");
    if (r.through) dragVec3(s, tr(s, "through"), "object.rotation.through", *r.through);
    ImGui::PopID();
    if (remove) {
      t.rotations.erase(t.rotations.begin() + ptrdiff_t(i));
      break;
    }
  }
  if (ImGui::SmallButton(tr(s, "add rotation"))) t.rotations.push_back({{0, 1, 0}, 0, {}});
  tooltip(s, "Rotations act in the order listed: the first one first.");
}

void objectEditor(ViewerState& s, SceneObject& o) {
  fitLabel(tr(s, "name"));
  ImGui::InputText(tr(s, "name"), &o.name);
  checkbox(tr(s, "visible"), &o.visible);
  ImGui::SameLine();
  glm::vec3 color(o.color);  // ColorEdit3 edits floats; the scene's colours are doubles
  fitLabel(tr(s, "colour"));
  if (ImGui::ColorEdit3(tr(s, "colour"), &color.x, ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_Float))
    o.color = Vec3(color);
  if (o.shape == Shape::cylinder || o.shape == Shape::sphere) {
    int n = o.segments;
    fitLabel(tr(s, "segments"));
    if (ImGui::SliderInt(tr(s, "segments"), &n, o.shape == Shape::sphere ? 4 : 3, 128)) {
      if (o.shape == Shape::sphere) n += n % 2;
      SceneObject rebuilt = o;
      rebuilt.segments = n;
      rebuilt.mesh = primitiveMesh(rebuilt);
      o = std::move(rebuilt);
    }
    tooltip(s, "n: the number of facets around (lecture notes 16.2).");
  }
  if (o.shape == Shape::mesh) {
    const std::string file = o.obj ? tr(s, "carried in the scene") : o.file;
    const std::string faces = std::to_string(o.mesh ? o.mesh->faceCount() : 0);
    ImGui::TextDisabled("%s", tr(s, "OBJ: {1} ({2} faces)", {file, faces}).c_str());
  }
  transformEditor(s, o);
}

// User clip planes (DGL wiki, glClipPlane): kept is the half-space the normal points into.
void clipPlanesEditor(ViewerState& s) {
  std::vector<UserClipPlane>& planes = s.doc.scene().clipPlanes;
  for (size_t i = 0; i < planes.size(); ++i) {
    ImGui::PushID(int(i) + 1000);
    UserClipPlane& p = planes[i];
    checkbox("##on", &p.enabled);
    ImGui::SameLine();
    ImGui::TextUnformatted(tr(s, "plane {1}", {std::to_string(i + 1)}).c_str());
    ImGui::SameLine();
    const bool remove = ImGui::SmallButton(tr(s, "remove"));
    dragVec3(s, tr(s, "normal"), "clipplane.normal", p.normal, 0.01f);
    if (glm::length(p.normal) < 1e-9) p.normal = {1, 0, 0};
    dragVec3(s, tr(s, "point"), "clipplane.point", p.point);
    ImGui::PopID();
    if (remove) {
      planes.erase(planes.begin() + ptrdiff_t(i));
      break;
    }
  }
  if (planes.size() < size_t(kMaxUserPlanes) && ImGui::SmallButton(tr(s, "add a clip plane")))
    planes.push_back({{-1, 0, 0}, s.doc.scene().camera.vrp, true});
  tooltip(s, "Up to six planes in WC; what lies on the side the normal points to is kept. The CPU clipper and the "
             "GPU (gl_ClipDistance) apply them alike.");
}

}  // namespace

void scenePanel(ViewerState& s, FileChooser& dialog) {
  Scene& scene = s.doc.scene();
  ImGui::TextDisabled("%s", tr(s, "objects"));
  if (ImGui::BeginListBox("##objects", ImVec2(-1, ImGui::GetTextLineHeightWithSpacing() * 5.5f))) {
    for (size_t i = 0; i < scene.objects.size(); ++i) {
      const SceneObject& o = scene.objects[i];
      const std::string& name = nameIn(o, s.display.language);
      const std::string label = (o.visible ? name : tr(s, "(hidden) {1}", {name})) + "##" + std::to_string(i);
      if (ImGui::Selectable(label.c_str(), s.selectedObject == int(i))) s.selectedObject = int(i);
    }
    ImGui::EndListBox();
  }
  if (ImGui::Button(tr(s, "+ cube"))) addObject(s, Shape::cube);
  sameLineIfFits(tr(s, "+ tetrahedron"));
  if (ImGui::Button(tr(s, "+ tetrahedron"))) addObject(s, Shape::tetrahedron);
  sameLineIfFits(tr(s, "+ cylinder"));
  if (ImGui::Button(tr(s, "+ cylinder"))) addObject(s, Shape::cylinder);
  if (ImGui::Button(tr(s, "+ sphere"))) addObject(s, Shape::sphere);
  sameLineIfFits(tr(s, "+ polygon"));
  if (ImGui::Button(tr(s, "+ polygon"))) addObject(s, Shape::polygon);
  sameLineIfFits(tr(s, "+ OBJ mesh file"));
  if (ImGui::Button(tr(s, "+ OBJ mesh file")))
    dialog.open(tr(s, "Load an OBJ mesh###Load an OBJ mesh"), FileChooser::Mode::open, {".obj"},
                scene.path.parent_path(),
                [&s](const std::filesystem::path& file) {
                  // Relative to the scene file where there is one, as the scene format expects.
                  const std::filesystem::path base = s.doc.scene().path.parent_path();
                  std::error_code ec;
                  const std::filesystem::path rel = base.empty() ? file : std::filesystem::relative(file, base, ec);
                  addObject(s, Shape::mesh, (ec || rel.empty() ? file : rel).string());
                });
  if (scene.objects.empty()) {
    section(tr(s, "user clip planes (DGL wiki)"));
    clipPlanesEditor(s);
    return;
  }
  s.selectedObject = std::clamp(s.selectedObject, 0, int(scene.objects.size()) - 1);
  ImGui::Separator();
  ImGui::PushID(s.selectedObject);
  objectEditor(s, scene.objects[size_t(s.selectedObject)]);
  ImGui::PopID();
  if (ImGui::Button(tr(s, "remove this object"))) {
    scene.objects.erase(scene.objects.begin() + s.selectedObject);
    s.probe.reset();
  }
  scrollAnchor(s, "scene.clipPlanes");
  section(tr(s, "user clip planes (DGL wiki)"));
  clipPlanesEditor(s);
}

}  // namespace vplab::ui
