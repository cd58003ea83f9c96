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
#include "app/render/view_camera.h"
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
  /// Where the last view drawn put its labels (x0, y0, x1, y1, pixels), for the tests.
  const std::vector<glm::vec4>& labelsPlaced() const { return text_->placed(); }
  /// Larger text, lines and points for a projector (lecture mode).
  void setScale(float scale);

 private:
  struct ObjectPass {
    int volumeMode = 0;  // 0 none, 1 inside the volume only, 2 outside only
    Mat4 volumeNpcFromWc{1.0};
    float alpha = 1.f;
    bool shaded = true;
    bool userPlanes = false;  // clip by the scene's user clip planes (gl_ClipDistance, seed 003)
  };
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
  void drawPolygons(const std::vector<PolygonSet>& sets, const ViewCamera& view, const ObjectPass& pass);
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
  gl::VertexArray polygonVao_;  // CPU polygons (NPC view): position and normal per corner
  gl::Buffer polygonVbo_;
};

}  // namespace vplab
