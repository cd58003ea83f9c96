// GLFW window backend. GLFW's errors are read with glfwGetError right after a failing call, so no
// error callback (a process-wide global) is needed.
#include "app/context/context_glfw.h"

#include "base/error.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace vplab {

namespace {

std::string glfwProblem() {
  const char* description = nullptr;
  const int code = glfwGetError(&description);
  return description ? std::string(description) : "GLFW error " + std::to_string(code);
}

/// A hidden 1 × 1 window: GLFW makes contexts only with windows. Created and destroyed on the main
/// thread (GLFW requires it); current on the render thread in between.
class GlfwSharedContext final : public GlContext {
 public:
  GlfwSharedContext(GLFWwindow* share, bool debug) {
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    window_ = glfwCreateWindow(1, 1, "vplab views", nullptr, share);
    glfwWindowHint(GLFW_VISIBLE, GLFW_TRUE);
    if (!window_) throw Error("a second OpenGL context for the views could not be created: " + glfwProblem());
    glfwMakeContextCurrent(window_);
    try {
      loadGl(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress), debug, "glfw");
    } catch (...) {
      glfwMakeContextCurrent(share);
      glfwDestroyWindow(window_);
      throw;
    }
    glfwMakeContextCurrent(share);
  }
  ~GlfwSharedContext() override { glfwDestroyWindow(window_); }
  std::string_view backend() const override { return "glfw"; }
  void makeCurrent() override { glfwMakeContextCurrent(window_); }
  void releaseCurrent() override { glfwMakeContextCurrent(nullptr); }

 private:
  GLFWwindow* window_ = nullptr;
};

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
  // X11's WM_CLASS: the desktop entry's StartupWMClass (packaging/vplab.desktop) matches the window to
  // the menu's entry and its icon.
  glfwWindowHintString(GLFW_X11_CLASS_NAME, "vplab");
  glfwWindowHintString(GLFW_X11_INSTANCE_NAME, "vplab");
  createAndLoad(width, height, title, debug, "glfw",
                [] { return "the viewer's window with OpenGL 3.3 core could not be created: " + glfwProblem(); });
  glfwSwapInterval(1);
}

std::unique_ptr<GlContext> GlfwWindow::createShared() { return std::make_unique<GlfwSharedContext>(window_, debug()); }
void GlfwWindow::releaseCurrent() { glfwMakeContextCurrent(nullptr); }
void GlfwWindow::setIcon(int width, int height, const std::uint8_t* rgba) {
  if (width <= 0 || height <= 0 || !rgba) return;
  GLFWimage image{width, height, const_cast<unsigned char*>(rgba)};  // GLFW only reads it
  glfwSetWindowIcon(window_, 1, &image);
  glfwGetError(nullptr);  // Wayland has no window icons: its error is not the next call's
}
bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_); }
bool GlfwWindow::readingErrorsWaits() const { return false; }  // a native driver answers from its own state
void GlfwWindow::setShouldClose(bool close) { glfwSetWindowShouldClose(window_, close ? GLFW_TRUE : GLFW_FALSE); }
void GlfwWindow::swapBuffers() { glfwSwapBuffers(window_); }
void GlfwWindow::framebufferSize(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

}  // namespace vplab
