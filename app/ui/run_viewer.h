// The interactive viewer in a GLFW window (`vplab`, `vplab --scene FILE`).
#pragma once

#include "base/language.h"
#include "course/grade_report.h"
#include "pipeline/scene.h"

#include <functional>
#include <optional>
#include <string>

namespace vplab {

class Viewer;
class InputQueue;
class GlfwWindow;

/// The status of a viewer that ended by an error after its window had opened (EX_SOFTWARE): never 0.
inline constexpr int kUnexpectedEnd = 70;

/// Plays the user (the monkey test, tests/app/window/monkey_test.cpp): called before every frame with
/// the viewer, the window's input queue (events put there are handed to ImGui as GLFW's are) and
/// the window, and the seconds the last frame took; false ends the viewer as quitting does (one more
/// frame is drawn: the last, with screenshotOnQuit's picture). With a
/// driver every frame is drawn, none waited for.
using ViewerDriver = std::function<bool(Viewer&, InputQueue&, GlfwWindow&, double lastFrameSeconds)>;

struct ViewerLaunch {
  Scene scene;
  std::string lesson;               // a lesson file to present (docs/lecturers.md "Lessons"), or empty
  size_t lessonStep = 0;            // its step to open, from 0
  std::string exercise;             // an exercise's folder to practise (`vplab exercise --out DIR`), or empty
  Reveal reveal = Reveal::stages;   // what Check shows of the reference (course/grade_report.h)
  int width = 1280, height = 720;   // the window, in screen units
  float uiScale = 1.f;              // larger fonts and handles for projectors
  std::optional<Language> language; // --lang; else the remembered choice, else the locale's (app/document/preferences.h)
  int quitAfterFrames = 0;          // > 0: quit by itself after that many frames (smoke tests)
  std::string screenshotOnQuit;     // a PNG of the whole window written when quitting
  /// How long a screenshot (F12, screenshotOnQuit) and the scripted end (quitAfterFrames) wait for
  /// every shown view's current image; past it the scripted end fails (status 1) naming the views.
  double waitForViews = 30;
  bool glDebug = false;
  bool reportFrames = false;        // print the number of frames drawn when the viewer ends (tests)
  ViewerDriver driver;              // empty: the user drives
};

/// Runs until the window is closed (0), or a signal ends it (128 + SIGTERM, SIGINT or SIGHUP, after writing
/// the recovery file of unsaved changes), or the scripted end found views not ready within
/// waitForViews (1), or an error escaped the frame's own guard (kUnexpectedEnd, after writing the
/// recovery file). Throws vplab::Error only when no window can be opened.
int runViewerWindow(ViewerLaunch launch);

}  // namespace vplab
