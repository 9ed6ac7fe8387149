// The two ways the GL layer fails. `Unavailable`: no OpenGL 4.5 core context with compute
// shaders can be made here (no libEGL, no EGL platform or device, a driver below 4.5, no
// display for a window); it carries the reason, and tests that need GL skip with it.
// `GlError`: a context exists but a GL call, a shader compile or a link failed; its message
// names the call or the shader's files and lines.
#pragma once

#include <string>

#include "base/error.h"

namespace sg::gl {

class Unavailable : public Error {
 public:
  explicit Unavailable(const std::string& reason)
      : Error("OpenGL 4.5 unavailable: " + reason), reason_(reason) {}
  const std::string& reason() const { return reason_; }

 private:
  std::string reason_;
};

class GlError : public Error {
 public:
  explicit GlError(const std::string& what) : Error(what) {}
};

}  // namespace sg::gl
