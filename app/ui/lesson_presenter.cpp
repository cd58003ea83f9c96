// Index: 1 moving between steps  2 the keys  3 the caption box  4 the marks in the views
#include "app/ui/lesson_presenter.h"

#include "app/views/caption_text.h"
#include "app/inspect/picking.h"
#include "app/ui/keys.h"
#include "app/ui/widgets.h"

#define IMGUI_DEFINE_MATH_OPERATORS
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cctype>

namespace vplab::ui {

// ---------------------------------------------------------------- 1 moving between steps

namespace {

/// What the lab shows now, as a step's state: where a move into the next step starts.
LessonState shownState(const ViewerState& s) {
  LessonState shown;
  shown.scene = s.doc.scene();
  shown.display = s.display;
  shown.strategy = s.pipeline.strategy;
  shown.boundingBoxTest = s.pipeline.boundingBoxTest;
  shown.morphShown = s.showMorph;
  shown.selected = size_t(std::max(0, s.selectedObject));
  return shown;
}

/// The state of this moment: the document's scene (recorded as one undo step once the move is over),
/// the views' settings but the user's preferences (theme, language), the strategy.
void applyState(ViewerState& s, const LessonState& state) {
  s.doc.scene() = state.scene;
  const Theme theme = s.display.theme;
  const Language language = s.display.language;
  s.display = state.display;
  s.display.theme = theme;
  s.display.language = language;
  s.pipeline.strategy = state.strategy;
  s.pipeline.boundingBoxTest = state.boundingBoxTest;
  s.showMorph = state.morphShown;
  s.selectedObject = int(state.selected);
}

/// Where in its tab's panel a step's evidence starts (ui::scrollAnchor): the fields, derived values
/// or counts its highlights point at. A matrix scrolls itself into sight (lessonScroll).
std::string evidencePlace(const LessonState& state) {
  auto highlights = [&](LessonHighlight::Kind kind, auto&& test) {
    return std::any_of(state.highlights.begin(), state.highlights.end(),
                       [&](const LessonHighlight& h) { return h.kind == kind && test(h); });
  };
  const auto any = [](const LessonHighlight&) { return true; };
  if (state.tab == "camera") {
    if (highlights(LessonHighlight::Kind::axis, any)) return "camera.derived";
    if (highlights(LessonHighlight::Kind::handle, [](const LessonHighlight& h) {
          return h.handle == Handle::windowLeft || h.handle == Handle::windowRight || h.handle == Handle::windowBottom ||
                 h.handle == Handle::windowTop;
        }))
      return "camera.window";
    if (highlights(LessonHighlight::Kind::handle, [](const LessonHighlight& h) { return h.handle == Handle::front || h.handle == Handle::back; }))
      return "camera.planes";
    return "camera.points";
  }
  if (state.tab == "clipping") return "clipping.counts";
  if (state.tab == "probe") return "probe";
  if (state.tab == "scene" && highlights(LessonHighlight::Kind::plane, [](const LessonHighlight& h) { return h.plane >= kPlaneCount; }))
    return "scene.clipPlanes";
  if (state.tab == "lecture") return state.stepThrough ? "lecture.stepThrough" : state.morphShown ? "lecture.morph" : "lecture.vanishing";
  return {};
}

/// Once the step is reached: its tab, probe, step-through and highlights.
void applyMarks(ViewerState& s, const LessonState& state) {
  if (!state.tab.empty()) selectTab(s, state.tab);
  s.probe = state.probe;
  s.probeShown = state.probe;  // the step chose the tab; a probe does not bring its own forward
  if (state.stepThrough) {
    s.stepThrough = {true, int(state.stepThrough->object), state.stepThrough->face, state.stepThrough->plane};
    if (state.tab.empty()) s.showStepThrough = true;
    // A phone shows one view: the one where the polygon is clipped (it showed the world view).
    if (s.compactShown) s.compactView = ViewKind::npc;
  } else {
    s.stepThrough.active = false;
  }
  s.lessonMarks = state.highlights;
  s.lessonScroll = !state.highlights.empty();
  s.lessonScrollTo = evidencePlace(state);
  s.lessonScrollFrames = 3;
  s.morphPlaying = false;
}

}  // namespace

void goToStep(ViewerState& s, size_t step, double now) {
  if (!s.lesson) return;
  const bool sameScene = sameSceneObjects(s.doc.scene(), s.lesson->lesson().steps[std::min(step, s.lesson->stepCount() - 1)].state.scene);
  s.lesson->go(step, shownState(s), now, sameScene ? s.lessonSeconds : 0);
  s.lessonMarks.clear();
  s.lessonTyped.clear();
}

bool lessonMoving(const ViewerState& s, double now) { return s.lesson && s.lesson->moving(now); }

void lessonFrame(ViewerState& s, double now) {
  if (!s.lesson || s.lesson->settled()) return;
  applyState(s, s.lesson->stateAt(now));
  if (s.lesson->moving(now)) return;
  applyMarks(s, s.lesson->current().state);
  s.lesson->markMarksShown();
}

void lessonEndFrame(ViewerState& s, double now) {
  if (!s.lesson || s.lesson->settled() || s.lesson->moving(now) || !s.lesson->marksShown()) return;
  s.lesson->markSettled();
  s.doc.markClean();
}

// ---------------------------------------------------------------- 2 the keys

bool lessonKeys(ViewerState& s, double now) {
  if (!s.lesson) return false;
  if (ImGui::GetIO().WantTextInput || ImGui::GetIO().KeyCtrl) return true;
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  const size_t step = s.lesson->step(), last = s.lesson->stepCount() - 1;
  if (pressed(keys::kRight) || pressed(keys::kSpace) || pressed(keys::kPageDown)) goToStep(s, std::min(step + 1, last), now);
  if (pressed(keys::kLeft) || pressed(keys::kPageUp)) goToStep(s, step == 0 ? 0 : step - 1, now);
  if (ImGui::IsKeyPressed(keys::kHome, false)) goToStep(s, 0, now);
  if (ImGui::IsKeyPressed(keys::kEnd, false)) goToStep(s, last, now);
  for (ImWchar c : ImGui::GetIO().InputQueueCharacters)
    if (c >= '0' && c <= '9' && s.lessonTyped.size() < 4) s.lessonTyped += char(c);
  if ((ImGui::IsKeyPressed(keys::kEnter, false) || ImGui::IsKeyPressed(keys::kKeypadEnter, false)) && !s.lessonTyped.empty()) {
    const size_t n = size_t(std::stoul(s.lessonTyped));  // numbered from 1, as the caption box shows them
    goToStep(s, n == 0 ? 0 : n - 1, now);
  }
  if (ImGui::IsKeyPressed(keys::kEscape, false)) {
    if (!s.lessonTyped.empty()) s.lessonTyped.clear();
    else if (!s.lectureMode) {
      s.lesson.reset();
      s.lessonMarks.clear();
    }
  }
  return true;
}

// ---------------------------------------------------------------- 3 the caption box

namespace {

/// One piece of a caption placed on a line, relative to the caption's top left corner.
struct Placed {
  std::string text;
  ImVec2 at;
  float size;
  bool math;
};

/// Lays the caption out in lines `width` wide with the current font (layOutCaption): sub- and
/// superscripts smaller and shifted.
std::vector<Placed> layOut(const std::string& caption, float width, float* height) {
  ImFont* font = ImGui::GetFont();
  const float size = ImGui::GetFontSize(), small = size * 0.72f, line = ImGui::GetTextLineHeightWithSpacing();
  auto sizeOf = [&](CaptionRun::Script script) { return script == CaptionRun::Script::normal ? size : small; };
  const CaptionMeasure widthOf = [&](std::string_view text, CaptionRun::Script script) {
    return double(font->CalcTextSizeA(sizeOf(script), FLT_MAX, 0, text.data(), text.data() + text.size()).x);
  };
  int lines = 0;
  const std::vector<CaptionPiece> pieces = layOutCaption(caption, width, widthOf, widthOf(" ", CaptionRun::Script::normal), &lines);
  std::vector<Placed> placed;
  for (const CaptionPiece& p : pieces) {
    const float dy = p.script == CaptionRun::Script::sub ? size * 0.42f : p.script == CaptionRun::Script::super ? -size * 0.08f : 0;
    placed.push_back({p.text, ImVec2(float(p.x), p.line * line + dy), sizeOf(p.script), p.math});
  }
  if (height) *height = std::max(1, lines) * line;
  return placed;
}

/// "lecture notes 15.2.2", "Hill 7.4": the step's source as the lesson's language names it.
std::string sectionText(const Lesson& lesson, const std::string& section) {
  if (section.empty()) return "";
  const bool lectureNotes = std::isdigit(static_cast<unsigned char>(section[0]));
  return lectureNotes ? text::fill(lesson.language, "lecture notes {1}", {section}) : section;
}

/// The caption box's heading row: the heading where it fits beside the buttons, else (a phone
/// upright) on its own line above them, the buttons then sharing the width as a finger's row.
struct HeadingRow {
  std::string heading, source;
  const char *back, *next, *close;
  float buttons = 0;     // the buttons' width beside the heading
  bool ownRow = false;   // the buttons on a row of their own under the heading
};

HeadingRow headingRow(const LessonPlayer& player, float width) {
  const Lesson& lesson = player.lesson();
  const LessonStep& step = player.current();
  const ImGuiStyle& style = ImGui::GetStyle();
  HeadingRow row;
  row.back = text::Text("← Back").in(lesson.language);
  row.next = text::Text("Next →").in(lesson.language);
  row.close = text::Text("Close").in(lesson.language);
  row.buttons = ImGui::CalcTextSize(row.back).x + ImGui::CalcTextSize(row.next).x + ImGui::CalcTextSize(row.close).x +
                style.FramePadding.x * 6 + style.ItemSpacing.x * 2;
  // The heading left of the buttons, never under them: the lesson's title, the step and the source
  // where they fit; else the step and the source (the title is in the menu and the first step);
  // else the step alone (at 1024 × 768 "← Zurück" covered the source); else, on a screen too narrow
  // for the step beside the buttons, the heading on its own line.
  const std::string stepOf =
      text::fill(lesson.language, "step {1} / {2}", {std::to_string(player.step() + 1), std::to_string(player.stepCount())});
  const std::string titled = text::fill(lesson.language, "{1}  ·  step {2} / {3}",
                                        {lesson.title, std::to_string(player.step() + 1), std::to_string(player.stepCount())});
  const std::string sourceText = step.section.empty() ? "" : "(" + sectionText(lesson, step.section) + ")";
  auto widthOf = [&](const std::string& heading, const std::string& source) {
    return ImGui::CalcTextSize(heading.c_str()).x + (source.empty() ? 0 : style.ItemSpacing.x + ImGui::CalcTextSize(source.c_str()).x);
  };
  row.ownRow = widthOf(stepOf, "") > width - row.buttons - style.ItemSpacing.x;
  const float room = row.ownRow ? width : width - row.buttons - style.ItemSpacing.x;
  row.heading = titled;
  row.source = sourceText;
  if (widthOf(row.heading, row.source) > room) row.heading = stepOf;
  if (widthOf(row.heading, row.source) > room) row.source.clear();
  return row;
}

/// The note under the caption: the typed step number, or a free step's note ("" for none).
std::string captionNote(const ViewerState& s) {
  const Lesson& lesson = s.lesson->lesson();
  if (!s.lessonTyped.empty()) return text::fill(lesson.language, "go to step {1} (Enter)", {s.lessonTyped});
  if (s.lesson->current().free) return text::Text("Explore freely: the next step restores its own state.").in(lesson.language);
  return "";
}

/// The height of the caption and its note laid out `width` wide.
float captionTextHeight(const ViewerState& s, float width) {
  float h = 0;
  layOut(s.lesson->current().caption, width, &h);
  const std::string note = captionNote(s);
  if (!note.empty()) h += ImGui::GetStyle().ItemSpacing.y + ImGui::CalcTextSize(note.c_str(), nullptr, false, width).y;
  return h;
}

/// The share of the display's height a caption box takes at most: a longer caption scrolls in it
/// (on a phone on its side a whole caption left the view a sliver).
constexpr float kCaptionShare = 0.4f;

}  // namespace

float lessonCaptionHeight(const ViewerState& s, float width) {
  if (!s.lesson) return 0;
  const ImGuiStyle& style = ImGui::GetStyle();
  const float inner = width - style.WindowPadding.x * 2;
  // The current step's caption, and at least two lines: the box leaves the rest to the step's
  // evidence (sized for the longest caption, it took a third of a 720-line projector at 1.6).
  const float text = std::max(2 * ImGui::GetTextLineHeightWithSpacing(), captionTextHeight(s, inner));
  const float rows = headingRow(*s.lesson, inner).ownRow ? 2.f : 1.f;
  const float h = std::floor(text + rows * ImGui::GetFrameHeightWithSpacing() + style.WindowPadding.y * 2 + 2);
  return std::min(h, std::floor(ImGui::GetIO().DisplaySize.y * kCaptionShare));
}

void lessonCaption(ViewerState& s, const Rect& rect, double now) {
  if (!s.lesson) return;
  const LessonPlayer& player = *s.lesson;
  const LessonStep& step = player.current();
  ImGui::SetNextWindowPos(rect.pos);
  ImGui::SetNextWindowSize(rect.size);
  ImGui::SetNextWindowBgAlpha(0.94f);
  ImGui::Begin("##lesson", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
  recordRect("lesson.caption");

  // The heading: title, step k of n, the source; the buttons at the right, or under it on a narrow
  // screen, a third of the width each. The box speaks the lesson's language, whatever the viewer's.
  const ImGuiStyle& style = ImGui::GetStyle();
  const HeadingRow row = headingRow(player, ImGui::GetContentRegionAvail().x);
  ImGui::BeginGroup();
  ImGui::PushStyleColor(ImGuiCol_Text, accentColor());
  ImGui::TextUnformatted(row.heading.c_str());
  ImGui::PopStyleColor();
  if (!row.source.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", row.source.c_str());
  }
  ImGui::EndGroup();
  recordRect("lesson.heading");
  const float third = std::floor((ImGui::GetContentRegionAvail().x - style.ItemSpacing.x * 2) / 3);
  const ImVec2 button(row.ownRow ? third : 0, 0);
  if (!row.ownRow) ImGui::SameLine(std::max(ImGui::GetCursorPosX(), ImGui::GetWindowContentRegionMax().x - row.buttons));
  ImGui::BeginDisabled(player.step() == 0);
  if (ImGui::Button(row.back, button)) goToStep(s, player.step() - 1, now);
  ImGui::EndDisabled();
  recordRect("lesson.back");
  ImGui::SameLine();
  ImGui::BeginDisabled(player.step() + 1 >= player.stepCount());
  if (ImGui::Button(row.next, button)) goToStep(s, player.step() + 1, now);
  ImGui::EndDisabled();
  recordRect("lesson.next");
  ImGui::SameLine();
  const bool closing = ImGui::Button(row.close, button);
  recordRect("lesson.close");

  // The caption, its mathematics in the accent colour, and its note; what the box cannot hold
  // scrolls (a swipe on a phone, the wheel on the desktop).
  ImGui::BeginChild("##captionText", ImVec2(0, 0), false);
  float height = 0;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const std::vector<Placed> placed = layOut(step.caption, ImGui::GetContentRegionAvail().x, &height);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text), math = ImGui::ColorConvertFloat4ToU32(accentColor());
  for (const Placed& p : placed) draw->AddText(ImGui::GetFont(), p.size, origin + p.at, p.math ? math : text, p.text.c_str());
  ImGui::Dummy(ImVec2(ImGui::GetContentRegionAvail().x, height));
  recordRect("lesson.text");
  // The note wraps (on a phone "…stellt seinen Zustand wieder her" ran off the box).
  if (const std::string note = captionNote(s); !note.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", note.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::EndChild();
  ImGui::End();
  if (closing) {
    s.lesson.reset();
    s.lessonMarks.clear();
  }
}

// ---------------------------------------------------------------- 4 the marks in the views

void addLessonMarks(const ViewerState& s, Highlights& hl) {
  for (const LessonHighlight& h : s.lessonMarks) {
    if (h.kind == LessonHighlight::Kind::handle) {
      const char* name = handleName(h.handle);
      auto it = std::find_if(hl.handles.begin(), hl.handles.end(), [&](const Highlights::HandleMark& m) { return m.name == name; });
      if (it != hl.handles.end()) it->hot = true;
      else hl.handles.push_back({handlePosition(s.run(), h.handle), name, true});
    } else if (h.kind == LessonHighlight::Kind::plane) {
      hl.planes.push_back(h.plane);
    } else if (h.kind == LessonHighlight::Kind::axis) {
      hl.axes.push_back(h.axis);
    } else if (h.kind == LessonHighlight::Kind::vertex && !s.probe) {
      hl.probeWc = probePosition(s.run(), h.vertex, ViewKind::world);
      hl.probeNpc = probePosition(s.run(), h.vertex, ViewKind::npc);
      hl.probeDc = probePosition(s.run(), h.vertex, ViewKind::camera);
    }
  }
}

}  // namespace vplab::ui
