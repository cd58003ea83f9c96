#include "app/ui/run_viewer.h"

#include "app/context/context_glfw.h"
#include "app/gl/render_target.h"
#include "app/ui/viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>

#include <chrono>
#include <ctime>

namespace vplab {

namespace {

// ImGui's GLFW backend is set up after the viewer made the ImGui context and shut down before the
// viewer destroys it.
struct GlfwBackend {
  explicit GlfwBackend(GLFWwindow* w) { ImGui_ImplGlfw_InitForOpenGL(w, true); }
  ~GlfwBackend() { ImGui_ImplGlfw_Shutdown(); }
};

std::string screenshotName() {
  const std::time_t now = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "vplab-%Y%m%d-%H%M%S.png", std::localtime(&now));
  return buf;
}

}  // namespace

int runViewerWindow(ViewerLaunch launch) {
  const std::string title = "vplab";
  GlfwWindow window(launch.width, launch.height, title, launch.glDebug);
  Viewer viewer(window, std::move(launch.scene), launch.uiScale);
  GlfwBackend backend(window.handle());
  std::string shownTitle;
  for (int frame = 1;; ++frame) {
    glfwPollEvents();
    if (window.shouldClose()) {
      viewer.requestQuit();  // asks first when the scene has unsaved changes
      window.setShouldClose(false);
    }
    ImGui_ImplGlfw_NewFrame();
    int w = 0, h = 0;
    window.framebufferSize(w, h);
    if (w > 0 && h > 0) viewer.frame(0, w, h);
    const bool last = viewer.shouldQuit() || (launch.quitAfterFrames > 0 && frame >= launch.quitAfterFrames);
    if (viewer.screenshotRequested() || (last && !launch.screenshotOnQuit.empty())) {
      const std::string file = viewer.screenshotRequested() ? screenshotName() : launch.screenshotOnQuit;
      writePng(gl::readPixels(window.gl(), 0, w, h), file);
      viewer.screenshotTaken(file);
    }
    window.swapBuffers();
    if (viewer.title() != shownTitle) window.setTitle(shownTitle = viewer.title());
    if (last) break;
  }
  return 0;
}

}  // namespace vplab
