// The viewer without a window: frames drawn into an off-screen target with synthetic input fed to
// ImGui. `vplab render --view ui`, the UI tests and the input-to-frame benchmark use it.
#pragma once

#include "app/ui/input_queue.h"
#include "app/ui/viewer.h"

namespace vplab {

class HeadlessViewer {
 public:
  HeadlessViewer(GlContext& context, Scene scene, int width, int height, float uiScale = 1.f);

  /// One frame of 1/60 s with the current input; returns nothing, see image().
  void frame();
  /// Several frames (ImGui settles its layout over the first two).
  void frames(int n);
  Image image() const { return target_.read(); }

  // Synthetic input, in the window's pixels.
  void mouseMove(double x, double y);
  void mouseButton(int button, bool down);
  void wheel(float steps);
  /// Presses and releases a key (a code of ui/keys.h) over two frames.
  void key(int code, bool ctrl = false, bool shift = false);
  /// Types `text` (characters, as a keyboard's text input delivers them) in one frame.
  void type(const std::string& text);
  /// Press at `from`, move to `to` in `steps` frames, release: a drag as a user makes it.
  void drag(double fromX, double fromY, double toX, double toY, int button = 0, int steps = 8);
  /// A click without motion.
  void click(double x, double y, int button = 0);
  /// Input as the window delivers it: events queued between frames (a press and its release may
  /// arrive before the same frame). Once used, each frame() feeds ImGui from this queue, as the
  /// window does, instead of the direct calls above.
  InputQueue& input() {
    inputQueued_ = true;
    return input_;
  }

  Viewer& viewer() { return viewer_; }
  ViewerState& state() { return viewer_.state(); }
  /// Where named widgets, handles and views were drawn last frame (app/ui/widgets.h).
  const ui::RectLog& rects() const { return viewer_.rects(); }
  /// The centre of a rect recorded under `id` (ui::RectLog, app/ui/widgets.h). Throws vplab::Error if unknown.
  std::pair<double, double> centreOf(const std::string& id) const;

 private:
  Viewer viewer_;
  gl::RenderTarget target_;
  int width_, height_;
  InputQueue input_;
  bool inputQueued_ = false;
};

}  // namespace vplab
