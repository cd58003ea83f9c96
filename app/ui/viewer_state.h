// Everything the interactive viewer knows between frames, in one owned struct (no globals).
#pragma once

#include "app/document/assets.h"
#include "app/document/document.h"
#include "app/lessons/lesson_player.h"
#include "app/inspect/picking.h"
#include "app/lessons/tabs.h"
#include "app/views/views.h"
#include "pipeline/pipeline.h"

#include <imgui.h>

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string_view>
#include <string>

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

struct ViewerState;
/// Brings the tab `name` (one of kTabNames) forward; false for any other name.
bool selectTab(ViewerState& s, std::string_view name);

struct ViewerState {
  explicit ViewerState(Scene scene) : doc(std::move(scene)) {}

  Document doc;
  DisplaySettings display;     // how the views show the scene: styles, observers, overlays (kept, linked)
  Highlights highlights;       // this frame's marks: the probe, the handles, the step-through (never kept)
  PipelineOptions pipeline = kFreshPipeline;
  /// The CPU pipeline's run of doc.shown(), published whole (app/ui/viewer.h, updateRun): the
  /// render thread draws from the same run, never a copy.
  std::shared_ptr<const PipelineRun> ran = std::make_shared<const PipelineRun>();
  const PipelineRun& run() const { return *ran; }
  /// The scene `ran` ran on: the views draw the two together. With the pipeline on a worker thread
  /// (the window) it may be older than doc.shown() for a few frames.
  std::shared_ptr<const Scene> ranScene = std::make_shared<const Scene>();
  std::string runError;         // when even the shown scene could not be run
  std::optional<Probe> probe;
  Handle hovered = Handle::none;
  Drag drag;
  int selectedObject = 0;
  double worldAspect = 1.6;    // of the world view's image, for framing the observer
  bool keepAspect = true;       // the window keeps the device's aspect ratio
  bool antialias = true;        // 4× multisampling in the world, NPC and morph views (off by default on
                                // a software renderer, where it costs more than all the drawing)
  bool seedForm = false;        // matrices in the lecture notes' row-vector form (transposed)
  bool showHelp = false;
  bool quitRequested = false;   // asked to quit; a dirty document asks first
  bool screenshotRequested = false;  // F12 or the menu: the window (or the page) reads the frame back
  bool quitConfirmed = false;
  // Lecture features.
  bool showMorph = false;       // the stage morph window
  bool morphPlaying = false;
  double morphSpeed = 0.5;      // stages per second
  StepThrough stepThrough;
  bool lectureMode = false;     // one view fills the window, no panels (F11)
  // The compact layout of a phone's screen (ui::tooSmallForDesktop): one view at a time, chosen in
  // the switcher at the bottom, and at most one panel below it (upright) or beside it (on its side).
  bool compactAllowed = false;  // the page allows it; the desktop window keeps its layout
  ViewKind compactView = ViewKind::world;
  enum CompactPanel { noPanel, controlsPanel, inspectPanel };
  int compactPanel = noPanel;
  bool compactShown = false;    // the last frame had the compact layout
  ViewKind lectureView = ViewKind::world;
  float uiScale = 1.f;          // fonts and handles; applied at the start of the next frame
  std::vector<SceneFileInfo> presets;  // assets/scenes/, for the presets menu
  std::optional<SceneObject> objectToLoad;  // an OBJ mesh object to add: its mesh is built on a worker thread

  // The window draws only on input (run_viewer.cpp): a panel showing something timed (a fading
  // notice) keeps frames coming until this ImGui time (ImGui::GetTime()).
  double animateUntil = 0;
  struct Typing {
    ImGuiID id = 0;             // the drag field whose text is being typed (0: none)
    ImGuiID field = 0;          // which of its components
    std::array<double, 4> values{};  // its values so far, applied when it loses focus
  } typing;
  struct Copied {
    std::string id;             // the copy button that copied last
    double at = 0;              // when (ImGui time, s)
  } copied;
  std::optional<Probe> probeShown;  // the probe the inspector showed last frame (a new one brings its tab forward)
  enum ControlsTab { cameraTab, sceneTab, clippingTab, displayTab, lectureTab };
  enum InspectTab { probeTab, matricesTab, depthTab };
  int controlsTab = cameraTab;
  int inspectTab = probeTab;
  bool showStepThrough = false; // bring the Lecture tab's step-through forward (Shift+click in the camera view)

  // A lesson being presented (app/ui/lesson_presenter.h): its steps and the move into the step shown.
  std::optional<LessonPlayer> lesson;
  double lessonSeconds = 0.8;   // how long the move from one step into the next takes
  std::string lessonTyped;      // the digits of a step number typed so far (Enter goes there)
  std::vector<LessonHighlight> lessonMarks;  // the highlights of the step reached (none while moving)
  bool lessonScroll = false;    // the step's highlighted matrix is still to be scrolled into sight
  std::string lessonScrollTo;   // the panel's place the step's evidence starts at (ui::scrollAnchor), still to be scrolled to
  int lessonScrollFrames = 0;   // the frames it is still scrolled to
  std::vector<ViewKind> embedViews;  // the embed form (a link's `embed=`): only these views and the caption
  float captionHeight = 0;      // the lesson's caption box, across the bottom of the layout (0: none)

  std::string status;           // the last message (saved, loaded, an error)
  bool statusIsError = false;

  // Where named widgets and views were drawn last frame (screen coordinates): the UI tests drive
  // the viewer through them with synthetic input.
  std::map<std::string, ImVec4> rects;  // x, y, width, height
  // The part of each rect recorded in the last frame that could be seen: inside its window and its
  // scroll region, not scrolled away (a lesson step's evidence must be on screen: issue 37).
  std::map<std::string, ImVec4> visibleRects;
};

}  // namespace vplab
