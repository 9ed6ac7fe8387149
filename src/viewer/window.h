// The viewer's window: a GLFW window with an OpenGL 4.5 core context (GLX on X11; under
// Xvfb on a machine without a display) and Dear ImGui on top, drawn by ImGui's GLFW and
// OpenGL 3 backends (Debian's libimgui-dev ships both in libimgui.a). The GL layer
// (gl/) works in this context as in a headless one: libepoxy resolves GL through GLX here.
//
// A frame: begin_frame() (events, ImGui's new frame, the default framebuffer bound), the
// caller's drawing (gl/ compute dispatches, TextureView::draw, ImGui widgets), then
// end_frame(), which draws ImGui, optionally reads the finished frame back (a screenshot:
// RGBA8, rows top first, before the swap, while the back buffer holds it) and swaps.
// No display, a display that cannot be opened, or no OpenGL 4.5 core context there throw
// gl::Unavailable with the reason. One window at a time (GLFW and ImGui are process-wide).
// ImGui writes no imgui.ini.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gl/context.h"

struct GLFWwindow;

namespace sg::viewer {

struct WindowOptions {
  int width = 1280, height = 720;  // the framebuffer's size in pixels
  std::string title = "sunglint";
  bool vsync = false;  // swap interval 1; scripted runs and timings leave it off
};

class Window {
 public:
  explicit Window(const WindowOptions& options = {});
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // The GL_* fields of the window's context; platform "GLX".
  const gl::ContextInfo& info() const { return info_; }
  GLFWwindow* handle() const { return window_; }
  int width() const { return width_; }
  int height() const { return height_; }

  bool should_close() const;
  void begin_frame();
  // Draws ImGui; when `screenshot` is given, fills it with the frame (width * height * 4
  // bytes, rows top first); swaps.
  void end_frame(std::vector<std::uint8_t>* screenshot = nullptr);

 private:
  GLFWwindow* window_ = nullptr;
  gl::ContextInfo info_;
  int width_ = 0, height_ = 0;
};

}  // namespace sg::viewer
