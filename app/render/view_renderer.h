// Draws the views (views.h) into render targets: the filled scene through the GLSL path with the
// pipeline's matrices, the overlays from the CPU pipeline's run. One instance per GL context; it
// owns the programs, the meshes on the GPU and the targets.
#pragma once

#include "app/context/context.h"
#include "app/gl/render_target.h"
#include "app/gl/shader.h"
#include "app/render/gpu_mesh.h"
#include "app/render/overlay.h"
#include "app/render/text.h"
#include "app/views/view_camera.h"
#include "app/views/views.h"
#include "pipeline/pipeline.h"

#include <array>
#include <functional>
#include <memory>
#include <optional>

namespace vplab {

class ViewRenderer {
 public:
  explicit ViewRenderer(GlContext& context, float textScale = 1.f);

  /// Each draws one view into `target` (already sized; the camera view is pixel-aligned with DC when
  /// the target is the device's W × H). `run` is the CPU pipeline's run of `scene` (with clipEdges
  /// for the wireframe overlays).
  void drawCamera(const Scene& scene, const PipelineRun& run, const FrameSettings& s, gl::RenderTarget& target);
  void drawWorld(const Scene& scene, const PipelineRun& run, const FrameSettings& s, gl::RenderTarget& target);
  void drawNpc(const Scene& scene, const PipelineRun& run, const FrameSettings& s, gl::RenderTarget& target);
  void drawMorph(const Scene& scene, const PipelineRun& run, const FrameSettings& s, gl::RenderTarget& target);

  /// Renders a view headless into an image: camera at width × height, world and NPC likewise,
  /// all as three panels of width × height with a title strip.
  Image render(ViewKind kind, const Scene& scene, const PipelineRun& run, const FrameSettings& s, int width,
               int height);

  GlContext& context() { return ctx_; }
  /// Whether the world view draws each of its two passes from the faces that can show in it
  /// (partitionByVolume; on by default, used only without multisampling). Off: every face in both
  /// passes, as the tests compare.
  void setPartitionedWorld(bool on) { partitionedWorld_ = on; }
  /// The triangles the last partitioned world view drew of scene object `i` in its inside and its
  /// outside pass ({0, 0} when it was not partitioned).
  std::array<size_t, 2> partitionedTriangles(size_t i) const {
    if (i >= volumeParts_.size() || !volumeParts_[i].valid) return {0, 0};
    const VolumePart& p = volumeParts_[i];
    return {size_t(p.count[kInsideFaces] + p.count[kInsidePass]) / 3, size_t(p.count[kOutsidePass]) / 3};
  }
  /// Where the last view drawn put its labels (x0, y0, x1, y1, pixels), for the tests.
  const std::vector<glm::vec4>& labelsPlaced() const { return text_->placed(); }
  /// Larger text, lines and points for a projector (lecture mode).
  void setScale(float scale);
  float scale() const { return text_->scale(); }

 private:
  struct ObjectPass {
    int volumeMode = 0;  // 0 none, 1 inside the volume only, 2 outside only
    Mat4 volumeNpcFromWc{1.0};
    float alpha = 1.f;
    bool shaded = true;
    bool userPlanes = false;  // clip by the scene's user clip planes (gl_ClipDistance, DGL wiki)
    /// With volumeMode ≠ 0: draw only the faces partitionByVolume kept for that mode.
    bool partitioned = false;
  };
  /// For the world view's two passes (inside the scene camera's view volume solid, outside faded):
  /// which faces of each object can have a fragment in each pass. A face whose vertices all lie
  /// outside one plane of the volume has none inside it; one whose vertices all lie inside has none
  /// outside. Both by a margin far above the GPU's float rounding (of the matrices, the positions
  /// and the interpolation), so the fragment shader's own test would discard every fragment of a
  /// face left out: the picture is the same, and each pass draws about half the faces instead of all.
  /// From `run`'s homogeneous NPC (the same npcFromWc the shader tests with); an object whose run is
  /// not the scene's (a stale run after an invalid camera) is drawn whole in both passes.
  /// Only without multisampling: with it, a fragment's inputs are evaluated at the pixel centre
  /// even where the triangle covers only some samples, extrapolated beyond the face, where no
  /// margin on the vertices bounds them.
  void partitionByVolume(const Scene& scene, const PipelineRun& run);
  /// Binds the target, clears it to `background` and sets the state every view starts from.
  void beginView(gl::RenderTarget& target, const Vec3& background);
  void drawObjects(const Scene& scene, const ViewCamera& view, const ObjectPass& pass);
  /// The hidden-line styles' first pass: `draw` fills only the depth buffer, its polygons pushed back
  /// by glPolygonOffset(1, 2) so their own edges pass the depth test (app/export/svg.cpp mirrors it).
  void depthOnly(const std::function<void()>& draw);
  void drawEdges(const Scene& scene, const ViewCamera& view, int width, int height, Style style);
  /// Polygons the CPU made (clipped polygons in NPC), filled through the GLSL path.
  /// Flat arrays: polygon i is points[ends[i − 1] .. ends[i]) (no allocation per polygon).
  struct PolygonSet {
    glm::vec3 color;
    std::vector<Vec3> points;
    std::vector<uint32_t> ends;
    void add(std::span<const Vec3> polygon) {
      points.insert(points.end(), polygon.begin(), polygon.end());
      ends.push_back(uint32_t(points.size()));
    }
  };
  /// `slot`: which of the streaming buffers below holds the data. Each pass of a frame that draws
  /// CPU polygons uses its own, so filling one never waits for the rasterizer to finish another.
  enum PolygonSlot { kNpcInside = 0, kNpcFaded, kMorph, kPolygonSlots };
  void drawPolygons(const std::vector<PolygonSet>& sets, const ViewCamera& view, const ObjectPass& pass,
                    PolygonSlot slot);
  void setLights(const Scene& scene, const ViewCamera& view);
  Image compose(const Image& camera, const Image& world, const Image& npc, int width, int height);

  GlContext& ctx_;
  const GladGLContext& gl_;
  /// scene.vert/.frag in the variant a pass needs (compiled on first use): with the test against
  /// another camera's view volume, lit by `lights` lights (0: flat), with user clip planes.
  const gl::Program& sceneProgram(bool volumeTest, int lights, bool userPlanes);
  std::array<std::optional<gl::Program>, 2 * 5 * 2> scenePrograms_;
  const gl::Program* scene_ = nullptr;  // the one in use
  GpuMeshCache meshes_;
  OverlayRenderer overlay_;
  std::unique_ptr<TextRenderer> text_;  // replaced by setScale
  /// CPU polygons (NPC and morph views): position and normal per corner, fan-triangulated. The
  /// buffer keeps its storage from frame to frame and is written in place through glMapBufferRange:
  /// the 1M-triangle mesh's 72 MB are neither copied twice nor allocated (page-faulted) anew.
  struct PolygonBuffer {
    gl::VertexArray vao;
    gl::Buffer vbo;
    GLsizeiptr capacity = 0;  // bytes of storage allocated for vbo
  };
  std::array<PolygonBuffer, kPolygonSlots> polygonBuffers_;
  /// partitionByVolume's faces per scene object: triangle indices into the object's GpuMesh, in
  /// face order: the inside pass's faces inside every plane by the margin (drawn first, without the
  /// fragment test), its other faces, and the outside pass's faces.
  enum PartList { kInsideFaces = 0, kInsidePass, kOutsidePass, kPartLists };
  struct VolumePart {
    bool valid = false;
    std::array<gl::Buffer, kPartLists> indices;
    std::array<GLsizeiptr, kPartLists> capacity{};
    std::array<GLsizei, kPartLists> count{};
  };
  std::vector<VolumePart> volumeParts_;
  bool partitionedWorld_ = true;
  std::array<std::vector<uint32_t>, kPartLists> partIndices_;  // scratch, kept between frames
  std::vector<uint8_t> vertexSides_;                  // scratch: per vertex, see partitionByVolume
  /// The NPC view's polygons, kept so their storage is reused from frame to frame.
  std::vector<PolygonSet> npcInside_, npcFaded_;
};

}  // namespace vplab
