// What the desktop's window (context_glfw.cpp) and the page's canvas (context_web.cpp) share: a GlfwWindow
// once GLFW is set up and its hints are given. Each platform's file gives the hints and what differs.
#include "app/context/context_glfw.h"

#include "base/error.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace vplab {

void GlfwWindow::createAndLoad(int width, int height, const std::string& title, bool debug, const char* backend,
                               std::string (*noWindow)()) {
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = noWindow();  // read before glfwTerminate clears GLFW's error
    glfwTerminate();
    throw Error(why);
  }
  glfwMakeContextCurrent(window_);
  try {
    loadGl(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress), debug, backend);
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

}  // namespace vplab
