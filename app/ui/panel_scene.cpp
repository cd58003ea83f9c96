// The scene panel: the objects (lecture notes, chapter 16) and their modeling transforms (lecture notes 13, 15.2.1).
#include "app/ui/panels.h"
#include "app/ui/widgets.h"
#include "app/session/session.h"

#include "pipeline/clipping.h"
#include "base/error.h"
#include "io/obj_mesh.h"
#include "io/build_mesh.h"

#include <imgui_stdlib.h>

namespace vplab::ui {

namespace {

void transformEditor(Widgets& w, SceneObject& o) {
  ModelTransform& t = o.transform;
  dragVec3(w, tr(w, "translate"), "object.translate", t.translate);
  tooltip(w, "T(translate), applied last: wcFromMc = T · R_k ⋯ R_1 · S.");
  bool uniform = t.scale.x == t.scale.y && t.scale.y == t.scale.z;
  if (uniform) {
    double k = t.scale.x;
    if (dragDouble(w, tr(w, "scale"), "object.scale", k, 0.01f)) t.scale = Vec3(k == 0 ? 1e-3 : k);
  } else {
    dragVec3(w, tr(w, "scale"), "object.scale", t.scale, 0.01f);
  }
  tooltip(w, "S(scale), applied first. 0 is refused: it would flatten the object.");
  for (size_t i = 0; i < t.rotations.size(); ++i) {
    ImGui::PushID(int(i));
    Rotation& r = t.rotations[i];
    ImGui::TextUnformatted(tr(w, "rotation {1}", {std::to_string(i + 1)}).c_str());
    ImGui::SameLine();
    const bool remove = ImGui::SmallButton(tr(w, "remove"));
    dragVec3(w, tr(w, "axis"), "object.rotation.axis", r.axis, 0.01f);
    dragDouble(w, tr(w, "deg"), "object.rotation.deg", r.deg, 0.5f, 0, 0, "%.1f");
    bool through = r.through.has_value();
    if (checkbox(tr(w, "axis through a point"), &through))
      r.through = through ? std::optional<Vec3>(t.translate) : std::nullopt;
    tooltip(w, "Rotate about the line through this point (lecture notes 13.3: translate, rotate, translate back).");
    if (r.through) dragVec3(w, tr(w, "through"), "object.rotation.through", *r.through);
    ImGui::PopID();
    if (remove) {
      t.rotations.erase(t.rotations.begin() + ptrdiff_t(i));
      break;
    }
  }
  if (ImGui::SmallButton(tr(w, "add rotation"))) t.rotations.push_back({{0, 1, 0}, 0, {}});
  tooltip(w, "Rotations act in the order listed: the first one first.");
}

void objectEditor(Widgets& w, SceneObject& o) {
  fitLabel(tr(w, "name"));
  ImGui::InputText(tr(w, "name"), &o.name);
  checkbox(tr(w, "visible"), &o.visible);
  ImGui::SameLine();
  glm::vec3 color(o.color);  // ColorEdit3 edits floats; the scene's colours are doubles
  fitLabel(tr(w, "colour"));
  if (ImGui::ColorEdit3(tr(w, "colour"), &color.x, ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_Float))
    o.color = Vec3(color);
  if (o.shape == Shape::cylinder || o.shape == Shape::sphere) {
    int n = o.segments;
    // A typed value is held to the slider's range too: Ctrl+click lets one type "99999999999", which
    // ImGui reads as 1215752192 (the monkey test, seed 37). A scene's larger count (the 1024-segment
    // sphere) is shown as it is until the slider is moved (the meshes of up to 128 are built at once).
    const int lo = o.shape == Shape::sphere ? 4 : 3, hi = 128;
    fitLabel(tr(w, "segments"));
    if (ImGui::SliderInt(tr(w, "segments"), &n, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp)) {
      n = std::clamp(n, lo, hi);
      if (o.shape == Shape::sphere) n += n % 2;  // hi is even for a sphere
      SceneObject rebuilt = o;
      rebuilt.segments = n;
      rebuilt.mesh = primitiveMesh(rebuilt);
      o = std::move(rebuilt);
    }
    tooltip(w, "n: the number of facets around (lecture notes 16.2).");
  }
  if (o.shape == Shape::mesh) {
    const std::string file = o.obj ? tr(w, "carried in the scene") : o.file;
    const std::string faces = std::to_string(o.mesh ? o.mesh->faceCount() : 0);
    ImGui::TextDisabled("%s", tr(w, "OBJ: {1} ({2} faces)", {file, faces}).c_str());
  }
  transformEditor(w, o);
}

// User clip planes (DGL wiki, glClipPlane): kept is the half-space the normal points into.
void clipPlanesEditor(Widgets& w, DocumentPart& d) {
  std::vector<UserClipPlane>& planes = d.doc.scene().clipPlanes;
  for (size_t i = 0; i < planes.size(); ++i) {
    ImGui::PushID(int(i) + 1000);
    UserClipPlane& p = planes[i];
    checkbox("##on", &p.enabled);
    ImGui::SameLine();
    ImGui::TextUnformatted(tr(w, "plane {1}", {std::to_string(i + 1)}).c_str());
    ImGui::SameLine();
    const bool remove = ImGui::SmallButton(tr(w, "remove"));
    dragVec3(w, tr(w, "normal"), "clipplane.normal", p.normal, 0.01f);
    if (glm::length(p.normal) < 1e-9) p.normal = {1, 0, 0};
    dragVec3(w, tr(w, "point"), "clipplane.point", p.point);
    ImGui::PopID();
    if (remove) {
      planes.erase(planes.begin() + ptrdiff_t(i));
      break;
    }
  }
  if (planes.size() < size_t(kMaxUserPlanes) && ImGui::SmallButton(tr(w, "add a clip plane")))
    planes.push_back({{-1, 0, 0}, d.doc.scene().camera.vrp, true});
  tooltip(w, "Up to six planes in WC; what lies on the side the normal points to is kept. The CPU clipper and the "
             "GPU (gl_ClipDistance) apply them alike.");
}

}  // namespace

void scenePanel(Widgets& w, DocumentPart& d, EditPart& e, StatusPart& st, FileChooser& dialog) {
  Scene& scene = d.doc.scene();
  ImGui::TextDisabled("%s", tr(w, "objects"));
  if (ImGui::BeginListBox("##objects", ImVec2(-1, ImGui::GetTextLineHeightWithSpacing() * 5.5f))) {
    for (size_t i = 0; i < scene.objects.size(); ++i) {
      const SceneObject& o = scene.objects[i];
      const std::string& name = nameIn(o, w.language());
      const std::string label = (o.visible ? name : tr(w, "(hidden) {1}", {name})) + "##" + std::to_string(i);
      if (ImGui::Selectable(label.c_str(), e.selectedObject == int(i))) e.selectedObject = int(i);
    }
    ImGui::EndListBox();
  }
  if (ImGui::Button(tr(w, "+ cube"))) addObject(d, e, st, Shape::cube);
  sameLineIfFits(tr(w, "+ tetrahedron"));
  if (ImGui::Button(tr(w, "+ tetrahedron"))) addObject(d, e, st, Shape::tetrahedron);
  sameLineIfFits(tr(w, "+ cylinder"));
  if (ImGui::Button(tr(w, "+ cylinder"))) addObject(d, e, st, Shape::cylinder);
  if (ImGui::Button(tr(w, "+ sphere"))) addObject(d, e, st, Shape::sphere);
  sameLineIfFits(tr(w, "+ polygon"));
  if (ImGui::Button(tr(w, "+ polygon"))) addObject(d, e, st, Shape::polygon);
  sameLineIfFits(tr(w, "+ OBJ mesh file"));
  if (ImGui::Button(tr(w, "+ OBJ mesh file")))
    dialog.open(tr(w, "Load an OBJ mesh###Load an OBJ mesh"), FileChooser::Mode::open, {".obj"},
                scene.path.parent_path(),
                [&d, &e, &st](const std::filesystem::path& file) {
                  // Relative to the scene file where there is one, as the scene format expects.
                  const std::filesystem::path base = d.doc.scene().path.parent_path();
                  std::error_code ec;
                  const std::filesystem::path rel = base.empty() ? file : std::filesystem::relative(file, base, ec);
                  addObject(d, e, st, Shape::mesh, (ec || rel.empty() ? file : rel).string());
                });
  if (scene.objects.empty()) {
    section(tr(w, "user clip planes (DGL wiki)"));
    clipPlanesEditor(w, d);
    return;
  }
  e.selectedObject = std::clamp(e.selectedObject, 0, int(scene.objects.size()) - 1);
  ImGui::Separator();
  ImGui::PushID(e.selectedObject);
  objectEditor(w, scene.objects[size_t(e.selectedObject)]);
  ImGui::PopID();
  if (ImGui::Button(tr(w, "remove this object"))) {
    scene.objects.erase(scene.objects.begin() + e.selectedObject);
    e.probe.reset();
  }
  scrollAnchor(w, "scene.clipPlanes");
  section(tr(w, "user clip planes (DGL wiki)"));
  clipPlanesEditor(w, d);
}

}  // namespace vplab::ui
