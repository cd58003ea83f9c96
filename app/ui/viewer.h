// The interactive viewer (docs/lecturers.md "The viewer"): the three views in resizable ImGui windows beside
// the panels (camera, scene, matrices, vertex probe, clipping, display). It draws one frame at a
// time into the bound framebuffer, so the same code runs in a GLFW window and headless (`vplab
// render --view ui`, the UI tests). It owns ImGui's context and composes the frame from its parts:
//   ShownRun   the pipeline's run of the shown scene (app/ui/shown_run.h)
//   ViewImages the views' images, here or on the render thread (app/render/view_images.h)
//   ViewPanes  the views in their windows and the mouse in them (app/ui/view_panes.h)
//   Session    files, autosave, recovery, links (app/ui/session.h)
//   Menus      the menus, keys, help and export (app/ui/menus.h)
// and the panels (app/ui/panels.h), all over one ViewerState (app/ui/viewer_state.h).
#pragma once

#include "app/context/context.h"
#include "app/gl/render_target.h"
#include "app/ui/menus.h"
#include "app/ui/session.h"
#include "app/ui/shown_run.h"
#include "app/ui/view_panes.h"
#include "app/ui/viewer_state.h"
#include "app/render/view_images.h"
#include "app/render/view_renderer.h"

#include <algorithm>
#include <array>
#include <functional>
#include <memory>

struct ImGuiContext;

namespace vplab {

class Viewer {
 public:
  /// Creates the ImGui context and its OpenGL3 renderer on `context` (current).
  Viewer(GlContext& context, Scene scene, float uiScale = 1.f);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  /// Builds and draws one frame into `framebuffer` (0: the window) of width × height pixels. The
  /// platform has fed ImGui its input, display size and time step before. Never throws: an error
  /// that arises in a frame (a lesson move, a view, the GL driver) is caught, the ImGui frame is
  /// closed, the last state a frame was drawn from is shown again, and the status line says why
  /// (issue 37: no input ends the window).
  void frame(GLuint framebuffer, int width, int height);
  /// How many errors frame() caught (a frame's exception, a GL error, a view's image that failed on
  /// the render thread), and the last one's message: none is expected, so the monkey test fails on any.
  unsigned caughtErrors() const { return caught_.count; }
  const std::string& lastCaughtError() const { return caught_.last; }

  /// The document's file, autosave, recovery and links (app/ui/session.h).
  Session& session() { return session_; }
  const Session& session() const { return session_; }
  /// Makes this viewer's ImGui context the current one (input is fed to the current context).
  void makeCurrent();
  ViewerState& state() { return s_; }
  const ViewerState& state() const { return s_; }
  /// The window's close button or Ctrl+Q: quits at once when nothing is unsaved, else asks.
  void requestQuit() { s_.quitRequested = true; }
  bool shouldQuit() const { return s_.quitConfirmed; }
  /// The window title: "vplab — scene.json *" (the star: unsaved changes).
  std::string title() const;

  /// Seconds until the viewer needs its next frame while no input arrives: 0 while something moves
  /// (the stage morph plays, a scene loads, ImGui settles after a change), the text cursor's blink
  /// while a field is edited, the next autosave; a large number when idle. The window's event wait
  /// uses it as its timeout (docs/lecturers.md "The viewer": an idle window uses no CPU).
  double wakeIn() const;
  /// How many times a view was drawn (not reused from its last image): tests check hover frames cost none.
  unsigned viewsDrawn() const { return images_.drawn(); }
  /// The views asked for in the last frame, what each was drawn from, and the metrics their labels
  /// are measured with (for the tests of where the labels went: tests/app/ui/lesson_layout_test.cpp).
  std::vector<ViewKind> viewsShown() const { return images_.asked(); }
  const ViewRequest* viewRequest(ViewKind kind) const { return images_.lastRequest(kind); }
  const TextMetrics& viewTextMetrics() const { return renderer_.textMetrics(); }
  /// Draws the views on a render thread with `context` (GlContext::createShared of the window's):
  /// a view whose image is not ready within the frame shows its last image with a busy mark.
  /// `wake` wakes the window's event wait (called on the render thread). Without it (headless, the
  /// UI tests) each view is drawn in the frame that needs it.
  void useViewWorker(std::unique_ptr<GlContext> context, std::function<void()> wake) {
    images_.useWorker(std::move(context), std::move(wake));
  }
  /// Runs the CPU pipeline on a worker thread: the frame that changed the scene waits a few ms for
  /// its run (a small scene's arrives in it), later frames show the last run until the new one is
  /// finished. `wake` wakes the window's event wait (called on the worker). Without it (headless,
  /// the UI tests) the pipeline runs in the frame that needs it.
  void usePipelineWorker(std::function<void()> wake);
  /// Without threads (the page): the pipeline runs in steps, about `secondsPerFrame` of each frame
  /// (PipelineJob), so no frame waits for a large scene's run.
  void runPipelineInSteps(double secondsPerFrame) { run_.runInSteps(secondsPerFrame); }
  /// Whether a run of the pipeline is under way on the worker or in steps (the views show the last one).
  bool runPending() const { return run_.pending(); }
  /// How far the run in steps is (0 to 1), while one is under way.
  std::optional<double> runProgress() const { return run_.progress(); }
  /// Whether `kind` shows an older image while its current one is being drawn.
  bool viewBusy(ViewKind kind) const { return images_.busy(kind); }
  /// Without a render thread (the page): the views are drawn across frames in slices of about this
  /// many triangles to begin with (ViewImages::drawInSlices), so no frame waits for a million of them.
  void drawViewsInSlices(size_t trianglesPerFrame) { images_.drawInSlices(trianglesPerFrame); }
  /// Asks for `n` more frames (something changed that ImGui shows only after it laid it out again).
  void requestFrames(int n) { settleFrames_ = std::max(settleFrames_, n); }

  /// The view as File > Export draws it (the shown settings) at width × height pixels, with this
  /// viewer's GL backend; the bound framebuffer stays bound.
  Image exportImage(ViewKind kind, int width, int height);
  /// Every view is drawn again in the next frame (the browser's frame-time benchmark).
  void forgetViewImages();
  /// The context lost every GL object and is usable again (a WebGL context lost and restored): the
  /// views' backend, their render targets and ImGui's renderer (its shaders and font texture) are
  /// made again. The document, its undo history, the views' observers and settings stay: they hold
  /// no GL object. Throws vplab::Error when the context cannot make them.
  void recreateGlObjects();

  /// Written by F12 into the working directory; the runner reads the window back.
  bool screenshotRequested() const { return s_.screenshotRequested; }
  void screenshotTaken(const std::string& file);
  /// F12's screenshot could not be taken (`why`: the views not ready in time): said in the status line.
  void screenshotFailed(const std::string& why);
  /// The views shown in the last frame with an older image and the busy mark, while the render thread
  /// draws their current one. A screenshot is taken only when this is empty: it shows what was asked
  /// for, never an "updating…" frame (on a fresh machine llvmpipe compiles the views' shaders for the
  /// first ~0.8 s).
  std::vector<ViewKind> viewsNotReady() const;

 private:
  void drawFrame(GLuint framebuffer, int width, int height);
  /// After a frame ended in `what`: ImGui's frame closed, the last good state back, the reason said.
  void recoverFrom(const std::string& what);
  void controlsWindow();
  void inspectWindow();
  void compactSwitcher();
  /// The pipeline's run of the shown scene, when it changed (app/ui/shown_run.h).
  void updateRun();
  void setStatus(std::string message, bool error);
  void applyUiScale(float scale);

  GlContext& ctx_;
  ImGuiContext* imgui_ = nullptr;
  ViewRenderer renderer_;
  ViewImages images_;
  ViewerState s_;
  ShownRun run_;
  ViewPanes panes_;
  Session session_;
  Menus menus_;
  float uiScale_;
  Theme styledTheme_ = Theme::dark;  // the ImGui colours set up (StyleColorsDark or Light)
  int lastWidth_ = 0, lastHeight_ = 0;
  bool inspectorLeft_ = false;  // the lesson layout's inspector in the tall column (ui::lessonEvidenceInInspector)
  bool relayout_ = true;
  unsigned lastActive_ = 0;  // the ImGui item active in the previous frame
  int settleFrames_ = 2;     // frames still to draw without input (wakeIn)
  // The state the last frame that ended well was drawn from: what recoverFrom shows again.
  struct LastGood {
    Scene scene;
    unsigned revision = 0, generation = 0;  // the document's shownRevision and generation it is of
    DisplaySettings display;
    PipelineOptions pipeline;
  };
  std::optional<LastGood> lastGood_;
  struct Caught {
    unsigned count = 0;
    unsigned inARow = 0;
    std::string last;
  } caught_;
};

}  // namespace vplab
