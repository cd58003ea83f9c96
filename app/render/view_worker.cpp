// The views' render thread (view_worker.h).
#include "app/render/view_worker.h"

#include "app/workers/background_priority.h"
#include "base/error.h"

#include <chrono>

namespace vplab {

ViewWorker::ViewWorker(std::unique_ptr<GlContext> context, std::function<void()> wake)
    : ctx_(std::move(context)), queue_(kViews, std::move(wake)) {
  if (!ctx_) throw Error("the views' render thread needs a GL context");
  queue_.start([this] { run(); });
}

ViewWorker::~ViewWorker() { queue_.stop(); }

uint64_t ViewWorker::request(ViewRequest r) {
  const size_t view = size_t(r.kind);
  return queue_.request(view, std::move(r));
}

std::optional<ViewWorker::Finished> ViewWorker::take(ViewKind kind, uint64_t ticket, double seconds) {
  Buffers& b = buffers_[size_t(kind)];
  return queue_.take(size_t(kind), ticket, seconds, [&](const Finished& taken) {
    b.untaken = false;
    if (taken.texture) b.shown = b.finished;  // never drawn into until a newer image is taken
  });
}

bool ViewWorker::hasFinished(ViewKind kind) const { return queue_.hasFinished(size_t(kind)); }

unsigned ViewWorker::drawn() const { return queue_.published(); }

size_t ViewWorker::freeBuffer(size_t view) const {
  const Buffers& s = buffers_[view];
  for (size_t b = 0; b < kBuffers; ++b)
    if (b != s.shown && !(s.untaken && b == s.finished)) return b;
  return 0;  // unreachable: three buffers, at most two in use
}

// The render thread: draws the latest request of the view asked longest ago into a buffer neither
// shown nor waiting to be taken, and publishes it. glFinish before publishing: the window's context
// samples the texture only after the drawing is complete (objects shared between contexts are not
// synchronised otherwise).
void ViewWorker::run() {
  runBelowTheWindow();
  ctx_->makeCurrent();
  {
    ViewRenderer renderer(*ctx_);
    float scale = 1.f;
    std::vector<ViewTargets> targets;
    for (size_t b = 0; b < kBuffers; ++b) targets.emplace_back(ctx_->gl());
    size_t buffer = 0;
    while (auto job = queue_.next([&](const auto& j) { buffer = freeBuffer(j.slot); })) {
      const ViewRequest& r = job->request;
      Finished done{job->ticket, 0, {}};
      try {
        if (r.uiScale != scale) renderer.setScale(scale = r.uiScale);
        done.texture = drawViewInto(*ctx_, renderer, targets[buffer], r);
        ctx_->gl().BindFramebuffer(GL_FRAMEBUFFER, 0);
        ctx_->gl().Finish();
        ctx_->checkErrors("drawing a view on the render thread");
      } catch (const std::exception& e) {
        done.texture = 0;
        done.error = e.what();
      }
      queue_.finish(*job, std::move(done), [&] {
        buffers_[job->slot].finished = buffer;
        buffers_[job->slot].untaken = true;
      });
    }
  }  // the renderer and targets are freed with the context current
  ctx_->releaseCurrent();
}

}  // namespace vplab
