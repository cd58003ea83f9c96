// Where the viewer's windows go on a display: controls on the left, the world and camera views
// above, the NPC view and the inspector below. Fits a 1280 × 720 projector and laptop screens; the
// user may move and resize them, and the layout is computed again when the display changes size.
// A phone's screen cannot hold that (docs/students.md "In the browser"): there the compact layout shows one
// view at a time, a switcher at the bottom, and one panel below the view (upright) or beside it.
#pragma once

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "app/ui/viewer_state.h"

namespace vplab::ui {

struct Rect {
  ImVec2 pos, size;
};

struct Layout {
  Rect controls, world, camera, npc, inspect;
  bool compact = false;  // then the views share one rect, the panels another, and only the chosen are shown
  Rect switcher;         // compact: the bar that chooses the view and the panel
  Rect caption;          // a lesson's caption box across the bottom (empty without a lesson)
  std::vector<ViewKind> onlyViews;  // the embed form: only these views, side by side, and no panels
  /// Whether the view `kind` has a window in this layout (compact: the one chosen, `compactView`).
  bool shows(ViewKind kind, ViewKind compactView) const {
    if (!onlyViews.empty()) return std::find(onlyViews.begin(), onlyViews.end(), kind) != onlyViews.end();
    return !compact || compactView == kind;
  }
};

/// Whether a display of `display` pixels at UI scale `scale` is too small for the desktop layout:
/// narrower than 760 or lower than 460 units (a phone upright or on its side; the desktop layout's
/// controls take 300 units and each view needs some 200 to be more than a sliver).
inline bool tooSmallForDesktop(ImVec2 display, float scale) {
  return display.x < 760.f * scale || display.y < 460.f * scale;
}

/// The compact layout: the view fills what the menu and the switcher leave; a panel, when one is
/// open, takes the lower 58 % upright or the right half on its side (the view stays in sight while
/// a field is dragged).
inline Layout computeCompactLayout(ImVec2 display, float menuHeight, float switcherHeight, bool panelOpen,
                                   float captionHeight = 0) {
  Layout l;
  l.compact = true;
  const float top = menuHeight;
  const float h = std::max(1.f, display.y - top - switcherHeight - captionHeight);
  l.switcher = {{0, top + h + captionHeight}, {display.x, switcherHeight}};
  l.caption = {{0, top + h}, {display.x, captionHeight}};
  Rect view{{0, top}, {display.x, h}}, panel = view;
  if (panelOpen && display.x >= display.y) {  // on its side: the panel beside the view
    const float w = std::floor(display.x * 0.5f);
    view.size.x = w;
    panel = {{w, top}, {display.x - w, h}};
  } else if (panelOpen) {  // upright: the panel below the view
    const float upper = std::floor(h * 0.42f);
    view.size.y = upper;
    panel = {{0, top + upper}, {display.x, h - upper}};
  }
  l.world = l.camera = l.npc = view;
  l.controls = l.inspect = panel;
  return l;
}

/// The desktop layout; a lesson's caption box, `captionHeight` high, takes the bottom across the
/// whole width, and the windows share what is left above it. A lesson step whose evidence is in the
/// inspector (its probe, a matrix, the depth plot) gives the inspector the tall column on the left
/// (`inspectorLeft`) and the controls its place: the cited values are read there, from the back row.
inline Layout computeLayout(ImVec2 display, float menuHeight, float scale, float captionHeight = 0,
                            bool inspectorLeft = false) {
  Layout l;
  const float top = menuHeight;
  const float h = std::max(1.f, display.y - top - captionHeight);
  l.caption = {{0, top + h}, {display.x, captionHeight}};
  const float left = std::clamp(display.x * 0.26f, 300.f * scale, 430.f * scale);
  const float rw = display.x - left;
  const float upper = std::floor(h * 0.56f);
  const float wWorld = std::floor(rw * 0.55f);
  l.controls = {{0, top}, {left, h}};
  l.world = {{left, top}, {wWorld, upper}};
  l.camera = {{left + wWorld, top}, {rw - wWorld, upper}};
  l.npc = {{left, top + upper}, {wWorld, h - upper}};
  l.inspect = {{left + wWorld, top + upper}, {rw - wWorld, h - upper}};
  if (inspectorLeft) std::swap(l.controls, l.inspect);
  return l;
}

/// Whether the lesson's current step shows its evidence in the inspector (its tab is one of the
/// inspector's), or an exercise's Tasks tab is open (its fields need the height): the layout then
/// puts the inspector in the tall column.
inline bool lessonEvidenceInInspector(const ViewerState& s) {
  if (s.lectureMode) return false;
  if (s.practice && s.inspectTab == ViewerState::tasksTab) return true;
  if (!s.lesson) return false;
  const std::string& tab = s.lesson->current().state.tab;
  return tab == "probe" || tab == "matrices" || tab == "depth";
}

/// The embed form (a figure in a course page, `#embed=camera,world`): the named views side by side in
/// their order, filling the display above the caption box; no menu, no panels.
inline Layout computeEmbedLayout(ImVec2 display, float captionHeight, const std::vector<ViewKind>& views) {
  Layout l;
  l.onlyViews = views;
  const float h = std::max(1.f, display.y - captionHeight);
  l.caption = {{0, h}, {display.x, captionHeight}};
  const float w = std::floor(display.x / float(std::max<size_t>(1, views.size())));
  for (size_t i = 0; i < views.size(); ++i) {
    const Rect r{{w * float(i), 0}, {i + 1 == views.size() ? display.x - w * float(i) : w, h}};
    if (views[i] == ViewKind::world) l.world = r;
    if (views[i] == ViewKind::camera) l.camera = r;
    if (views[i] == ViewKind::npc) l.npc = r;
  }
  return l;
}

/// Positions the next window: always on a relayout frame or in the compact layout (whose windows
/// do not move), else only the first time.
inline void placeNext(const Layout& l, const Rect& r, bool relayout) {
  const ImGuiCond cond = relayout || l.compact || !l.onlyViews.empty() ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
  ImGui::SetNextWindowPos(r.pos, cond);
  ImGui::SetNextWindowSize(r.size, cond);
}

/// The windows' flags in layout `l` besides `flags`: fixed in place in the compact layout.
inline ImGuiWindowFlags layoutFlags(const Layout& l, ImGuiWindowFlags flags) {
  return l.compact || !l.onlyViews.empty() ? flags | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse : flags;
}

/// The switcher's buttons' padding: twice the frame's height for a finger with a mouse's style; the
/// touch style's frames are a finger's size already (app/ui/touch.h).
inline ImVec2 switcherPadding(bool touch) {
  const ImGuiStyle& style = ImGui::GetStyle();
  return ImVec2(style.FramePadding.x * 1.5f, style.FramePadding.y * (touch ? 1 : 2));
}

/// The switcher's height (a row of buttons large enough for a finger).
inline float switcherHeight(bool touch) {
  return ImGui::GetFontSize() + switcherPadding(touch).y * 2 + ImGui::GetStyle().WindowPadding.y * 2;
}

/// The layout of this frame: compact where it is allowed and the display is too small.
inline Layout currentLayout(const ViewerState& s, float scale) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  if (!s.embedViews.empty()) return computeEmbedLayout(display, s.captionHeight, s.embedViews);
  if (s.compactAllowed && tooSmallForDesktop(display, scale))
    return computeCompactLayout(display, ImGui::GetFrameHeight(), switcherHeight(s.touch), s.compactPanel != ViewerState::noPanel,
                                s.captionHeight);
  return computeLayout(display, ImGui::GetFrameHeight(), scale, s.captionHeight, lessonEvidenceInInspector(s));
}

}  // namespace vplab::ui
