#include "viewer/window.h"

#include <epoxy/gl.h>
// GLFW after epoxy, and without its own GL header.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdlib>
#include <string>

#include "gl/check.h"
#include "gl/error.h"
#include "gl/framebuffer.h"

namespace sg::viewer {
namespace {

std::string last_glfw_error;
bool window_open = false;

void on_glfw_error(int code, const char* message) {
  last_glfw_error = std::string(message ? message : "") + " (GLFW error 0x";
  char hex[16];
  std::snprintf(hex, sizeof hex, "%05x)", code);
  last_glfw_error += hex;
}

bool set(const char* name) {
  const char* v = std::getenv(name);
  return v && *v;
}

}  // namespace

Window::Window(const WindowOptions& options) : width_(options.width), height_(options.height) {
  if (window_open) throw Error("viewer: a window is already open (one at a time)");
  if (options.width < 1 || options.height < 1)
    throw Error("viewer: window size " + std::to_string(options.width) + " x " +
                std::to_string(options.height) + " is empty");
  if (!set("DISPLAY") && !set("WAYLAND_DISPLAY"))
    throw gl::Unavailable(
        "no display: DISPLAY is not set (without a screen, run under Xvfb: xvfb-run -a ...)");
  last_glfw_error.clear();
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) throw gl::Unavailable("no display: " + last_glfw_error);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
#ifndef NDEBUG
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
#endif
  window_ =
      glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
  gl::pin_dri_drivers();  // before any glfwTerminate (gl/context.h)
  if (!window_) {
    std::string why = last_glfw_error;
    glfwTerminate();
    throw gl::Unavailable("no OpenGL 4.5 core window: " + why);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(options.vsync ? 1 : 0);
  glfwGetFramebufferSize(window_, &width_, &height_);
  info_.platform = "GLX";
  gl::query_gl_info(info_);
#ifndef NDEBUG
  gl::enable_debug_output();
  info_.debug = true;
#endif
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
  window_open = true;
  gl::check_errors("creating the window");
}

Window::~Window() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
  window_open = false;
}

bool Window::should_close() const {
  return glfwWindowShouldClose(window_);
}

void Window::request_close() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void Window::begin_frame() {
  glfwPollEvents();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width_, height_);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void Window::end_frame(std::vector<std::uint8_t>* screenshot) {
  ImGui::Render();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width_, height_);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (screenshot) {
    glReadBuffer(GL_BACK);
    *screenshot = gl::read_framebuffer_rgba8(0, 0, width_, height_);
  }
  glfwSwapBuffers(window_);
  gl::check_errors("frame");
}

}  // namespace sg::viewer
