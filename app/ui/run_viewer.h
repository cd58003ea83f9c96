// The interactive viewer in a GLFW window (`vplab`, `vplab --scene FILE`).
#pragma once

#include "pipeline/scene.h"

#include <string>

namespace vplab {

struct ViewerLaunch {
  Scene scene;
  int width = 1280, height = 720;   // the window, in screen units
  float uiScale = 1.f;              // larger fonts and handles for projectors
  int quitAfterFrames = 0;          // > 0: quit by itself after that many frames (smoke tests)
  std::string screenshotOnQuit;     // a PNG of the whole window written when quitting
  bool glDebug = false;
};

/// Runs until the window is closed. Throws vplab::Error when no window can be opened.
int runViewerWindow(ViewerLaunch launch);

}  // namespace vplab
