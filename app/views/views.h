// The views that make the pipeline visible (docs/lecturers.md "The views"):
//   camera  what the synthetic camera sees, W × H pixels, pixel-aligned with DC
//   world   an orbiting observer's view of the scene, the camera (VRP, PRP, VUP, U, V, N), the view
//           plane's window and the frustum; what lies outside the view volume is faded and the
//           edges clipping created are highlighted
//   npc     the unit cube of NPC with the scene after view mapping, clipping and division
//   all     the three side by side, with titles (for slides and tests)
//   morph   the stage morph: the visible scene moving from MC through WC, VRC and NPC to DC
//   divide-first  what the wrong strategy draws: the divide-first run's clipped polygons in DC, flat
//           (the Clipping lesson's comparison beside the camera view; Hill 7.4)
//   depth-plot    NPC z and GL's window depth against VRC z between B and F, and the objects'
//           depth ranges (lecture notes 15.2.4; the inspector's Depth tab)
#pragma once

#include "app/views/display_list.h"
#include "app/views/labels.h"
#include "app/views/observer.h"
#include "app/views/theme.h"
#include "base/enum_table.h"
#include "base/language.h"
#include "pipeline/pipeline.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

enum class ViewKind { camera, world, npc, all, morph, divideFirst, depth };
/// The command line's --view, links' views.
inline constexpr EnumTable<ViewKind, 7> kViewKindNames = {
    {{ViewKind::camera, "camera"}, {ViewKind::world, "world"}, {ViewKind::npc, "npc"}, {ViewKind::all, "all"},
     {ViewKind::morph, "morph"}, {ViewKind::divideFirst, "divide-first"}, {ViewKind::depth, "depth-plot"}}};
inline constexpr size_t kViewKindCount = std::size(kViewKindNames);
constexpr const auto& namesOf(ViewKind) { return kViewKindNames; }

/// flat: each object's colour, unlit. shaded: lit by the scene's lights. wire: every edge.
/// hiddenLine: visible edges solid, hidden ones dashed (lecture notes figure 16.1). hiddenRemoved: only the
/// visible edges (lecture notes figure 16.3).
enum class Style { flat, shaded, wire, hiddenLine, hiddenRemoved };
inline constexpr EnumTable<Style, 5> kStyleNames = {{{Style::flat, "flat"}, {Style::shaded, "shaded"}, {Style::wire, "wire"},
                                                     {Style::hiddenLine, "hidden-line"},
                                                     {Style::hiddenRemoved, "hidden-removed"}}};
constexpr const auto& namesOf(Style) { return kStyleNames; }
inline bool isFilled(Style s) { return s == Style::flat || s == Style::shaded; }

struct OverlaySettings {
  bool frustum = true;       // world: front and back planes, edges from PRP
  bool viewPlane = true;     // world: the window in the view plane
  bool cameraAxes = true;    // world: VRP, PRP, VUP and U, V, N
  bool labels = true;        // names next to points and axes, view titles
  bool fadeOutside = true;   // world and NPC: what lies outside the view volume, faded
  bool newEdges = true;      // world and NPC: edges created by clipping, highlighted
  bool cube = true;          // NPC: the unit cube and its axes
  bool cpuPolygons = false;  // camera: the CPU clipper's DC polygons over the GPU image
  bool difference = false;   // camera: where the GPU image and the CPU raster differ
  bool vanishingPoints = false;  // camera: the selected object's vanishing points and lines (lecture notes 14.2)
  bool vertexNames = false;      // world and NPC: the polygons' vertices named P1 … Pn (as the exercise sheets do)
  bool operator==(const OverlaySettings&) const = default;
};

struct ViewSettings {
  Style style = Style::shaded;
  Orbit orbit;  // world and NPC views only
  bool operator==(const ViewSettings&) const = default;
};

/// Interactive marks, worked out from the interaction each frame and drawn over the views: the
/// probed vertex in each view's space, the world view's camera handles, the clipping step-through,
/// the object whose vanishing points are shown. They are not display settings: never saved, linked
/// or given to `vplab render` (a RenderRequest has none unless the viewer passes its own).
struct Highlights {
  std::optional<Vec3> probeWc, probeNpc, probeDc;
  struct HandleMark {
    Vec3 wc;
    std::string name;
    bool hot;  // under the mouse or being dragged
    bool operator==(const HandleMark&) const = default;
  };
  std::vector<HandleMark> handles;
  /// The clipping step-through: the polygon after the current step (NPC), which of its vertices
  /// that step created, and the plane it applied (−1: none yet).
  struct Step {
    std::vector<Vec3> polygonNpc;
    std::vector<bool> created;
    int plane = -1;
    bool operator==(const Step&) const = default;
  };
  std::optional<Step> step;
  /// A lesson step's highlights (app/lessons/lesson.h): planes (0–5 the view volume's, left, right,
  /// bottom, top, back, front; 6 + k the scene's user clip plane k) and axes of VRC (0 U, 1 V, 2 N).
  std::vector<int> planes;
  std::vector<int> axes;
  int vanishingObject = -1;  // scene index of the object whose vanishing points are drawn
  /// An exercise's numbers as the student gave them (app/practice/practice_marks.h), drawn in the
  /// student's colour beside the lab's: points as rings, polygons and the view volume dashed.
  struct Student {
    std::vector<Vec3> pointsWc;   // their P1 in WC, and their P1 in VRC placed in WC by the lab's wcFromVrc
    std::vector<Vec3> pointsNpc;  // their P1 in NPC (their homogeneous NPC divided by their w)
    std::vector<Vec3> pointsDc;   // their P1 in DC
    std::vector<Vec3> labWc, labNpc, labDc;  // the lab's P1, shown only when the exercise reveals values
    std::vector<Vec3> polygonWc;  // the polygon placed in WC by their wcFromMc
    std::vector<Vec3> polygonNpc; // their polygon after a Sutherland–Hodgman pass, divided by their w
    std::vector<Vec3> polygonDc;  // their clipped polygon in DC
    std::vector<Vec3> volumeWc;   // their view volume: the NPC cube's corners (cubeCorner order) by their matrices
    bool operator==(const Student&) const = default;
    bool empty() const { return *this == Student{}; }
  };
  Student student;
  bool operator==(const Highlights&) const = default;
};

/// The stage morph (pipeline/stage_morph.h): t from 0 (MC) to 4 (DC), and the observer's angles
/// (its distance and target follow the morphing scene so it stays framed).
struct MorphSettings {
  double t = 0;
  Orbit orbit{{0, 0, 0}, 30, 22, 10, 40};
  bool operator==(const MorphSettings&) const = default;
};

/// How the views show the scene, as the user set it: each view's style and observer, the morph, the
/// overlays. Kept with the session and carried by a link (app/document/url_state.h).
struct DisplaySettings {
  ViewSettings camera{Style::flat, {}};
  ViewSettings world{Style::shaded, {}};
  ViewSettings npc{Style::shaded, defaultNpcOrbit()};
  ViewSettings morph{Style::shaded, {}};
  MorphSettings morphing;
  OverlaySettings overlays;
  Theme theme = Theme::dark;            // app/views/theme.h: the screen's, or light for print and bright halls
  Language language = Language::en;     // of the labels in the views (the viewer's, a sheet's)
  // Equal settings (and highlights) draw equal views (the viewer reuses a view's last image,
  // app/render/view_images.h).
  bool operator==(const DisplaySettings&) const = default;
};

/// What a view is built from. `run` is the CPU pipeline's run of `scene` (with clipEdges for the
/// wireframe styles); the display lists built point into both, which must outlive them.
struct ViewInput {
  const Scene& scene;
  const PipelineRun& run;
  const DisplaySettings& settings;  // the user's: styles, observers, overlays, the morph (kept, linked)
  const Highlights& highlights;     // this frame's marks, worked out from the interaction (never kept)
  int width = 0, height = 0;  // each view's pixels (ViewKind::all: each of its three panels)
  const TextMetrics& text;    // measures the labels; its scale() grows text, lines and markers
};

/// Each view as a display list, a pure function of its input (app/views/<view>_view.cpp). Every
/// batch is in the observer's space or in the view's pixels: the camera view looks at WC through
/// the scene camera (its DC overlays are in pixels, DC scaled to the view's size), the world view
/// at WC, the NPC view at NPC and the morph view at the morph's space, each through its orbit.
draw::DisplayList cameraView(const ViewInput& in);
draw::DisplayList worldView(const ViewInput& in);
draw::DisplayList npcView(const ViewInput& in);
draw::DisplayList morphView(const ViewInput& in);

/// The same, built into `out` (overwritten), reusing its storage where it can: the NPC and morph
/// views' polygon arrays keep their capacity from frame to frame.
void cameraView(const ViewInput& in, draw::DisplayList& out);
void worldView(const ViewInput& in, draw::DisplayList& out);
void npcView(const ViewInput& in, draw::DisplayList& out);
void morphView(const ViewInput& in, draw::DisplayList& out);

/// The divide-first comparison (app/views/divide_first_view.cpp): what the wrong strategy draws,
/// the clipped polygons of `in.run`, which must be a run of ClipStrategy::divideFirst (else
/// std::invalid_argument), each object's flat colour, on the scene's background. One unlit Fill in
/// Space::dc (the run's DC), seen through the device mapping undone (observer: npcFromDc, so DC
/// fills in.width × in.height and z_dc is the depth: the nearer, larger z_dc wins, the first
/// polygon drawn keeping a tie), as the CPU raster (app/export/cpu_raster.h) fills them.
draw::DisplayList divideFirstView(const ViewInput& in);
void divideFirstView(const ViewInput& in, draw::DisplayList& out);

/// The picture of a view kind: one panel, or for ViewKind::all the camera, world and NPC views side
/// by side under a strip of titles. `out` is overwritten; its storage is reused where it can be
/// (a frame of the 1M-triangle scene's NPC view is not allocated anew).
void buildPicture(ViewKind kind, const ViewInput& in, draw::Picture& out);
draw::Picture buildPicture(ViewKind kind, const ViewInput& in);

}  // namespace vplab
