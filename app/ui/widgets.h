// Small ImGui helpers shared by the panels: double-precision drags, bilingual tooltips, and the
// record of where named widgets were drawn (for the UI tests).
#pragma once

#include "app/text/catalogue.h"
#include "app/ui/viewer_state.h"

#include <imgui.h>

#include <initializer_list>
#include <map>
#include <string>
#include <string_view>

namespace vplab::ui {

/// What the panels draw their widgets with: the language, what the widgets remember between frames,
/// the lesson's place to scroll to (scrollAnchor) and how long frames must come (a fading notice). A
/// panel is handed this and the parts of the state it reads and edits (app/ui/panels.h).
struct Widgets {
  explicit Widgets(ViewerState& s)
      : views(s), memory(s.widgets), scrollTo(s.lessonScrollTo), scrollFrames(s.lessonScrollFrames), animateUntil(s.animateUntil), touch(s.touch) {}
  const ViewsPart& views;  // the language
  WidgetMemory& memory;
  std::string& scrollTo;   // LecturePart::lessonScrollTo
  int& scrollFrames;       // LecturePart::lessonScrollFrames
  double& animateUntil;    // LayoutPart::animateUntil
  bool touch;              // LayoutPart::touch: a finger's targets (app/ui/touch.h)
  Language language() const { return views.display.language; }
};

/// A text of the catalogue (app/text/catalogue.h) in the viewer's language (View ▸ Language, --lang):
/// ui::tr(s, "Undo").
inline const char* tr(const ViewsPart& s, text::Text t) { return t.in(s.display.language); }
/// The text with {1}, {2}, … filled in.
inline std::string tr(const ViewsPart& s, text::Text t, std::initializer_list<std::string_view> values) {
  return text::fill(s.display.language, t, values);
}
inline const char* tr(const Widgets& w, text::Text t) { return tr(w.views, t); }
inline std::string tr(const Widgets& w, text::Text t, std::initializer_list<std::string_view> values) {
  return tr(w.views, t, values);
}

/// Where named widgets, handles and views were drawn, in screen coordinates (x, y, width, height):
/// the UI tests and the page's tests drive the viewer through them. A test hook, not the viewer's
/// state: the Viewer owns one and hands it to its ImGui context (io.UserData), where recordRect
/// finds it.
struct RectLog {
  std::map<std::string, ImVec4> rects;
  /// The part of each rect recorded in the last frame that could be seen: inside its window and its
  /// scroll region, not scrolled away (a lesson step's evidence must be on screen: issue 37).
  std::map<std::string, ImVec4> visible;
};
/// The current ImGui context's RectLog; none in a context without a viewer.
RectLog* rectLog();

/// On touch, the rows of a menu or of a combo's list a finger's height apart (an entry's hit box
/// spans the gaps to its neighbours, ImGui's Selectable); nothing with a mouse. Lives while the rows
/// are submitted.
class FingerRows {
 public:
  explicit FingerRows(bool touch);
  ~FingerRows();
  FingerRows(const FingerRows&) = delete;
  FingerRows& operator=(const FingerRows&) = delete;

 private:
  bool pushed_;
};

/// A drag field for a WC vector; records its rect as `id` (recordRect).
bool dragVec3(Widgets& w, const char* label, const char* id, Vec3& v, float speed = 0.02f);
bool dragDouble(Widgets& w, const char* label, const char* id, double& v, float speed = 0.01f,
                double min = 0, double max = 0, const char* format = "%.3f");
/// Remembers the last item's screen rect, and the part of it that can be seen, under `id` (RectLog).
void recordRect(const char* id);
/// A place in a panel a lesson step may scroll to (LecturePart::lessonScrollTo): when the step names
/// `id`, the panel scrolls so that what follows starts at its top, once.
void scrollAnchor(Widgets& w, const char* id);
/// A row of tabs that wraps onto further lines when the window is narrow (a large UI scale) rather
/// than shortening the names ("Cam…"); `current` is the selected tab's index. Records each tab's rect
/// as "tab.ID.NAME" with the English NAME (in either language).
void tabRow(Widgets& w, const char* id, std::initializer_list<text::Text> names, int& current);
/// ImGui's checkbox and radio button with the label wrapped at the window's edge (clicking the
/// label toggles, as ImGui's does). The last item afterwards is the label (for tooltips).
bool checkbox(const char* label, bool* v);
bool radio(const char* label, int* v, int value);
/// SameLine() when a button labelled `next` (or, with button = false, the text `next`) still fits
/// on the line, else the next line.
void sameLineIfFits(const char* next, bool button = true);
/// Makes the next widget narrow enough for its label (after "##", nothing) to fit beside it.
void fitLabel(const char* label);
/// A tooltip on the last item: the text in the viewer's language; in English the lecture notes'
/// German follows in grey.
void tooltip(const Widgets& w, text::Text t);
/// A (?) marker with a tooltip.
void help(const Widgets& w, text::Text t);
/// The colour of errors: a message, an offending field's frame.
ImU32 errorColour();
void errorText(const std::string& text);
/// Colours of text that read on the current style's ground (the dark or the light theme): titles,
/// a boundary coordinate inside (≥ 0) and outside (< 0).
ImVec4 accentColor();
ImVec4 insideColor();
ImVec4 outsideColor();
/// A separator with a small heading.
void section(const char* title);
/// A number of a panel with formatNumber (app/views/number_text.h): `digits` significant digits, noise
/// relative to `scale` (the numbers shown with it) printed as 0.
std::string num(double v, double scale = 0, int digits = 4);
/// A small button that copies `text` to the clipboard; remembers the copy for copiedNotice.
bool copyButton(Widgets& w, const char* label, const char* id, const std::string& text);
/// "copied" beside the button `id` for two seconds after it copied.
void copiedNotice(Widgets& w, const char* id);
/// "(0.1235, -2, 3.5)", through formatVector.
std::string vecText(const Vec3& v);
std::string vecText(const Vec4& v);

}  // namespace vplab::ui
