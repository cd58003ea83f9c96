// Index: 1 construction (ImGui context, fonts, style)  2 the frame  3 layout and windows
//        4 menus, shortcuts and dialogs  5 files: open, save, autosave and recovery
#include "app/ui/viewer.h"

#include "app/gl/shader.h"
#include "app/gl/texture_io.h"
#include "app/ui/assets.h"
#include "app/render/headless.h"
#include "app/export/svg.h"
#include "app/ui/keys.h"
#include "app/ui/layout.h"
#include "app/ui/panels.h"
#include "app/ui/widgets.h"
#include "app/views/render_request.h"
#include "pipeline/error.h"
#include "pipeline/scene_io.h"

#define IMGUI_DEFINE_MATH_OPERATORS
#include <imgui.h>
#include <imgui_internal.h>
#include <backends/imgui_impl_opengl3.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace vplab {

// ---------------------------------------------------------------- 1 construction

namespace {

// Latin, Greek (φ, α), punctuation, arrows and mathematical operators for the labels and tooltips.
constexpr ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x206F, 0x2070, 0x209F,
                                    0x2190, 0x21FF, 0x2200, 0x22FF, 0x22C5, 0x22C5, 0};

void setUpFonts(float scale) {
  ImGuiIO& io = ImGui::GetIO();
  const char* file = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  if (std::filesystem::exists(file)) io.Fonts->AddFontFromFileTTF(file, 15.f * scale, nullptr, kGlyphRanges);
  else io.Fonts->AddFontDefault();
}

void setUpStyle(float scale) {
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 3;
  style.FrameRounding = 2;
  style.WindowBorderSize = 1;
  style.ItemSpacing = ImVec2(7, 5);
  style.ScaleAllSizes(scale);
}

/// The busy mark's spinner steps 10 times a second (a frame each, nothing else while idle).
constexpr double kBusyMarkStep = 0.1;

/// Where "save a copy" of a bundled scene starts: its name in the working directory.
std::filesystem::path copyName(const std::filesystem::path& bundled) {
  std::error_code ec;
  const std::filesystem::path cwd = std::filesystem::current_path(ec);
  return cwd / (bundled.empty() ? std::filesystem::path("lecture-scene.json") : bundled.filename());
}

}  // namespace

Viewer::Viewer(GlContext& context, Scene scene, float uiScale)
    : ctx_(context),
      renderer_(context, uiScale),
      images_(context, renderer_),
      s_(std::move(scene)),
      uiScale_(uiScale) {
  IMGUI_CHECKVERSION();
  imgui_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(imgui_);  // CreateContext makes it current only when none is
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is computed, not stored in the working directory
  io.ConfigWindowsMoveFromTitleBarOnly = true;
  setUpFonts(uiScale);
  setUpStyle(uiScale);
  // WebGL2 (the browser) and OpenGL ES are GLSL ES 3.00; the desktop's window is OpenGL 3.3 core.
  const bool es = gl::dialectOf(context.gl()) == gl::GlslDialect::es300;
  if (!ImGui_ImplOpenGL3_Init(es ? "#version 300 es" : "#version 330 core")) {
    ImGui::DestroyContext(imgui_);
    throw Error("ImGui's OpenGL3 renderer could not be initialised on the " + std::string(context.backend()) +
                " context (it loads OpenGL through libGL.so.1: use a window or the EGL backend)");
  }
  s_.frame.camera.style = Style::shaded;
  s_.antialias = !context.softwareRenderer();
  s_.uiScale = uiScale;
  s_.presets = listPresetScenes();
  s_.frame.world.orbit = defaultWorldOrbit(s_.doc.shown(), s_.worldAspect);
  updateRun();
}

void Viewer::applyUiScale(float scale) {
  uiScale_ = scale;
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  setUpFonts(scale);
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
  ImGui::GetStyle() = ImGuiStyle();
  setUpStyle(scale);
  renderer_.setScale(scale);
  relayout_ = true;
}

Viewer::~Viewer() {
  ImGui::SetCurrentContext(imgui_);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext(imgui_);
}

std::string Viewer::title() const {
  const auto& path = s_.doc.path();
  return "vplab — " + (path.empty() ? std::string("default lecture scene") : path.filename().string()) +
         (s_.doc.dirty() ? " *" : "");
}

void Viewer::screenshotTaken(const std::string& file) {
  screenshotRequested_ = false;
  setStatus("screenshot saved: " + file, false);
}

void Viewer::screenshotFailed(const std::string& why) {
  screenshotRequested_ = false;
  setStatus("no screenshot: " + why, true);
}

void Viewer::setStatus(std::string message, bool error) {
  s_.status = std::move(message);
  s_.statusIsError = error;
}

// ---------------------------------------------------------------- 2 the frame

void Viewer::updateRun() {
  const PipelineOptions& o = s_.pipeline;
  const bool same = ranOnce_ && s_.doc.shownRevision() == ranShownRevision_ && o.strategy == ranOptions_.strategy &&
                    o.boundingBoxTest == ranOptions_.boundingBoxTest && o.clipEdges == ranOptions_.clipEdges;
  if (same) return;
  ranOnce_ = true;
  ranShownRevision_ = s_.doc.shownRevision();
  ranOptions_ = o;
  // Into the run published before the current one when nothing holds it any more: its buffers are
  // reused (a large scene's arrays are not allocated anew). The render thread may still draw from
  // it: then a new one.
  std::shared_ptr<PipelineRun>& into = runs_[0] == s_.ran ? runs_[1] : runs_[0];
  if (!into || into.use_count() > 1) into = std::make_shared<PipelineRun>();
  try {
    vplab::runPipeline(s_.doc.shown(), s_.pipeline, *into);
    s_.ran = into;
    ++runRevision_;
    s_.runError.clear();
  } catch (const Error& e) {
    s_.runError = e.what();  // the previous run stays
  }
}

void Viewer::makeCurrent() { ImGui::SetCurrentContext(imgui_); }

double Viewer::wakeIn() const {
  if (settleFrames_ > 0 || s_.morphPlaying || loader_.busy() || askRecovery_ || s_.animateUntil > imgui_->Time) return 0;
  double wake = 1e9;
  // The busy mark's spinner turns while a view is drawn on the render thread; its new image is
  // shown at once.
  if (const std::optional<double> views = images_.wakeIn(kBusyMarkStep)) {
    if (*views <= 0) return 0;
    wake = *views;
  }
  // ImGui 1.86 blinks the text cursor (on 0.8 s, off 0.4 s): a few frames a second while typing.
  if (imgui_->IO.WantTextInput) wake = std::min(wake, 0.2);
  if (autosave_) wake = std::min(wake, autosave_->dueIn(imgui_->Time));
  return wake;
}

void Viewer::frame(GLuint framebuffer, int width, int height) {
  ImGui::SetCurrentContext(imgui_);
  if (s_.uiScale != uiScale_) applyUiScale(s_.uiScale);  // the font atlas is locked during a frame
  if (settleFrames_ > 0) --settleFrames_;
  images_.beginFrame();
  if (s_.objectToLoad) {  // "+ OBJ mesh…" of the scene panel
    const std::filesystem::path& path = s_.doc.scene().path;
    loader_.startObject(std::move(*s_.objectToLoad), path.empty() ? std::filesystem::path() : path.parent_path());
    s_.objectToLoad.reset();
  }
  if (auto loaded = loader_.poll()) {
    if (loaded->scene) {
      const std::string file = loaded->scene->path.string();
      startDocument(std::move(*loaded->scene));
      setStatus("opened " + file, false);
    } else if (loaded->object) {  // one undo step, recorded at the end of this frame
      Scene& scene = s_.doc.scene();
      setStatus("added " + loaded->object->file, false);
      scene.objects.push_back(std::move(*loaded->object));
      s_.selectedObject = int(scene.objects.size()) - 1;
    } else {
      setStatus(loaded->error, true);  // the open scene stays
    }
    requestFrames(2);
  }
  const Scene atFrameStart = s_.doc.scene();
  const unsigned generation = s_.doc.generation();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  if (s_.morphPlaying) {
    s_.frame.morphing.t = std::min(4.0, s_.frame.morphing.t + ImGui::GetIO().DeltaTime * s_.morphSpeed);
    if (s_.frame.morphing.t >= 4) s_.morphPlaying = false;
  }
  if (width != lastWidth_ || height != lastHeight_) relayout_ = true;
  lastWidth_ = width;
  lastHeight_ = height;

  shortcuts();
  if (s_.lectureMode) {
    s_.doc.endFrame(true);
    updateRun();
    lectureWindow();
  } else {
    menuBar();
    controlsWindow();
    s_.doc.endFrame(true);  // validate what the panels changed; recorded at the end of the frame
    updateRun();
    viewWindows();
    inspectWindow();
    morphWindow();
  }
  helpWindow();
  loadingWindow();
  recoveryDialog();
  quitDialog();
  discardDialog();
  dialog_->draw();
  relayout_ = false;
  images_.endFrame();
  if (const auto error = images_.takeError()) setStatus(*error, true);
  ImGui::Render();

  // Going straight from one field into the next keeps some item active in every frame: the change
  // of the active item ends one undo step and begins the next.
  // A document started in this frame (opened, New) begins with an empty history: the scene at
  // the frame's start belongs to the previous document.
  const ImGuiID active = ImGui::GetActiveID();
  if (active != lastActive_ && lastActive_ != 0 && s_.doc.generation() == generation) s_.doc.recordStep(atFrameStart);
  lastActive_ = active;
  const bool editing = active != 0 || s_.drag.kind == Drag::Kind::handle;
  s_.doc.endFrame(editing);
  if (autosave_) {
    autosave_->update(s_.doc, ImGui::GetTime());
    if (autosave_->error() != autosaveError_) {  // say it once, not every frame
      autosaveError_ = autosave_->error();
      if (!autosaveError_.empty()) setStatus(autosaveError_, true);
    }
  }

  const GladGLContext& gl = ctx_.gl();
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  gl.Viewport(0, 0, width, height);
  gl.ClearColor(0.06f, 0.065f, 0.08f, 1.f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  ctx_.checkErrors("drawing the viewer's frame");
}

// ---------------------------------------------------------------- 3 layout and windows

void Viewer::controlsWindow() {
  const ui::Layout l = ui::computeLayout(ImGui::GetIO().DisplaySize, ImGui::GetFrameHeight(), uiScale_);
  ui::placeNext(l.controls, relayout_);
  ImGui::Begin("Controls", nullptr, ImGuiWindowFlags_NoCollapse);
  const Scene& scene = s_.doc.scene();
  if (!scene.title.empty() || !scene.caption.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.86f, 0.45f, 1.f));
    ImGui::TextWrapped("%s", scene.title.empty() ? "Scene" : scene.title.c_str());
    ImGui::PopStyleColor();
    if (!scene.caption.empty()) ImGui::TextWrapped("%s", scene.caption.c_str());
    ImGui::Spacing();
  }
  // The tabs stay in place while their panel scrolls; the status line stays below.
  if (s_.showStepThrough) s_.controlsTab = ViewerState::lectureTab;
  ui::tabRow(s_, "controls", {"Camera", "Scene", "Clipping", "Display", "Lecture"}, s_.controlsTab);
  const float wrap = ImGui::GetContentRegionAvail().x;
  float footer = 0;
  for (const std::string* text : {&s_.status, &s_.runError})
    if (!text->empty())
      footer += ImGui::CalcTextSize(text->c_str(), nullptr, false, wrap).y + ImGui::GetStyle().ItemSpacing.y * 2 + 1;
  if (ImGui::BeginChild("panel", ImVec2(0, -footer))) {
    switch (s_.controlsTab) {
      case ViewerState::cameraTab: ui::cameraPanel(s_); break;
      case ViewerState::sceneTab: ui::scenePanel(s_, *dialog_); break;
      case ViewerState::clippingTab: ui::clippingPanel(s_); break;
      case ViewerState::displayTab: ui::displayPanel(s_); break;
      default: ui::lecturePanel(s_); break;
    }
  }
  ImGui::EndChild();
  if (!s_.status.empty()) {
    ImGui::Separator();
    if (s_.statusIsError) ui::errorText(s_.status);
    else ImGui::TextWrapped("%s", s_.status.c_str());
  }
  if (!s_.runError.empty()) ui::errorText(s_.runError);
  ImGui::End();
}

void Viewer::inspectWindow() {
  const ui::Layout l = ui::computeLayout(ImGui::GetIO().DisplaySize, ImGui::GetFrameHeight(), uiScale_);
  ui::placeNext(l.inspect, relayout_);
  ImGui::Begin("Inspect", nullptr, ImGuiWindowFlags_NoCollapse);
  // A new probe (a vertex clicked in a view) brings the probe forward; the tabs stay in place while
  // the panel scrolls.
  if (s_.probe && s_.probe != s_.probeShown) s_.inspectTab = ViewerState::probeTab;
  s_.probeShown = s_.probe;
  ui::tabRow(s_, "inspect", {"Vertex probe", "Matrices", "Depth"}, s_.inspectTab);
  if (ImGui::BeginChild("panel")) {
    switch (s_.inspectTab) {
      case ViewerState::probeTab: ui::probePanel(s_); break;
      case ViewerState::matricesTab: ui::matricesPanel(s_); break;
      default: ui::depthPanel(s_); break;
    }
  }
  ImGui::EndChild();
  ImGui::End();
}

void Viewer::helpWindow() {
  if (!s_.showHelp) return;
  // Fits the display at any UI scale; the text wraps inside.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowSize(ImMin(ImVec2(560, 520) * uiScale_, display * 0.9f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos(ImGui::GetIO().DisplaySize * 0.5f, ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
  if (ImGui::Begin("Help (F1)", &s_.showHelp)) {
    ImGui::TextUnformatted("Mouse");
    for (const char* line : {"world and NPC views: left-drag orbits, right- or middle-drag pans, the wheel zooms",
                             "world view: drag the handles (VRP, PRP, the window's edges, front and back planes)",
                             "any view: click a vertex to probe it through the pipeline"}) {
      ImGui::Bullet();
      ImGui::TextWrapped("%s", line);
    }
    ImGui::Spacing();
    ImGui::TextUnformatted("Keys");
    const char* keys[][2] = {{"Ctrl+Z", "undo"},
                             {"Ctrl+Y, Ctrl+Shift+Z", "redo"},
                             {"Ctrl+N", "new: the default lecture scene"},
                             {"Ctrl+O", "open a scene"},
                             {"Ctrl+S / Ctrl+Shift+S", "save (a bundled scene: as a copy) / save as"},
                             {"Ctrl+Q", "quit (asks when the scene has unsaved changes)"},
                             {"1 to 5", "style of every view: flat, shaded, wire, hidden-line, hidden removed"},
                             {"P", "next projection: perspective, parallel, oblique"},
                             {"C", "next clipping strategy: NPC, WC, divide first (wrong)"},
                             {"B", "bounding-box test on or off"},
                             {"R", "reset the observers of the world and NPC views"},
                             {"Esc", "clear the vertex probe"},
                             {"F1", "this help"},
                             {"F11", "lecture mode: one view fills the window (Esc returns)"},
                             {"Shift+click", "in the camera view: step through the clipping of that polygon"},
                             {"F12", "screenshot of the whole window (PNG in the working directory)"}};
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
      for (const auto& k : keys) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(k[0]);
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", k[1]);
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

// ---------------------------------------------------------------- 4 menus, shortcuts and dialogs

void Viewer::menuBar() {
  if (!ImGui::BeginMainMenuBar()) return;
  const bool fileMenu = ImGui::BeginMenu("File");
  ui::recordRect(s_, "menu.file");
  if (fileMenu) {
    // The browser owns Ctrl+N, Ctrl+O, Ctrl+S, Ctrl+W and F11, F12: the page offers these here only.
    auto key = [this](const char* shortcut) { return browser_ ? nullptr : shortcut; };
    if (ImGui::MenuItem("New (default lecture scene)", key("Ctrl+N"))) unlessUnsaved([this] { startDocument(defaultScene()); });
    ui::recordRect(s_, "menu.new");
    if (browser_) {
      if (ImGui::MenuItem("Open a scene or an OBJ mesh…")) chooseFileToOpen();
      ui::recordRect(s_, "menu.open");
      if (ImGui::MenuItem("Save (download)")) saveScene(s_.doc.path());
      ui::recordRect(s_, "menu.save");
    } else {
      if (ImGui::MenuItem("Open scene…", "Ctrl+O")) chooseFileToOpen();
      if (ImGui::MenuItem("Save", "Ctrl+S")) saveScene(s_.doc.path());
      if (ImGui::MenuItem("Save as…", "Ctrl+Shift+S")) saveAs();
    }
    if (ImGui::BeginMenu("Presets", !s_.presets.empty())) {
      for (const SceneFileInfo& p : s_.presets)
        if (ImGui::MenuItem(p.title.c_str())) {
          const std::filesystem::path file = p.file;
          unlessUnsaved([this, file] { openScene(file); });
        }
      ImGui::EndMenu();
    }
    ImGui::Separator();
    const bool exportOpen = ImGui::BeginMenu("Export a view");
    ui::recordRect(s_, "menu.export");
    if (exportOpen) {
      exportMenu();
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Screenshot", key("F12"))) screenshotRequested_ = true;
    if (!browser_ && ImGui::MenuItem("Quit", "Ctrl+Q")) requestQuit();  // a page is closed by its tab
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    if (ImGui::MenuItem("Undo", "Ctrl+Z", false, s_.doc.canUndo())) s_.doc.undo();
    if (ImGui::MenuItem("Redo", "Ctrl+Y", false, s_.doc.canRedo())) s_.doc.redo();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Mouse and keys", "F1")) s_.showHelp = true;
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

void Viewer::shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (io.KeyCtrl) {
    if (pressed(keys::kZ) && io.KeyShift) s_.doc.redo();
    else if (pressed(keys::kZ)) s_.doc.undo();
    if (pressed(keys::kY)) s_.doc.redo();
    if (browser_) return;  // Ctrl+S, Ctrl+O, Ctrl+N, Ctrl+W, Ctrl+Q are the browser's: the File menu has them
    if (pressed(keys::kS)) {
      if (io.KeyShift) saveAs();
      else saveScene(s_.doc.path());
    }
    if (pressed(keys::kN)) unlessUnsaved([this] { startDocument(defaultScene()); });
    if (pressed(keys::kO)) chooseFileToOpen();
    if (pressed(keys::kQ)) requestQuit();
    return;
  }
  if (pressed(keys::kF11) && !browser_) s_.lectureMode = !s_.lectureMode;
  if (pressed(keys::kEscape) && s_.lectureMode) {
    s_.lectureMode = false;
    return;
  }
  if (pressed(keys::kF1)) s_.showHelp = !s_.showHelp;
  if (pressed(keys::kF12) && !browser_) screenshotRequested_ = true;
  if (pressed(keys::kEscape)) s_.probe.reset();
  for (int i = 0; i < 5; ++i)
    if (pressed(keys::kDigit1 + i)) s_.frame.camera.style = s_.frame.world.style = s_.frame.npc.style = Style(i);
  if (pressed(keys::kP)) {
    Camera& c = s_.doc.scene().camera;
    c.projection = Projection((int(c.projection) + 1) % 3);
  }
  if (pressed(keys::kC)) s_.pipeline.strategy = ClipStrategy((int(s_.pipeline.strategy) + 1) % 3);
  if (pressed(keys::kB)) s_.pipeline.boundingBoxTest = !s_.pipeline.boundingBoxTest;
  if (pressed(keys::kR)) {
    s_.frame.world.orbit = defaultWorldOrbit(s_.doc.shown(), s_.worldAspect);
    s_.frame.npc.orbit = defaultNpcOrbit();
  }
}

void Viewer::quitDialog() {
  if (s_.quitRequested && !s_.doc.dirty()) s_.quitConfirmed = true;
  if (s_.quitRequested && s_.doc.dirty() && !ImGui::IsPopupOpen("Unsaved changes")) ImGui::OpenPopup("Unsaved changes");
  if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::Text("The scene has unsaved changes. Save them before quitting?");
  if (ImGui::Button("Save")) {
    ImGui::CloseCurrentPopup();
    if (s_.doc.path().empty() || isBundled(s_.doc.path())) {
      s_.quitRequested = false;
      dialog_->open("Save a copy of the scene", FileChooser::Mode::save, {".json"}, copyName(s_.doc.path()), [this](const std::filesystem::path& f) {
        saveScene(f);
        if (!s_.doc.dirty()) s_.quitConfirmed = true;
      });
    } else {
      saveScene(s_.doc.path());
      s_.quitConfirmed = !s_.doc.dirty();
      s_.quitRequested = s_.quitConfirmed;
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Discard them and quit")) {
    ImGui::CloseCurrentPopup();
    s_.quitConfirmed = true;
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) {
    ImGui::CloseCurrentPopup();
    s_.quitRequested = false;
  }
  ImGui::EndPopup();
}

namespace {

// A view as the viewer shows it, as a request (app/views/render_request.h): its size, every view
// setting (styles, observers, overlays, probe, step-through, morph), the pipeline's options and
// the UI scale: what the render thread draws it from.
RenderRequest shownViewRequest(const ViewerState& s, ViewKind kind, int width, int height, float scale) {
  RenderRequest r;
  r.view = kind;
  r.width = width;
  r.height = height;
  r.pipeline = s.pipeline;
  r.scale = scale;
  r.frame = s.frame;
  return r;
}

}  // namespace

// Each view as it is shown, to PNG, and the wireframe styles also as SVG (vector lines). The PNG is
// the image on screen, read back (drawn by the render thread from the same settings: drawing it
// again here would make the window wait for a large scene); the SVG is made from the view's request.
void Viewer::exportMenu() {
  struct Entry {
    ViewKind kind;
    const char* name;
  };
  const Entry entries[] = {{ViewKind::camera, "camera"}, {ViewKind::world, "world"}, {ViewKind::npc, "NPC"}};
  for (const Entry& e : entries) {
    // The image shown (drawn in this thread or on the views' render thread: textures are shared).
    const GLuint texture = images_.texture(e.kind);
    const ViewKind kind = e.kind;
    const int w = cachedWidth(kind), h = cachedHeight(kind);
    const std::string png = std::string(e.name) + " view as PNG…";
    const bool pngChosen = ImGui::MenuItem(png.c_str(), nullptr, false, texture != 0);
    ui::recordRect(s_, ("export." + std::string(toString(e.kind)) + ".png").c_str());
    if (pngChosen) {
      dialog_->open("Export the " + std::string(e.name) + " view", FileChooser::Mode::save, {".png"},
                   "vplab-" + std::string(toString(e.kind)) + ".png", [this, texture, kind, w, h](const std::filesystem::path& f) {
                     try {
                       // OpenGL ES (the browser's WebGL2) cannot read a texture back, and the page has
                       // no render thread to wait for: the view is drawn again, as it is shown.
                       const bool es = gl::dialectOf(ctx_.gl()) == gl::GlslDialect::es300;
                       const bool camera = kind == ViewKind::camera;  // shown at the device's W × H
                       writePng(es ? exportImage(kind, camera ? 0 : w, camera ? 0 : h) : readTexture(ctx_.gl(), texture), f);
                       setStatus("exported " + f.string(), false);
                     } catch (const Error& err) {
                       setStatus(err.what(), true);
                     }
                   });
    }
    const std::optional<std::string> why = svgExportError(e.kind, s_.doc.shown(), s_.frame);
    const std::string svg = std::string(e.name) + " view as SVG…";
    const bool svgChosen = ImGui::MenuItem(svg.c_str(), nullptr, false, !why && texture != 0);
    ui::recordRect(s_, ("export." + std::string(toString(e.kind)) + ".svg").c_str());
    if (svgChosen) {
      dialog_->open("Export the " + std::string(e.name) + " view", FileChooser::Mode::save, {".svg"},
                   "vplab-" + std::string(toString(kind)) + ".svg", [this, kind, w, h](const std::filesystem::path& f) {
                     try {
                       writeSvg(svgOfRequest(s_.doc.shown(), shownViewRequest(s_, kind, w, h, uiScale_)), f);
                       setStatus("exported " + f.string(), false);
                     } catch (const Error& err) {
                       setStatus(err.what(), true);
                     }
                   });
    }
    if (why && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", why->c_str());
  }
}

void Viewer::unlessUnsaved(std::function<void()> action) {
  if (!s_.doc.dirty()) {
    action();
    return;
  }
  pendingReplace_ = std::move(action);
  askDiscard_ = true;
}

void Viewer::discardDialog() {
  if (askDiscard_) {
    ImGui::OpenPopup("Discard unsaved changes?");
    askDiscard_ = false;
  }
  if (!ImGui::BeginPopupModal("Discard unsaved changes?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::Text("The scene has unsaved changes. They are lost if another scene is opened.");
  if (ImGui::Button("Discard them")) {
    ImGui::CloseCurrentPopup();
    if (pendingReplace_) pendingReplace_();
    pendingReplace_ = nullptr;
  }
  ui::recordRect(s_, "discard.confirm");
  ImGui::SameLine();
  if (ImGui::Button("Keep editing")) {
    ImGui::CloseCurrentPopup();
    pendingReplace_ = nullptr;
  }
  ImGui::EndPopup();
}

// ---------------------------------------------------------------- 5 files: open, save, autosave and recovery

void Viewer::startDocument(Scene scene, bool dirty) {
  loader_.cancel();  // an OBJ still loading for the previous document must not land in this one
  s_.doc.replace(std::move(scene), dirty);
  s_.probe.reset();
  s_.selectedObject = 0;
  s_.stepThrough = {};
  s_.drag = {};
  s_.morphPlaying = false;
  // The view settings of a fresh start (see the constructor); the user's UI scale, aspect lock and
  // antialiasing are preferences, not choices for a scene, and stay.
  s_.frame = FrameSettings{};
  s_.frame.camera.style = Style::shaded;
  s_.pipeline = ViewerState(Scene{}).pipeline;
  s_.frame.world.orbit = defaultWorldOrbit(s_.doc.shown(), s_.worldAspect);
  updateRun();
  requestFrames(2);
}

void Viewer::openScene(const std::filesystem::path& file) {
  loader_.start(file);
  setStatus("opening " + file.string() + " …", false);
  requestFrames(2);
}

void Viewer::cancelLoading() {
  if (!loader_.busy()) return;
  setStatus("opening " + loader_.file().string() + " cancelled; the open scene stays", false);
  loader_.cancel();
  requestFrames(2);
}

// A small window over the views while a scene loads: the views stay live underneath.
void Viewer::loadingWindow() {
  if (!loader_.busy()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(420 * uiScale_, 0), ImGuiCond_Always);
  ImGui::Begin("Loading", nullptr,
               ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
  ImGui::TextWrapped("Reading and tessellating %s", loader_.file().filename().string().c_str());
  // The reader reports no fraction: the bar sweeps to show the work goes on, the time counts.
  const double t = loader_.elapsed();
  char label[32];
  std::snprintf(label, sizeof label, "%.1f s", t);
  ImGui::ProgressBar(float(std::fmod(t, 1.5) / 1.5), ImVec2(-1, 0), label);
  if (ImGui::Button("Cancel")) cancelLoading();
  ui::recordRect(s_, "load.cancel");
  ImGui::End();
}

bool Viewer::isBundled(const std::filesystem::path& file) const {
  if (file.empty()) return true;  // the built-in default scene
  std::error_code ec;
  for (const SceneFileInfo& p : s_.presets)
    if (std::filesystem::equivalent(p.file, file, ec)) return true;
  const std::filesystem::path assets = assetsDirectory();
  if (assets.empty()) return false;
  const auto dir = std::filesystem::weakly_canonical(assets / "scenes", ec);
  const auto parent = std::filesystem::weakly_canonical(file, ec).parent_path();
  return !ec && parent == dir;
}

void Viewer::saveAs() {
  dialog_->open("Save the scene", FileChooser::Mode::save, {".json"}, isBundled(s_.doc.path()) ? copyName(s_.doc.path()) : s_.doc.path(),
               [this](const std::filesystem::path& f) { saveScene(f); });
}

void Viewer::saveScene(const std::filesystem::path& file) {
  if (dialog_->downloads()) {  // the browser: every save is a new download, named after the scene
    dialog_->open("Save the scene", FileChooser::Mode::save, {".json"},
                  file.empty() ? std::filesystem::path("lecture-scene.json") : file.filename(),
                  [this](const std::filesystem::path& f) { writeScene(f); });
    return;
  }
  if (file.empty() || isBundled(file)) {  // never over a scene shipped with vplab: save a copy
    dialog_->open("Save a copy of the scene", FileChooser::Mode::save, {".json"}, copyName(file),
                 [this](const std::filesystem::path& f) {
                   if (isBundled(f)) setStatus(f.string() + " is a scene shipped with vplab: save the copy elsewhere", true);
                   else saveScene(f);
                 });
    return;
  }
  writeScene(file);
}

void Viewer::writeScene(const std::filesystem::path& file) {
  try {
    s_.doc.save(file);
    setStatus("saved " + file.string(), false);
  } catch (const Error& e) {
    setStatus(e.what(), true);
  }
}

void Viewer::chooseFileToOpen() {
  if (browser_) {
    dialog_->open("Open a scene or an OBJ mesh", FileChooser::Mode::open, {".json", ".obj"}, s_.doc.path(),
                  [this](const std::filesystem::path& f) { openFile(f); });
    return;
  }
  dialog_->open("Open a scene", FileChooser::Mode::open, {".json"}, s_.doc.path(),
                [this](const std::filesystem::path& f) { unlessUnsaved([this, f] { openScene(f); }); });
}

void Viewer::openFile(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".obj") {
    unlessUnsaved([this, file] { openScene(file); });
    return;
  }
  ui::addObject(s_, Shape::mesh, file.string());  // as the scene panel's "+ OBJ mesh…"
  setStatus("adding " + file.string() + " …", false);
  requestFrames(2);
}

void Viewer::useFileChooser(std::unique_ptr<FileChooser> chooser, bool browser) {
  dialog_ = std::move(chooser);
  browser_ = browser;
}

Image Viewer::exportImage(ViewKind kind, int width, int height) {
  const GLint previous = [&] {
    GLint fb = 0;
    ctx_.gl().GetIntegerv(GL_FRAMEBUFFER_BINDING, &fb);
    return fb;
  }();
  Image image = renderImage(renderer_, s_.doc.shown(), shownViewRequest(s_, kind, width, height, uiScale_));
  ctx_.gl().BindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
  return image;
}

UrlState Viewer::urlState() const {
  UrlState u;
  // The built-in scene is the bundled default.json (the same dump): a link names it as "default".
  if (s_.doc.path().empty()) u.scene = "default";
  else if (isBundled(s_.doc.path())) u.scene = s_.doc.path().stem().string();
  u.camera = cameraLinkOf(s_.doc.scene().camera);
  u.cameraStyle = s_.frame.camera.style;
  u.worldStyle = s_.frame.world.style;
  u.npcStyle = s_.frame.npc.style;
  u.worldOrbit = s_.frame.world.orbit;
  u.npcOrbit = s_.frame.npc.orbit;
  u.strategy = s_.pipeline.strategy;
  return u;
}

void Viewer::showUrlState(const UrlState& link, bool atStart) {
  auto showViews = [this, link] {
    if (link.cameraStyle) s_.frame.camera.style = *link.cameraStyle;
    if (link.worldStyle) s_.frame.world.style = *link.worldStyle;
    if (link.npcStyle) s_.frame.npc.style = *link.npcStyle;
    if (link.worldOrbit) s_.frame.world.orbit = *link.worldOrbit;
    if (link.npcOrbit) s_.frame.npc.orbit = *link.npcOrbit;
    if (link.strategy) s_.pipeline.strategy = *link.strategy;
    updateRun();
    requestFrames(2);
  };
  const bool otherScene = !link.scene.empty() && link.scene != urlState().scene;
  if (otherScene || (atStart && !link.camera.empty())) {
    Scene scene = s_.doc.scene();
    if (otherScene) {
      const auto preset = std::find_if(s_.presets.begin(), s_.presets.end(),
                                       [&](const SceneFileInfo& p) { return p.file.stem() == link.scene; });
      if (preset == s_.presets.end()) throw Error("the link's scene \"" + link.scene + "\" is not one of vplab's bundled scenes");
      scene = loadScene(preset->file);
    }
    scene.camera = link.camera.over(scene.camera);
    unlessUnsaved([this, scene = std::move(scene), showViews]() mutable {
      startDocument(std::move(scene));
      showViews();
    });
    return;
  }
  if (const Camera c = link.camera.over(s_.doc.scene().camera); c != s_.doc.scene().camera) s_.doc.scene().camera = c;
  showViews();
}

void Viewer::forgetViewImages() { images_.forget(); }

void Viewer::enableAutosave(const std::filesystem::path& directory, double delaySeconds) {
  autosave_ = std::make_unique<Autosave>(directory, delaySeconds);
}

std::filesystem::path Viewer::writeRecoveryNow() {
  if (!autosave_ || !autosave_->writeNow(s_.doc)) return {};
  return autosave_->file();
}

void Viewer::endSession() {
  if (autosave_) autosave_->removeFile();
}

void Viewer::offerRecovery(Recovery recovery) {
  recovery_ = std::move(recovery);
  askRecovery_ = true;
}

void Viewer::recoveryDialog() {
  if (askRecovery_) {
    ImGui::OpenPopup("Recover unsaved changes?");
    askRecovery_ = false;
  }
  if (!ImGui::BeginPopupModal("Recover unsaved changes?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const std::string scene = recovery_->scenePath.empty() ? "the default lecture scene" : recovery_->scenePath.string();
  ImGui::Text("vplab did not end normally. Unsaved changes of %s", scene.c_str());
  ImGui::Text("were kept at %s (%s).", recovery_->savedAt.c_str(), recovery_->file.string().c_str());
  if (ImGui::Button("Recover them")) {
    ImGui::CloseCurrentPopup();
    try {
      startDocument(Autosave::load(*recovery_), /*dirty=*/true);
      Autosave::discard(*recovery_);  // this session's autosave keeps them from now on
      if (autosave_) autosave_->writeNow(s_.doc);
      setStatus("recovered the unsaved changes of " + scene, false);
    } catch (const Error& e) {
      setStatus(e.what(), true);  // the file stays for another try
    }
    recovery_.reset();
  }
  ui::recordRect(s_, "recovery.recover");
  ImGui::SameLine();
  if (ImGui::Button("Discard them")) {
    ImGui::CloseCurrentPopup();
    Autosave::discard(*recovery_);
    recovery_.reset();
  }
  ui::recordRect(s_, "recovery.discard");
  ImGui::EndPopup();
}

}  // namespace vplab
