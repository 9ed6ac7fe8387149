// The engines a method runs on (`--engine cpu|gl`): the CPU engine (engine/render.h, every
// method) and the GL engine (gl_engine/gl_engine.h: the kernel methods, on the GPU).
#pragma once

#include <memory>
#include <string>

#include "methods/method.h"

namespace sg {

enum class Engine { cpu, gl };

// "cpu" or "gl"; throws sg::Error naming `flag` otherwise.
Engine parse_engine(const std::string& text, const std::string& flag = "--engine");
const char* engine_name(Engine e);

// The method `name` on `engine` (make_method for the CPU). Throws sg::Error naming what the
// GL engine lacks, or gl::Unavailable when it cannot start.
std::unique_ptr<Method> make_method_on(Engine engine, const std::string& name,
                                       const MethodOptions& options);

}  // namespace sg
