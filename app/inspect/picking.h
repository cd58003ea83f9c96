// Which vertex or camera handle lies under the mouse in a view: everything is projected with the
// view's own synthetic camera (the pipeline's matrices) and the nearest within a radius wins.
#pragma once

#include "app/views/view_camera.h"
#include "app/views/views.h"
#include "base/enum_table.h"
#include "pipeline/pipeline.h"

#include <optional>

namespace vplab {

/// A probed vertex: an object of the scene (index into scene.objects) and a vertex of its mesh.
struct Probe {
  size_t object = 0;
  uint32_t vertex = 0;
  bool operator==(const Probe&) const = default;
};

/// What can be grabbed in the world view to change the camera directly.
enum class Handle { none, vrp, prp, windowLeft, windowRight, windowBottom, windowTop, front, back };
/// The handles' labels in the views (also their ids in the UI tests' hook).
inline constexpr EnumTable<Handle, 9> kHandleNames = {
    {{Handle::none, ""}, {Handle::vrp, "VRP"}, {Handle::prp, "PRP"}, {Handle::windowLeft, "xmin"},
     {Handle::windowRight, "xmax"}, {Handle::windowBottom, "ymin"}, {Handle::windowTop, "ymax"},
     {Handle::front, "front F"}, {Handle::back, "back B"}}};
constexpr const auto& namesOf(Handle) { return kHandleNames; }

/// Where the world view's handles are, in WC: VRP, PRP, the window's edge midpoints (view plane)
/// and the centres of the front and back planes.
Vec3 handlePosition(const PipelineRun& run, Handle h);
inline constexpr Handle kHandles[] = {Handle::vrp,         Handle::prp,       Handle::windowLeft, Handle::windowRight,
                                      Handle::windowBottom, Handle::windowTop, Handle::front,      Handle::back};
inline const char* handleName(Handle h) { return nameIn(kHandleNames, h).data(); }  // a literal: NUL-terminated

/// The handle within `radiusPx` of the pixel, nearest first.
Handle pickHandle(const PipelineRun& run, const ViewCamera& view, int width, int height, Vec2 pixel, double radiusPx);

/// The space a view shows the vertices in: world (WC through an observer), camera (DC through the
/// scene camera), npc (NPC through an observer).
std::optional<Probe> pickVertex(const PipelineRun& run, ViewKind view, const ViewCamera& observer, int width, int height,
                                Vec2 pixel, double radiusPx);

/// The probed vertex in a view's space (WC, DC or NPC); nullopt when it has no position there
/// (behind the eye in NPC or DC).
std::optional<Vec3> probePosition(const PipelineRun& run, const Probe& probe, ViewKind view);

/// The front-most clipped polygon covering a DC point: (scene index of the object, face).
std::optional<std::pair<size_t, size_t>> pickFace(const PipelineRun& run, Vec2 dc);

/// Moves a handle by a mouse motion of (dx, dy) pixels in the world view, changing the camera:
/// VRP and PRP move parallel to the observer's view plane; window edges along U or V; the front
/// and back planes along N. With `aspect` (the device's W : H, "keep the aspect ratio"), a dragged
/// window edge takes the other axis along, as the panel's fields do (keepWindowAspect).
void dragHandle(Camera& camera, const PipelineRun& run, Handle h, const ViewCamera& observer, int height, Vec2 deltaPx,
                std::optional<double> aspect = std::nullopt);

/// Gives the window the aspect ratio width : height = `aspect`: after x changed, the y extent
/// follows about its centre, else the x extent. Nothing changes for an empty or inverted window.
void keepWindowAspect(ViewWindow& w, double aspect, bool xChanged);

}  // namespace vplab
