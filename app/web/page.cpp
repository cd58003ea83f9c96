// The lab as a web page (docs/students.md "In the browser"): the browser's counterpart of `vplab`
// (app/commands/cli.cpp) and of the window's event loop (app/ui/run_viewer.cpp). The viewer, its panels, views and GL
// backend are the desktop's; what differs is only how frames are driven and where files go.
//
// Frames: the browser calls `tick` before each repaint (requestAnimationFrame). Like the window's
// loop it draws only when something changed (input, a resize, the viewer's wakeIn: an animation,
// ImGui settling, the text cursor), so an idle page costs a few checks per repaint and no drawing.
//
// index.html calls the exported functions at the end (vplab_*) with the Page's address, which it
// gets at start: the page's state lives in one owned struct, not in globals.
#include "app/context/context_glfw.h"
#include "app/document/autosave.h"
#include "app/gl/render_target.h"
#include "app/ui/text_fit.h"
#include "app/ui/viewer.h"
#include "app/ui/widgets.h"
#include "app/ui/window_input.h"
#include "app/web/page_services.h"
#include "course/mistake_models.h"
#include "io/dump.h"
#include "io/limits.h"
#include "base/error.h"
#include "io/scene_io.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <imgui.h>
#include <imgui_internal.h>  // ImTextCharFromUtf8
#include <backends/imgui_impl_glfw.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <iostream>
#include <memory>
#include <optional>

namespace vplab {

namespace {

constexpr int kSettleFrames = 3;  // as the window's loop: ImGui shows the effect of input over ~2 frames
constexpr double kLongestWait = 60.0;
constexpr size_t kFirstSliceTriangles = 20000;  // then adapted to the frame times (ViewImages)
constexpr double kPipelineSecondsPerFrame = 0.025;  // of a frame, from its start, for the pipeline's run in steps (ShownRun)
// The autosave's directory in the in-memory file system, mirrored to this tab's localStorage key
// after each frame. The scenes kept by tabs that are gone are brought back under kKeptDir, each
// file standing for its localStorage key until it is recovered or discarded.
const std::filesystem::path kStateDir = "/state/vplab";
const std::filesystem::path kKeptDir = "/state/kept";

}  // namespace

/// The UI scale the page's size asks for: the canvas's pixels are screen pixels (devicePixelRatio
/// × CSS pixels), so the scale follows the ratio (text and handles keep their size on a high-DPI
/// screen), and a phone's small CSS size (its shorter side under 440 CSS px) takes it down a little,
/// to 0.85 at most, so that a panel holds a line of fields (docs/students.md "In the browser").
double pageScale() {
  const double ratio = std::clamp(page::devicePixelRatio(), 1.0, 4.0);
  const auto [cssWidth, cssHeight] = page::canvasCssSize();
  const double shorter = std::min(cssWidth, cssHeight);
  return ratio * (shorter > 0 ? std::clamp(shorter / 440.0, 0.85, 1.0) : 1.0);
}

struct Page {
  double pixelRatio = pageScale();  // the scale the page's size asked for last (pageScale)
  GlfwWindow window{1280, 720, "vplab", false};
  Viewer viewer{window, defaultScene(), float(pixelRatio)};
  GlfwBackend backend{window.handle()};
  WindowInput input{window.handle()};
  page::BrowserFiles* files = nullptr;  // owned by the viewer
  double nextWake = 0;                  // emscripten_get_now() ms at which the viewer wants a frame
  unsigned frames = 0;
  bool graphicsLost = false;  // between webglcontextlost and webglcontextrestored: nothing is drawn
  std::string shownHash, shownTitle;
  // A link with parts left out stays in the address as it was given, and its note over the views,
  // until the user changes what it showed (issue 41: the student sees what was wrong).
  bool holdingLink = false;
  std::optional<std::string> heldShows;  // what the held link showed, once its scene is read
  bool shownUnsaved = false;
  bool keysWanted = false;
  bool fullScreen = false;  // lecture mode asked for the browser's full screen (and has not left it)  // ImGui wanted text input in the last frame (the on-screen keyboard's focus)
  std::string storedAutosave;  // what this tab's localStorage key holds (empty: nothing)
  std::vector<std::pair<std::filesystem::path, std::string>> kept;  // offered kept scenes: file, key
  std::string reply;  // the last string handed to JavaScript (valid until the next call)
  // The loader worker's answer as it arrives, mesh by mesh (vplab_loader_mesh) and each mesh's arrays
  // a part at a time (vplab_loader_part), for request arrivingId.
  uint64_t arrivingId = 0;
  std::vector<std::shared_ptr<Mesh>> arriving;
  std::vector<std::array<size_t, 5>> arrivingCounts;  // each mesh's arrays' announced sizes (elements)

  Page() {
    auto chooser = std::make_unique<page::BrowserFiles>();
    files = chooser.get();
    viewer.session().files().useFileChooser(std::move(chooser), /*browser=*/true);
    viewer.state().compactAllowed = true;  // a phone's screen: one view at a time (app/ui/layout.h)
    viewer.state().inBrowser = true;
    viewer.state().cssPixel = float(std::clamp(page::devicePixelRatio(), 1.0, 4.0));
    // SwiftShader takes about 7 s for the three views of a million triangles: a large scene's views
    // are drawn across frames (docs/measured.md "Large scenes in the page").
    viewer.images().drawInSlices(kFirstSliceTriangles);
    // Each frame's parts as performance measures, for the browser's profiler and the tests (issue 42).
    viewer.parts().setSink(page::partWorked);
    // Its pipeline run (0.5 s for the million-triangle sphere) in steps of a few ms a frame.
    viewer.run().runInSteps(kPipelineSecondsPerFrame);
    // ... and its meshes built in the loader worker (loader-worker.js): the page answers meanwhile,
    // with the desktop's progress window and Cancel.
    viewer.session().loader().useRemote(page::buildInWorker);
    // The language: View ▸ Language's last choice, else the browser's (index.html decides it, for its
    // own texts too); a choice in the menu is kept in localStorage, as the desktop keeps it in its
    // preferences file (app/ui/run_viewer.cpp). Set before a link is shown: a lesson named without
    // its language opens in this one.
    auto rememberLanguage = [](Language lang) {
      if (!page::rememberLanguage(lang))
        throw Error(text::Text("the browser cannot remember the language (its localStorage is full or disabled)").in(lang));
    };
    viewer.session().start({.language = page::language(),
                            .rememberLanguage = rememberLanguage,
                            .recoveries = keptRecoveries(),
                            .autosaveDirectory = kStateDir,
                            .answers = page::answerShelf()});
    showLink(page::locationHash(), /*atStart=*/true);
  }

  /// Unsaved changes of tabs that are gone (closed, crashed, this one before a reload), all of them,
  /// newest first, to be offered back (the recovery dialog); this tab's are autosaved under its own key.
  std::vector<Recovery> keptRecoveries() {
    std::error_code ec;
    std::filesystem::create_directories(kKeptDir, ec);
    std::vector<Recovery> offered;
    for (const page::KeptScene& scene : page::keptScenes()) {
      const std::filesystem::path file = kKeptDir / (std::to_string(kept.size()) + ".json");
      std::ofstream(file, std::ios::binary) << scene.text;
      if (std::optional<Recovery> r = Autosave::read(file)) {
        offered.push_back(std::move(*r));
        kept.emplace_back(file, scene.key);
      } else {
        page::dropKeptScene(scene.key);  // not a scene of ours: nothing to recover from it
      }
    }
    // Newest first, as the desktop's (saved_at is "YYYY-MM-DD HH:MM:SS": its text sorts as its time).
    std::stable_sort(offered.begin(), offered.end(), [](const Recovery& a, const Recovery& b) { return a.savedAt > b.savedAt; });
    return offered;
  }

  /// localStorage follows the autosave file: written when it was, removed when the session has
  /// nothing unsaved any more (saved, discarded, recovered and saved). Frames are drawn only on a
  /// change, and the file is a scene without its meshes (a few kB): it is read and compared. A kept
  /// scene recovered or discarded (its file gone) leaves localStorage too.
  void mirrorAutosave() {
    std::erase_if(kept, [](const auto& k) {
      std::error_code ec;
      if (std::filesystem::exists(k.first, ec)) return false;
      page::dropKeptScene(k.second);
      return true;
    });
    const Autosave* autosave = viewer.session().recovery().autosave();
    if (!autosave) return;
    std::ifstream in(autosave->file(), std::ios::binary);
    if (in) {
      std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      if (text == storedAutosave) return;
      if (!page::storeRecovery(text)) {
        viewer.state().status = ui::tr(viewer.state(), "the browser keeps no autosave of this scene (its localStorage is full or disabled)");
        viewer.state().statusIsError = true;
      }
      storedAutosave = std::move(text);
    } else if (!storedAutosave.empty()) {
      page::storeRecovery("");
      storedAutosave.clear();
    }
  }

  /// A link's state (app/document/url_state.h); a fragment that is not understood is said in the status line.
  void showLink(const std::string& fragment, bool atStart) {
    if (fragment.empty() || fragment == shownHash) return;
    // The address is the link until the page writes what it shows (afterFrame): a scene still
    // loading, or a load cancelled or failed, puts the shown state's link back, so the same link
    // followed again is a change the page hears of.
    shownHash = fragment;
    try {
      viewer.session().links().showUrlState(decodeUrlState(fragment), atStart);
    } catch (const Error& e) {
      viewer.state().status = e.what();
      viewer.state().statusIsError = true;
    }
    holdingLink = !viewer.state().linkProblems.empty();
    heldShows.reset();
    input.changed = true;
  }

  /// Follows devicePixelRatio (browser zoom, a window moved to another screen) and the CSS size (a
  /// phone turned) with the UI scale; a scale the user chose (View ▸ UI scale) is kept relative.
  void followPixelRatio() {
    const double ratio = pageScale();
    if (ratio == pixelRatio) return;
    viewer.state().uiScale = float(viewer.state().uiScale * ratio / pixelRatio);
    viewer.state().cssPixel = float(std::clamp(page::devicePixelRatio(), 1.0, 4.0));
    pixelRatio = ratio;
    input.changed = true;
  }

  void tick() {
    if (graphicsLost) return;
    followPixelRatio();
    int w = 0, h = 0;
    window.framebufferSize(w, h);  // resizes the canvas to the page first
    const double now = emscripten_get_now();
    if (input.changed || !input.queue.empty()) viewer.requestFrames(kSettleFrames);
    const bool due = input.changed || !input.queue.empty() || viewer.wakeIn() <= 0 || now >= nextWake;
    if (!due) return;  // idle: nothing is drawn
    input.changed = false;
    const double start = emscripten_get_now();
    drawFrame(w, h);
    // The frame's own work (the wasm's, and the WebGL calls it makes; not the GPU process's drawing),
    // as a performance measure "vplab frame" (issue 42: no frame of the page's over 50 ms).
    page::frameWorked(start, emscripten_get_now());
    nextWake = emscripten_get_now() + 1000 * std::min(viewer.wakeIn(), kLongestWait);
  }

  void drawFrame(int w, int h) {
    viewer.makeCurrent();
    ImGui_ImplGlfw_NewFrame();
    input.queue.feed(ImGui::GetIO());
    if (w > 0 && h > 0) viewer.frame(0, w, h);
    ++frames;
    // The page draws its views in the frame (no render thread), so this holds at once; the rule is
    // the window's: a screenshot shows every view's current image.
    if (viewer.screenshotRequested() && viewer.viewsNotReady().empty()) {
      const std::filesystem::path file = "/downloads/vplab-screenshot.png";
      std::error_code ec;
      std::filesystem::create_directories(file.parent_path(), ec);
      writePng(gl::readPixels(window.gl(), 0, w, h), file);
      page::download(file, file.filename().string());
      viewer.screenshotTaken(file.filename().string());
    }
    const auto timed = viewer.parts().time("after frame");
    afterFrame();
  }

  /// The page around the canvas follows what the frame showed: the title, the link, the warning
  /// before leaving with unsaved changes; and the first frame resolves window.vplab.ready.
  void afterFrame() {
    mirrorAutosave();
    if (viewer.title() != shownTitle) page::setPageTitle(shownTitle = viewer.title());
    const std::string hash = encodeUrlState(viewer.session().links().urlState());
    if (holdingLink) {
      if (!heldShows) {
        if (!viewer.session().loader().busy()) heldShows = hash;  // what the link showed, its scene read
      } else if (hash != *heldShows) {  // the user changed it: the address follows again
        holdingLink = false;
        viewer.state().linkProblems.clear();
        input.changed = true;
      }
    }
    if (!holdingLink && hash != shownHash) page::replaceLocationHash(shownHash = hash);
    const bool unsaved = viewer.state().doc.dirty();
    if (unsaved != shownUnsaved) page::setUnsavedChanges(shownUnsaved = unsaved);
    if (frames == 1) page::firstFrameDrawn();
    // Lecture mode fills the screen, as F11 does on the desktop: it asks the browser's full screen
    // (a click moments ago is the gesture a browser requires: its transient activation lasts a few
    // seconds) and leaves it with lecture mode; the browser's own Esc leaving full screen ends it.
    if (viewer.state().lectureMode != fullScreen) page::setFullScreen(fullScreen = viewer.state().lectureMode);
    // A field's text closed (Enter, a tap elsewhere): the on-screen keyboard goes with it.
    const bool wants = viewer.wantsText();
    if (wants != keysWanted) page::setKeysWanted(keysWanted = wants);
  }

  /// Whether the finger lifting now gives a field the keys (index.html then focuses its hidden input,
  /// which opens a phone's on-screen keyboard: only a handler of the tap itself may). A number field
  /// held and not dragged opens its text as it is let go (editInPlace); a text field took the keys as
  /// it was pressed. A press not yet seen by ImGui (a tap quicker than a frame) is drawn first.
  bool takesKeysOnRelease() {
    if (!graphicsLost && !input.queue.empty()) {
      int w = 0, h = 0;
      window.framebufferSize(w, h);
      drawFrame(w, h);
    }
    return viewer.state().widgets.pressed.id != 0 || viewer.wantsText();
  }

  /// The browser took the WebGL context away (webglcontextlost): nothing is drawn until it is given
  /// back, and unsaved changes are kept in localStorage at once, for a reload if it never is.
  void loseGraphics() {
    graphicsLost = true;
    viewer.session().recovery().writeRecoveryNow();
    mirrorAutosave();
  }

  /// The context is back, empty (webglcontextrestored): every GL object is made again and the frame
  /// drawn; the document, its undo history and the views' settings never left.
  void restoreGraphics() {
    window.makeCurrent();
    page::forgetLostGlObjects();
    viewer.recreateGlObjects();
    graphicsLost = false;
    input.changed = true;
    nextWake = 0;
  }

  /// The exercise practised (issue 40), for the browser tests: its fields in the sheet's order (their
  /// rects' ids, what they hold), and the last Check.
  static nlohmann::json exerciseJson(const ViewerState& s) {
    const Practice& p = *s.practice;
    nlohmann::json fields = nlohmann::json::array();
    static constexpr const char* kKinds[] = {"number", "vector", "matrix", "outcode", "polygon"};
    for (const ItemFields& f : p.fields)
      fields.push_back({{"path", f.item.path}, {"kind", kKinds[size_t(f.kind)]}, {"rows", f.rows}, {"columns", f.columns},
                        {"texts", f.texts}});
    nlohmann::json e = {{"key", exerciseKey(p.ref)}, {"reveal", toString(p.reveal)}, {"fields", fields}, {"edits", p.edits}};
    if (s.check) {
      e["check"] = {{"edits", s.check->edits},
                    {"points", s.check->grade.points},
                    {"maxPoints", s.check->grade.maxPoints},
                    {"passed", s.check->report.passed},
                    {"mistake", s.check->grade.mistake ? std::string(mistakeModel(*s.check->grade.mistake).key) : ""},
                    {"diagnosis", s.check->report.diagnosis},
                    {"items", [&] {
                       nlohmann::json items = nlohmann::json::array();
                       for (const GradeCase& c : s.check->report.cases)
                         items.push_back({{"name", c.name}, {"passed", c.passed}, {"message", c.message}, {"details", c.details}});
                       return items;
                     }()},
                    {"seconds", s.check->seconds}};
    }
    return e;
  }

  /// The state the browser tests read (window.vplab.state()).
  std::string stateJson() {
    const ViewerState& s = viewer.state();
    const Camera& c = s.doc.scene().camera;
    nlohmann::json j;
    j["frames"] = frames;
    j["viewsDrawn"] = viewer.images().drawn();
    j["viewsBusy"] = viewer.viewsNotReady().size();  // still being drawn (or the run they show)
    j["title"] = viewer.title();
    j["scene"] = s.doc.path().string();
    j["dirty"] = s.doc.dirty();
    j["status"] = s.status;
    j["language"] = std::string(text::languageCode(s.display.language));
    j["labels"] = {{"menu.file", ui::tr(s, "File")}};  // the File menu's title as the menu bar shows it
    j["statusIsError"] = s.statusIsError;
    j["caughtErrors"] = viewer.caught().count;  // errors a frame caught (none is expected: the monkey test fails on any)
    j["lastCaughtError"] = viewer.caught().last;
    j["hash"] = shownHash;
    j["camera"] = {{"vrp", {c.vrp.x, c.vrp.y, c.vrp.z}},
                   {"prp", {c.prp.x, c.prp.y, c.prp.z}},
                   {"vup", {c.vup.x, c.vup.y, c.vup.z}},
                   {"window", {c.window.xmin, c.window.xmax, c.window.ymin, c.window.ymax}},
                   {"front", c.front},
                   {"back", c.back},
                   {"projection", toString(c.projection)}};
    if (s.lesson)
      j["lesson"] = {{"title", s.lesson->lesson().title},
                     {"file", s.lesson->lesson().file.filename().string()},
                     {"step", s.lesson->step() + 1},  // from 1, as the caption box and the link count
                     {"steps", s.lesson->stepCount()},
                     {"settled", s.lesson->settled()}};
    if (s.practice) j["exercise"] = exerciseJson(s);
    j["linkProblems"] = nlohmann::json::array();
    for (const LinkProblem& p : s.linkProblems)
      j["linkProblems"].push_back({{"key", p.key}, {"value", p.value}, {"said", p.said(s.display.language)}});
    j["embed"] = nlohmann::json::array();
    for (ViewKind v : s.embedViews) j["embed"].push_back(std::string(toString(v)));
    nlohmann::json rects = nlohmann::json::object();
    for (const auto& [id, r] : viewer.rects().rects) rects[id] = {r.x, r.y, r.z, r.w};
    j["rects"] = std::move(rects);
    int w = 0, h = 0;
    glfwGetFramebufferSize(window.handle(), &w, &h);
    j["canvas"] = {w, h};
    j["devicePixelRatio"] = page::devicePixelRatio();
    j["uiScale"] = s.uiScale;
    j["touch"] = s.touch;
    j["keysWanted"] = keysWanted;
    j["lectureMode"] = s.lectureMode;
    j["compact"] = s.compactShown;
    j["compactView"] = std::string(toString(s.compactView));
    j["compactPanel"] = s.compactPanel == ViewerState::controlsPanel ? "controls"
                        : s.compactPanel == ViewerState::inspectPanel ? "inspect" : "";
    j["loading"] = viewer.session().loader().busy();
    if (const std::optional<double> p = viewer.run().progress()) j["runProgress"] = *p;
    j["run"] = {{"polygons", s.run().stats.polygons}, {"vertices", s.run().stats.vertices}};
    j["graphicsLost"] = graphicsLost;
    j["recoveryOffered"] = !viewer.session().recovery().recoveries().empty();
    j["recoveriesOffered"] = viewer.session().recovery().recoveries().size();
    return j.dump();
  }
};

namespace {

void tick(void* arg) {
  auto* p = static_cast<Page*>(arg);
  try {
    p->tick();
  } catch (const std::exception& e) {
    // The context went in the middle of a frame, before its webglcontextlost event: that event
    // comes next and says so; this is no reason to stop.
    if (page::graphicsContextLost()) {
      p->loseGraphics();
      return;
    }
    emscripten_cancel_main_loop();
    page::showFatalError(ui::tr(p->viewer.state(), "vplab stopped: {1}", {e.what()}));
  }
}

}  // namespace

}  // namespace vplab

using vplab::Page;

int main() {
  try {
    auto* page = new Page();  // lives as long as the page: the browser drives it from now on
    EM_ASM({ vplabPage.started($0); }, page);
    emscripten_set_main_loop_arg(vplab::tick, page, 0, false);
  } catch (const std::exception& e) {
    vplab::page::showFatalError(vplab::text::fill(vplab::page::language(), "vplab could not start: {1}", {e.what()}));
    return 1;
  }
  return 0;
}

// ---------------------------------------------------------------- called by index.html
extern "C" {

/// The user picked `file` (copied to /uploads) in the picker the viewer opened; a drop when it opened none.
EMSCRIPTEN_KEEPALIVE void vplab_file_chosen(Page* p, const char* file) {
  if (!p->files->chosen(file)) p->viewer.session().files().openFile(file);
  p->input.changed = true;
}

/// A file dropped on the page (copied to /uploads).
EMSCRIPTEN_KEEPALIVE void vplab_file_dropped(Page* p, const char* file) {
  p->viewer.session().files().openFile(file);
  p->input.changed = true;
}

/// A message from the page's side (a file too large to read, a file that could not be read).
EMSCRIPTEN_KEEPALIVE void vplab_status(Page* p, const char* message, int error) {
  p->viewer.state().status = message;
  p->viewer.state().statusIsError = error != 0;
  p->input.changed = true;
}

/// A touch as the mouse: one finger moves the pointer (canvas pixels) with the left button held
/// (`down` 1) or released (0); -1 moves only.
EMSCRIPTEN_KEEPALIVE void vplab_pointer(Page* p, double x, double y, int down) {
  p->input.queue.mouseMove(x, y);
  if (down >= 0) p->input.queue.mouseButton(0, down == 1);
}

/// The last pointer was a finger (`touch` 1: a touch began; the page started on a coarse pointer) or
/// a mouse (0): a finger's targets and handle radius (app/ui/touch.h), from the next frame.
EMSCRIPTEN_KEEPALIVE void vplab_touch(Page* p, int touch) {
  p->viewer.state().touch = touch != 0;
  p->input.changed = true;
}

/// The browser left full screen (its Esc, F11, a gesture): lecture mode ends with it.
EMSCRIPTEN_KEEPALIVE void vplab_full_screen_left(Page* p) {
  if (!p->fullScreen) return;
  p->fullScreen = false;
  p->viewer.state().lectureMode = false;
  p->input.changed = true;
}

/// The finger lifts moving at (vx, vy) canvas pixels a second, measured from its touch events' times.
EMSCRIPTEN_KEEPALIVE void vplab_finger_lifting(Page* p, double vx, double vy) { p->viewer.fingerLifting(float(vx), float(vy)); }

/// 1 when the finger lifting now gives a field the keys (Page::takesKeysOnRelease).
EMSCRIPTEN_KEEPALIVE int vplab_takes_keys(Page* p) { return p->takesKeysOnRelease() ? 1 : 0; }

/// Text typed on the on-screen keyboard (UTF-8), which came without key events.
EMSCRIPTEN_KEEPALIVE void vplab_text(Page* p, const char* utf8) {
  for (const char* c = utf8; *c;) {
    unsigned codepoint = 0;
    const int length = ImTextCharFromUtf8(&codepoint, c, nullptr);
    if (length <= 0) break;
    p->input.queue.character(codepoint);
    c += length;
  }
}

/// A key the on-screen keyboard sent without a key event (Backspace as "deleteContentBackward"),
/// pressed and let go; `code` is GLFW's (app/ui/keys.h).
EMSCRIPTEN_KEEPALIVE void vplab_key_stroke(Page* p, int code) {
  p->input.queue.key(code, true);
  p->input.queue.key(code, false);
}

/// Two fingers pan a view: their midpoint (canvas pixels) as the pointer with the right button held
/// (`down` 1: the second finger landed; 0: one lifted; -1 moves only), which pans every view.
EMSCRIPTEN_KEEPALIVE void vplab_pan_fingers(Page* p, double x, double y, int down) {
  p->input.queue.mouseMove(x, y);
  if (down >= 0) p->input.queue.mouseButton(1, down == 1);
}

/// A pinch as the mouse wheel: steps > 0 zoom in.
EMSCRIPTEN_KEEPALIVE void vplab_wheel(Page* p, double x, double y, double steps) {
  p->input.queue.mouseMove(x, y);
  p->input.queue.wheel(0, steps);
}

/// The address's fragment changed (a link pasted, the back button): shown unless it is the page's own.
/// The loader worker's answer to request `id` (index.html), one mesh at a time and in order: makes
/// object i's mesh for arrays of these sizes in bytes (positions, indices, face starts, normals,
/// normal indices), reserved but empty (vplab_loader_part fills them). 0 when the sizes cannot be a
/// mesh's within the limits (checked before allocating; the answer is then an error).
EMSCRIPTEN_KEEPALIVE int vplab_loader_mesh(Page* p, double id, int i, double positions, double indices,
                                           double faceStarts, double normals, double normalIndices) {
  if (uint64_t(id) != p->arrivingId) {
    p->arrivingId = uint64_t(id);
    p->arriving.clear();
    p->arrivingCounts.clear();
  }
  const vplab::Limits& l = vplab::kDefaultLimits;
  auto count = [](double bytes, double each, size_t most) -> std::optional<size_t> {
    if (!(bytes >= 0) || std::fmod(bytes, each) != 0 || bytes / each > double(most)) return std::nullopt;
    return size_t(bytes / each);
  };
  const auto v = count(positions, sizeof(vplab::Vec3), l.vertices), c = count(indices, 4, l.corners),
             f = count(faceStarts, 4, l.faces + 1), n = count(normals, sizeof(vplab::Vec3), std::max(l.vertices, l.corners)),
             ni = count(normalIndices, 4, l.corners);
  if (i != int(p->arriving.size()) || i >= 100000 || !v || !c || !f || !n || !ni) return 0;
  auto mesh = std::make_shared<vplab::Mesh>();
  mesh->positions.reserve(*v);
  mesh->indices.reserve(*c);
  mesh->faceStart.clear();  // a new Mesh's list holds face 0's start: it comes with the others
  mesh->faceStart.reserve(*f);
  mesh->normals.reserve(*n);
  mesh->normalIndices.reserve(*ni);
  p->arrivingCounts.push_back({*v, *c, *f, *n, *ni});
  p->arriving.push_back(std::move(mesh));
  return 1;
}

/// The next `bytes` of array k (0 positions, 1 indices, 2 face starts, 3 normals, 4 normal indices) of the mesh
/// vplab_loader_mesh made last for request `id`: grows the array by them and returns where
/// JavaScript copies them. A large mesh arrives in parts of a few MB, each in a task of its own, so
/// that no frame waits for 100 MB to be copied. 0 for another request, a part that is no whole
/// number of elements or one past the announced size.
EMSCRIPTEN_KEEPALIVE uint32_t vplab_loader_part(Page* p, double id, int k, double bytes) {
  if (uint64_t(id) != p->arrivingId || p->arriving.empty() || k < 0 || k > 4) return 0;
  vplab::Mesh& mesh = *p->arriving.back();
  const size_t announced = p->arrivingCounts.back()[size_t(k)];
  auto grow = [&](auto& array) -> uint32_t {
    using T = typename std::decay_t<decltype(array)>::value_type;
    if (!(bytes > 0) || std::fmod(bytes, double(sizeof(T))) != 0) return 0;
    const size_t more = size_t(bytes / sizeof(T));
    if (more > announced - array.size()) return 0;
    const size_t at = array.size();
    array.resize(at + more);  // within the reserved capacity: no copy of what came before
    return uint32_t(uintptr_t(array.data() + at));
  };
  switch (k) {
    case 0: return grow(mesh.positions);
    case 1: return grow(mesh.indices);
    case 2: return grow(mesh.faceStart);
    case 3: return grow(mesh.normals);
    default: return grow(mesh.normalIndices);
  }
}

/// The loader worker's answer is complete: its meshes (vplab_loader_mesh) or its error go to the
/// loader, which drops them when the load was cancelled meanwhile.
EMSCRIPTEN_KEEPALIVE void vplab_loader_done(Page* p, double id, const char* error, int meshes) {
  vplab::BuiltMeshes built;
  bool whole = true;  // every array as long as announced (JavaScript stops a copy it cannot finish)
  if (uint64_t(id) == p->arrivingId)
    for (size_t m = 0; m < p->arriving.size(); ++m) {
      const vplab::Mesh& mesh = *p->arriving[m];
      const std::array<size_t, 5> got{mesh.positions.size(), mesh.indices.size(), mesh.faceStart.size(),
                                      mesh.normals.size(), mesh.normalIndices.size()};
      whole = whole && got == p->arrivingCounts[m];
      built.push_back(std::move(p->arriving[m]));
    }
  p->arriving.clear();
  p->arrivingCounts.clear();
  std::string e = error;
  const vplab::ViewerState& s = p->viewer.state();
  if (e.empty() && int(built.size()) != meshes)
    e = vplab::ui::tr(s, "the page's loader sent {1} meshes; {2} of them fit the limits",
                      {std::to_string(meshes), std::to_string(built.size())});
  if (e.empty() && !whole) e = vplab::ui::tr(s, "the page's loader sent a mesh in part");
  p->viewer.session().loader().deliver(uint64_t(id), std::move(built), std::move(e));
  p->input.changed = true;
}

EMSCRIPTEN_KEEPALIVE void vplab_hash_changed(Page* p, const char* fragment) { p->showLink(fragment, false); }

/// webglcontextlost (index.html prevented its default, so the browser may give the context back).
EMSCRIPTEN_KEEPALIVE void vplab_graphics_lost(Page* p) { p->loseGraphics(); }

/// webglcontextrestored: returns "" when the lab draws again, else why not.
EMSCRIPTEN_KEEPALIVE const char* vplab_graphics_restored(Page* p) {
  p->reply.clear();
  try {
    p->restoreGraphics();
  } catch (const std::exception& e) {
    p->reply = e.what();
  }
  return p->reply.c_str();
}

/// The desktop's cut-off rule on the page's last frame (ui::textCutOff): a JSON list of the places
/// where text is cut off, empty when everything fits.
EMSCRIPTEN_KEEPALIVE const char* vplab_text_cut_off(Page* p) {
  p->viewer.makeCurrent();
  return (p->reply = nlohmann::json(vplab::ui::textCutOff()).dump()).c_str();
}

EMSCRIPTEN_KEEPALIVE const char* vplab_state_json(Page* p) { return (p->reply = p->stateJson()).c_str(); }

/// Writes a PNG of `view` at width × height as File > Export draws it; returns its path in the
/// in-memory file system, or "" with the error in the status line.
EMSCRIPTEN_KEEPALIVE const char* vplab_export_png(Page* p, const char* view, int width, int height) {
  p->reply.clear();
  try {
    const vplab::ViewerState& s = p->viewer.state();
    const auto kind = vplab::fromString<vplab::ViewKind>(view);
    if (!kind) throw vplab::Error(vplab::ui::tr(s, "no view \"{1}\"", {view}));
    if (p->graphicsLost) throw vplab::Error(vplab::ui::tr(s, "the graphics context is lost: nothing can be drawn until the browser gives it back"));
    if (width < 1 || height < 1 || width > 8192 || height > 8192)
      throw vplab::Error(vplab::ui::tr(s, "an exported view has 1 to 8192 pixels a side, not {1} × {2}",
                                       {std::to_string(width), std::to_string(height)}));
    p->window.makeCurrent();
    const std::filesystem::path file = "/exports/vplab-" + std::string(view) + ".png";
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    vplab::writePng(p->viewer.exportImage(*kind, width, height), file);
    p->reply = file.string();
  } catch (const std::exception& e) {
    vplab_status(p, e.what(), 1);
  }
  return p->reply.c_str();
}

/// The open scene as File > Save writes it.
EMSCRIPTEN_KEEPALIVE const char* vplab_scene_text(Page* p) {
  return (p->reply = vplab::sceneToJson(p->viewer.state().doc.scene())).c_str();
}

/// The CPU pipeline's dump of the open scene, as `vplab dump --scene FILE` prints it for its file.
EMSCRIPTEN_KEEPALIVE const char* vplab_dump(Page* p) {
  try {
    p->reply = vplab::dumpJson(vplab::runPipeline(p->viewer.state().doc.scene(), vplab::PipelineOptions{}), 2);
  } catch (const std::exception& e) {
    p->reply = std::string("error: ") + e.what();
  }
  return p->reply.c_str();
}

/// Draws `frames` frames that each draw the three views again; returns the milliseconds per frame,
/// the GPU's work included: the last frame is read back (Chromium's WebGL finish() does not wait for
/// its GPU process; a read of a pixel does).
EMSCRIPTEN_KEEPALIVE double vplab_bench_frames(Page* p, int frames) {
  frames = std::clamp(frames, 1, 1000);
  if (p->graphicsLost) return -1;
  int w = 0, h = 0;
  p->window.framebufferSize(w, h);
  p->viewer.images().drawInSlices(0);  // each frame draws the three views whole: what is measured
  const double start = emscripten_get_now();
  for (int i = 0; i < frames; ++i) {
    p->viewer.images().forget();
    p->drawFrame(w, h);
  }
  p->viewer.images().drawInSlices(vplab::kFirstSliceTriangles);
  unsigned char pixel[4];
  p->window.gl().BindFramebuffer(GL_FRAMEBUFFER, 0);
  p->window.gl().ReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  return (emscripten_get_now() - start) / frames;
}

}  // extern "C"
