// The interactive viewer in a GLFW window (`vplab`, `vplab --scene FILE`).
#pragma once

#include "pipeline/language.h"
#include "pipeline/scene.h"

#include <optional>
#include <string>

namespace vplab {

struct ViewerLaunch {
  Scene scene;
  std::string lesson;               // a lesson file to present (README "Lessons"), or empty
  size_t lessonStep = 0;            // its step to open, from 0
  int width = 1280, height = 720;   // the window, in screen units
  float uiScale = 1.f;              // larger fonts and handles for projectors
  std::optional<Language> language; // --lang; else the remembered choice, else the locale's (app/core/preferences.h)
  int quitAfterFrames = 0;          // > 0: quit by itself after that many frames (smoke tests)
  std::string screenshotOnQuit;     // a PNG of the whole window written when quitting
  /// How long a screenshot (F12, screenshotOnQuit) and the scripted end (quitAfterFrames) wait for
  /// every shown view's current image; past it the scripted end fails (status 1) naming the views.
  double waitForViews = 30;
  bool glDebug = false;
  bool reportFrames = false;        // print the number of frames drawn when the viewer ends (tests)
};

/// Runs until the window is closed (0), or a signal ends it (128 + SIGTERM, SIGINT or SIGHUP, after writing
/// the recovery file of unsaved changes), or the scripted end found views not ready within
/// waitForViews (1). Throws vplab::Error when no window can be opened.
int runViewerWindow(ViewerLaunch launch);

}  // namespace vplab
