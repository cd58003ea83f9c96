// Index: 1 construction (ImGui context, fonts, style)  2 the frame  3 layout and windows
//        4 menus, shortcuts and dialogs  5 files
#include "app/ui/viewer.h"

#include "app/export/svg.h"
#include "app/ui/keys.h"
#include "app/ui/layout.h"
#include "app/ui/panels.h"
#include "app/ui/widgets.h"
#include "pipeline/error.h"
#include "pipeline/scene_io.h"

#define IMGUI_DEFINE_MATH_OPERATORS
#include <imgui.h>
#include <imgui_internal.h>
#include <backends/imgui_impl_opengl3.h>

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

}  // namespace

Viewer::Viewer(GlContext& context, Scene scene, float uiScale)
    : ctx_(context),
      renderer_(context, uiScale),
      s_(std::move(scene)),
      world_(context.gl()),
      camera_(context.gl()),
      npc_(context.gl()),
      morph_(context.gl()),
      uiScale_(uiScale) {
  IMGUI_CHECKVERSION();
  imgui_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(imgui_);  // CreateContext makes it current only when none is
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is computed, not stored in the working directory
  io.ConfigWindowsMoveFromTitleBarOnly = true;
  setUpFonts(uiScale);
  setUpStyle(uiScale);
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    ImGui::DestroyContext(imgui_);
    throw Error("ImGui's OpenGL3 renderer could not be initialised on the " + std::string(context.backend()) +
                " context (it loads OpenGL through libGL.so.1: use a window or the EGL backend)");
  }
  s_.frame.camera.style = Style::shaded;
  s_.antialias = !context.softwareRenderer();
  s_.uiScale = uiScale;
  s_.presets = listPresetScenes();
  s_.frame.world.orbit = defaultWorldOrbit(s_.doc.shown(), s_.worldAspect);
  runPipeline();
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

void Viewer::setStatus(std::string message, bool error) {
  s_.status = std::move(message);
  s_.statusIsError = error;
}

// ---------------------------------------------------------------- 2 the frame

void Viewer::runPipeline() {
  try {
    vplab::runPipeline(s_.doc.shown(), s_.pipeline, s_.run);
    s_.runError.clear();
  } catch (const Error& e) {
    s_.runError = e.what();  // the previous run stays
  }
}

void Viewer::makeCurrent() { ImGui::SetCurrentContext(imgui_); }

void Viewer::frame(GLuint framebuffer, int width, int height) {
  ImGui::SetCurrentContext(imgui_);
  if (s_.uiScale != uiScale_) applyUiScale(s_.uiScale);  // the font atlas is locked during a frame
  const Scene atFrameStart = s_.doc.scene();
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
    runPipeline();
    lectureWindow();
  } else {
    menuBar();
    controlsWindow();
    s_.doc.endFrame(true);  // validate what the panels changed; recorded at the end of the frame
    runPipeline();
    viewWindows();
    inspectWindow();
    morphWindow();
  }
  helpWindow();
  quitDialog();
  discardDialog();
  dialog_.draw();
  relayout_ = false;
  ImGui::Render();

  // Going straight from one field into the next keeps some item active in every frame: the change
  // of the active item ends one undo step and begins the next.
  const ImGuiID active = ImGui::GetActiveID();
  if (active != lastActive_ && lastActive_ != 0) s_.doc.recordStep(atFrameStart);
  lastActive_ = active;
  const bool editing = active != 0 || s_.drag.kind == Drag::Kind::handle;
  s_.doc.endFrame(editing);

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
      case ViewerState::sceneTab: ui::scenePanel(s_, dialog_); break;
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
                             {"Ctrl+O", "open a scene"},
                             {"Ctrl+S / Ctrl+Shift+S", "save / save as"},
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
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Open scene…", "Ctrl+O"))
      dialog_.open("Open a scene", FileDialog::Mode::open, {".json"}, s_.doc.path(),
                   [this](const std::filesystem::path& f) { unlessUnsaved([this, f] { openScene(f); }); });
    if (ImGui::MenuItem("Save", "Ctrl+S")) saveScene(s_.doc.path());
    if (ImGui::MenuItem("Save as…", "Ctrl+Shift+S"))
      dialog_.open("Save the scene", FileDialog::Mode::save, {".json"}, s_.doc.path(),
                   [this](const std::filesystem::path& f) { saveScene(f); });
    if (ImGui::BeginMenu("Presets", !s_.presets.empty())) {
      for (const SceneFileInfo& p : s_.presets)
        if (ImGui::MenuItem(p.title.c_str())) {
          const std::filesystem::path file = p.file;
          unlessUnsaved([this, file] { openScene(file); });
        }
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Default lecture scene"))
      unlessUnsaved([this] {
        s_.doc.replace(defaultScene());
        s_.probe.reset();
        s_.frame.world.orbit = defaultWorldOrbit(s_.doc.shown(), s_.worldAspect);
      });
    ImGui::Separator();
    if (ImGui::BeginMenu("Export a view")) {
      exportMenu();
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Screenshot", "F12")) screenshotRequested_ = true;
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) requestQuit();
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
    if (pressed(keys::kS)) {
      if (io.KeyShift || s_.doc.path().empty())
        dialog_.open("Save the scene", FileDialog::Mode::save, {".json"}, s_.doc.path(),
                     [this](const std::filesystem::path& f) { saveScene(f); });
      else
        saveScene(s_.doc.path());
    }
    if (pressed(keys::kO))
      dialog_.open("Open a scene", FileDialog::Mode::open, {".json"}, s_.doc.path(),
                   [this](const std::filesystem::path& f) { unlessUnsaved([this, f] { openScene(f); }); });
    if (pressed(keys::kQ)) requestQuit();
    return;
  }
  if (pressed(keys::kF11)) s_.lectureMode = !s_.lectureMode;
  if (pressed(keys::kEscape) && s_.lectureMode) {
    s_.lectureMode = false;
    return;
  }
  if (pressed(keys::kF1)) s_.showHelp = !s_.showHelp;
  if (pressed(keys::kF12)) screenshotRequested_ = true;
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
    if (s_.doc.path().empty()) {
      s_.quitRequested = false;
      dialog_.open("Save the scene", FileDialog::Mode::save, {".json"}, {}, [this](const std::filesystem::path& f) {
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

// Each view as it is shown, to PNG, and the wireframe styles also as SVG (vector lines).
void Viewer::exportMenu() {
  struct Entry {
    ViewKind kind;
    const char* name;
    gl::RenderTarget* target;
  };
  const Entry entries[] = {{ViewKind::camera, "camera", &camera_}, {ViewKind::world, "world", &world_},
                           {ViewKind::npc, "NPC", &npc_}};
  for (const Entry& e : entries) {
    const std::string png = std::string(e.name) + " view as PNG…";
    if (ImGui::MenuItem(png.c_str(), nullptr, false, e.target->width() > 0)) {
      gl::RenderTarget* target = e.target;
      dialog_.open("Export the " + std::string(e.name) + " view", FileDialog::Mode::save, {".png"},
                   "vplab-" + std::string(toString(e.kind)) + ".png", [this, target](const std::filesystem::path& f) {
                     try {
                       writePng(target->read(), f);
                       setStatus("exported " + f.string(), false);
                     } catch (const Error& err) {
                       setStatus(err.what(), true);
                     }
                   });
    }
    const std::optional<std::string> why = svgExportError(e.kind, s_.frame);
    const std::string svg = std::string(e.name) + " view as SVG…";
    if (ImGui::MenuItem(svg.c_str(), nullptr, false, !why && e.target->width() > 0)) {
      const ViewKind kind = e.kind;
      const int w = e.target->width(), h = e.target->height();
      dialog_.open("Export the " + std::string(e.name) + " view", FileDialog::Mode::save, {".svg"},
                   "vplab-" + std::string(toString(kind)) + ".svg", [this, kind, w, h](const std::filesystem::path& f) {
                     try {
                       writeSvg(svgOfView(kind, s_.doc.shown(), s_.run, s_.frame, w, h, uiScale_), f);
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
  ImGui::SameLine();
  if (ImGui::Button("Keep editing")) {
    ImGui::CloseCurrentPopup();
    pendingReplace_ = nullptr;
  }
  ImGui::EndPopup();
}

// ---------------------------------------------------------------- 5 files

void Viewer::openScene(const std::filesystem::path& file) {
  try {
    Scene scene = loadScene(file);  // throws before anything changes: the current scene is kept
    s_.doc.replace(std::move(scene));
    s_.probe.reset();
    s_.selectedObject = 0;
    s_.frame.world.orbit = defaultWorldOrbit(s_.doc.shown(), s_.worldAspect);
    setStatus("opened " + file.string(), false);
  } catch (const Error& e) {
    setStatus(e.what(), true);
  }
}

void Viewer::saveScene(const std::filesystem::path& file) {
  if (file.empty()) {
    dialog_.open("Save the scene", FileDialog::Mode::save, {".json"}, {},
                 [this](const std::filesystem::path& f) { saveScene(f); });
    return;
  }
  try {
    s_.doc.save(file);
    setStatus("saved " + file.string(), false);
  } catch (const Error& e) {
    setStatus(e.what(), true);
  }
}

}  // namespace vplab
