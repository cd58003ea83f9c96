// The interactive viewer's context: a GLFW window with an OpenGL 3.3 core context.
#pragma once

#include "app/context/context.h"

#include <cstdint>

#include <string>

struct GLFWwindow;

namespace vplab {

class GlfwWindow final : public GlContext {
 public:
  /// Opens a window of width × height screen units. Throws vplab::Error when there is no display or
  /// no suitable OpenGL, with GLFW's own description of the problem.
  GlfwWindow(int width, int height, const std::string& title, bool debug);
  ~GlfwWindow() override;

  std::string_view backend() const override { return "glfw"; }
  void makeCurrent() override;
  /// A hidden window whose context shares this window's objects (the views' render thread).
  std::unique_ptr<GlContext> createShared() override;
  void releaseCurrent() override;
  bool readingErrorsWaits() const override;  // in the page (WebGL)

  GLFWwindow* handle() const { return window_; }
  void setTitle(const std::string& title);
  /// The window's icon (the desktop's task bar and switcher; X11's _NET_WM_ICON): width × height
  /// RGBA8 pixels, top row first. Not every platform has one (Wayland): then nothing happens.
  void setIcon(int width, int height, const std::uint8_t* rgba);
  bool shouldClose() const;
  void setShouldClose(bool close);
  void swapBuffers();
  /// Framebuffer size in pixels (differs from the window size on high-DPI screens).
  void framebufferSize(int& width, int& height) const;

 private:
  /// Creates the window with the hints given, makes it current and loads GL (glfw_window.cpp). On
  /// failure GLFW is terminated and the Error thrown says `noWindow()` when no window was made.
  void createAndLoad(int width, int height, const std::string& title, bool debug, const char* backend,
                     std::string (*noWindow)());

  GLFWwindow* window_ = nullptr;
};

}  // namespace vplab
