// What the view builders (app/views/*_view.cpp) share to fill a display list: marks collected as
// the overlays have always been grouped (triangles, then lines by width and dash, then points by
// size), the scene's meshes, lights and user clip planes as batches want them, and the storage of a
// previous list, reused so that a frame of a large scene does not allocate its polygons anew.
#pragma once

#include "app/views/display_list.h"
#include "pipeline/pipeline.h"

#include <map>
#include <utility>
#include <vector>

namespace vplab::draw {

/// Storage taken from a previous display list: its PolygonSets keep their capacity for the new list.
class Recycled {
 public:
  Recycled() = default;
  /// Takes the polygon sets of `old`'s fills (in order) and clears `old`'s batches.
  explicit Recycled(DisplayList& old);
  /// `count` polygon sets, cleared, from the next fill of the old list when it had one.
  std::vector<PolygonSet> polygonSets(size_t count);

 private:
  std::vector<std::vector<PolygonSet>> sets_;
  size_t next_ = 0;
};

/// Lines, points and translucent triangles of one space, grouped as they are drawn: triangles first,
/// then lines by (width, dash) ascending, then points by size ascending. Widths and sizes are the
/// theme's; `emit` multiplies them by the text scale (lecture mode), dash lengths are not scaled.
class Marks {
 public:
  void line(const Vec3& a, const Vec3& b, const glm::vec4& color, float widthPx = 2.f, float dashPx = 0.f);
  void polyline(std::span<const Vec3> points, bool closed, const glm::vec4& color, float widthPx = 2.f,
                float dashPx = 0.f);
  void point(const Vec3& p, const glm::vec4& color, float sizePx = 10.f);
  /// A run's clipped edges by reference (RunEdges), drawn after the copied lines of their style.
  void runEdges(const RunEdges& edges, float widthPx = 2.f, float dashPx = 0.f);
  void triangle(const Vec3& a, const Vec3& b, const Vec3& c, const glm::vec4& color);
  void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const glm::vec4& color);
  bool empty() const { return lines_.empty() && points_.empty() && triangles_.empty(); }

  /// Appends the marks to `list` as batches in `space` with `depth` (none when empty). The
  /// triangles are pushed back (Triangles::pushedBack) when `pushedBack`. With Depth::xray the
  /// views emit one Marks at the end of their 3D batches: the old OverlayRenderer drew the faint
  /// hidden parts of all of its batches first, then the visible parts, so a backend that draws a run
  /// of consecutive xray batches in those two passes draws the very same pixels.
  void emit(DisplayList& list, Space space, Depth depth, float scale, bool pushedBack = false);

 private:
  struct LineGroup {
    std::vector<Vertex> segments;
    std::vector<RunEdges> runEdges;
  };
  std::map<std::pair<float, float>, LineGroup> lines_;
  std::map<float, std::vector<Vertex>> points_;
  std::vector<Vertex> triangles_;
};

/// The visible scene objects' meshes in WC (wcFromMc of each transform), in scene order. With
/// `run`: each instance names its object's ObjectRun when that run is this scene's run of it (the
/// same mesh, transform and vertex and face counts), for the volume passes' partition.
std::vector<MeshInstance> sceneMeshes(const Scene& scene, const PipelineRun* run = nullptr);

/// The lights a lit fill of the scene uses: the scene's (at most kMaxSceneLights), or one white
/// light at the scene camera's PRP when it has none. Ambient: kSceneAmbient.
inline constexpr size_t kMaxSceneLights = 4;
inline constexpr float kSceneAmbient = 0.28f;
std::vector<Light> sceneLights(const Scene& scene);

/// The light of the CPU's polygons (NPC and morph views): one white light above and to the right of
/// the observer's eye, in the observer's space. Ambient: kPolygonAmbient.
inline constexpr float kPolygonAmbient = 0.3f;
std::vector<Light> polygonLights(const ViewCamera& observer);

/// The scene's enabled user clip planes (DGL wiki) as linear forms in WC, at most kMaxUserPlanes.
std::vector<Vec4> userClipPlanes(const Scene& scene);

}  // namespace vplab::draw
