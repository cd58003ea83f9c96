// The interactive viewer (README "The viewer"): the three views in resizable ImGui windows beside
// the panels (camera, scene, matrices, vertex probe, clipping, display). It draws one frame at a
// time into the bound framebuffer, so the same code runs in a GLFW window and headless (`vplab
// render --view ui`, the UI tests).
#pragma once

#include "app/context/context.h"
#include "app/gl/render_target.h"
#include "app/ui/autosave.h"
#include "app/ui/file_dialog.h"
#include "app/ui/loader.h"
#include "app/ui/url_state.h"
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
  /// platform has fed ImGui its input, display size and time step before.
  void frame(GLuint framebuffer, int width, int height);

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
  /// uses it as its timeout (README "The viewer": an idle window uses no CPU).
  double wakeIn() const;
  /// How many times a view was drawn (not reused from its last image): tests check hover frames cost none.
  unsigned viewsDrawn() const { return images_.drawn(); }
  /// Draws the views on a render thread with `context` (GlContext::createShared of the window's):
  /// a view whose image is not ready within the frame shows its last image with a busy mark.
  /// `wake` wakes the window's event wait (called on the render thread). Without it (headless, the
  /// UI tests) each view is drawn in the frame that needs it.
  void useViewWorker(std::unique_ptr<GlContext> context, std::function<void()> wake) {
    images_.useWorker(std::move(context), std::move(wake));
  }
  /// Whether `kind` shows an older image while its current one is being drawn.
  bool viewBusy(ViewKind kind) const { return images_.busy(kind); }
  /// Asks for `n` more frames (something changed that ImGui shows only after it laid it out again).
  void requestFrames(int n) { settleFrames_ = std::max(settleFrames_, n); }

  /// Opens a scene file on a worker thread (File > Open, presets); the views keep drawing the open
  /// scene, with a progress bar and Cancel, until it has loaded.
  void openScene(const std::filesystem::path& file);
  const SceneLoader& loader() const { return loader_; }
  SceneLoader& loader() { return loader_; }
  /// Cancel of the loading bar.
  void cancelLoading();

  /// Turns on autosave into `directory` (Autosave::defaultDirectory() in the window).
  void enableAutosave(const std::filesystem::path& directory, double delaySeconds);
  const Autosave* autosave() const { return autosave_.get(); }
  /// Asked to end by a signal: writes the recovery file if there are unsaved changes. Returns it, or
  /// an empty path when nothing needed saving.
  std::filesystem::path writeRecoveryNow();
  /// A normal end (quit): this session leaves no recovery file.
  void endSession();
  /// At start: an earlier session left unsaved changes; a dialog offers to recover them.
  void offerRecovery(Recovery recovery);
  bool recoveryOffered() const { return recovery_.has_value(); }

  /// Whether `file` is one of the scenes shipped with vplab (assets/scenes/): Save never writes there.
  bool isBundled(const std::filesystem::path& file) const;
  const FileChooser& fileDialog() const { return *dialog_; }
  /// Replaces the ImGui file dialog (the browser's picker and downloads); `browser`: the shortcuts
  /// the browser owns (Ctrl+S, Ctrl+O, Ctrl+N, Ctrl+Q, F11, F12) are left to it and Quit is not offered.
  void useFileChooser(std::unique_ptr<FileChooser> chooser, bool browser);
  /// Opens a file given by the platform (a drop, the browser's picker): an OBJ joins the scene as a
  /// mesh object, anything else is opened as a scene (asking first when changes would be lost).
  void openFile(const std::filesystem::path& file);
  /// The view as File > Export draws it (the shown settings) at width × height pixels, with this
  /// viewer's GL backend; the bound framebuffer stays bound.
  Image exportImage(ViewKind kind, int width, int height);
  /// What is shown, for a link (app/ui/url_state.h): the bundled scene's name, the camera, the
  /// views' styles and observers, the clipping strategy.
  UrlState urlState() const;
  /// Shows a link's state. A named bundled scene starts a new document with the link's camera (at
  /// start, or asking first when changes would be lost); a camera alone is an edit of the open
  /// scene (undoable). Throws vplab::Error when the scene is not bundled or cannot be read.
  void showUrlState(const UrlState& link, bool atStart);
  /// Every view is drawn again in the next frame (the browser's frame-time benchmark).
  void forgetViewImages();

  /// Written by F12 into the working directory; the runner reads the window back.
  bool screenshotRequested() const { return screenshotRequested_; }
  void screenshotTaken(const std::string& file);
  /// F12's screenshot could not be taken (`why`: the views not ready in time): said in the status line.
  void screenshotFailed(const std::string& why);
  /// The views shown in the last frame with an older image and the busy mark, while the render thread
  /// draws their current one. A screenshot is taken only when this is empty: it shows what was asked
  /// for, never an "updating…" frame (on a fresh machine llvmpipe compiles the views' shaders for the
  /// first ~0.8 s).
  std::vector<ViewKind> viewsNotReady() const { return images_.notReady(); }

 private:
  void menuBar();
  void shortcuts();
  void controlsWindow();
  void inspectWindow();
  void viewWindows();
  void helpWindow();
  void quitDialog();
  /// Runs `action` (which replaces the scene) at once, or after the user agreed to lose unsaved changes.
  void unlessUnsaved(std::function<void()> action);
  void discardDialog();
  void exportMenu();
  /// Runs the CPU pipeline when the shown scene or the options changed (frames drawn for hover and
  /// ImGui's settling cost none) and publishes the run.
  void updateRun();
  /// A new document (opened, preset, New, recovered): clean unless recovered, no undo history, and
  /// the view settings of a fresh start (a style chosen for the old scene, e.g. hidden-line, may be
  /// far too slow for the new one; README "The viewer").
  void startDocument(Scene scene, bool dirty = false);
  void saveScene(const std::filesystem::path& file);
  void writeScene(const std::filesystem::path& file);
  void chooseFileToOpen();
  void saveAs();
  void loadingWindow();
  void recoveryDialog();
  void setStatus(std::string message, bool error);
  std::optional<Vec3> probePositionOf(ViewKind view) const;
  void orbitInteraction(bool hovered, ViewKind view, Orbit& orbit, const ViewCamera& observer, int w, int h, Vec2 mouse);
  void recordHandles(ImVec2 origin, const ViewCamera& observer, ImVec2 fbScale);
  void worldInteraction(bool hovered, const ViewCamera& observer, int w, int h, Vec2 mouse);
  void morphInteraction(bool hovered);
  void cameraWindowContents();
  void applyUiScale(float scale);
  void morphWindow();
  void lectureWindow();
  void stepHighlight();
  /// Draws a view into its target for an image of `size` screen units; returns the texture. Reuses
  /// the last image while nothing it shows changed.
  GLuint drawView(ViewKind kind, ImVec2 size);
  /// A spinner and "updating…" in the top right corner of the last item (a view's image) while
  /// `kind` is busy.
  void busyMark(ViewKind kind);

  GlContext& ctx_;
  ImGuiContext* imgui_ = nullptr;
  ViewRenderer renderer_;
  ViewImages images_;
  ViewerState s_;
  std::unique_ptr<FileChooser> dialog_ = std::make_unique<FileDialog>();
  bool browser_ = false;
  float uiScale_;
  int lastWidth_ = 0, lastHeight_ = 0;
  bool relayout_ = true;
  bool screenshotRequested_ = false;
  std::function<void()> pendingReplace_;  // waiting for "discard the unsaved changes?"
  bool askDiscard_ = false;
  unsigned lastActive_ = 0;  // the ImGui item active in the previous frame
  /// The pixel size of the image of `kind` asked for last (for picking in it).
  int cachedWidth(ViewKind kind) const { return images_.width(kind); }
  int cachedHeight(ViewKind kind) const { return images_.height(kind); }
  /// The runs of the CPU pipeline: s_.ran is one of them; the other is run into next, reusing its
  /// buffers, when nothing else (the render thread) still holds it.
  std::array<std::shared_ptr<PipelineRun>, 2> runs_;
  unsigned runRevision_ = 0;      // counts the runs published
  unsigned ranShownRevision_ = 0; // the shown scene's revision (Document::shownRevision) of s_.ran
  PipelineOptions ranOptions_;
  bool ranOnce_ = false;
  int settleFrames_ = 2;     // frames still to draw without input (wakeIn)
  SceneLoader loader_;
  std::unique_ptr<Autosave> autosave_;
  std::string autosaveError_;  // the last one shown
  std::optional<Recovery> recovery_;
  bool askRecovery_ = false;
};

}  // namespace vplab
