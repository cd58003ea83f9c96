// The views' images (docs/lecturers.md "The viewer"): one render target per view, drawn again only when what
// it shows changed (its stamp), either in the frame that needs it or, with a render thread
// (app/render/view_worker.h), while the window goes on drawing its panels. Both paths draw through
// one function, drawViewInto. A view of a million triangles takes seconds on a software renderer: the
// window draws frames for any input (hover, ImGui settling) and must not draw the view each time.
#pragma once

#include "app/context/context.h"
#include "app/gl/render_target.h"
#include "app/render/frame_parts.h"
#include "app/render/view_renderer.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vplab {

/// Everything a view's image is drawn from. `run` is the CPU pipeline's run of `scene`, both
/// published together and never copied (app/ui/shown_run.h): asking for a view every frame copies
/// two pointers.
struct ViewRequest {
  ViewKind kind = ViewKind::world;
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const PipelineRun> run;
  DisplaySettings settings;
  Highlights highlights;
  int width = 0, height = 0, samples = 1;
  float uiScale = 1.f;
};

/// The render targets of one image of each view, and the camera view's difference image.
struct ViewTargets {
  explicit ViewTargets(const GladGLContext& gl, bool checkComplete = true)
      : world(gl, checkComplete), camera(gl, checkComplete), npc(gl, checkComplete), morph(gl, checkComplete) {}
  gl::RenderTarget world, camera, npc, morph;
  gl::Texture difference;
  /// The target `kind` is drawn into (the camera view's for camera and all).
  gl::RenderTarget& of(ViewKind kind);
};

/// Draws one view into `targets` on the current context; returns the texture that shows it (the
/// camera view at the device's W × H, or its difference image with the CPU's polygons).
GLuint drawViewInto(GlContext& context, ViewRenderer& renderer, ViewTargets& targets, const ViewRequest& r);
/// The texture that shows the camera view drawn into `targets.camera`: its colour, or with the
/// difference overlay the image of where it differs from the CPU's clipped polygons.
GLuint showCameraView(GlContext& context, ViewTargets& targets, const ViewRequest& r);

/// How many triangles the views drawn in slices (the page) may draw in a frame, adapted to how long
/// the GPU took for the last slice (AIMD: halved after a slice over kMostSeconds, a quarter more after
/// one under kAimSeconds, never under kMinTriangles unless it started lower).
struct SlicePacing {
  /// The time a slice aims at, from its draw calls to the GPU's fence after them (SwiftShader runs
  /// them after the frame that made them). The next slice waits for that fence, so the page's own
  /// work never waits for the GPU's (issue 42; docs/measured.md "Large scenes in the page").
  static constexpr double kAimSeconds = 0.05, kMostSeconds = 0.1;
  /// The most of a frame a slice's own work may take (its polygons' buffers, their upload: a browser's
  /// upload behind a busy GPU waits for it): over it the slice is too large, however fast the GPU.
  static constexpr double kMostOwnSeconds = 0.02;
  /// A view's new list (a million triangles' takes the page 20-50 ms) is started in a frame only when
  /// no other was and the frame has spent less than this (a pipeline step, a scene's arrival), or
  /// when it was put off once already.
  static constexpr double kListStartSeconds = 0.01;
  /// SwiftShader draws about 400 000 triangles a second (three views of a million in 7 s): 10 000
  /// take it some 25 ms, so even a slow machine's frames keep a view filling in.
  static constexpr size_t kMinTriangles = 10000, kMaxTriangles = size_t(1) << 24;

  size_t triangles = 0;  // in the next frame; 0: views drawn whole

  /// The pacing after a slice that took the GPU `sliceSeconds` (its draw calls to its fence) and the
  /// frame `ownSeconds` of its own work.
  SlicePacing after(double sliceSeconds, double ownSeconds = 0) const;
};

class ViewWorker;

class ViewImages {
 public:
  /// Draws on `context` with `renderer` (the window's) until useWorker.
  ViewImages(GlContext& context, ViewRenderer& renderer);
  ~ViewImages();
  ViewImages(const ViewImages&) = delete;
  ViewImages& operator=(const ViewImages&) = delete;

  /// Draws the views on a render thread with `context` (GlContext::createShared of the window's):
  /// a view whose image is not ready within the frame shows its last image, busy. `wake` wakes the
  /// window's event wait (called on the render thread).
  void useWorker(std::unique_ptr<GlContext> context, std::function<void()> wake);
  /// Without a render thread (the page): draws each view in slices across frames, about
  /// `trianglesPerFrame` triangles of all views in a frame to begin with, then paced by the frame
  /// times (SlicePacing); a view shows its last image, busy, until its new one is complete.
  /// 0: each view whole in the frame that asks for it (the default).
  void drawInSlices(size_t trianglesPerFrame);
  /// Times a slice's list, its drawing and the camera view's showing as parts of the frame (the page).
  void timeParts(const FrameParts& parts) { parts_ = &parts; }

  /// A new frame: no view asked for yet; the frame may wait a little for the render thread.
  void beginFrame();
  /// The end of the frame's views: a view not asked for in it is not shown, nor waited for.
  void endFrame();

  /// The texture that shows `r` (drawn from the run of revision `runRevision`): its last image when
  /// nothing it shows changed, else drawn now, or on the render thread (then maybe an older image,
  /// and busy(r.kind)). 0 before its first image. A failure is kept for takeError().
  GLuint image(ViewRequest r, unsigned runRevision);
  /// The divide-first comparison at the device's size, drawn again only for a new run.
  GLuint divideFirst(const Scene& scene, const PipelineRun& run, const DisplaySettings& settings, unsigned runRevision);

  /// Whether a view's new list was put off to this frame (drawn in slices): the frame leaves the
  /// pipeline's step for it (Viewer::updateRun).
  bool listPutOff() const;
  /// Whether `kind` shows an older image in this frame while its current one is drawn.
  bool busy(ViewKind kind) const { return slots_[size_t(kind)].busy; }
  /// The views asked for in this frame that are busy: a screenshot waits until there are none.
  std::vector<ViewKind> notReady() const;
  /// The views asked for in this frame.
  std::vector<ViewKind> asked() const;
  /// Seconds until the window should draw again for the views: 0 when a render-thread image is
  /// finished, `busyStep` while one is drawn (the busy mark turns), else nothing (nullopt).
  std::optional<double> wakeIn(double busyStep) const;
  /// The image shown last of `kind`, and its size in pixels as asked last (the camera view's is
  /// the device's).
  GLuint texture(ViewKind kind) const { return slots_[size_t(kind)].texture; }
  int width(ViewKind kind) const { return slots_[size_t(kind)].width; }
  int height(ViewKind kind) const { return slots_[size_t(kind)].height; }
  /// What `kind`'s image was last drawn from (or is being drawn from): the tests build its display
  /// list again to see where its labels went. Null before its first image.
  const ViewRequest* lastRequest(ViewKind kind) const {
    const auto& r = slots_[size_t(kind)].lastRequest;
    return r ? &*r : nullptr;
  }
  /// How many images were drawn (not reused): tests check hover frames cost none.
  unsigned drawn() const { return drawn_; }
  /// Every view is drawn again when next asked for.
  void forget();
  /// The context lost every object (a WebGL context lost and restored): the render targets are
  /// made again and every view is drawn anew. Only without a render thread (the page has none).
  void recreateGlObjects();
  /// The last failure to draw a view, once.
  std::optional<std::string> takeError();

 private:
  /// What an image was drawn from: equal stamps give equal images. The scene is the run's; the
  /// settings and the frame's highlights are both drawn, so both key the image.
  struct Stamp {
    unsigned runRevision = 0;
    DisplaySettings settings;
    Highlights highlights;
    int width = 0, height = 0, samples = 0;
    float uiScale = 0;
    bool operator==(const Stamp&) const = default;
  };
  struct Slot {
    Stamp stamp;
    GLuint texture = 0;
    int width = 0, height = 0;
    // With the render thread: the image asked for and not yet shown.
    Stamp requested;
    uint64_t ticket = 0;
    uint64_t askedAt = 0;  // the frame that asked for it
    bool pending = false;
    bool busy = false;   // shown with an older image in this frame
    bool asked = false;  // asked for in this frame
    double lastSeconds = 0;  // how long its last image took on the render thread, from the request
    std::chrono::steady_clock::time_point askedTime;
    // Drawn in slices (drawInSlices): the image asked for, drawn into back_ (its scene and run kept
    // alive for the list, which points into them), and how far.
    std::optional<ViewRequest> slicing;
    ViewRenderer::Slices slices;
    bool putOff = false;  // its new list was put off to the next frame (inSlices)
    std::optional<ViewRequest> lastRequest;  // what its image was last drawn from (lastRequest())
  };
  GLuint onWorker(Slot& slot, ViewRequest r, Stamp stamp);
  GLuint inSlices(Slot& slot, ViewRequest r, Stamp stamp);
  /// Whether the GPU passed the last slices' fence (gpuBehind_ when not); when it did, paces the next.
  void passedSliceFence();

  static constexpr size_t kViews = kViewKindCount;
  GlContext& ctx_;
  ViewRenderer& renderer_;
  ViewTargets targets_;           // the images drawn in the window's thread
  ViewTargets back_;              // drawn in slices: the images not complete yet (swapped in when they are)
  SlicePacing pacing_;            // drawInSlices
  size_t trianglesLeft_ = 0;      // in this frame
  bool slicedThisFrame_ = false;
  bool listStartedThisFrame_ = false;
  std::chrono::steady_clock::time_point frameBegan_;
  // The fence after the last frame's slices, until the GPU passed it: its time paces the next
  // (SlicePacing), and in WebGL no slice is drawn meanwhile (an upload behind a busy GPU waits for it:
  // GlContext::readingErrorsWaits).
  GLsync sliceFence_ = nullptr;
  std::chrono::steady_clock::time_point sliceSubmitted_;
  double sliceOwnSeconds_ = 0;    // the slices' own work in this frame
  double fencedOwnSeconds_ = 0;   // ... in the frame sliceFence_ follows
  bool gpuBehind_ = false;  // in this frame: sliceFence_ not passed yet
  gl::RenderTarget divideFirst_;
  unsigned divideFirstRevision_ = 0;  // the run it was drawn from (0: none yet)
  std::array<Slot, kViews> slots_;
  std::unique_ptr<ViewWorker> worker_;
  double frameWaitLeft_ = 0;  // seconds this frame may still wait for the render thread
  uint64_t frameNumber_ = 0;
  unsigned drawn_ = 0;
  std::optional<std::string> error_;
  FrameParts noParts_;
  const FrameParts* parts_ = &noParts_;  // timeParts
};

}  // namespace vplab
