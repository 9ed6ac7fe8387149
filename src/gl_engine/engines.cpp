#include "gl_engine/engines.h"

#include "base/error.h"
#include "gl_engine/gl_method.h"

namespace sg {

Engine parse_engine(const std::string& text, const std::string& flag) {
  if (text == "cpu") return Engine::cpu;
  if (text == "gl") return Engine::gl;
  throw Error(flag + ": unknown engine '" + text + "' (choose cpu or gl)");
}

const char* engine_name(Engine e) {
  return e == Engine::cpu ? "cpu" : "gl";
}

std::unique_ptr<Method> make_method_on(Engine engine, const std::string& name,
                                       const MethodOptions& options) {
  if (engine == Engine::cpu) return make_method(name, options);
  make_method(name, options);  // the name and options as the catalogue checks them
  return std::make_unique<gl_engine::GlMethod>(name, options);
}

}  // namespace sg
