// The viewer's menus (File, Edit, Help), its keys (docs/lecturers.md "The viewer": F1 lists them), the help
// window and File > Export a view. What they do goes to the session (open, save, quit's questions)
// or into the ViewerState (styles, projection, strategy, a screenshot asked for); nothing here draws
// a view.
#pragma once

#include "app/context/context.h"
#include "app/lessons/lesson.h"
#include "app/render/view_images.h"
#include "app/render/view_renderer.h"
#include "app/session/session.h"
#include "app/ui/viewer_state.h"

#include <map>
#include <vector>

namespace vplab {

class Menus {
 public:
  Menus(GlContext& context, ViewerState& state, Session& session, ViewImages& images, ViewRenderer& renderer)
      : ctx_(context), s_(state), session_(session), images_(images), renderer_(renderer) {}

  /// A new frame at UI scale `uiScale`.
  void beginFrame(float uiScale) { uiScale_ = uiScale; }
  /// The main menu bar.
  void menuBar();
  /// The keys (not while a field takes text): undo and redo, files, styles, projection, strategy,
  /// lecture mode, help, screenshot.
  void shortcuts();
  /// The help window (F1), when shown.
  void helpWindow();
  /// The view as File > Export draws it (the shown settings) at width × height pixels, with the
  /// viewer's GL backend; the bound framebuffer stays bound.
  Image exportImage(ViewKind kind, int width, int height);

 private:
  void exportMenu();
  /// File > Lessons: the bundled lessons (app/lessons/lesson.h).
  void lessonsMenu();
  /// View > Language: English or German, remembered (Session::chooseLanguage).
  void languageMenu();
  /// listBundledLessons(lang), read once.
  const std::vector<LessonFileInfo>& bundledLessons(Language lang);

  GlContext& ctx_;
  ViewerState& s_;
  Session& session_;
  ViewImages& images_;
  ViewRenderer& renderer_;
  float uiScale_ = 1.f;
  std::map<Language, std::vector<LessonFileInfo>> bundledLessons_;
};

}  // namespace vplab
