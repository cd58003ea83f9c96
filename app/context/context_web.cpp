// The browser's context: a WebGL2 context on the page's canvas, through emscripten's GLFW (the GLFW
// 3.2 API, -sUSE_GLFW=3), behind the same GlfwWindow interface as the desktop's window
// (context_glfw.h). WebGL2 is OpenGL ES 3.0: GlContext::loadGl loads its functions as it does on
// EGL's ES context, and the GL backend takes the GLSL ES 3.00 path. The canvas fills the page: its
// pixel size follows the page's size times devicePixelRatio (framebufferSize).
//
// The page has no second context (no threads without SharedArrayBuffer, which needs headers a
// course page cannot set) and none of the desktop's headless backends.
#include "app/context/context_glfw.h"

#include "base/error.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <emscripten/html5.h>

#include <algorithm>
#include <cmath>

namespace vplab {

namespace {

constexpr const char* kCanvas = "#canvas";
constexpr int kLargestCanvas = 8192;  // WebGL's drawing buffer is capped by the browser anyway

}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title, bool debug) {
  if (!glfwInit()) throw Error("the page's canvas could not be set up (glfwInit failed)");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  glfwWindowHint(GLFW_ALPHA_BITS, 0);  // an opaque canvas: the page behind never shows through
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  static_cast<void>(debug);  // WebGL has no KHR_debug: errors are read with glGetError (checkErrors)
  createAndLoad(width, height, title, false, "webgl2", [] {
    return std::string("this browser gives the page no WebGL2 context (vplab needs WebGL2: a current Chrome, "
                       "Edge, Firefox or Safari 15.2 and later, with hardware acceleration or its software "
                       "fallback on)");
  });
}

std::unique_ptr<GlContext> GlfwWindow::createShared() { return nullptr; }  // the page draws its views itself
void GlfwWindow::releaseCurrent() {}
bool GlfwWindow::shouldClose() const { return false; }  // a page is closed by its tab, not by itself
bool GlfwWindow::readingErrorsWaits() const { return true; }  // getError is a round trip to the GPU process
void GlfwWindow::setShouldClose(bool) {}
void GlfwWindow::swapBuffers() {}  // the browser presents the canvas when the frame's callback returns

void GlfwWindow::framebufferSize(int& width, int& height) const {
  // The canvas's CSS size (the page's layout: the whole window) times devicePixelRatio, so that one
  // pixel of the picture is one pixel of the screen on a high-DPI laptop or a tablet.
  double cssWidth = 0, cssHeight = 0;
  emscripten_get_element_css_size(kCanvas, &cssWidth, &cssHeight);
  const double ratio = std::clamp(emscripten_get_device_pixel_ratio(), 0.25, 8.0);
  const int w = std::clamp(int(std::lround(cssWidth * ratio)), 1, kLargestCanvas);
  const int h = std::clamp(int(std::lround(cssHeight * ratio)), 1, kLargestCanvas);
  int current = 0, currentHeight = 0;
  glfwGetWindowSize(window_, &current, &currentHeight);
  // Not glfwSetWindowSize: Emscripten's GLFW asks the browser for full screen when the size it is
  // given equals the screen's (a phone's page, a browser in kiosk mode), which a page may not do
  // without a user's gesture (Chromium rejects it: "TypeError: Permissions check failed"; found by
  // the monkey test). Browser.setCanvasSize sets canvas.width and .height and tells GLFW the size.
  if (w != current || h != currentHeight) EM_ASM({ Browser.setCanvasSize($0, $1); }, w, h);
  glfwGetFramebufferSize(window_, &width, &height);
}

// The desktop's headless backends do not exist in a page.
std::unique_ptr<GlContext> createEglContext(bool) { throw Error("EGL is not available in the browser"); }
std::unique_ptr<GlContext> createEglEsContext(bool) { throw Error("EGL is not available in the browser"); }
std::unique_ptr<GlContext> createOsMesaContext(bool) { throw Error("OSMesa is not available in the browser"); }

}  // namespace vplab
