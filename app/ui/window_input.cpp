#include "app/ui/window_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>

namespace vplab {

GlfwBackend::GlfwBackend(GLFWwindow* w) { ImGui_ImplGlfw_InitForOpenGL(w, false); }
GlfwBackend::~GlfwBackend() { ImGui_ImplGlfw_Shutdown(); }

namespace {
WindowInput& of(GLFWwindow* w) { return *static_cast<WindowInput*>(glfwGetWindowUserPointer(w)); }
}  // namespace

WindowInput::WindowInput(GLFWwindow* handle) : window(handle) {
  GLFWwindow* const h = handle;
  glfwSetWindowUserPointer(h, this);
  glfwSetCursorPosCallback(h, [](GLFWwindow* w, double x, double y) { of(w).queue.mouseMove(x, y); });
  glfwSetCursorEnterCallback(h, [](GLFWwindow* w, int entered) {
    if (!entered) of(w).queue.mouseMove(-1e30, -1e30);  // ImGui: no mouse over the window
    of(w).changed = true;
  });
  glfwSetMouseButtonCallback(h, [](GLFWwindow* w, int button, int action, int) {
    of(w).queue.mouseButton(button, action == GLFW_PRESS);
  });
  glfwSetScrollCallback(h, [](GLFWwindow* w, double dx, double dy) { of(w).queue.wheel(dx, dy); });
  glfwSetKeyCallback(h, [](GLFWwindow* w, int key, int, int action, int) {
    if (action != GLFW_REPEAT) of(w).queue.key(key, action == GLFW_PRESS);
    else of(w).changed = true;  // ImGui repeats held keys itself, given frames
  });
  glfwSetCharCallback(h, [](GLFWwindow* w, unsigned c) { of(w).queue.character(c); });
  glfwSetWindowFocusCallback(h, [](GLFWwindow* w, int focused) {
    if (!focused) of(w).queue.focusLost();
    of(w).changed = true;
  });
  glfwSetWindowRefreshCallback(h, [](GLFWwindow* w) { of(w).changed = true; });
  glfwSetFramebufferSizeCallback(h, [](GLFWwindow* w, int, int) { of(w).changed = true; });
}

WindowInput::~WindowInput() { glfwSetWindowUserPointer(window, nullptr); }

}  // namespace vplab
