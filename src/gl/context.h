// A headless OpenGL 4.5 core context through EGL, for the GL engine and its tests: no
// window, no display server. Two EGL platforms serve: the device platform
// (EGL_EXT_platform_device: a GPU named by an EGLDevice, which is how NVIDIA's driver renders
// without X) and Mesa's surfaceless platform (EGL_MESA_platform_surfaceless: llvmpipe on a
// machine without a GPU, no LIBGL_ALWAYS_SOFTWARE needed). Platform::automatic takes the
// first hardware device (one without EGL_MESA_device_software), else surfaceless, else a
// software device; each candidate that fails is skipped and its reason kept, and when none
// gives a 4.5 core context, Unavailable lists them all. libepoxy loads libEGL and GL at run
// time, so a binary without a usable libEGL still starts and reports the reason.
//
// The context is current on the thread that made it (make_current moves it). GL objects
// (gl/buffer.h, gl/texture.h, ...) must be destroyed while it exists and is current.
#pragma once

#include <memory>
#include <string>
#include <string_view>

namespace sg::gl {

enum class Platform { automatic, device, surfaceless };

// "auto", "device", "surfaceless" <-> Platform; parse_platform throws sg::Error naming the
// value otherwise.
Platform parse_platform(std::string_view name);
const char* platform_name(Platform p);

struct ContextOptions {
  Platform platform = Platform::automatic;
  // A debug context with the KHR_debug callback (gl/check.h); on by default in builds
  // without NDEBUG.
#ifdef NDEBUG
  bool debug = false;
#else
  bool debug = true;
#endif
};

struct ContextInfo {
  std::string platform;     // "device 0 (EGL_NV_device_cuda ...)" or "surfaceless"
  std::string egl_vendor;   // "NVIDIA", "Mesa Project"
  std::string egl_version;  // "1.5"
  std::string gl_vendor;    // GL_VENDOR
  std::string
      gl_renderer;  // GL_RENDERER: "llvmpipe (LLVM 15.0.6, 256 bits)", "NVIDIA H200/PCIe/SSE2"
  std::string gl_version;    // GL_VERSION: "4.5 (Core Profile) Mesa 22.3.6"
  std::string glsl_version;  // GL_SHADING_LANGUAGE_VERSION
  int major = 0, minor = 0;  // GL_MAJOR_VERSION, GL_MINOR_VERSION
  bool software = false;     // a CPU rasteriser (llvmpipe, softpipe, swrast)
  bool debug = false;        // created with the debug flag, callback installed
  // One line: "GL_RENDERER | GL_VERSION | EGL platform".
  std::string summary() const;
};

class HeadlessContext {
 public:
  // Makes the context and makes it current; throws Unavailable with the reasons.
  explicit HeadlessContext(const ContextOptions& options = {});
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  const ContextInfo& info() const { return info_; }
  void make_current() const;

  struct Egl;  // the EGL handles (context.cpp)

 private:
  std::unique_ptr<Egl> egl_;
  ContextInfo info_;
};

// Fills the GL_* fields and `software` of `info` from the current context (any context:
// EGL's or a window's).
void query_gl_info(ContextInfo& info);

// In sanitizer builds, keeps Mesa's DRI drivers (*_dri.so) loaded until exit; elsewhere
// nothing. eglTerminate and glfwTerminate make Mesa unload its driver (swrast_dri.so) with
// memory still referenced from the driver's globals: LeakSanitizer then reports it as
// leaked, in frames of an unloaded module that no suppression can match. Pinned
// (RTLD_NODELETE), that memory stays reachable. Call it once a driver is loaded (after
// eglInitialize, or once GLFW has tried to make a context).
void pin_dri_drivers();

}  // namespace sg::gl
