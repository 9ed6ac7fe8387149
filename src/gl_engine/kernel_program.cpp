#include "gl_engine/kernel_program.h"

#include <cstdint>
#include <cstdio>
#include <vector>

#include "base/fnv1a.h"
#include "embedded/kernel_sources.h"

namespace sg::gl_engine {
namespace {

std::vector<gl::ShaderSource> sources() {
  const auto& table = kernel_sources();
  std::vector<gl::ShaderSource> s;
  s.push_back(gl::embedded_source(table, "kernel/glsl_prelude.glsl"));
  s.push_back(gl::embedded_source(table, "kernel/interface.glsl"));
  for (gl::ShaderSource& part : gl::expand_includes(table, "kernel/kernel.glsl"))
    s.push_back(std::move(part));
  s.push_back(gl::embedded_source(table, "gl_engine/shaders/main.glsl"));
  return s;
}

std::string header(KernelEntry entry, int segments) {
  const char* method = entry == KernelEntry::point           ? "SG_METHOD_POINT"
                       : entry == KernelEntry::stratified    ? "SG_METHOD_STRATIFIED"
                       : entry == KernelEntry::reference     ? "SG_METHOD_REFERENCE"
                       : entry == KernelEntry::staa_temporal ? "SG_METHOD_STAA_TEMPORAL"
                                                             : "SG_METHOD_STAA";
  return std::string("#define ") + method + "\n#define SG_MAX_SEGMENTS " +
         std::to_string(segments) + "\n";
}

}  // namespace

const char* entry_name(KernelEntry e) {
  switch (e) {
    case KernelEntry::point:
      return "point";
    case KernelEntry::stratified:
      return "stratified";
    case KernelEntry::reference:
      return "reference";
    case KernelEntry::staa_temporal:
      return "staa-temporal";
    case KernelEntry::staa:
      return "staa";
  }
  return "?";
}

gl::Program kernel_program(KernelEntry entry, int segments) {
  const std::vector<gl::ShaderSource> s = sources();
  return gl::Program::compute(s, header(entry, segments));
}

std::string kernel_program_text(KernelEntry entry, int segments) {
  const std::vector<gl::ShaderSource> s = sources();
  return gl::assemble_shader(s, header(entry, segments)).text;
}

std::string kernel_fingerprint() {
  uint64_t h = kFnv1aBasis;
  for (const EmbeddedFile& f : kernel_sources()) {
    h = fnv1a64(f.name, h);
    h = fnv1a64(std::string_view("\0", 1), h);
    h = fnv1a64(f.bytes, h);
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

}  // namespace sg::gl_engine
