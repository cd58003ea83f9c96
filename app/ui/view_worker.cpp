// The views' render thread (view_worker.h).
#include "app/ui/view_worker.h"

#include "app/export/image_compare.h"
#include "app/export/cpu_raster.h"
#include "pipeline/error.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <chrono>

namespace vplab {

namespace {
[[maybe_unused]] constexpr int kNice = 5;
}  // namespace

Image readTexture(const GladGLContext& gl, GLuint texture) {
  if (!gl.GetTexLevelParameteriv || !gl.GetTexImage)  // OpenGL ES and WebGL2 have neither
    throw Error("this OpenGL cannot read a view's texture back (OpenGL ES has no glGetTexImage)");
  GLint w = 0, h = 0;
  gl.BindTexture(GL_TEXTURE_2D, texture);
  gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
  if (w <= 0 || h <= 0) throw Error("the view has no image to export yet");
  std::vector<Rgba> rows(size_t(w) * size_t(h));
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  Image image;
  image.width = w;
  image.height = h;
  image.pixels.resize(rows.size());
  for (int y = 0; y < h; ++y)
    std::copy_n(rows.begin() + ptrdiff_t(h - 1 - y) * w, w, image.pixels.begin() + ptrdiff_t(y) * w);
  return image;
}

GLuint uploadImageTo(const GladGLContext& gl, gl::Texture& texture, const Image& image) {
  std::vector<Rgba> rows(image.pixels.size());
  for (int y = 0; y < image.height; ++y)
    std::copy_n(image.pixels.begin() + ptrdiff_t(y) * image.width, image.width,
                rows.begin() + ptrdiff_t(image.height - 1 - y) * image.width);
  if (!texture) texture = gl::makeTexture(gl);
  gl.BindTexture(GL_TEXTURE_2D, texture.id());
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                rows.data());
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return texture.id();
}

GLuint drawViewInto(GlContext& context, ViewRenderer& renderer, ViewTargets& t, const ViewRequest& r) {
  const PipelineRun& run = *r.run;
  switch (r.kind) {
    case ViewKind::world:
      t.world.resize(r.width, r.height, r.samples);
      renderer.drawWorld(r.scene, run, r.frame, t.world);
      t.world.resolve();
      return t.world.colorTexture();
    case ViewKind::npc:
      t.npc.resize(r.width, r.height, r.samples);
      renderer.drawNpc(r.scene, run, r.frame, t.npc);
      t.npc.resolve();
      return t.npc.colorTexture();
    case ViewKind::morph:
      t.morph.resize(r.width, r.height, r.samples);
      renderer.drawMorph(r.scene, run, r.frame, t.morph);
      t.morph.resolve();
      return t.morph.colorTexture();
    case ViewKind::camera:
    case ViewKind::all:
      // At the device's W × H: pixel-aligned with DC (shown scaled to fit).
      t.camera.resize(r.scene.device.width, r.scene.device.height, 1);
      renderer.drawCamera(r.scene, run, r.frame, t.camera);
      if (!r.frame.overlays.difference) return t.camera.colorTexture();
      {
        // The GPU's image against the CPU's clipped polygons filled: differing pixels in magenta.
        const Image gpu = t.camera.read();
        const Image cpu = rasterizeClippedPolygons(run, r.scene.background, gpu.width, gpu.height);
        return uploadImageTo(context.gl(), t.difference, differenceImage(gpu, cpu, 0));
      }
    case ViewKind::divideFirst:
    case ViewKind::depth: break;  // drawn by the panels that show them, not as view windows
  }
  return 0;
}

ViewWorker::ViewWorker(std::unique_ptr<GlContext> context, std::function<void()> wake)
    : ctx_(std::move(context)), wake_(std::move(wake)) {
  if (!ctx_) throw Error("the views' render thread needs a GL context");
  thread_ = std::thread([this] { run(); });
}

ViewWorker::~ViewWorker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

uint64_t ViewWorker::request(ViewRequest r) {
  std::lock_guard lock(mutex_);
  ViewSlot& slot = slots_[size_t(r.kind)];
  slot.pending = std::move(r);
  slot.pendingTicket = nextTicket_++;
  changed_.notify_all();
  return slot.pendingTicket;
}

std::optional<ViewWorker::Finished> ViewWorker::take(ViewKind kind, uint64_t ticket, double seconds) {
  std::unique_lock lock(mutex_);
  ViewSlot& slot = slots_[size_t(kind)];
  if (seconds > 0)
    changed_.wait_for(lock, std::chrono::duration<double>(seconds),
                      [&] { return stop_ || (slot.finished && slot.finished->ticket >= ticket); });
  if (!slot.finished) return std::nullopt;
  std::optional<Finished> taken = std::move(slot.finished);
  slot.finished.reset();
  if (taken->texture) slot.shownBuffer = slot.finishedBuffer;
  return taken;
}

bool ViewWorker::hasFinished(ViewKind kind) const {
  std::lock_guard lock(mutex_);
  return slots_[size_t(kind)].finished.has_value();
}

unsigned ViewWorker::drawn() const {
  std::lock_guard lock(mutex_);
  return drawn_;
}

size_t ViewWorker::freeBuffer(size_t view) const {
  const ViewSlot& s = slots_[view];
  for (size_t b = 0; b < kBuffers; ++b)
    if (b != s.shownBuffer && !(s.finished && b == s.finishedBuffer)) return b;
  return 0;  // unreachable: three buffers, at most two in use
}

// The render thread: takes the oldest view's latest request, draws it with the lock released and
// publishes it. glFinish before publishing: the window's context samples the texture only after
// the drawing is complete (objects shared between contexts are not synchronised otherwise).
void ViewWorker::run() {
  // Below the window's thread: its frames come first when both want a core (the nice value of a
  // thread on Linux; the window's frames take a few ms, a view of a large mesh seconds).
#ifdef SYS_gettid  // Linux; the browser build has no render thread at all
  setpriority(PRIO_PROCESS, pid_t(syscall(SYS_gettid)), kNice);
#endif
  ctx_->makeCurrent();
  {
    ViewRenderer renderer(*ctx_);
    float scale = 1.f;
    std::vector<ViewTargets> buffers;
    for (size_t b = 0; b < kBuffers; ++b) buffers.emplace_back(ctx_->gl());
    std::unique_lock lock(mutex_);
    for (;;) {
      changed_.wait(lock, [&] {
        if (stop_) return true;
        for (const ViewSlot& s : slots_)
          if (s.pending) return true;
        return false;
      });
      if (stop_) break;
      size_t view = 0;
      uint64_t oldest = UINT64_MAX;
      for (size_t v = 0; v < kViews; ++v)
        if (slots_[v].pending && slots_[v].pendingTicket < oldest) oldest = slots_[v].pendingTicket, view = v;
      ViewRequest r = std::move(*slots_[view].pending);
      slots_[view].pending.reset();
      const size_t buffer = freeBuffer(view);
      lock.unlock();
      Finished done{oldest, 0, {}};
      try {
        if (r.uiScale != scale) renderer.setScale(scale = r.uiScale);
        done.texture = drawViewInto(*ctx_, renderer, buffers[buffer], r);
        ctx_->gl().BindFramebuffer(GL_FRAMEBUFFER, 0);
        ctx_->gl().Finish();
        ctx_->checkErrors("drawing a view on the render thread");
      } catch (const std::exception& e) {
        done.texture = 0;
        done.error = e.what();
      }
      lock.lock();
      ++drawn_;
      ViewSlot& slot = slots_[view];
      slot.finished = std::move(done);
      slot.finishedBuffer = buffer;
      changed_.notify_all();
      if (wake_) wake_();
    }
    lock.unlock();
  }  // the renderer and targets are freed with the context current
  ctx_->releaseCurrent();
}

}  // namespace vplab
