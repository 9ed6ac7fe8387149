#include "gl/context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <map>
#include <mutex>
#include <vector>

#ifdef __SANITIZE_ADDRESS__
#include <dlfcn.h>
#include <link.h>

#include <cstring>
#endif

#include "gl/check.h"
#include "gl/error.h"

namespace sg::gl {

struct HeadlessContext::Egl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
};

namespace {

// EGL displays are per device and process-wide, and eglTerminate ends every context on
// one; so each is terminated when the last context made on it goes.
std::mutex display_mutex;
std::map<EGLDisplay, int> display_users;

void acquire_display(EGLDisplay d) {
  std::lock_guard<std::mutex> lock(display_mutex);
  ++display_users[d];
}

void release_display(EGLDisplay d) {
  std::lock_guard<std::mutex> lock(display_mutex);
  if (--display_users[d] == 0) {
    display_users.erase(d);
    eglTerminate(d);
  }
}

std::string egl_error_name(EGLint e) {
  switch (e) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    default:
      return "EGL error " + std::to_string(e);
  }
}

std::string str(const char* s) {
  return s ? s : "";
}

bool has_word(const std::string& list, const char* word) {
  return epoxy_extension_in_string(list.c_str(), word);
}

struct Candidate {
  std::string name;  // "device 0 (...)" or "surfaceless"
  EGLenum platform;
  void* native;  // the EGLDeviceEXT, or EGL_DEFAULT_DISPLAY
  bool software;
};

// The candidates in the order `p` tries them; `notes` collects why others are absent.
std::vector<Candidate> candidates(Platform p, std::vector<std::string>& notes) {
  const std::string client = str(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS));
  std::vector<Candidate> hardware, software;
  if (p != Platform::surfaceless) {
    if (!has_word(client, "EGL_EXT_platform_device") ||
        !has_word(client, "EGL_EXT_device_enumeration")) {
      notes.push_back("device platform: libEGL lacks EGL_EXT_platform_device");
    } else {
      EGLint n = 0;
      eglQueryDevicesEXT(0, nullptr, &n);
      std::vector<EGLDeviceEXT> devices(static_cast<size_t>(n));
      if (n > 0) eglQueryDevicesEXT(n, devices.data(), &n);
      if (n <= 0) notes.push_back("device platform: no EGL devices");
      for (int k = 0; k < n; ++k) {
        std::string ext = str(eglQueryDeviceStringEXT(devices[size_t(k)], EGL_EXTENSIONS));
        bool sw = has_word(ext, "EGL_MESA_device_software");
        Candidate c{
            "device " + std::to_string(k) + " (" + (ext.empty() ? "no extensions" : ext) + ")",
            EGL_PLATFORM_DEVICE_EXT, devices[size_t(k)], sw};
        (sw ? software : hardware).push_back(c);
      }
    }
  }
  std::vector<Candidate> out = hardware;
  if (p != Platform::device) {
    if (has_word(client, "EGL_MESA_platform_surfaceless"))
      out.push_back({"surfaceless", EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, false});
    else
      notes.push_back("surfaceless platform: libEGL lacks EGL_MESA_platform_surfaceless");
  }
  out.insert(out.end(), software.begin(), software.end());
  return out;
}

// Tries one candidate; fills `egl` and returns "" on success, else the reason.
std::string try_candidate(const Candidate& c, bool debug, HeadlessContext::Egl& egl,
                          ContextInfo& info) {
  EGLDisplay d = eglGetPlatformDisplayEXT(c.platform, c.native, nullptr);
  if (d == EGL_NO_DISPLAY) return "eglGetPlatformDisplay: " + egl_error_name(eglGetError());
  EGLint major = 0, minor = 0;
  if (!eglInitialize(d, &major, &minor)) return "eglInitialize: " + egl_error_name(eglGetError());
  pin_dri_drivers();
  acquire_display(d);
  auto fail = [&](const std::string& why) {
    release_display(d);
    return why;
  };
  const std::string ext = str(eglQueryString(d, EGL_EXTENSIONS));
  if (!has_word(ext, "EGL_KHR_create_context") && (major * 10 + minor) < 15)
    return fail("EGL " + std::to_string(major) + "." + std::to_string(minor) +
                " without EGL_KHR_create_context");
  if (!has_word(ext, "EGL_KHR_surfaceless_context"))
    return fail("display lacks EGL_KHR_surfaceless_context");
  if (!eglBindAPI(EGL_OPENGL_API)) return fail("eglBindAPI(EGL_OPENGL_API): no desktop OpenGL");

  EGLConfig config = nullptr;
  if (!has_word(ext, "EGL_KHR_no_config_context")) {
    // EGL_SURFACE_TYPE 0: any (the context never draws to a surface).
    const EGLint attrs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLint n = 0;
    if (!eglChooseConfig(d, attrs, &config, 1, &n) || n < 1)
      return fail("no EGL config renders OpenGL");
  }
  std::vector<EGLint> attrs = {
      EGL_CONTEXT_MAJOR_VERSION_KHR,       4,
      EGL_CONTEXT_MINOR_VERSION_KHR,       5,
      EGL_CONTEXT_OPENGL_PROFILE_MASK_KHR, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT_KHR};
  if (debug) attrs.insert(attrs.end(), {EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR});
  attrs.push_back(EGL_NONE);
  EGLContext ctx = eglCreateContext(d, config, EGL_NO_CONTEXT, attrs.data());
  if (ctx == EGL_NO_CONTEXT)
    return fail("no OpenGL 4.5 core context (eglCreateContext: " + egl_error_name(eglGetError()) +
                ")");
  if (!eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
    std::string why = "eglMakeCurrent: " + egl_error_name(eglGetError());
    eglDestroyContext(d, ctx);
    return fail(why);
  }
  info = ContextInfo{};
  info.platform = c.name;
  info.egl_vendor = str(eglQueryString(d, EGL_VENDOR));
  info.egl_version = std::to_string(major) + "." + std::to_string(minor);
  query_gl_info(info);
  if (info.major * 10 + info.minor < 45) {
    std::string why = "the context is OpenGL " + info.gl_version + ", below 4.5";
    eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(d, ctx);
    return fail(why);
  }
  egl.display = d;
  egl.context = ctx;
  return "";
}

}  // namespace

Platform parse_platform(std::string_view name) {
  if (name == "auto") return Platform::automatic;
  if (name == "device") return Platform::device;
  if (name == "surfaceless") return Platform::surfaceless;
  throw Error("EGL platform '" + std::string(name) + "': expected auto, device or surfaceless");
}

const char* platform_name(Platform p) {
  switch (p) {
    case Platform::device:
      return "device";
    case Platform::surfaceless:
      return "surfaceless";
    default:
      return "auto";
  }
}

std::string ContextInfo::summary() const {
  return gl_renderer + " | " + gl_version + " | EGL " + egl_version + " " + egl_vendor + ", " +
         platform;
}

void query_gl_info(ContextInfo& info) {
  info.gl_vendor = str(reinterpret_cast<const char*>(glGetString(GL_VENDOR)));
  info.gl_renderer = str(reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  info.gl_version = str(reinterpret_cast<const char*>(glGetString(GL_VERSION)));
  info.glsl_version = str(reinterpret_cast<const char*>(glGetString(GL_SHADING_LANGUAGE_VERSION)));
  glGetIntegerv(GL_MAJOR_VERSION, &info.major);
  glGetIntegerv(GL_MINOR_VERSION, &info.minor);
  const std::string& r = info.gl_renderer;
  info.software = r.find("llvmpipe") != std::string::npos ||
                  r.find("softpipe") != std::string::npos || r.find("swrast") != std::string::npos;
}

HeadlessContext::HeadlessContext(const ContextOptions& options) : egl_(std::make_unique<Egl>()) {
  if (!epoxy_has_egl())
    throw Unavailable(
        "libEGL.so.1 cannot be loaded (needs the glvnd loader libegl1 and a driver: Mesa's "
        "libegl-mesa0 or NVIDIA's)");
  std::vector<std::string> reasons;
  std::vector<Candidate> list = candidates(options.platform, reasons);
  for (const Candidate& c : list) {
    std::string why = try_candidate(c, options.debug, *egl_, info_);
    if (why.empty()) {
      if (options.debug) {
        enable_debug_output();
        info_.debug = true;
      }
      check_errors("creating the OpenGL context");
      return;
    }
    reasons.push_back(c.name + ": " + why);
  }
  std::string text = std::string("no EGL platform gave a context (platform ") +
                     platform_name(options.platform) + ")";
  for (const std::string& r : reasons)
    text += "; " + r;
  throw Unavailable(text);
}

HeadlessContext::~HeadlessContext() {
  if (egl_->context == EGL_NO_CONTEXT) return;
  if (eglGetCurrentContext() == egl_->context)
    eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(egl_->display, egl_->context);
  release_display(egl_->display);
}

void HeadlessContext::make_current() const {
  if (eglGetCurrentContext() == egl_->context) return;
  if (!eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_->context))
    throw GlError("eglMakeCurrent: " + egl_error_name(eglGetError()));
}

void pin_dri_drivers() {
#ifdef __SANITIZE_ADDRESS__
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void*) {
        if (info->dlpi_name && std::strstr(info->dlpi_name, "_dri.so"))
          dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
      },
      nullptr);
#endif
}

}  // namespace sg::gl
