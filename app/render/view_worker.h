// The views drawn on a render thread (docs/lecturers.md "The viewer": the window never waits for a view;
// app/render/view_images.h decides what is drawn where). A view of a million triangles takes seconds
// on a software renderer; meanwhile the window keeps drawing its panels and shows the view's last finished image with a busy mark. The thread has its
// own GL context sharing the window's textures (GlContext::createShared); the ViewRenderer, whose
// vertex arrays cannot be shared, lives entirely on it. The latest request for a view replaces one
// not yet started (the latest camera wins: no queue of stale work).
#pragma once

#include "app/context/context.h"
#include "app/workers/latest_wins.h"
#include "app/render/view_images.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace vplab {

class ViewWorker {
 public:
  /// Starts the render thread on `context` (shares the window's objects; made on this thread).
  /// `wake` is called on the render thread when an image is finished (glfwPostEmptyEvent).
  ViewWorker(std::unique_ptr<GlContext> context, std::function<void()> wake);
  /// Lets the image being drawn finish, then ends the thread and frees its GL objects.
  ~ViewWorker();
  ViewWorker(const ViewWorker&) = delete;
  ViewWorker& operator=(const ViewWorker&) = delete;

  /// Asks for an image; replaces this view's request not yet started. Returns its ticket.
  uint64_t request(ViewRequest r);
  /// A finished image: ticket says which request it answers (tickets grow).
  struct Finished {
    uint64_t ticket = 0;
    GLuint texture = 0;
    std::string error;  // what went wrong drawing it (texture 0)
  };
  /// The newest image of `kind` finished since the last call, waiting up to `seconds` for the
  /// request `ticket` to finish. The image returned is the one shown from now on: the thread
  /// never draws into it until a newer one of the same view is taken.
  std::optional<Finished> take(ViewKind kind, uint64_t ticket, double seconds);
  /// Whether an image of `kind` is finished and not yet taken (the window then draws a frame at once).
  bool hasFinished(ViewKind kind) const;
  /// How many images the thread has drawn.
  unsigned drawn() const;

 private:
  static constexpr size_t kViews = kViewKindCount;
  static constexpr size_t kBuffers = 3;  // shown, finished not yet taken, being drawn
  void run();
  size_t freeBuffer(size_t view) const;

  std::unique_ptr<GlContext> ctx_;
  LatestWins<ViewRequest, Finished> queue_;
  // Under the queue's lock: which of a view's three image buffers is shown, which holds the image
  // finished and not yet taken.
  struct Buffers {
    size_t shown = kBuffers;  // none
    size_t finished = 0;
    bool untaken = false;
  };
  std::array<Buffers, kViews> buffers_;
};

}  // namespace vplab
