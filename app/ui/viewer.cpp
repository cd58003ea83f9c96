// Index: 1 construction (ImGui context, fonts, style)  2 the frame  3 layout and windows
//        4 menus and shortcuts  5 export
#include "app/ui/viewer.h"

#include "app/fonts/font_file.h"
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

void setUpFonts(float scale) {
  static_assert(sizeof(ImWchar) == sizeof(kFontGlyphRanges[0]), "Dear ImGui built with 16-bit ImWchar");
  ImGuiIO& io = ImGui::GetIO();
  if (std::filesystem::exists(kFontFile))
    io.Fonts->AddFontFromFileTTF(kFontFile, 15.f * scale, nullptr, reinterpret_cast<const ImWchar*>(kFontGlyphRanges));
  else io.Fonts->AddFontDefault();
}

/// The value after `value` in `all` (the enum's table), the first after the last: the keys' cycles.
template <typename Enum, size_t N>
Enum nextOf(const std::array<Enum, N>& all, Enum value) {
  for (size_t i = 0; i < N; ++i)
    if (all[i] == value) return all[(i + 1) % N];
  return all[0];
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


}  // namespace

Viewer::Viewer(GlContext& context, Scene scene, float uiScale)
    : ctx_(context),
      renderer_(context, uiScale),
      images_(context, renderer_),
      s_(std::move(scene)),
      run_(s_),
      panes_(context, s_, images_, run_),
      session_(s_,
               [this] {
                 updateRun();
                 requestFrames(2);
               }),
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
  s_.display.camera.style = Style::shaded;
  s_.antialias = !context.softwareRenderer();
  s_.uiScale = uiScale;
  s_.presets = listPresetScenes();
  s_.display.world.orbit = defaultWorldOrbit(s_.doc.shown(), s_.worldAspect);
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

void Viewer::setStatus(std::string message, bool error) { session_.setStatus(std::move(message), error); }

// ---------------------------------------------------------------- 2 the frame

void Viewer::updateRun() { run_.update(); }

void Viewer::usePipelineWorker(std::function<void()> wake) { run_.useWorker(std::move(wake)); }

std::vector<ViewKind> Viewer::viewsNotReady() const {
  // While a run is under way every view shows the last one: none is of the current state.
  return run_.pending() ? images_.asked() : images_.notReady();
}

void Viewer::makeCurrent() { ImGui::SetCurrentContext(imgui_); }

double Viewer::wakeIn() const {
  if (settleFrames_ > 0 || s_.morphPlaying || s_.animateUntil > imgui_->Time) return 0;
  double wake = 1e9;
  // A run of the pipeline or a view's image finished on its thread is shown at once; until then the
  // busy mark's spinner turns.
  if (const std::optional<double> run = run_.wakeIn(kBusyMarkStep)) {
    if (*run <= 0) return 0;
    wake = *run;
  }
  if (const std::optional<double> views = images_.wakeIn(kBusyMarkStep)) {
    if (*views <= 0) return 0;
    wake = std::min(wake, *views);
  }
  // ImGui 1.86 blinks the text cursor (on 0.8 s, off 0.4 s): a few frames a second while typing.
  if (imgui_->IO.WantTextInput) wake = std::min(wake, 0.2);
  if (const std::optional<double> session = session_.wakeIn(imgui_->Time)) wake = std::min(wake, *session);
  return wake;
}

void Viewer::frame(GLuint framebuffer, int width, int height) {
  ImGui::SetCurrentContext(imgui_);
  if (s_.uiScale != uiScale_) applyUiScale(s_.uiScale);  // the font atlas is locked during a frame
  if (settleFrames_ > 0) --settleFrames_;
  images_.beginFrame();
  run_.beginFrame();
  if (session_.beginFrame()) requestFrames(2);
  const Scene atFrameStart = s_.doc.scene();
  const unsigned generation = s_.doc.generation();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  if (s_.morphPlaying) {
    s_.display.morphing.t = std::min(4.0, s_.display.morphing.t + ImGui::GetIO().DeltaTime * s_.morphSpeed);
    if (s_.display.morphing.t >= 4) s_.morphPlaying = false;
  }
  if (width != lastWidth_ || height != lastHeight_) relayout_ = true;
  lastWidth_ = width;
  lastHeight_ = height;
  panes_.beginFrame(uiScale_, relayout_);

  shortcuts();
  if (s_.lectureMode) {
    s_.doc.endFrame(true);
    updateRun();
    panes_.lectureWindow();
  } else {
    menuBar();
    controlsWindow();
    s_.doc.endFrame(true);  // validate what the panels changed; recorded at the end of the frame
    updateRun();
    panes_.viewWindows();
    inspectWindow();
    panes_.morphWindow();
  }
  helpWindow();
  session_.drawDialogs(uiScale_);
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
  session_.endFrame(ImGui::GetTime());

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
      case ViewerState::sceneTab: ui::scenePanel(s_, session_.fileDialog()); break;
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

// ---------------------------------------------------------------- 4 menus and shortcuts

void Viewer::menuBar() {
  if (!ImGui::BeginMainMenuBar()) return;
  const bool fileMenu = ImGui::BeginMenu("File");
  ui::recordRect(s_, "menu.file");
  if (fileMenu) {
    // The browser owns Ctrl+N, Ctrl+O, Ctrl+S, Ctrl+W and F11, F12: the page offers these here only.
    auto key = [this](const char* shortcut) { return session_.browser() ? nullptr : shortcut; };
    if (ImGui::MenuItem("New (default lecture scene)", key("Ctrl+N"))) session_.newDocument();
    ui::recordRect(s_, "menu.new");
    if (session_.browser()) {
      if (ImGui::MenuItem("Open a scene or an OBJ mesh…")) session_.chooseFileToOpen();
      ui::recordRect(s_, "menu.open");
      if (ImGui::MenuItem("Save (download)")) session_.save();
      ui::recordRect(s_, "menu.save");
    } else {
      if (ImGui::MenuItem("Open scene…", "Ctrl+O")) session_.chooseFileToOpen();
      if (ImGui::MenuItem("Save", "Ctrl+S")) session_.save();
      if (ImGui::MenuItem("Save as…", "Ctrl+Shift+S")) session_.saveAs();
    }
    if (ImGui::BeginMenu("Presets", !s_.presets.empty())) {
      for (const SceneFileInfo& p : s_.presets)
        if (ImGui::MenuItem(p.title.c_str())) {
          const std::filesystem::path file = p.file;
          session_.unlessUnsaved([this, file] { session_.openScene(file); });
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
    if (!session_.browser() && ImGui::MenuItem("Quit", "Ctrl+Q")) requestQuit();  // a page is closed by its tab
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
    if (session_.browser()) return;  // Ctrl+S, Ctrl+O, Ctrl+N, Ctrl+W, Ctrl+Q are the browser's: the File menu has them
    if (pressed(keys::kS)) {
      if (io.KeyShift) session_.saveAs();
      else session_.save();
    }
    if (pressed(keys::kN)) session_.newDocument();
    if (pressed(keys::kO)) session_.chooseFileToOpen();
    if (pressed(keys::kQ)) requestQuit();
    return;
  }
  if (pressed(keys::kF11) && !session_.browser()) s_.lectureMode = !s_.lectureMode;
  if (pressed(keys::kEscape) && s_.lectureMode) {
    s_.lectureMode = false;
    return;
  }
  if (pressed(keys::kF1)) s_.showHelp = !s_.showHelp;
  if (pressed(keys::kF12) && !session_.browser()) screenshotRequested_ = true;
  if (pressed(keys::kEscape)) s_.probe.reset();
  for (size_t i = 0; i < kAllStyles.size(); ++i)  // 1 to 5
    if (pressed(keys::kDigit1 + int(i)))
      s_.display.camera.style = s_.display.world.style = s_.display.npc.style = kAllStyles[i];
  if (pressed(keys::kP)) {
    Camera& c = s_.doc.scene().camera;
    c.projection = nextOf(kAllProjections, c.projection);
  }
  if (pressed(keys::kC)) s_.pipeline.strategy = nextOf(kAllClipStrategies, s_.pipeline.strategy);
  if (pressed(keys::kB)) s_.pipeline.boundingBoxTest = !s_.pipeline.boundingBoxTest;
  if (pressed(keys::kR)) {
    s_.display.world.orbit = defaultWorldOrbit(s_.doc.shown(), s_.worldAspect);
    s_.display.npc.orbit = defaultNpcOrbit();
  }
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
  r.display = s.display;
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
    const int w = images_.width(kind), h = images_.height(kind);
    const std::string png = std::string(e.name) + " view as PNG…";
    const bool pngChosen = ImGui::MenuItem(png.c_str(), nullptr, false, texture != 0);
    ui::recordRect(s_, ("export." + std::string(toString(e.kind)) + ".png").c_str());
    if (pngChosen) {
      session_.fileDialog().open("Export the " + std::string(e.name) + " view", FileChooser::Mode::save, {".png"},
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
    const std::optional<std::string> why = svgExportError(e.kind, s_.doc.shown(), s_.display);
    const std::string svg = std::string(e.name) + " view as SVG…";
    const bool svgChosen = ImGui::MenuItem(svg.c_str(), nullptr, false, !why && texture != 0);
    ui::recordRect(s_, ("export." + std::string(toString(e.kind)) + ".svg").c_str());
    if (svgChosen) {
      session_.fileDialog().open("Export the " + std::string(e.name) + " view", FileChooser::Mode::save, {".svg"},
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

// ---------------------------------------------------------------- 5 export

Image Viewer::exportImage(ViewKind kind, int width, int height) {
  const GLint previous = [&] {
    GLint fb = 0;
    ctx_.gl().GetIntegerv(GL_FRAMEBUFFER_BINDING, &fb);
    return fb;
  }();
  Image image = renderImage(renderer_, *s_.ranScene, shownViewRequest(s_, kind, width, height, uiScale_));
  ctx_.gl().BindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
  return image;
}

void Viewer::forgetViewImages() { images_.forget(); }

}  // namespace vplab
