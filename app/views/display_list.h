// One description of each view, as data: what is drawn, in which space, in which order (as Dear
// ImGui's ImDrawList is for its windows). The views (app/views/*_view.cpp) build display lists from
// the scene, the CPU pipeline's run and the settings; the backends only draw them:
//   app/render/gl_backend.h   desktop GL 3.3 core and, from the same shaders, GLSL ES 3.00 (WebGL2)
//   app/export/svg.h          SVG documents
// A backend decides nothing about what is drawn: colours, widths in pixels, dashes, what is hidden
// and how (Depth), the labels' places, the order, all are here. It only decides how: a GL backend
// with a depth buffer, the SVG backend with the CPU's visibility (app/views/hidden_lines.h).
//
// No GL, no ImGui: this layer builds without either (tests/architecture checks it).
#pragma once

#include "app/views/labels.h"
#include "app/views/view_camera.h"
#include "base/enum_table.h"
#include "pipeline/memory_use.h"
#include "pipeline/mesh.h"
#include "pipeline/scene.h"

#include <glm/glm.hpp>

#include <memory>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace vplab {
struct ObjectRun;
}

namespace vplab::draw {

/// The space a batch's coordinates are in. A view looks at one 3D space through its observer
/// (DisplayList::observer); its overlays of text and marks are in its pixels.
enum class Space {
  wc,      // world coordinates (the world view)
  npc,     // normalized projection coordinates, the unit cube (the NPC view)
  dc,      // device coordinates of the scene's device, y down (the camera view)
  morph,   // the stage morph's space of the moment (pipeline/stage_morph.h)
  pixels,  // the view's own pixels: origin top-left, x right, y down
};
inline constexpr EnumTable<Space, 5> kSpaceNames = {
    {{Space::wc, "WC"}, {Space::npc, "NPC"}, {Space::dc, "DC"}, {Space::morph, "morph"}, {Space::pixels, "pixels"}}};
constexpr const auto& namesOf(Space) { return kSpaceNames; }

/// How a view's 3D space reaches its pixels: a synthetic camera of the pipeline itself
/// (vrcFromWc, npcFromVrc; "WC" meaning the space looked at), then the view's device mapping.
struct Observer {
  Space space = Space::wc;
  ViewCamera camera;
};

/// What becomes of the parts of a line, point or translucent triangle hidden behind the filled
/// faces drawn before it (those that write depth).
enum class Depth {
  ignore,      // drawn whole, over everything
  test,        // the hidden parts are not drawn
  hiddenOnly,  // only the hidden parts are drawn (hidden-line style: the dashed hidden edges)
  xray,        // the hidden parts faint (alpha × kXrayAlpha), the visible parts as they are
};
/// The x-ray's alpha factor for hidden parts (camera markers inside objects stay visible).
inline constexpr float kXrayAlpha = 0.3f;

/// A scene object's mesh, by reference (a 1M-triangle mesh is not copied into every frame's list).
struct MeshInstance {
  std::shared_ptr<const Mesh> mesh;
  Mat4 spaceFromMc{1.0};       // MC → the batch's space (wcFromMc for the scene's objects)
  glm::vec4 color{1, 1, 1, 1};
  /// The CPU pipeline's run of this object when `Fill::volume` is that run's camera (world view):
  /// lets a backend skip faces that lie wholly inside or outside the volume. Null: none. Points into
  /// the run the list was built from, which must outlive the list.
  const ObjectRun* run = nullptr;
};

/// Polygons made on the CPU (the clipper's output), all of one colour: in flat arrays (polygon i is
/// points[ends[i − 1] .. ends[i])), or by reference to a run's faces in NPC, read when drawn (the
/// NPC view of a million triangles copies 4 MB of face numbers instead of 72 MB of points, and a
/// backend can share the run's vertices between the faces that meet at them).
struct PolygonSet {
  glm::vec3 color{1, 1, 1};
  std::vector<Vec3> points;
  std::vector<uint32_t> ends;
  /// Set: polygon i is a face of this run in NPC: clipped face faces[i] (ObjectRun::clippedFace), or
  /// with `wholeFaces` mesh face faces[i] as it is (one whose corners all lie in front of the eye,
  /// w > 0: the NPC view's faded faces inside its grown cube). Either way its corners are
  /// references into the run's vertices, mesh vertices first and then those clipping created
  /// (ObjectRun::clippedNpc(ref), divided by w). Points into the run the list was built from, which
  /// must outlive the list.
  const ObjectRun* npcOf = nullptr;
  bool wholeFaces = false;
  std::vector<uint32_t> faces;

  void add(std::span<const Vec3> polygon) {
    points.insert(points.end(), polygon.begin(), polygon.end());
    ends.push_back(uint32_t(points.size()));
  }
  size_t polygonCount() const { return npcOf ? faces.size() : ends.size(); }
  size_t polygonSize(size_t i) const { return npcOf ? refs(i).size() : ends[i] - (i ? ends[i - 1] : 0); }
  /// Polygon i's corners as references into npcOf's vertices (npcOf set only).
  std::span<const uint32_t> refs(size_t i) const;
  /// Polygon i's points: in `points`, or (npcOf) worked out into `scratch`.
  std::span<const Vec3> polygon(size_t i, std::vector<Vec3>& scratch) const;
  void clear() {
    points.clear();
    ends.clear();
    npcOf = nullptr;
    wholeFaces = false;
    faces.clear();
  }
};

/// Which part of the filled faces a fill keeps, by another camera's boundary coordinates (Hill 7.4):
/// the world view shows what lies inside the scene camera's view volume solid, the rest faded.
struct VolumeTest {
  enum class Keep { all, inside, outside };
  Keep keep = Keep::all;
  Mat4 npcFromSpace{1.0};  // that camera's homogeneous NPC of the batch's space
};

/// Filled faces: lit (Blinn–Phong, lecture notes 13.5) or flat in their colour.
struct Fill {
  Space space = Space::wc;
  std::vector<MeshInstance> meshes;
  std::vector<PolygonSet> polygons;  // normals: each polygon's plane's (Newell's; GL: the fragment's derivatives)
  bool lit = false;
  std::vector<Light> lights;  // in the batch's space; the viewer's eye is the observer's
  float ambient = 0.28f;
  float alpha = 1.f;          // < 1: blended over what is behind, without writing depth
  /// Hidden-line styles (lecture notes 16.1): fills only the depth buffer, pushed back by
  /// glPolygonOffset(1, 2) so the faces' own edges in front of it pass the depth test.
  bool depthOnly = false;
  VolumeTest volume;
  std::vector<Vec4> clipPlanes;  // user clip planes in the batch's space (DGL wiki): p · x ≥ 0 kept
};

struct Vertex {
  Vec3 position;
  glm::vec4 color;
};

/// A run's clipped edges by reference (the world and NPC views' wireframes: a million edges are not
/// copied into each frame's list as 120–160 MB of segments, issue 42): edge i of `run` from a to b,
/// whole or only its visible part [t0, t1] (EdgeRange; none when it is not visible), in `color`; in
/// the space of the Lines that hold it (WC: wc(a) to wc(b); NPC: clipped where the strategy clips,
/// then divided by w). Points into the run the list was built from, which must outlive the list.
struct RunEdges {
  const ObjectRun* run = nullptr;
  glm::vec4 color{1, 1, 1, 1};
  bool visiblePart = true;  // false: every edge whole
  /// NPC only, instead: the edges with an end outside (outcode ≠ 0: every face they bound was cut or
  /// rejected), as far as they lie in the cube grown by geometry::kFadedMargin (which keeps w > 0),
  /// whole: the outlines of what clipping cut away, each edge once.
  bool fadedPart = false;
  size_t count() const;     // the run's edges with their ranges
};

/// Wide lines with a one-pixel smooth edge, solid or dashed (dashPx on, dashPx off, measured in
/// pixels from each segment's start).
struct Lines {
  Space space = Space::wc;
  std::vector<Vertex> segments;        // segment i: segments[2i] → segments[2i + 1]
  std::vector<RunEdges> runEdges;      // then these, segment by segment (WC or NPC)
  std::vector<MeshInstance> meshEdges; // every edge of these meshes, in their colour
  float widthPx = 2.f;
  float dashPx = 0.f;
  Depth depth = Depth::ignore;
  std::vector<Vec4> clipPlanes;        // user clip planes in the batch's space, for meshEdges
  void line(const Vec3& a, const Vec3& b, const glm::vec4& color) {
    segments.push_back({a, color});
    segments.push_back({b, color});
  }
  void polyline(std::span<const Vec3> points, bool closed, const glm::vec4& color);
  /// The segments: its own, then the runs' edges (an edge not visible counts, and draws nothing).
  size_t segmentCount() const;
  /// Appends the end points of segments [first, end) that draw something to `out` (two a segment),
  /// working out the runs' edges as the world view did when it copied them.
  void segmentsInto(size_t first, size_t end, std::vector<Vertex>& out) const;
};

/// Round markers sizePx across with a dark rim.
struct Points {
  Space space = Space::wc;
  std::vector<Vertex> points;
  float sizePx = 10.f;
  Depth depth = Depth::ignore;
};

/// Translucent triangles in their vertices' colours (the window, the frustum's faces, clip planes).
struct Triangles {
  Space space = Space::wc;
  std::vector<Vertex> vertices;  // triangle i: vertices[3i .. 3i + 2]
  Depth depth = Depth::ignore;
  /// Pushed back by glPolygonOffset(1, 2): loses every depth tie (the NPC cube's front face, in
  /// z = 1 where clipping puts the cut faces).
  bool pushedBack = false;
  void triangle(const Vec3& a, const Vec3& b, const Vec3& c, const glm::vec4& color) {
    vertices.insert(vertices.end(), {{a, color}, {b, color}, {c, color}});
  }
  void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const glm::vec4& color) {
    triangle(a, b, c, color);
    triangle(a, c, d, color);
  }
};

/// Labels placed in the view's pixels (labels.h placed them, once, for every backend).
struct Text {
  std::vector<PlacedLabel> labels;
  glm::vec3 outline{0, 0, 0};  // the colour of the labels' outline (PlacedLabel::shadow): the theme's ground's opposite
};

using Batch = std::variant<Fill, Lines, Points, Triangles, Text>;

/// One view: cleared to `background`, then its batches in order.
struct DisplayList {
  int width = 0, height = 0;  // pixels
  glm::vec3 background{0, 0, 0};
  Observer observer;
  /// Multisampled in GL (the world, NPC and morph views); the camera view is pixel-aligned with DC.
  bool antialiased = false;
  std::vector<Batch> batches;

  template <class B>
  B& add(B batch) {
    batches.emplace_back(std::move(batch));
    return std::get<B>(batches.back());
  }
  /// The labels of every Text batch (for the tests: where each went).
  std::vector<PlacedLabel> labels() const;
};

/// The list's heap bytes by kind of batch (`vplab bench --memory`): meshes by reference count only
/// their instances, polygons by reference only their face numbers.
MemoryUse memoryUse(const DisplayList& list);

/// A picture of one or more views: the "all" composition is three panels and a title strip.
struct Panel {
  int x = 0, y = 0;  // the panel's top-left corner in the picture's pixels
  DisplayList list;
};
struct Picture {
  int width = 0, height = 0;
  glm::vec3 background{0, 0, 0};  // between the panels
  std::vector<Panel> panels;
};

}  // namespace vplab::draw
