// The viewer's state between frames without ImGui or GL (issue 39 item 2), in parts: each part is
// what one concern of the viewer keeps, so a function can be handed the part it works on (the
// session: the document, the views' choices, the lecture's state and the status; a panel: the parts
// it edits). ViewerModel is all of them; ViewerState (app/ui/viewer_state.h) adds what the widgets
// remember between frames. No mutable globals: the viewer owns one.
#pragma once

#include "app/document/document.h"
#include "app/document/url_state.h"
#include "app/inspect/picking.h"
#include "app/lessons/lesson_player.h"
#include "app/practice/practice.h"
#include "app/views/views.h"
#include "pipeline/pipeline.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

/// A mouse drag in a view, from button press to release.
struct Drag {
  enum class Kind { none, orbit, pan, handle };
  Kind kind = Kind::none;
  ViewKind view = ViewKind::world;
  Handle handle = Handle::none;
};

/// The clipping step-through: a face of an object and how many of the six planes have been applied.
struct StepThrough {
  bool active = false;
  int object = 0;  // index into scene.objects
  int face = 0;
  int step = 0;    // 0: the original polygon; k: after the k-th plane (left, right, bottom, top, back, front)
};

/// The pipeline's options of a fresh document: clipping in NPC, no bounding-box test, the clipped edges.
inline constexpr PipelineOptions kFreshPipeline{ClipStrategy::npc, false, true};

/// The scene being edited, with its undo history and file (app/document/document.h).
struct DocumentPart {
  explicit DocumentPart(Scene scene) : doc(std::move(scene)) {}
  Document doc;
};

/// What the user chose to see: kept across documents' frames, written into links and recovery files.
struct ViewsPart {
  DisplaySettings display;     // styles, observers, overlays, theme, the labels' language
  PipelineOptions pipeline = kFreshPipeline;
  std::vector<ViewKind> embedViews;  // the embed form (a link's `embed=`): only these views and the caption
  Language language() const { return display.language; }
};

/// The CPU pipeline's run the views draw (app/ui/shown_run.h publishes it whole).
struct RunPart {
  /// The render thread draws from the same run, never a copy.
  std::shared_ptr<const PipelineRun> ran = std::make_shared<const PipelineRun>();
  const PipelineRun& run() const { return *ran; }
  /// The scene `ran` ran on: the views draw the two together. With the pipeline on a worker thread
  /// (the window) it may be older than doc.shown() for a few frames.
  std::shared_ptr<const Scene> ranScene = std::make_shared<const Scene>();
  std::string runError;         // when even the shown scene could not be run
};

/// What the pointer and the panels work on.
struct EditPart {
  Highlights highlights;        // this frame's marks: the probe, the handles, the step-through (never kept)
  std::optional<Probe> probe;
  std::optional<Probe> probeShown;  // the probe the inspector showed last frame (a new one brings its tab forward)
  Handle hovered = Handle::none;
  Drag drag;
  int selectedObject = 0;
  std::optional<SceneObject> objectToLoad;  // an OBJ mesh object to add: its mesh is built on a worker thread
};

/// The lecture's features and the lesson being presented (app/ui/lesson_presenter.h).
struct LecturePart {
  bool showMorph = false;       // the stage morph window
  bool morphPlaying = false;
  double morphSpeed = 0.5;      // stages per second
  StepThrough stepThrough;
  bool showStepThrough = false; // bring the Lecture tab's step-through forward (Shift+click in the camera view)
  bool lectureMode = false;     // one view fills the window, no panels (F11)
  ViewKind lectureView = ViewKind::world;
  bool seedForm = false;        // matrices in the lecture notes' row-vector form (transposed)
  // A lesson: its steps and the move into the step shown.
  std::optional<LessonPlayer> lesson;
  double lessonAspect = 0;      // the world view's aspect the open lesson's steps were framed for
  bool lessonReframe = false;   // the world view first drawn in another shape: the lesson is framed again
  double lessonSeconds = 0.8;   // how long the move from one step into the next takes
  std::string lessonTyped;      // the digits of a step number typed so far (Enter goes there)
  std::vector<LessonHighlight> lessonMarks;  // the highlights of the step reached (none while moving)
  bool lessonScroll = false;    // the step's highlighted matrix is still to be scrolled into sight
  std::string lessonScrollTo;   // the panel's place the step's evidence starts at (ui::scrollAnchor), still to be scrolled to
  int lessonScrollFrames = 0;   // the frames it is still scrolled to
};

/// An exercise being practised (issue 40): the sheet in the Tasks panel, the student's fields, the
/// last Check (app/session/exercises.h).
struct PracticePart {
  std::optional<Practice> practice;
  std::optional<PracticeCheck> check;  // of practice->edits == check->edits: the fields as they are
  uint64_t keptEdits = 0;              // the fields' state last kept (the answer's autosave)
  bool showTasks = false;              // bring the Tasks tab forward (an exercise opened)
  bool focusFirstField = false;        // the first field takes the keys when the Tasks are next drawn
};

/// How the window is laid out and drawn.
struct LayoutPart {
  double worldAspect = 1.6;     // of the world view's image, for framing the observer
  bool keepAspect = true;       // the window keeps the device's aspect ratio
  bool antialias = true;        // 4× multisampling in the world, NPC and morph views (off by default on
                                // a software renderer, where it costs more than all the drawing)
  float uiScale = 1.f;          // fonts and handles; applied at the start of the next frame
  // The last pointer was a finger (the page on a touch screen): targets a finger's size, handles and
  // vertices hit within a finger's radius (app/ui/touch.h, issue 41); applied with uiScale.
  bool touch = false;
  float cssPixel = 1.f;         // screen pixels a CSS pixel has (the page's devicePixelRatio; 1 on the desktop)
  bool showHelp = false;
  // The compact layout of a phone's screen (ui::tooSmallForDesktop): one view at a time, chosen in
  // the switcher at the bottom, and at most one panel below it (upright) or beside it (on its side).
  bool compactAllowed = false;  // the page allows it; the desktop window keeps its layout
  bool inBrowser = false;       // the page: the browser owns F11, lecture mode takes the browser's full screen
  ViewKind compactView = ViewKind::world;
  enum CompactPanel { noPanel, controlsPanel, inspectPanel };
  int compactPanel = noPanel;
  bool compactShown = false;    // the last frame had the compact layout
  enum ControlsTab { cameraTab, sceneTab, clippingTab, displayTab, lectureTab };
  enum InspectTab { probeTab, matricesTab, depthTab, tasksTab };
  int controlsTab = cameraTab;
  int inspectTab = probeTab;
  float captionHeight = 0;      // the lesson's caption box, across the bottom of the layout (0: none)
  // The window draws only on input (run_viewer.cpp): a panel showing something timed (a fading
  // notice) keeps frames coming until this ImGui time.
  double animateUntil = 0;
};

/// Brings the tab `name` (one of kTabNames, app/lessons/tabs.h) forward; false for any other name.
bool selectTab(LayoutPart& layout, std::string_view name);

/// The status line and what the user asked of the program as a whole.
struct StatusPart {
  std::string status;           // the last message (saved, loaded, an error)
  bool statusIsError = false;
  bool quitRequested = false;   // asked to quit; a dirty document asks first
  bool quitConfirmed = false;
  bool screenshotRequested = false;  // F12 or the menu: the window (or the page) reads the frame back
  // The parts of the last link that were left out (issue 41): named over the views until the user
  // changes what the link showed (the page clears them) or follows another link.
  std::vector<LinkProblem> linkProblems;
  void setStatus(std::string message, bool error) {
    status = std::move(message);
    statusIsError = error;
  }
};

/// All the parts: what the viewer knows between frames, without the widgets' memory.
struct ViewerModel : DocumentPart, ViewsPart, RunPart, EditPart, LecturePart, PracticePart, LayoutPart, StatusPart {
  explicit ViewerModel(Scene scene) : DocumentPart(std::move(scene)) {}
};

}  // namespace vplab
