// GLFW window backend. GLFW's errors are read with glfwGetError right after a failing call, so no
// error callback (a process-wide global) is needed.
#include "app/context/context_glfw.h"

#include "pipeline/error.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace vplab {

namespace {

std::string glfwProblem() {
  const char* description = nullptr;
  const int code = glfwGetError(&description);
  return description ? std::string(description) : "GLFW error " + std::to_string(code);
}

}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title, bool debug) {
  if (!glfwInit())
    throw Error("no display for the interactive viewer: " + glfwProblem() +
                " (set DISPLAY, run under Xvfb, or use `vplab render` for headless pictures)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string problem = glfwProblem();
    glfwTerminate();
    throw Error("the viewer's window with OpenGL 3.3 core could not be created: " + problem);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  try {
    loadGl(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress), debug, "glfw");
  } catch (...) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw;
  }
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void GlfwWindow::makeCurrent() { glfwMakeContextCurrent(window_); }
void GlfwWindow::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }
bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_); }
void GlfwWindow::setShouldClose(bool close) { glfwSetWindowShouldClose(window_, close ? GLFW_TRUE : GLFW_FALSE); }
void GlfwWindow::swapBuffers() { glfwSwapBuffers(window_); }
void GlfwWindow::framebufferSize(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

}  // namespace vplab
