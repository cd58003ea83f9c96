// The views' render thread (view_worker.h).
#include "app/render/view_worker.h"

#include "app/core/background_priority.h"
#include "pipeline/error.h"

#include <chrono>

namespace vplab {

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
  runBelowTheWindow();
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
