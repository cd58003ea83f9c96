// The views in their windows (view_panes.h).
//
// Index: 1 helpers  2 drawing a view  3 the windows (the mouse in them: view_mouse.cpp)
#define IMGUI_DEFINE_MATH_OPERATORS
#include "app/session/exercises.h"
#include "app/ui/layout.h"
#include "app/inspect/camera_text.h"
#include "app/lessons/lesson_marks.h"
#include "app/inspect/picking.h"
#include "app/ui/view_panes.h"
#include "app/ui/view_mouse.h"
#include "app/ui/lesson_presenter.h"
#include "app/ui/widgets.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>

namespace vplab {

// ---------------------------------------------------------------- 1 helpers

namespace {

constexpr ImGuiWindowFlags kViewFlags = ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoScrollbar;

ImTextureID textureId(GLuint texture) { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture)); }

// An interactive image: an invisible button over the whole region takes the mouse (so dragging in
// a view never moves its window), the view's texture is drawn into it, flipped (GL's rows go up).
bool viewImage(const char* id, GLuint texture, ImVec2 size) {
  const ImVec2 at = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  if (texture) ImGui::GetWindowDrawList()->AddImage(textureId(texture), at, at + size, ImVec2(0, 1), ImVec2(1, 0));
  else ImGui::GetWindowDrawList()->AddRectFilled(at, at + size, IM_COL32(0, 0, 0, 255));  // its first image is drawn
  return ImGui::IsItemHovered();
}

// The next view window draws no background: its image covers it, and the viewer clears the screen
// with the background's colour, so the padding and a letterbox look the same. Why: the page without
// a GPU fills about one 1280 × 720 screen of blended pixels in 15 ms (SwiftShader on two cores), and
// backgrounds under the views' images were a third of every frame's fill there. (Not NoBackground:
// that also drops the window's border.) Only for windows that tile the screen: a floating one would
// show what lies under its padding.
void nextViewWindowTransparent() { ImGui::SetNextWindowBgAlpha(0.f); }

// A caption in the top-left corner of an image `width` wide, on a dark background: the longest of
// `texts` that fits.
void caption(ImVec2 at, float width, ImU32 color, std::initializer_list<const char*> texts) {
  const char* text = *(texts.end() - 1);
  for (const char* t : texts)
    if (ImGui::CalcTextSize(t).x + 12 <= width) {
      text = t;
      break;
    }
  const ImVec2 size = ImGui::CalcTextSize(text);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(at + ImVec2(2, 2), at + ImVec2(10, 6) + size, IM_COL32(0, 0, 0, 170), 3.f);
  dl->AddText(at + ImVec2(6, 4), color, text);
}

Vec2 mouseIn(ImVec2 itemMin, ImVec2 scale) {
  const ImVec2 m = ImGui::GetIO().MousePos;
  return {(m.x - itemMin.x) * scale.x, (m.y - itemMin.y) * scale.y};
}


}  // namespace

// ---------------------------------------------------------------- 2 drawing a view

namespace {

/// The pixels of a view's image shown at `size` screen units.
std::array<int, 2> imagePixels(ImVec2 size) {
  const ImVec2 fb = ImGui::GetIO().DisplayFramebufferScale;
  return {std::max(8, int(size.x * fb.x)), std::max(8, int(size.y * fb.y))};
}

/// The aspect ratio of the world view's image at `size`: its observer is framed for it.
double aspectOf(ImVec2 size) {
  const auto [w, h] = imagePixels(size);
  return double(w) / h;
}

}  // namespace

// A view is drawn again only when what it shows changed (app/render/view_images.h). Drawing
// changes no state: what it shows was settled before.
GLuint ViewPanes::drawView(ViewKind kind, ImVec2 size) {
  const auto [w, h] = imagePixels(size);
  return images_.image({kind, s_.ranScene, s_.ran, s_.display, s_.highlights, w, h, s_.antialias ? 4 : 1, uiScale_}, run_.revision());
}

void ViewPanes::busyMark(ViewKind kind) {
  if (!images_.busy(kind) && !run_.pending()) return;
  const ImVec2 max = ImGui::GetItemRectMax();
  const ImVec2 min = ImGui::GetItemRectMin();
  // A run in steps (the page) says how far it is; a view drawn in slices only that it is busy.
  const std::optional<double> p = run_.progress();
  const std::string progress = p ? ui::tr(s_, "updating… {1} %", {std::to_string(int(*p * 100))}) : ui::tr(s_, "updating…");
  const char* text = progress.c_str();
  const float pad = 4 * uiScale_, radius = ImGui::GetTextLineHeight() * 0.4f;
  const ImVec2 textSize = ImGui::CalcTextSize(text);
  const ImVec2 size(pad * 3 + radius * 2 + textSize.x, pad * 2 + textSize.y);
  const ImVec2 at(std::max(min.x, max.x - size.x - pad), min.y + pad);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(at, at + size, IM_COL32(20, 22, 28, 210), 3 * uiScale_);
  // A quarter circle turning once a second.
  const ImVec2 centre = at + ImVec2(pad + radius, size.y * 0.5f);
  const float a0 = float(std::fmod(ImGui::GetTime(), 1.0) * 2 * M_PI);
  draw->PathArcTo(centre, radius, a0, a0 + float(M_PI) * 1.5f, 12);
  draw->PathStroke(IM_COL32(255, 200, 90, 255), false, 2 * uiScale_);
  draw->AddText(at + ImVec2(pad * 2 + radius * 2, pad), IM_COL32(235, 235, 235, 255), text);
}

void ViewPanes::lastValidNote() {
  if (s_.doc.error().empty()) return;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  const Camera& edited = s_.doc.scene().camera;
  const std::optional<CameraProblem> problem = cameraProblem(edited);
  const std::string why = problem ? cameraProblemText(*problem, edited, s_.display.language) : s_.doc.error();
  std::string note = problem ? ui::tr(s_, "This view shows the last valid camera: {1}", {why})
                             : ui::tr(s_, "This view shows the last valid scene: {1}", {why});
  // Across the view's bottom, wrapped to its width, over a dark band: readable on any picture. A
  // view too small for the reason (a projector's 1.6) keeps most of its picture: the reason is in the
  // camera panel beside it.
  const float pad = 5 * uiScale_, wrap = std::max(1.f, max.x - min.x - 2 * pad);
  ImVec2 text = ImGui::CalcTextSize(note.c_str(), nullptr, false, wrap);
  if (text.y > (max.y - min.y) * 0.3f) {
    note = problem ? ui::tr(s_, "This view shows the last valid camera (why: camera panel)")
                   : ui::tr(s_, "This view shows the last valid scene (why: status line)");
    text = ImGui::CalcTextSize(note.c_str(), nullptr, false, wrap);
  }
  const float top = std::max(min.y, max.y - text.y - 2 * pad);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(min, max, true);
  draw->AddRectFilled(ImVec2(min.x, top), max, IM_COL32(20, 22, 28, 225));
  draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(min.x + pad, top + pad), IM_COL32(255, 110, 100, 255),
                note.c_str(), nullptr, wrap);
  draw->PopClipRect();
  ui::recordRect("view.lastValidNote");
}

void ViewPanes::linkNote() {
  if (s_.linkProblems.empty() || linkNoteDrawn_) return;
  linkNoteDrawn_ = true;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  const float pad = 5 * uiScale_, wrap = std::max(1.f, max.x - min.x - 2 * pad);
  // A line for each part left out, as many as fit in half the view; the others counted.
  std::string note = ui::tr(s_, "Not understood in the link, and left out:");
  const float room = (max.y - min.y) * 0.5f;
  for (size_t i = 0; i < s_.linkProblems.size(); ++i) {
    const std::string line = "\n\u2022 " + s_.linkProblems[i].said(s_.display.language);
    const std::string rest = "\n" + ui::tr(s_, "and {1} more (the status line)", {std::to_string(s_.linkProblems.size() - i)});
    if (ImGui::CalcTextSize((note + line + rest).c_str(), nullptr, false, wrap).y > room && i + 1 < s_.linkProblems.size()) {
      note += rest;
      break;
    }
    note += line;
  }
  const ImVec2 text = ImGui::CalcTextSize(note.c_str(), nullptr, false, wrap);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(min, max, true);
  draw->AddRectFilled(min, ImVec2(max.x, std::min(max.y, min.y + text.y + 2 * pad)), IM_COL32(20, 22, 28, 230));
  draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(min.x + pad, min.y + pad), IM_COL32(255, 200, 90, 255),
                note.c_str(), nullptr, wrap);
  draw->PopClipRect();
}

std::optional<Vec3> ViewPanes::probePositionOf(ViewKind view) const {
  return s_.probe ? probePosition(s_.run(), *s_.probe, view) : std::nullopt;
}

// The clipping step-through's current polygon and plane, for the NPC and world views.
void ViewPanes::stepHighlight() {
  const StepThrough& st = s_.stepThrough;
  if (st.active) s_.highlights.step = stepThroughMark(s_.run(), st.object, st.face, st.step);
}

// ---------------------------------------------------------------- 3 the windows

void ViewPanes::viewWindows() {
  ImGuiIO& io = ImGui::GetIO();
  const ImVec2 fbScale = io.DisplayFramebufferScale;
  const ui::Layout layout = ui::currentLayout(s_, uiScale_);
  // The compact layout shows only the view chosen in its switcher.
  auto shown = [&](ViewKind kind) { return layout.shows(kind, s_.compactView); };
  const ImGuiWindowFlags flags = ui::layoutFlags(layout, kViewFlags);

  Highlights& hl = s_.highlights;
  hl = {};
  if (s_.probe) {
    hl.probeWc = probePositionOf(ViewKind::world);
    hl.probeNpc = probePositionOf(ViewKind::npc);
    hl.probeDc = probePositionOf(ViewKind::camera);
  }
  for (Handle handle : kHandles)
    hl.handles.push_back({handlePosition(s_.run(), handle), handleName(handle),
                          handle == s_.hovered || (s_.drag.kind == Drag::Kind::handle && s_.drag.handle == handle)});
  hl.vanishingObject = s_.selectedObject;
  stepHighlight();
  ui::addLessonMarks(s_, hl);
  hl.student = studentMarks(s_, s_.stepThrough);

  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left) && !ImGui::IsMouseDown(ImGuiMouseButton_Right) &&
      !ImGui::IsMouseDown(ImGuiMouseButton_Middle))
    s_.drag = {};

  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2, 2));
  linkNoteDrawn_ = false;
  if (shown(ViewKind::world)) worldWindow(layout, flags, fbScale);
  if (shown(ViewKind::camera)) {
    ui::placeNext(layout, layout.camera, relayout_);
    nextViewWindowTransparent();
    if (ImGui::Begin(ui::tr(s_, "Camera view (DC)###Camera view (DC)"), nullptr, flags)) cameraWindowContents();
    ImGui::End();
  }
  if (shown(ViewKind::npc)) npcWindow(layout, flags, fbScale);
  ImGui::PopStyleVar();
  ctx_.gl().BindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ViewPanes::worldWindow(const ui::Layout& layout, ImGuiWindowFlags flags, ImVec2 fbScale) {
  ui::placeNext(layout, layout.world, relayout_);
  nextViewWindowTransparent();
  if (ImGui::Begin(ui::tr(s_, "World view (WC)###World view (WC)"), nullptr, flags)) {
    const ImVec2 size = ImGui::GetContentRegionAvail();
    if (size.x >= 8 && size.y >= 8) {
      // In the page the scene is framed for the shape the view is shown in (PRP and the whole view
      // volume in sight, issue 41): the shape the view first has (a tablet's view is nearly square,
      // not the 1.6 assumed before the first frame), and on a phone every shape the panel and the
      // phone's turn give it, until the user turns the view (then the user's observer stays). A
      // lesson's steps keep the shape the lesson opened in (lesson_framing.h), but on a phone. The
      // desktop window keeps its observer, as its goldens show it.
      const double aspect = aspectOf(size);
      const bool firstShape = s_.inBrowser && worldFramesDrawn_ < 3 && !s_.lesson;  // ImGui settles the layout over two frames
      if (s_.inBrowser && worldFramesDrawn_ < 3 && s_.lesson && std::abs(aspect / s_.lessonAspect - 1) > 0.05)
        s_.lessonReframe = true;  // opened from the link before the view had its shape
      ++worldFramesDrawn_;
      if ((layout.compact || firstShape) && std::abs(aspect - s_.worldAspect) > 1e-3 &&
          s_.display.world.orbit == defaultWorldOrbit(s_.doc.shown(), s_.worldAspect))
        s_.display.world.orbit = defaultWorldOrbit(s_.doc.shown(), aspect);
      s_.worldAspect = aspect;
      const GLuint texture = drawView(ViewKind::world, size);
      const ViewCamera observer = viewCameraOf(observerCamera(s_.display.world.orbit, s_.worldAspect));
      const bool hovered = viewImage("world", texture, size);
      ui::recordRect("view.world");
      busyMark(ViewKind::world);
      lastValidNote();
      linkNote();
      const ImVec2 origin = ImGui::GetItemRectMin();
      const int w = cachedWidth(ViewKind::world), h = cachedHeight(ViewKind::world);
      mouse_.world(hovered, observer, w, h, mouseIn(origin, fbScale));
      mouse_.recordHandles(origin, observer, w, h, fbScale);
    }
  }
  ImGui::End();
}

void ViewPanes::npcWindow(const ui::Layout& layout, ImGuiWindowFlags flags, ImVec2 fbScale) {
  ui::placeNext(layout, layout.npc, relayout_);
  nextViewWindowTransparent();
  if (ImGui::Begin(ui::tr(s_, "NPC view###NPC view"), nullptr, flags)) {
    const ImVec2 size = ImGui::GetContentRegionAvail();
    if (size.x >= 8 && size.y >= 8) {
      const GLuint texture = drawView(ViewKind::npc, size);
      const ViewCamera observer = viewCameraOf(observerCamera(s_.display.npc.orbit, double(cachedWidth(ViewKind::npc)) / cachedHeight(ViewKind::npc)));
      const bool hovered = viewImage("npc", texture, size);
      busyMark(ViewKind::npc);
      lastValidNote();
      linkNote();
      ui::recordRect("view.npc");
      mouse_.orbit(hovered, ViewKind::npc, s_.display.npc.orbit, observer, cachedWidth(ViewKind::npc), cachedHeight(ViewKind::npc),
                       mouseIn(ImGui::GetItemRectMin(), fbScale));
    }
  }
  ImGui::End();
}

// The camera view: the GPU's image at the device's size, scaled to fit. With the divide-first
// strategy the CPU's (wrong) polygons are shown beside it, with the reason.
void ViewPanes::cameraWindowContents() {
  const Device& device = s_.ranScene->device;  // the image is of the run's scene
  const bool demo = !isCorrect(s_.pipeline.strategy);
  ImVec2 avail = ImGui::GetContentRegionAvail();
  // The reason under the two pictures, whole: the longest wording whose wrapped lines take at most
  // 45 % of the pane (at 1024 × 768 the long one stopped mid-sentence under a small pane).
  const char* reason = nullptr;
  if (demo) {
    const char* reasons[] = {
        ui::tr(s_, "Dividing by w first flips x/w and y/w of every point behind the eye (w < 0), so an edge that "
                   "reaches behind the eye wraps around through infinity. Clipping at z ≤ w first cuts it before w "
                   "reaches 0 (Hill 7.4 and the DGL wiki)."),
        ui::tr(s_, "Divided first, a point behind the eye (w < 0) flips sign: its edge wraps around through infinity."),
        ui::tr(s_, "w < 0 flips the sign (Hill 7.4)")};
    for (const char* r : reasons) {
      reason = r;
      const float height = ImGui::CalcTextSize(r, nullptr, false, avail.x).y + ImGui::GetStyle().ItemSpacing.y * 2;
      if (height <= avail.y * 0.45f) break;
    }
    avail.y -= ImGui::CalcTextSize(reason, nullptr, false, avail.x).y + ImGui::GetStyle().ItemSpacing.y * 2;
  }
  const float panels = demo ? 2.f : 1.f;
  const float fit = std::min(avail.x / panels / device.width, avail.y / device.height);
  if (fit <= 0) return;
  const ImVec2 size(device.width * fit, device.height * fit);
  const GLuint texture = drawView(ViewKind::camera, size);
  if (demo) {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    // A render target's texture like the views': flipped the same way (GL's rows go up).
    if (const GLuint divided = images_.divideFirst(*s_.ranScene, s_.run(), s_.display, run_.revision()))
      ImGui::Image(textureId(divided), size, ImVec2(0, 1), ImVec2(1, 0));
    else  // the strategy's run failed (its error is in the status line): no picture of it
      ImGui::Dummy(size);
    ui::recordRect("view.divideFirst");
    caption(at, size.x, IM_COL32(255, 120, 110, 255),
            {ui::tr(s_, "divide first, then clip (wrong)"), ui::tr(s_, "divide first (wrong)"), ui::tr(s_, "(wrong)")});
    ImGui::SameLine();
  } else {
    ImGui::SetCursorPos(ImGui::GetCursorPos() + (avail - size) * 0.5f);
  }
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const bool hovered = viewImage("camera", texture, size);
  busyMark(ViewKind::camera);
  lastValidNote();
  linkNote();
  ui::recordRect("view.camera");
  if (demo) {
    caption(at, size.x, IM_COL32(140, 230, 140, 255),
            {ui::tr(s_, "clip, then divide (right)"), ui::tr(s_, "clip first (right)"), ui::tr(s_, "(right)")});
    ui::errorText(reason);
    ui::recordRect("view.divideFirst.reason");
  }
  if (!hovered || !ui::viewClicked()) return;
  const Vec2 mouse = mouseIn(ImGui::GetItemRectMin(), ImVec2(1, 1));
  if (ImGui::GetIO().KeyShift) {
    // Shift+click: the front-most clipped polygon under the mouse, for the step-through.
    const Vec2 dc = mouse * Vec2(device.width / size.x, device.height / size.y);
    if (const auto face = pickFace(s_.run(), dc)) {
      s_.stepThrough = {true, int(face->first), int(face->second), 0};
      s_.showStepThrough = true;  // the Lecture tab's step-through comes forward
    }
    return;
  }
  ViewCamera none;
  s_.probe = pickVertex(s_.run(), ViewKind::camera, none, int(size.x), int(size.y), mouse, mouse_.pickRadius());
}

void ViewPanes::morphWindow() {
  if (!s_.showMorph) return;
  // On a phone the morph takes the view's place (a floating window of 560 units hung off a 390 px
  // screen's left edge); its close button gives the view back.
  const ui::Layout layout = ui::currentLayout(s_, uiScale_);
  if (layout.compact) {
    ui::placeNext(layout, layout.world, relayout_);
  } else {
    ImGui::SetNextWindowSize(ImVec2(560, 420) * uiScale_, ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowPos(ImGui::GetIO().DisplaySize * 0.5f, ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
  }
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2, 2));
  if (ImGui::Begin(ui::tr(s_, "Stage morph###Stage morph"), &s_.showMorph, ui::layoutFlags(layout, kViewFlags))) {
    const ImVec2 size = ImGui::GetContentRegionAvail();
    if (size.x >= 8 && size.y >= 8) {
      const GLuint texture = drawView(ViewKind::morph, size);
      const bool hovered = viewImage("morph", texture, size);
      busyMark(ViewKind::morph);
      lastValidNote();
      ui::recordRect("view.morph");
      mouse_.morph(hovered);
    }
  }
  ImGui::End();
  ImGui::PopStyleVar();
  ctx_.gl().BindFramebuffer(GL_FRAMEBUFFER, 0);
}

// Lecture mode: one view fills the window, no panels; the scene's title and caption at the top.
void ViewPanes::lectureWindow() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(io.DisplaySize);
  nextViewWindowTransparent();
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings;
  if (ImGui::Begin("##lecture", nullptr, flags)) {
    Highlights& hl = s_.highlights;
    hl = {};
    hl.vanishingObject = s_.selectedObject;
    stepHighlight();
    ui::addLessonMarks(s_, hl);
    const ImVec2 size = io.DisplaySize;
    const ViewKind kind = s_.lectureView;
    if (kind == ViewKind::camera) {
      const Device& d = s_.ranScene->device;
      const float fit = std::min(size.x / d.width, size.y / d.height);
      const ImVec2 shown(d.width * fit, d.height * fit);
      const GLuint texture = drawView(kind, shown);
      ImGui::SetCursorPos((size - shown) * 0.5f);
      viewImage("lecture", texture, shown);
      busyMark(kind);
      lastValidNote();
    } else {
      if (kind == ViewKind::world) s_.worldAspect = aspectOf(size);
      const GLuint texture = drawView(kind, size);
      const bool hovered = viewImage("lecture", texture, size);
      busyMark(kind);
      lastValidNote();
      const ImVec2 fb = io.DisplayFramebufferScale;
      const Vec2 mouse = mouseIn(ImGui::GetItemRectMin(), fb);
      if (kind == ViewKind::world)
        mouse_.orbit(hovered, kind, s_.display.world.orbit,
                         viewCameraOf(observerCamera(s_.display.world.orbit, s_.worldAspect)), cachedWidth(ViewKind::world),
                         cachedHeight(ViewKind::world), mouse);
      if (kind == ViewKind::npc)
        mouse_.orbit(hovered, kind, s_.display.npc.orbit,
                         viewCameraOf(observerCamera(s_.display.npc.orbit, double(cachedWidth(ViewKind::npc)) / cachedHeight(ViewKind::npc))),
                         cachedWidth(ViewKind::npc), cachedHeight(ViewKind::npc), mouse);
      if (kind == ViewKind::morph) mouse_.morph(hovered);
    }
    const Scene& scene = s_.doc.scene();
    // The title and caption on a dark panel (drawn behind them afterwards, in a lower channel), so
    // they read over any scene.
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float pad = 8 * uiScale_;
    auto panelBehind = [&](const std::function<void()>& text) {
      dl->ChannelsSplit(2);
      dl->ChannelsSetCurrent(1);
      ImGui::BeginGroup();
      text();
      ImGui::EndGroup();
      dl->ChannelsSetCurrent(0);
      dl->AddRectFilled(ImGui::GetItemRectMin() - ImVec2(pad, pad * 0.6f), ImGui::GetItemRectMax() + ImVec2(pad, pad * 0.6f),
                        IM_COL32(10, 11, 15, 200), 4.f * uiScale_);
      dl->ChannelsMerge();
      ui::recordRect("lecture.caption");
    };
    const std::string& title = titleIn(scene, s_.display.language);
    const std::string& sceneCaption = captionIn(scene, s_.display.language);
    if (!title.empty() || !sceneCaption.empty()) {
      ImGui::SetCursorPos(ImVec2(14, 10) * uiScale_);
      panelBehind([&] {
        ImGui::PushTextWrapPos(size.x * 0.6f);
        if (!title.empty()) ImGui::TextColored(ui::accentColor(), "%s", title.c_str());
        if (!sceneCaption.empty()) ImGui::TextWrapped("%s", sceneCaption.c_str());
        ImGui::PopTextWrapPos();
      });
    }
    ImGui::SetCursorPos(ImVec2(14 * uiScale_, size.y - ImGui::GetTextLineHeightWithSpacing() - 6 * uiScale_));
    panelBehind([this] {
      ImGui::TextDisabled("%s", ui::tr(s_, s_.inBrowser ? text::Text("lecture mode — Esc returns to the panels")
                                                        : text::Text("lecture mode — F11 or Esc returns to the panels")));
    });
  }
  ImGui::End();
  ImGui::PopStyleVar(2);
  ctx_.gl().BindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace vplab
