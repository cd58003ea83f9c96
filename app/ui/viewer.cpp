// Index: 1 construction (ImGui context, fonts, style)  2 the frame  3 layout and windows
//        4 export (the menus and keys: app/ui/menus.cpp)
#include "app/ui/viewer.h"

#include "app/fonts/font_file.h"
#include "app/gl/shader.h"
#include "app/ui/file_dialog.h"
#include "app/ui/layout.h"
#include "app/ui/lesson_presenter.h"
#include "app/ui/panels.h"
#include "app/ui/touch.h"
#include "app/ui/widgets.h"
#include "base/error.h"

#define IMGUI_DEFINE_MATH_OPERATORS
#include <imgui.h>
#include <imgui_internal.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <tuple>
#include <utility>

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

/// A finger's target height in pixels at UI scale `scale`, 0 for a mouse.
float touchTarget(const ViewerState& s, float scale) {
  return s.touch ? ui::fingerPixels(ui::kTouchTargetPx, scale, s.cssPixel) : 0.f;
}

/// The style at UI scale `scale`; `touchTarget` > 0: a finger's, every target that many pixels tall.
void setUpStyle(float scale, Theme theme, float touchTarget) {
  if (theme == Theme::light) ImGui::StyleColorsLight();
  else ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 3;
  style.FrameRounding = 2;
  style.WindowBorderSize = 1;
  style.ItemSpacing = ImVec2(7, 5);
  if (touchTarget > 0) {  // a finger's gaps (app/ui/touch.h), a button's label well inside it, a scrollbar a thumb can hold
    style.ItemSpacing = ImVec2(ui::kTouchGapPx, ui::kTouchGapPx);
    style.ItemInnerSpacing = ImVec2(ui::kTouchGapPx, ui::kTouchGapPx);
    style.FramePadding.x = 10;
    style.ScrollbarSize = 20;
    style.GrabMinSize = 20;
  }
  style.ScaleAllSizes(scale);
  if (touchTarget > 0) {
    // A field, a button, a tab, a checkbox, the menu bar are the font's height and twice the frame's
    // padding: padded to a target's height, rounded up so that no rounding makes one a pixel short.
    const ImGuiIO& io = ImGui::GetIO();
    const float font = io.Fonts->ConfigData.empty() ? 13.f : io.Fonts->ConfigData[0].SizePixels;
    style.FramePadding.y = std::ceil(std::max(0.f, touchTarget - font) / 2);
  }
}

/// The busy mark's spinner steps 10 times a second (a frame each, nothing else while idle).
constexpr double kBusyMarkStep = 0.1;


}  // namespace

Viewer::Viewer(GlContext& context, Scene scene, float uiScale)
    : ctx_(context),
      renderer_(context, uiScale),
      errors_(context, context.readingErrorsWaits()),
      images_(context, renderer_),
      s_(std::move(scene)),
      run_(s_),
      panes_(context, s_, images_, run_),
      session_(s_, std::make_unique<FileDialog>(),
               {.changed =
                    [this] {
                      updateRun();
                      requestFrames(2);
                    },
                .goToStep = [this](size_t step) { ui::goToStep(s_, step, imgui_->Time); }}),
      dialogs_(s_, session_),
      windows_(s_, session_),
      menus_(context, s_, session_, images_, renderer_),
      uiScale_(uiScale) {
  images_.timeParts(parts_);
  IMGUI_CHECKVERSION();
  imgui_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(imgui_);  // CreateContext makes it current only when none is
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is computed, not stored in the working directory
  io.UserData = &rects_;     // where the widgets record their rects (ui::recordRect)
  io.ConfigWindowsMoveFromTitleBarOnly = true;
  setUpFonts(uiScale);
  setUpStyle(uiScale, s_.display.theme, touchTarget(s_, uiScale));
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
  setUpStyle(scale, s_.display.theme, touchTarget(s_, scale));
  styledTheme_ = s_.display.theme;
  styledTouch_ = s_.touch;
  styledCssPixel_ = s_.cssPixel;
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
  return "vplab — " + (path.empty() ? std::string(ui::tr(s_, "default lecture scene")) : path.filename().string()) +
         (s_.doc.dirty() ? " *" : "");
}

void Viewer::screenshotTaken(const std::string& file) {
  s_.screenshotRequested = false;
  setStatus(ui::tr(s_, "screenshot saved: {1}", {file}), false);
}

void Viewer::screenshotFailed(const std::string& why) {
  s_.screenshotRequested = false;
  setStatus(ui::tr(s_, "no screenshot: {1}", {why}), true);
}

void Viewer::setStatus(std::string message, bool error) { s_.setStatus(std::move(message), error); }

// ---------------------------------------------------------------- 2 the frame

void Viewer::updateRun() {
  const auto timed = parts_.time("pipeline");
  // One long thing a frame in the page: a view's list put off to this frame, or the run's step.
  if (images_.listPutOff()) run_.leaveFrame();
  run_.update();
}

std::vector<ViewKind> Viewer::viewsNotReady() const {
  // While a run is under way every view shows the last one: none is of the current state.
  return run_.pending() ? images_.asked() : images_.notReady();
}

void Viewer::makeCurrent() { ImGui::SetCurrentContext(imgui_); }

bool Viewer::wantsText() const { return imgui_->IO.WantTextInput || s_.widgets.typing.id != 0; }

double Viewer::wakeIn() const {
  if (settleFrames_ > 0 || s_.morphPlaying || s_.animateUntil > imgui_->Time || touchScroll_.moving()) return 0;
  if (s_.lesson && (s_.lesson->moving(imgui_->Time) || !s_.lesson->settled())) return 0;  // moving into a step
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
  if (const std::optional<double> dialogs = dialogs_.wakeIn()) wake = std::min(wake, *dialogs);
  return wake;
}

void Viewer::frame(GLuint framebuffer, int width, int height) {
  ImGui::SetCurrentContext(imgui_);
  try {
    drawFrame(framebuffer, width, height);
    // The scene is copied only when it changed (a frame of hover copies nothing of it).
    if (!lastGood_ || lastGood_->revision != s_.doc.shownRevision() || lastGood_->generation != s_.doc.generation())
      lastGood_ = LastGood{s_.doc.shown(), s_.doc.shownRevision(), s_.doc.generation(), s_.display, s_.pipeline};
    lastGood_->display = s_.display;
    lastGood_->pipeline = s_.pipeline;
    caught_.inARow = 0;
  } catch (const std::exception& e) {
    recoverFrom(e.what());
  }
}

void Viewer::recoverFrom(const std::string& what) {
  ++caught_.count;
  ++caught_.inARow;
  caught_.last = what;
  // Close whatever the frame left open (windows, IDs, style), then the frame itself.
  ImGui::ErrorCheckEndFrameRecover(nullptr);
  if (ImGuiContext* g = ImGui::GetCurrentContext(); g->FrameCountEnded != g->FrameCount) ImGui::EndFrame();
  images_.endFrame();
  ctx_.discardErrors();
  // The lesson's move ends where it was going (a step's own state is valid: the lesson was checked
  // when read); anything else goes back to the state the last good frame was drawn from.
  if (s_.lesson) s_.lesson->cut();
  if (lastGood_) {
    if (s_.doc.scene() != lastGood_->scene) s_.doc.scene() = lastGood_->scene;
    s_.display = lastGood_->display;
    s_.pipeline = lastGood_->pipeline;
  }
  s_.drag = {};
  s_.doc.endFrame(false);
  setStatus(ui::tr(s_, "an error was stopped, the last working state is shown: {1}", {what}), true);
  // A frame to show it; a frame that fails again and again does not spin.
  if (caught_.inARow == 1) requestFrames(2);
}

void Viewer::drawFrame(GLuint framebuffer, int width, int height) {
  // The font atlas is locked during a frame: the scale (and with it the style) changes before one.
  if (s_.uiScale != uiScale_ || s_.display.theme != styledTheme_ || s_.touch != styledTouch_ || (s_.touch && s_.cssPixel != styledCssPixel_)) applyUiScale(s_.uiScale);
  if (settleFrames_ > 0) --settleFrames_;
  errors_.frameStarts();
  images_.beginFrame();
  rects_.visible.clear();  // filled again by this frame's widgets
  run_.beginFrame();
  if (const auto timed = parts_.time("session"); session_.beginFrame()) requestFrames(2);
  const Scene atFrameStart = s_.doc.scene();
  const unsigned generation = s_.doc.generation();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  if (s_.morphPlaying) {
    s_.display.morphing.t = std::min(4.0, s_.display.morphing.t + ImGui::GetIO().DeltaTime * s_.morphSpeed);
    if (s_.display.morphing.t >= 4) s_.morphPlaying = false;
  }
  const double now = ImGui::GetTime();
  // A modal dialog (recovery, unsaved changes, the file chooser) takes the keys: nothing behind it moves.
  const bool modal = dialogs_.open();
  if (!modal) ui::lessonKeys(s_, now);
  ui::lessonFrame(s_, now);
  // A lesson's caption box takes the bottom of the layout (not in lecture mode: there it lies over the view).
  const float captionHeight = s_.lectureMode ? 0 : ui::lessonCaptionHeight(s_, ImGui::GetIO().DisplaySize.x);
  const bool inspectorLeft = ui::lessonEvidenceInInspector(s_);
  if (width != lastWidth_ || height != lastHeight_ || captionHeight != s_.captionHeight || inspectorLeft != inspectorLeft_)
    relayout_ = true;
  inspectorLeft_ = inspectorLeft;
  lastWidth_ = width;
  lastHeight_ = height;
  s_.captionHeight = captionHeight;
  panes_.beginFrame(uiScale_, relayout_);
  menus_.beginFrame(uiScale_);
  {
    const auto timed = parts_.time("panels");
    windows(now, modal);
  }
  images_.endFrame();
  if (const auto error = images_.takeError()) {  // a view's image failed on the render thread: said, counted
    setStatus(*error, true);
    ++caught_.count;
    caught_.last = *error;
  }
  {
    const auto timed = parts_.time("panels' lists");
    ImGui::Render();
  }

  // Going straight from one field into the next keeps some item active in every frame: the change
  // of the active item ends one undo step and begins the next.
  // A document started in this frame (opened, New) begins with an empty history: the scene at
  // the frame's start belongs to the previous document.
  const ImGuiID active = ImGui::GetActiveID();
  if (active != lastActive_ && lastActive_ != 0 && s_.doc.generation() == generation) s_.doc.recordStep(atFrameStart);
  lastActive_ = active;
  // A move into a lesson's step is one undo step, recorded when it is over.
  const bool editing = active != 0 || s_.drag.kind == Drag::Kind::handle || ui::lessonMoving(s_, now);
  s_.doc.endFrame(editing);
  ui::lessonEndFrame(s_, now);
  session_.endFrame(ImGui::GetTime());

  const auto timed = parts_.time("panels drawn");
  const GladGLContext& gl = ctx_.gl();
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  gl.Viewport(0, 0, width, height);
  // The windows' background colour, opaque: the view windows have none of their own (view_panes.cpp).
  const ImVec4 bg = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
  gl.ClearColor(bg.x, bg.y, bg.z, 1.f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  errors_.frameEnds();
}

void Viewer::windows(double now, bool modal) {
  if (!modal) menus_.shortcuts();
  if (s_.lectureMode) {
    s_.doc.endFrame(true);
    updateRun();
    panes_.lectureWindow();
    if (s_.lesson) {
      const ImVec2 display = ImGui::GetIO().DisplaySize;
      const float h = std::min(display.y * 0.4f, ui::lessonCaptionHeight(s_, display.x));
      ui::lessonCaption(s_, {{0, display.y - h}, {display.x, h}}, now);
    }
  } else if (!s_.embedViews.empty()) {
    // The embed form: the named views and the caption, nothing else (a figure in a course page).
    s_.doc.endFrame(true);
    updateRun();
    panes_.viewWindows();
    ui::lessonCaption(s_, ui::currentLayout(s_, uiScale_).caption, now);
  } else {
    menus_.menuBar();
    windows_.controls(uiScale_, relayout_);
    s_.doc.endFrame(true);  // validate what the panels changed; recorded at the end of the frame
    updateRun();
    panes_.viewWindows();
    windows_.inspect(uiScale_, relayout_);
    windows_.compactSwitcher(uiScale_);
    panes_.morphWindow();
    ui::lessonCaption(s_, ui::currentLayout(s_, uiScale_).caption, now);
  }
  menus_.helpWindow();
  dialogs_.draw(uiScale_);
  touchScroll_.endOfFrame(s_.touch, now);
  relayout_ = false;
  if (std::exchange(s_.lessonReframe, false)) session_.reframeLesson();
}

// ---------------------------------------------------------------- 3 layout and windows




// ---------------------------------------------------------------- 4 export

Image Viewer::exportImage(ViewKind kind, int width, int height) { return menus_.exportImage(kind, width, height); }

void Viewer::recreateGlObjects() {
  makeCurrent();
  ImGui_ImplOpenGL3_Shutdown();  // deletes names a lost context took with it (errors, discarded)
  ctx_.discardErrors();
  renderer_.recreateGlObjects();
  images_.recreateGlObjects();
  errors_.forgetFence();
  const bool es = gl::dialectOf(ctx_.gl()) == gl::GlslDialect::es300;
  if (!ImGui_ImplOpenGL3_Init(es ? "#version 300 es" : "#version 330 core"))
    throw Error("ImGui's OpenGL3 renderer could not be initialised again on the " + std::string(ctx_.backend()) + " context");
  ctx_.discardErrors();  // the render targets' old names, deleted
  requestFrames(3);
}

}  // namespace vplab
