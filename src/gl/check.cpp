#include "gl/check.h"

#include <cstdio>
#include <mutex>
#include <vector>

#include "gl/error.h"

namespace sg::gl {
namespace {

// Messages kept by the callback until the next check_errors. The callback is synchronous,
// so it runs on the thread of the GL call; the mutex only guards against a driver that
// calls it from elsewhere all the same.
std::mutex pending_mutex;
std::vector<std::string> pending;

void GLAPIENTRY on_debug_message(GLenum source, GLenum type, GLuint id, GLenum severity,
                                 GLsizei length, const GLchar* message, const void* /*user*/) {
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  // Compile errors arrive through the shader's log, which Program maps to file:line.
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
  std::string text =
      length >= 0 ? std::string(message, static_cast<size_t>(length)) : std::string(message);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    text.pop_back();
  std::lock_guard<std::mutex> lock(pending_mutex);
  if (pending.size() >= 16) return;
  std::string entry = "[";
  entry += std::to_string(id);
  entry += "] ";
  entry += text;
  pending.push_back(std::move(entry));
}

}  // namespace

void enable_debug_output() {
  if (!epoxy_has_gl_extension("GL_KHR_debug") && epoxy_gl_version() < 43) return;
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(on_debug_message, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

std::string error_name(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW:
      return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW:
      return "GL_STACK_OVERFLOW";
    default: {
      char buf[16];
      std::snprintf(buf, sizeof buf, "0x%04x", error);
      return buf;
    }
  }
}

void check_errors(std::string_view what) {
  std::string errors;
  // glGetError keeps one flag per kind; a lost context reports GL_CONTEXT_LOST for ever,
  // hence the bound.
  for (int k = 0; k < 8; ++k) {
    GLenum e = glGetError();
    if (e == GL_NO_ERROR) break;
    if (!errors.empty()) errors += ", ";
    errors += error_name(e);
  }
  std::vector<std::string> messages;
  {
    std::lock_guard<std::mutex> lock(pending_mutex);
    messages.swap(pending);
  }
  if (errors.empty() && messages.empty()) return;
  std::string text(what);
  text += ": ";
  text += errors.empty() ? std::string("GL debug message") : errors;
  for (const std::string& m : messages) {
    text += "; ";
    text += m;
  }
  throw GlError(text);
}

}  // namespace sg::gl
