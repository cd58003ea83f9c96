// The interactive viewer (docs/lecturers.md "The viewer"): the three views in resizable ImGui windows beside
// the panels (camera, scene, matrices, vertex probe, clipping, display). It draws one frame at a
// time into the bound framebuffer, so the same code runs in a GLFW window and headless (`vplab
// render --view ui`, the UI tests). It owns ImGui's context and composes the frame from its parts:
//   ShownRun   the pipeline's run of the shown scene (app/ui/shown_run.h)
//   ViewImages the views' images, here or on the render thread (app/render/view_images.h)
//   FrameErrors, FrameParts  the frames' GL errors and where their time goes (app/render/frame_*.h)
//   ViewPanes  the views in their windows and the mouse in them (app/ui/view_panes.h)
//   Session    files, autosave, recovery, links, lessons opened, without ImGui (app/session/session.h),
//              and its dialogs (app/ui/session_dialogs.h)
//   Menus      the menus, keys, help and export (app/ui/menus.h)
//   PanelWindows  the controls and inspector windows and their panels (app/ui/panel_windows.h)
// and the panels (app/ui/panels.h), all over one ViewerState (app/ui/viewer_state.h).
#pragma once

#include "app/context/context.h"
#include "app/render/frame_errors.h"
#include "app/gl/render_target.h"
#include "app/ui/menus.h"
#include "app/ui/panel_windows.h"
#include "app/session/session.h"
#include "app/ui/session_dialogs.h"
#include "app/ui/shown_run.h"
#include "app/ui/touch_scroll.h"
#include "app/ui/view_panes.h"
#include "app/ui/viewer_state.h"
#include "app/ui/widgets.h"
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
  struct Caught {
    unsigned count = 0;
    std::string last;
    unsigned inARow = 0;  // frames that failed one after the other (the first asks for a frame to show why)
  };
  const Caught& caught() const { return caught_; }

  /// The document's file, autosave, recovery and links (app/session/session.h).
  Session& session() { return session_; }
  const Session& session() const { return session_; }
  /// Makes this viewer's ImGui context the current one (input is fed to the current context).
  void makeCurrent();
  /// Whether a field has the keys (a text field, or a number field's text open): a phone shows its
  /// on-screen keyboard for it (the page, issue 41).
  bool wantsText() const;
  /// A finger lifts moving at (vx, vy) pixels a second (the page measures it from its touch events'
  /// times): a swipe on a panel coasts at that speed (ui::TouchScroll).
  void fingerLifting(float vx, float vy) { touchScroll_.fingerLifting(ImVec2(vx, vy)); }
  ViewerState& state() { return s_; }
  const ViewerState& state() const { return s_; }
  /// Whether a modal dialog (a question of the session, the file chooser) takes the keys.
  bool dialogOpen() const { return dialogs_.open(); }
  /// Where named widgets, handles and views were drawn last frame (the tests' hook, app/ui/widgets.h).
  const ui::RectLog& rects() const { return rects_; }
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
  /// The views' images (app/render/view_images.h): drawn here, on a render thread (useWorker) or in
  /// slices across frames (drawInSlices, the page); what each was drawn from, how many were drawn.
  ViewImages& images() { return images_; }
  const ViewImages& images() const { return images_; }
  /// The pipeline's run of the shown scene (app/ui/shown_run.h): in the frame, on a worker thread
  /// (useWorker, the window) or in steps across frames (runInSteps, the page).
  /// The frame's parts, timed when a sink is set (the page: app/render/frame_parts.h).
  FrameParts& parts() { return parts_; }
  ShownRun& run() { return run_; }
  const ShownRun& run() const { return run_; }
  /// The metrics the views' labels are measured with (the tests of where the labels went).
  const TextMetrics& viewTextMetrics() const { return renderer_.textMetrics(); }
  /// Asks for `n` more frames (something changed that ImGui shows only after it laid it out again).
  void requestFrames(int n) { settleFrames_ = std::max(settleFrames_, n); }

  /// The view as File > Export draws it (the shown settings) at width × height pixels, with this
  /// viewer's GL backend; the bound framebuffer stays bound.
  Image exportImage(ViewKind kind, int width, int height);
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
  /// The frame's windows: the menus, panels, views and dialogs (the lecture's and the embed form's few).
  void windows(double now, bool modal);
  /// After a frame ended in `what`: ImGui's frame closed, the last good state back, the reason said.
  void recoverFrom(const std::string& what);
  /// The pipeline's run of the shown scene, when it changed (app/ui/shown_run.h).
  void updateRun();
  void setStatus(std::string message, bool error);
  void applyUiScale(float scale);

  GlContext& ctx_;
  ImGuiContext* imgui_ = nullptr;
  ViewRenderer renderer_;
  FrameParts parts_;
  FrameErrors errors_;  // the frames' GL errors (read later in the page: app/render/frame_errors.h)
  ViewImages images_;
  ViewerState s_;
  ShownRun run_;
  ViewPanes panes_;
  Session session_;
  SessionDialogs dialogs_;
  PanelWindows windows_;
  ui::RectLog rects_;
  Menus menus_;
  float uiScale_;
  Theme styledTheme_ = Theme::dark;  // the ImGui colours set up (StyleColorsDark or Light)
  ui::TouchScroll touchScroll_;      // a swipe scrolls the panel under the finger
  bool styledTouch_ = false;         // the style set up for a finger (app/ui/touch.h)
  float styledCssPixel_ = 1.f;       // ... of a CSS pixel this large
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
  Caught caught_;
};

}  // namespace vplab
