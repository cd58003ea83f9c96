// A GLFW window's input for the viewer, shared by the desktop's event loop (run_viewer.cpp) and the
// browser's frame loop (app/web/page.cpp): the window's callbacks feed an InputQueue, and ImGui's
// GLFW backend is set up without its own callbacks.
#pragma once

#include "app/ui/input_queue.h"

struct GLFWwindow;

namespace vplab {

/// ImGui's GLFW backend, set up after the viewer made the ImGui context and shut down before the
/// viewer destroys it. Its own callbacks stay off: WindowInput queues the input instead.
struct GlfwBackend {
  explicit GlfwBackend(GLFWwindow* window);
  ~GlfwBackend();
  GlfwBackend(const GlfwBackend&) = delete;
  GlfwBackend& operator=(const GlfwBackend&) = delete;
};

/// The window's input callbacks feed `queue`; `changed` says something arrived (input, a resize, an
/// expose) since the loop last looked.
struct WindowInput {
  InputQueue queue;
  bool changed = true;
  GLFWwindow* window;

  explicit WindowInput(GLFWwindow* handle);
  ~WindowInput();
  WindowInput(const WindowInput&) = delete;
  WindowInput& operator=(const WindowInput&) = delete;
};

}  // namespace vplab
