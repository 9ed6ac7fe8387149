// GL error checking. OpenGL reports errors out of band: glGetError's sticky flags, and
// (KHR_debug, core in 4.3) a callback with a message. `enable_debug_output` installs the
// callback, synchronous so that a message arrives inside the call that caused it; it keeps
// errors and high-severity messages, except the shader compiler's (Program reports those
// from the shader's log, with file and line). `check_errors(what)` drains both and throws a GlError
// naming `what` when there was any. The wrappers of this layer call it after their GL calls;
// a dispatch loop calls it once per frame. Debug builds create their contexts with the debug
// flag and the callback on (ContextOptions::debug), release builds rely on glGetError.
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <string_view>

namespace sg::gl {

// Installs the KHR_debug callback on the current context (a no-op when the context lacks
// KHR_debug).
void enable_debug_output();

// Throws GlError("what: GL_INVALID_OPERATION ...; debug: <messages>") if glGetError reported
// anything or the debug callback kept a message since the last check.
void check_errors(std::string_view what);

// "GL_INVALID_ENUM", ..., or the number in hexadecimal.
std::string error_name(GLenum error);

}  // namespace sg::gl
