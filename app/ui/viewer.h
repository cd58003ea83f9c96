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
#include "app/ui/view_worker.h"
#include "app/ui/viewer_state.h"
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
  unsigned viewsDrawn() const { return viewsDrawn_; }
  /// Draws the views on a render thread with `context` (GlContext::createShared of the window's):
  /// a view whose image is not ready within the frame shows its last image with a busy mark.
  /// `wake` wakes the window's event wait (called on the render thread). Without it (headless, the
  /// UI tests) each view is drawn in the frame that needs it.
  void useViewWorker(std::unique_ptr<GlContext> context, std::function<void()> wake);
  /// Whether `kind` shows an older image while its current one is being drawn.
  bool viewBusy(ViewKind kind) const { return viewCache_[size_t(kind)].busy; }
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
  std::vector<ViewKind> viewsNotReady() const;

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
  void runPipeline();
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
  GLuint differenceTexture();
  GLuint divideFirstTexture();
  GLuint uploadImage(gl::Texture& texture, const Image& image);
  void applyUiScale(float scale);
  void morphWindow();
  void lectureWindow();
  void stepHighlight();
  /// Draws a view into its target for an image of `size` screen units; returns the texture. Reuses
  /// the last image while nothing it shows changed.
  GLuint drawView(ViewKind kind, ImVec2 size);
  GLuint drawViewNow(ViewKind kind, int w, int h);
  /// A spinner and "updating…" in the top right corner of the last item (a view's image) while
  /// `kind` is busy.
  void busyMark(ViewKind kind);

  GlContext& ctx_;
  ImGuiContext* imgui_ = nullptr;
  ViewRenderer renderer_;
  ViewerState s_;
  gl::RenderTarget world_, camera_, npc_, morph_, divideFirst_;
  gl::Texture differenceTexture_;
  /// The divide-first comparison is drawn into divideFirst_ again only after a new run of the pipeline.
  unsigned divideFirstRevision_ = 0;  // the run it was drawn from (0: none yet)
  std::unique_ptr<FileChooser> dialog_ = std::make_unique<FileDialog>();
  bool browser_ = false;
  float uiScale_;
  int lastWidth_ = 0, lastHeight_ = 0;
  bool relayout_ = true;
  bool screenshotRequested_ = false;
  std::function<void()> pendingReplace_;  // waiting for "discard the unsaved changes?"
  bool askDiscard_ = false;
  unsigned lastActive_ = 0;  // the ImGui item active in the previous frame
  /// What a view's image was drawn from: equal stamps give equal images.
  struct ViewStamp {
    Scene scene;
    unsigned runRevision = 0;
    FrameSettings frame;
    int width = 0, height = 0, samples = 0;
    float uiScale = 0;
    bool operator==(const ViewStamp&) const = default;
  };
  struct ViewCache {
    ViewStamp stamp;
    GLuint texture = 0;
    int width = 0, height = 0;  // of the image asked for last, in pixels
    // With the render thread: the image asked for and not yet shown.
    ViewStamp requested;
    uint64_t ticket = 0;
    uint64_t askedAt = 0;  // the frame that asked for it
    bool pending = false;
    bool busy = false;  // shown with an older image in this frame
    bool asked = false;  // drawView was called for it in this frame
  };
  /// The render thread's image of `kind` if it finishes within what is left of the frame's wait.
  GLuint drawViewOnWorker(ViewKind kind, ViewStamp stamp, int w, int h);
  /// The pixel size of the image of `kind` asked for last (for picking in it).
  int cachedWidth(ViewKind kind) const { return viewCache_[size_t(kind)].width; }
  int cachedHeight(ViewKind kind) const { return viewCache_[size_t(kind)].height; }
  std::array<ViewCache, 5> viewCache_;  // by ViewKind
  unsigned runRevision_ = 0;            // counts the runs of the CPU pipeline
  unsigned viewsDrawn_ = 0;
  Scene ranScene_;                // the input of s_.run (runPipeline runs only when it changes)
  PipelineOptions ranOptions_;
  bool ranOnce_ = false;
  std::unique_ptr<ViewWorker> worker_;
  std::shared_ptr<const PipelineRun> workerRun_;  // s_.run of runRevision workerRunRevision_
  unsigned workerRunRevision_ = 0;
  double frameWaitLeft_ = 0;
  uint64_t frameNumber_ = 0;  // seconds this frame may still wait for the render thread
  int settleFrames_ = 2;     // frames still to draw without input (wakeIn)
  SceneLoader loader_;
  std::unique_ptr<Autosave> autosave_;
  std::string autosaveError_;  // the last one shown
  std::optional<Recovery> recovery_;
  bool askRecovery_ = false;
};

}  // namespace vplab
