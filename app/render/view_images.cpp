// The views' images (view_images.h).
#include "app/render/view_images.h"

#include "app/export/cpu_raster.h"
#include "app/export/image_compare.h"
#include "app/gl/texture_io.h"
#include "app/render/view_worker.h"
#include "base/error.h"

#include <chrono>
#include <utility>

namespace vplab {

namespace {

/// How long a frame may wait for the render thread's images before it shows the views' last ones: a
/// small scene's views (a few ms each on llvmpipe) appear in the frame that changed them. A view
/// whose last image took longer is not waited for at all (a million triangles: seconds).
constexpr double kFrameWaitForViews = 0.03;

}  // namespace

gl::RenderTarget& ViewTargets::of(ViewKind kind) {
  switch (kind) {
    case ViewKind::world: return world;
    case ViewKind::npc: return npc;
    case ViewKind::morph: return morph;
    case ViewKind::camera:
    case ViewKind::all: return camera;
    case ViewKind::divideFirst:
    case ViewKind::depth: break;
  }
  throw Error("the " + std::string(toString(kind)) + " view has no render target of its own");
}

GLuint showCameraView(GlContext& context, ViewTargets& t, const ViewRequest& r) {
  if (!r.settings.overlays.difference) return t.camera.colorTexture();
  // The GPU's image against the CPU's clipped polygons filled: differing pixels in magenta.
  const Image gpu = t.camera.read();
  const Image cpu = rasterizeClippedPolygons(*r.run, r.scene->background, gpu.width, gpu.height);
  return uploadImageTo(context.gl(), t.difference, differenceImage(gpu, cpu, 0));
}

GLuint drawViewInto(GlContext& context, ViewRenderer& renderer, ViewTargets& t, const ViewRequest& r) {
  const Scene& scene = *r.scene;
  const PipelineRun& run = *r.run;
  switch (r.kind) {
    case ViewKind::world:
      t.world.resize(r.width, r.height, r.samples);
      renderer.drawWorld(scene, run, r.settings, r.highlights, t.world);
      t.world.resolve();
      return t.world.colorTexture();
    case ViewKind::npc:
      t.npc.resize(r.width, r.height, r.samples);
      renderer.drawNpc(scene, run, r.settings, r.highlights, t.npc);
      t.npc.resolve();
      return t.npc.colorTexture();
    case ViewKind::morph:
      t.morph.resize(r.width, r.height, r.samples);
      renderer.drawMorph(scene, run, r.settings, r.highlights, t.morph);
      t.morph.resolve();
      return t.morph.colorTexture();
    case ViewKind::camera:
    case ViewKind::all:
      // At the device's W × H: pixel-aligned with DC (shown scaled to fit).
      t.camera.resize(scene.device.width, scene.device.height, 1);
      renderer.drawCamera(scene, run, r.settings, r.highlights, t.camera);
      return showCameraView(context, t, r);
    case ViewKind::divideFirst:
    case ViewKind::depth: break;  // drawn by the panels that show them, not as view windows
  }
  return 0;
}

namespace {

/// Whether the views' render targets ask the driver if they are complete: not where that waits for
/// the GPU (WebGL; gl::RenderTarget).
bool askComplete(const GlContext& context) { return !context.readingErrorsWaits(); }

}  // namespace

ViewImages::ViewImages(GlContext& context, ViewRenderer& renderer)
    : ctx_(context),
      renderer_(renderer),
      targets_(context.gl(), askComplete(context)),
      back_(context.gl(), askComplete(context)),
      divideFirst_(context.gl(), askComplete(context)) {}

ViewImages::~ViewImages() {
  if (sliceFence_) ctx_.gl().DeleteSync(sliceFence_);  // the context is current, as for the targets' objects
}

void ViewImages::useWorker(std::unique_ptr<GlContext> context, std::function<void()> wake) {
  worker_ = std::make_unique<ViewWorker>(std::move(context), std::move(wake));
  for (Slot& s : slots_) s = {};
}

void ViewImages::drawInSlices(size_t trianglesPerFrame) {
  if (worker_) throw Error("the views are drawn on a render thread: not in slices");
  pacing_ = {trianglesPerFrame};
  for (Slot& s : slots_) {  // an image under way is drawn again, as asked for next
    if (!s.slicing) continue;
    s.slicing.reset();
    s.pending = s.busy = false;
  }
}

SlicePacing SlicePacing::after(double sliceSeconds, double ownSeconds) const {
  // AIMD, as TCP paces what it sends: cut hard when a slice took far longer than aimed at, grow
  // gently when under it.
  if (sliceSeconds > kMostSeconds || ownSeconds > kMostOwnSeconds)  // down to kMinTriangles (a smaller start stays)
    return {std::max(std::min(kMinTriangles, triangles), triangles / 2)};
  if (sliceSeconds < kAimSeconds && ownSeconds < kMostOwnSeconds / 2) return {std::min(kMaxTriangles, triangles + triangles / 4)};
  return *this;
}

void ViewImages::passedSliceFence() {
  gpuBehind_ = false;
  if (!sliceFence_) return;
  const GladGLContext& gl = ctx_.gl();
  // Its status never blocks. (Not glClientWaitSync with no wait: through emscripten's table of GL
  // functions its 64-bit timeout is a signature mismatch, a trap.)
  GLint status = GL_SIGNALED;
  gl.GetSynciv(sliceFence_, GL_SYNC_STATUS, 1, nullptr, &status);
  if (status == GL_UNSIGNALED) {
    gpuBehind_ = ctx_.readingErrorsWaits();  // a native driver's upload does not wait: no need to hold back
    return;
  }
  pacing_ = pacing_.after(std::chrono::duration<double>(std::chrono::steady_clock::now() - sliceSubmitted_).count(),
                          fencedOwnSeconds_);
  gl.DeleteSync(sliceFence_);
  sliceFence_ = nullptr;
}

void ViewImages::beginFrame() {
  if (pacing_.triangles > 0) passedSliceFence();
  trianglesLeft_ = pacing_.triangles;
  slicedThisFrame_ = false;
  sliceOwnSeconds_ = 0;
  listStartedThisFrame_ = false;
  frameBegan_ = std::chrono::steady_clock::now();
  frameWaitLeft_ = kFrameWaitForViews;
  ++frameNumber_;
  for (Slot& s : slots_) s.asked = false;
}

void ViewImages::endFrame() {
  if (slicedThisFrame_ && !sliceFence_) {
    sliceFence_ = ctx_.gl().FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    ctx_.gl().Flush();  // a native driver starts on it (the browser sends a frame's commands anyway)
    sliceSubmitted_ = std::chrono::steady_clock::now();
    fencedOwnSeconds_ = sliceOwnSeconds_;
  }
  for (Slot& s : slots_)
    if (!s.asked) {  // not shown any more: its image is not waited for
      s.pending = s.busy = false;
      s.slicing.reset();
    }
}

GLuint ViewImages::image(ViewRequest r, unsigned runRevision) {
  Slot& slot = slots_[size_t(r.kind)];
  const bool device = r.kind == ViewKind::camera || r.kind == ViewKind::all;  // drawn at the device's W × H
  slot.width = device ? r.scene->device.width : r.width;
  slot.height = device ? r.scene->device.height : r.height;
  slot.busy = false;
  slot.asked = true;
  Stamp stamp{runRevision, r.settings, r.highlights, r.width, r.height, r.samples, r.uiScale};
  if (slot.texture != 0 && slot.stamp == stamp) return slot.texture;
  slot.lastRequest = r;
  if (worker_) return onWorker(slot, std::move(r), std::move(stamp));
  if (pacing_.triangles > 0) return inSlices(slot, std::move(r), std::move(stamp));
  try {
    slot.texture = drawViewInto(ctx_, renderer_, targets_, r);
  } catch (const std::exception& e) {
    error_ = "drawing the " + std::string(toString(r.kind)) + " view failed: " + e.what();
  }
  ++drawn_;
  slot.stamp = std::move(stamp);
  return slot.texture;
}

GLuint ViewImages::onWorker(Slot& slot, ViewRequest r, Stamp stamp) {
  const ViewKind kind = r.kind;
  if (!slot.pending || !(slot.requested == stamp)) {
    slot.ticket = worker_->request(std::move(r));
    slot.requested = std::move(stamp);
    slot.pending = true;
    slot.askedAt = frameNumber_;
    slot.askedTime = std::chrono::steady_clock::now();
  }
  // Only the frame that asked for the image waits for it, when it is expected in time (a small
  // scene's views appear in it); later frames only look whether it is finished, so they stay as
  // short as the panels make them.
  const bool expected = slot.lastSeconds <= frameWaitLeft_;
  const double wait = slot.askedAt == frameNumber_ && expected ? frameWaitLeft_ : 0;
  const auto start = std::chrono::steady_clock::now();
  const auto done = worker_->take(kind, slot.ticket, wait);
  frameWaitLeft_ -= std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (done) {
    if (!done->error.empty()) {
      error_ = "drawing the " + std::string(toString(kind)) + " view failed: " + done->error;
    } else {
      slot.texture = done->texture;  // the newest finished image, maybe of an older request
      ++drawn_;
    }
    if (done->ticket == slot.ticket) {
      slot.pending = false;
      slot.stamp = slot.requested;
      slot.lastSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - slot.askedTime).count();
    }
  }
  slot.busy = slot.pending;
  return slot.texture;
}

GLuint ViewImages::inSlices(Slot& slot, ViewRequest r, Stamp stamp) {
  const ViewKind kind = r.kind;
  try {
    gl::RenderTarget& back = back_.of(kind);
    bool listedNow = false;
    if (!slot.slicing || !(slot.requested == stamp)) {  // a new image: its list is built now
      // ... or in the next frame (SlicePacing::kListStartSeconds): shown busy meanwhile.
      const double intoFrame = std::chrono::duration<double>(std::chrono::steady_clock::now() - frameBegan_).count();
      if (listStartedThisFrame_ || (intoFrame > SlicePacing::kListStartSeconds && !slot.putOff)) {
        slot.putOff = true;
        slot.pending = slot.busy = true;
        return slot.texture;
      }
      slot.putOff = false;
      listStartedThisFrame_ = true;
      const bool device = kind == ViewKind::camera || kind == ViewKind::all;  // at the device's W × H
      back.resize(device ? r.scene->device.width : r.width, device ? r.scene->device.height : r.height,
                  device ? 1 : r.samples);
      const auto timed = parts_->time("view list");
      renderer_.startSlices(kind, *r.scene, *r.run, r.settings, r.highlights, back, slot.slices);
      slot.slicing = std::move(r);
      slot.requested = std::move(stamp);
      slot.pending = true;
      listedNow = true;
    }
    // A list that leaves the frame past its share is drawn from the next frame on: the NPC view's
    // first slice of a million faces writes the run's vertices (a list of 17 ms and that slice of 31 ms
    // made one frame of the page 50 ms long). A small scene's list leaves the frame well within it.
    const bool frameSpent =
        listedNow &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - frameBegan_).count() > SlicePacing::kListStartSeconds;
    if (!gpuBehind_ && !frameSpent && (trianglesLeft_ > 0 || slot.slices.cursor.batch == 0)) {
      slicedThisFrame_ = true;
      // A slice may draw nothing of the meshes (none left in this frame) and still the rest of the
      // list up to its first fill: a view of a small scene is complete in the frame that asks.
      const auto began = std::chrono::steady_clock::now();
      const bool complete = [&] {
        const auto timed = parts_->time("view slice");
        return renderer_.drawSlice(slot.slices, back, trianglesLeft_);
      }();
      sliceOwnSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
      if (complete) {
        const auto timed = parts_->time("view shown");
        back.resolve();
        std::swap(targets_.of(kind), back);  // the complete image is shown; the old one drawn over next
        slot.texture = kind == ViewKind::camera || kind == ViewKind::all ? showCameraView(ctx_, targets_, *slot.slicing)
                                                                         : targets_.of(kind).colorTexture();
        slot.stamp = slot.requested;
        slot.pending = false;
        slot.slicing.reset();
        ++drawn_;
      }
    }
  } catch (const std::exception& e) {
    error_ = "drawing the " + std::string(toString(kind)) + " view failed: " + e.what();
    slot.pending = false;
    slot.slicing.reset();
  }
  slot.busy = slot.pending;
  return slot.texture;
}

GLuint ViewImages::divideFirst(const Scene& scene, const PipelineRun& run, const DisplaySettings& settings,
                               unsigned runRevision) {
  // The GPU always clips correctly; the wrong strategy's result exists only as the CPU's clipped
  // polygons: divideFirstView's display list, drawn at the device's size (pixel-aligned with DC,
  // as the camera view beside it).
  if (run.options.strategy != ClipStrategy::divideFirst) return 0;
  const Device& d = run.device;
  if (divideFirstRevision_ != runRevision || divideFirst_.width() != d.width || divideFirst_.height() != d.height) {
    divideFirst_.resize(d.width, d.height, 1);
    renderer_.drawDivideFirst(scene, run, settings, divideFirst_);
    divideFirst_.resolve();
    divideFirstRevision_ = runRevision;
  }
  return divideFirst_.colorTexture();
}

bool ViewImages::listPutOff() const {
  return std::any_of(slots_.begin(), slots_.end(), [](const Slot& s) { return s.putOff && s.pending; });
}

std::vector<ViewKind> ViewImages::notReady() const {
  std::vector<ViewKind> kinds;
  for (ViewKind kind : allOf<ViewKind>())
    if (slots_[size_t(kind)].asked && slots_[size_t(kind)].busy) kinds.push_back(kind);
  return kinds;
}

std::vector<ViewKind> ViewImages::asked() const {
  std::vector<ViewKind> kinds;
  for (ViewKind kind : allOf<ViewKind>())
    if (slots_[size_t(kind)].asked) kinds.push_back(kind);
  return kinds;
}

std::optional<double> ViewImages::wakeIn(double busyStep) const {
  std::optional<double> wake;
  for (ViewKind kind : allOf<ViewKind>()) {
    if (!slots_[size_t(kind)].pending) continue;
    if (!worker_) return 0.0;  // drawn in slices: the next one in the next frame
    if (worker_->hasFinished(kind)) return 0.0;
    wake = busyStep;
  }
  return wake;
}

void ViewImages::forget() {
  for (Slot& s : slots_) {
    s.stamp = {};
    if (s.slicing) s.requested = {};  // started over when next asked for
  }
}

void ViewImages::recreateGlObjects() {
  if (worker_) throw Error("the views' render thread cannot recreate its context's objects");
  targets_ = ViewTargets(ctx_.gl(), askComplete(ctx_));
  back_ = ViewTargets(ctx_.gl(), askComplete(ctx_));
  sliceFence_ = nullptr;  // went with the context
  gpuBehind_ = false;
  divideFirst_ = gl::RenderTarget(ctx_.gl(), askComplete(ctx_));
  divideFirstRevision_ = 0;
  for (Slot& s : slots_) s = Slot{};
}

std::optional<std::string> ViewImages::takeError() { return std::exchange(error_, std::nullopt); }

}  // namespace vplab
