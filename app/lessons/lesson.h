// A lesson (docs/lecturers.md "Lessons"): the lecture as an ordered set of steps, each a state of the lab
// with a caption, that a lecturer advances with a key or a clicker and a student walks through alone.
//
// A lesson is a JSON file a lecturer writes in an editor, read as strictly as a scene (io/scene_io.h):
//
//   { "title": "View orientation", "language": "en",
//     "steps": [ { "caption": "VRP, PRP and VUP give $U$, $V$ and $N$ …", "section": "15.2.2",
//                  "scene": "default" or "scene_file": "my-scene.json",     (the first step names one)
//                  "camera": { any of the scene format's camera keys },
//                  "objects": { "NAME": {"visible": false, "translate": […], "rotate": […], "scale": s} },
//                  "clip_planes": [ … ],                                   (replace the scene's)
//                  "views": { "camera"|"world"|"npc": {"style": "wire", "orbit": {…}} },
//                  "overlays": { "frustum": true, "vertex_names": true, … },
//                  "strategy": "npc" | "wc" | "divide-first",  "bounding_box": true,
//                  "morph": 2.5,                        (and the stage morph's window opens)
//                  "select": "NAME",                    (its vanishing points are drawn)
//                  "tab": "matrices",
//                  "probe": {"object": "NAME", "vertex": 3},
//                  "step_through": {"object": "NAME", "face": 0, "plane": 4},
//                  "highlight": [ {"handle": "prp"}, {"matrix": "npcFromVrc", "row": 2, "column": 3},
//                                 {"vertex": {"object": "NAME", "vertex": 3}}, {"plane": "front"},
//                                 {"axis": "n"} ],
//                  "free": true } ] }
//
// Each step shows the previous step's state as written (not as the class left it) with its own
// changes: the scene and its changes, the views, overlays, strategy, morph, selection and tab carry on; a
// probe, a step-through and highlights belong to the step that names them. A new scene starts from
// the views of a fresh document. So a step's state is the same however the lesson was reached, and
// "free" (the class explores) costs nothing: the next step restores its own state.
//
// Every error names the file, the step and the key ("camera.en.json: /steps/3/camera: invalid
// camera: …"); the limits below are checked before anything is allocated for what they count.
#pragma once

#include "app/inspect/picking.h"
#include "app/document/url_state.h"
#include "app/views/views.h"
#include "io/limits.h"
#include "base/language.h"
#include "pipeline/pipeline.h"
#include "pipeline/scene.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

/// The most a lesson file may hold: a lecture's lesson has 5–20 steps of a few sentences each.
struct LessonLimits {
  std::uintmax_t fileBytes = std::uintmax_t(1) << 20;  // 1 MiB
  size_t steps = 200;
  size_t captionBytes = 4000;
  size_t highlights = 16;  // of one step
  size_t cites = 16;       // of one step
  size_t scenes = 16;      // different scenes a lesson loads
};
inline constexpr LessonLimits kDefaultLessonLimits{};

/// The matrices the inspector shows, as a highlight names them.
inline constexpr std::string_view kLessonMatrices[] = {"wcFromMc", "vrcFromWc", "npcFromVrc", "dcFromNpc", "dcFromMc"};
/// The clipping planes a highlight names: the view volume's six (in the step-through's order) and
/// the user clip planes "user1" … "user6".
inline constexpr std::string_view kLessonPlanes[] = {"left", "right", "bottom", "top", "back", "front"};

/// Something a step points at: the views mark it, the inspector pulses it.
struct LessonHighlight {
  enum class Kind { handle, matrix, vertex, plane, axis };
  Kind kind = Kind::handle;
  Handle handle = Handle::none;  // handle: VRP, PRP, a window edge, the front or back plane
  std::string matrix;            // matrix: one of kLessonMatrices
  int row = -1, column = -1;     // matrix: an entry, a row (column −1), a column (row −1) or all (both −1)
  Probe vertex;                  // vertex: an object's vertex (scene indices)
  int plane = -1;                // plane: 0–5 the view volume's (kLessonPlanes), 6 + k the user plane k
  int axis = -1;                 // axis: 0 U, 1 V, 2 N (VRC)
  bool operator==(const LessonHighlight&) const = default;
};

/// The clipping step-through a step opens: one face of an object after `plane` of the six planes.
struct LessonStepThrough {
  size_t object = 0;
  int face = 0;
  int plane = 0;  // 0: the original polygon; k: after the k-th plane (left, right, bottom, top, back,
                  // front, then the enabled user clip planes)
  bool operator==(const LessonStepThrough&) const = default;
};

/// The state of the lab a step shows, resolved: what the viewer restores when the step is entered.
struct LessonState {
  Scene scene;                // with the step's changes (camera, objects, clip planes)
  DisplaySettings display;    // styles, observers, overlays, the morph's t
  ClipStrategy strategy = ClipStrategy::npc;
  bool boundingBoxTest = false;  // lecture notes 15.3.4: reject an object whose box lies outside
  bool morphShown = false;    // the stage morph's window is open (a step giving "morph" opens it)
  size_t selected = 0;        // the object selected (its vanishing points are drawn)
  std::string tab;            // one of kTabNames (app/lessons/tabs.h), or empty: as the viewer has it
  std::optional<Probe> probe;
  std::optional<LessonStepThrough> stepThrough;
  std::vector<LessonHighlight> highlights;
};

struct LessonStep {
  std::string caption;  // a few sentences; $…$ is inline math
  std::string section;  // the lecture notes' section it follows ("15.2.2"), may be empty
  bool free = false;    // the class explores; nothing is restored until the next step
  /// The values the caption cites that a panel shows ("cites": ["6.44", "34"], as the caption writes
  /// them): the step's evidence, which the lesson's layout must put on screen (issue 37; the test in
  /// tests/app/ui/lesson_layout_test.cpp finds each among the numbers the window shows).
  std::vector<std::string> cites;
  LessonState state;
};

struct Lesson {
  std::filesystem::path file;
  std::string title;
  Language language = Language::en;
  std::vector<LessonStep> steps;
};

/// Where a lesson's scenes come from: bundled ones by name (assets/scenes/NAME.json) and files
/// relative to the lesson. `fresh` is the views' state of a new document (the viewer's own, with its
/// theme and language); `worldAspect` frames the world view's observer when a step changes the scene.
struct LessonContext {
  std::filesystem::path scenesDirectory;  // the bundled scenes
  DisplaySettings fresh;
  double worldAspect = 4.0 / 3.0;
  Limits limits = kDefaultLimits;
  LessonLimits lessonLimits = kDefaultLessonLimits;
};

/// Reads a lesson from JSON text (`source` names it in messages, `baseDir` resolves scene files)
/// and resolves every step's state. Throws vplab::Error "SOURCE: /steps/N/key: what is wrong".
Lesson parseLesson(std::string_view json, std::string_view source, const std::filesystem::path& baseDir,
                   const LessonContext& context);
/// The same for a file (only a regular file, at most lessonLimits.fileBytes).
Lesson loadLesson(const std::filesystem::path& file, const LessonContext& context);

/// The bundled lessons (assets/lessons/*.json) in `language`, by file name; each with its title.
struct LessonFileInfo {
  std::filesystem::path file;
  std::string title;
};
std::vector<LessonFileInfo> listBundledLessons(Language language);

/// A bundled lesson by its name: "02-view-orientation" in `language`, or with the language given,
/// "02-view-orientation.de". Empty when there is no such lesson or the name could reach a file
/// elsewhere (only letters, digits, -, _ and one . before the language).
std::filesystem::path bundledLessonFile(std::string_view name, Language language);

}  // namespace vplab
