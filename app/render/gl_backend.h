// The GL backend: draws a display list (app/views/display_list.h) into a render target, and a
// picture (panels of display lists) into an image. It decides nothing about what is drawn, only how
// each batch maps to GL state (see drawFill, drawLines, …). Desktop GL 3.3 core and OpenGL ES 3.0
// (WebGL2) run the same shaders (app/gl/shader.h); only user clip planes differ (gl_ClipDistance and
// its enables on desktop, a discard in the shaders on ES). One instance per GL context: it owns the
// programs, the meshes on the GPU, the streaming buffers and the text renderer.
#pragma once

#include "app/context/context.h"
#include "app/gl/render_target.h"
#include "app/gl/shader.h"
#include "app/render/gpu_mesh.h"
#include "app/render/overlay.h"
#include "app/render/text.h"
#include "app/render/volume_partition.h"
#include "app/views/display_list.h"
#include "app/views/image.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace vplab {

class GlBackend {
 public:
  /// `textScale` enlarges the text (lecture mode); widths and sizes come scaled in the lists.
  explicit GlBackend(GlContext& context, float textScale = 1.f);

  /// Clears `target` (bound, whole viewport) to the list's background and draws its batches in order.
  /// GL errors are left for the caller's GlContext::checkErrors, which names what it drew.
  void draw(const draw::DisplayList& list, gl::RenderTarget& target);

  /// CPU polygons, fan-triangulated, one slot per polygon fill of a list so that filling one never
  /// waits for the rasterizer to finish another. Polygons of points become GPU vertices (a position
  /// each); polygons by reference to a run's faces become indices into the run's vertices, which the
  /// list's first slice that needs them writes once for all its fills (a mesh vertex is shaded once
  /// for the faces around it, not once a corner). The normal comes from the fragment shader's
  /// derivatives (scene.frag, FACE_NORMAL). Each buffer keeps its storage from frame to frame and is
  /// written in place through glMapBufferRange.
  struct PolygonBuffer {
    gl::VertexArray vao;  // polygons of points: `vbo` holds a slice's fan-triangulated corners
    gl::Buffer vbo;
    GLsizeiptr capacity = 0;
    gl::VertexArray indexedVao;  // polygons by reference: the runs' vertices and a slice's `indices`
    gl::Buffer indices;
    GLsizeiptr indicesCapacity = 0;
    std::vector<GLuint> bases;  // per polygon set of the fill: its run's first vertex
  };
  struct PolygonBuffers {
    std::vector<PolygonBuffer> slots;
    /// The runs' vertices in NPC (ObjectRun::clippedNpc: mesh vertices, then those clipping made),
    /// each run's from its first vertex in `runs`, written for draw `serial`.
    gl::Buffer vertices;
    GLsizeiptr verticesCapacity = 0;
    uint64_t serial = 0;
    std::vector<std::pair<const ObjectRun*, GLuint>> runs;
  };

  /// Where a list drawn in slices goes on: the next batch and, in a fill, the next mesh instance (or
  /// polygon set), pass and index. A new Cursor is the list's start.
  struct Cursor {
    bool started = false;
    size_t batch = 0;
    size_t mesh = 0;     // the mesh instance, or in pass 2 the polygon set
    int pass = 0;        // 0: the whole mesh, or the inside faces drawn early; 1: the volume pass;
                         // 2: the fill's polygons (begun: their buffer is the fill's slot). Mesh
                         // edges: 0, or 1 for an x-ray's visible pass
    GLsizei index = 0;   // the next element of the pass's index list, polygon of the set or mesh edge
    size_t primitive = 0;    // in lines, points or triangles: the next one
    uint64_t serial = 0;     // the draw it is (the volume partition made for it)
    size_t polygonSlot = 0;  // the polygon buffers its fills took so far
  };
  /// Draws `list` as draw() does, in slices: from `cursor` on, at most `triangles` of its meshes' and
  /// polygons' triangles, counting a line, a mesh edge or a point as two (taken off the count; a
  /// run of x-ray batches, the overlays' few hundred primitives, is drawn whole when reached). The first slice clears `target`. A slice's GL state is its own and
  /// its polygons stay in `polygons` (the view's own buffers), so other lists may be drawn between
  /// two slices. True when the list is drawn to its end. A software renderer takes seconds for a
  /// million triangles: the page draws such a view across frames.
  bool drawSlice(const draw::DisplayList& list, gl::RenderTarget& target, Cursor& cursor, size_t& triangles,
                 PolygonBuffers& polygons);
  /// Each panel into its own target (4× multisampled when its list is antialiased), read back and
  /// put at the panel's place on the picture's background.
  Image render(const draw::Picture& picture);

  /// The metrics the builders measure labels with (the atlas the text is drawn from).
  const TextRenderer& text() const { return *text_; }
  void setTextScale(float scale) { text_ = std::make_unique<TextRenderer>(gl_, scale); }
  /// Whether fills with MeshInstance::run draw only the faces that can show in their volume pass
  /// (single-sampled targets only; see VolumePartitions). On by default; off: every face, as tests compare.
  void setPartitioned(bool on) { partitioned_ = on; }
  bool partitioned() const { return partitioned_; }
  /// The triangles the last partitioned fill drew of mesh instance `i` in its inside and outside
  /// pass ({0, 0} when it was not partitioned).
  std::array<size_t, 2> partitionedTriangles(size_t i) const { return partitions_.triangles(serial_, i); }
  /// The corners of a mesh's GPU chunks at most (GpuMeshCache::setChunkCorners), for tests.
  void setMeshChunkCorners(uint32_t corners) { meshes_.setChunkCorners(corners); }
  uint32_t meshChunkCorners() const { return meshes_.chunkCorners(); }
  /// Where the last draw call put its labels (x0, y0, x1, y1, pixels), for the tests.
  const std::vector<glm::vec4>& labelsPlaced() const { return labelsPlaced_; }
  /// The bytes of the meshes' GPU buffers (faces, edges), on llvmpipe and SwiftShader the process's own.
  MemoryUse gpuMemoryUse() const {
    return {{"gpu.mesh faces", meshes_.faceBytes()},
            {"gpu.mesh edges", meshes_.edgeBytes()},
            {"gpu.mesh corner map (CPU)", meshes_.cornerMapBytes()}};
  }

 private:
  struct View {
    int width = 0, height = 0;
    int samples = 1;
    draw::Space space;  // the observer's
    ViewCamera observer;
    ViewCamera pixels;  // Space::pixels: the view's own pixels, y down
    const ViewCamera& cameraFor(draw::Space s) const;
  };
  /// Each returns false when `triangles` ran out before the fill was drawn (see drawSlice).
  bool drawFill(const draw::Fill& fill, const View& view, Cursor& cursor, size_t& triangles, PolygonBuffers& polygons);
  bool drawMeshes(const draw::Fill& fill, const ViewCamera& camera, int samples, Cursor& cursor, size_t& triangles);
  bool drawPolygons(const draw::Fill& fill, const ViewCamera& camera, Cursor& cursor, size_t& triangles,
                    PolygonBuffers& polygons);
  /// Polygons [begin, end) of the fill's set `set`, as GPU vertices [first, first + count) of the
  /// slot's `vbo`, or (`indexed`: a set by reference) as indices [first, first + count).
  struct PolygonSegment {
    size_t set = 0, begin = 0, end = 0;
    bool indexed = false;
    GLint first = 0;
    GLsizei count = 0;
  };
  /// The fill's slot of `polygons`: the next one when `newSlot` (the fill's first slice, which also
  /// finds its sets' runs' vertices, writing them unless this draw did already), else the one it took.
  PolygonBuffer& polygonSlot(const draw::Fill& fill, bool newSlot, PolygonBuffers& polygons);
  void writeRunVertices(const draw::Fill& fill, PolygonBuffers& polygons, PolygonBuffer& slot);
  /// Fan-triangulates the segments' polygons into the slot: `vertices` GPU vertices of the polygons
  /// of points, `indices` indices of those by reference.
  void uploadPolygons(const draw::Fill& fill, const std::vector<PolygonSegment>& segments, GLsizei vertices,
                      GLsizei indices, PolygonBuffer& slot);
  /// Room for `bytes` in the buffer bound to `target` (grown by a quarter more than asked, shrunk
  /// when a quarter would do), mapped for writing; OpenGL ES (WebGL2), which has no mapping, gets
  /// staging memory that doneWriting hands over with glBufferSubData.
  void* startWriting(GLenum target, GLsizeiptr bytes, GLsizeiptr& capacity);
  void doneWriting(GLenum target, GLsizeiptr bytes);
  /// The mesh edges of `lines` from the cursor on, while `triangles` last (two an edge); true when done.
  bool drawMeshEdges(const draw::Lines& lines, const View& view, Cursor& cursor, size_t& triangles);
  /// One OverlayBatch's worth of lines, points and triangles, primitives [first, end) of each batch
  /// (a run of consecutive x-ray batches is drawn as one: all hidden parts first, then all visible
  /// ones, as the views expect).
  void drawMarks(const std::vector<const draw::Batch*>& batches, draw::Depth depth, const View& view,
                 size_t first = 0, size_t end = SIZE_MAX);
  /// A batch of lines, points or triangles that is no x-ray, from the cursor's primitive on while
  /// `triangles` last (at least one primitive); true when done.
  bool drawMarksSlice(const draw::Batch& batch, draw::Depth depth, const View& view, Cursor& cursor,
                      size_t& triangles);
  void setFillProgram(const gl::Program& p, const draw::Fill& fill, const ViewCamera& camera, int planes);
  void setClipDistances(int planes);

  /// scene.vert/.frag in the variant a fill needs (compiled on first use); `faceNormal`: lit by the
  /// normal of the plane each fragment lies in (CPU polygons, whose corners carry none).
  const gl::Program& sceneProgram(bool volumeTest, int lights, bool userPlanes, bool faceNormal = false);

  GlContext& ctx_;
  const GladGLContext& gl_;
  bool es_;  // OpenGL ES: no gl_ClipDistance enables
  std::array<std::optional<gl::Program>, 2 * 5 * 2 * 2> scenePrograms_;
  GpuMeshCache meshes_;
  /// A fence after a part of drawSlice, deleted with it.
  class PartFence {
   public:
    explicit PartFence(const GladGLContext& gl) : gl_(&gl) {}
    PartFence(PartFence&& o) noexcept : gl_(o.gl_), sync_(std::exchange(o.sync_, nullptr)) {}
    PartFence& operator=(PartFence&& o) noexcept;
    ~PartFence();
    void put();
    /// Until the rasterizer passed it (glFinish should the wait fail); then it is deleted.
    void wait();
    explicit operator bool() const { return sync_ != nullptr; }

   private:
    const GladGLContext* gl_;
    GLsync sync_ = nullptr;
  };
  /// A slice of drawSlice, up to `triangles`, with no wait for the rasterizer inside.
  bool drawPart(const draw::DisplayList& list, gl::RenderTarget& target, Cursor& cursor, size_t& triangles,
                PolygonBuffers& polygons);
  /// The triangles of a slice drawn before the rasterizer is waited for (drawSlice).
  static constexpr size_t kTrianglesAtOnce = size_t(1) << 14;
  /// The lines, points or triangles of a batch drawn at once at most (drawMarksSlice).
  static constexpr size_t kMarksAtOnce = size_t(1) << 16;
  std::vector<draw::Vertex> segmentScratch_;  // a part's segments (Lines::segmentsInto)
  OverlayRenderer overlay_;
  std::unique_ptr<TextRenderer> text_;
  PolygonBuffers polygonBuffers_;  // a list drawn whole (draw)
  size_t polygonSlot_ = 0;
  std::vector<std::byte> polygonStaging_;  // OpenGL ES (WebGL2): the polygons' data before glBufferSubData
  VolumePartitions partitions_;
  std::vector<glm::vec4> labelsPlaced_;
  bool partitioned_ = true;
  uint64_t serial_ = 0;      // the draw under way (its slices keep it)
  uint64_t lastSerial_ = 0;  // the last one given out: each draw's is new
};

}  // namespace vplab
