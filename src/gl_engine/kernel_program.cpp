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
    case KernelEntry::specaa:
      return "specaa";
    case KernelEntry::microspec:
      return "microspec";
    case KernelEntry::bruneton:
      return "bruneton";
    case KernelEntry::lean:
      return "lean";
    case KernelEntry::lean_map:
      return "lean-map";
    case KernelEntry::taa:
      return "taa";
    case KernelEntry::taa_resolve:
      return "taa-resolve";
  }
  return "?";
}

const char* entry_define(KernelEntry e) {
  switch (e) {
    case KernelEntry::point:
      return "SG_METHOD_POINT";
    case KernelEntry::stratified:
      return "SG_METHOD_STRATIFIED";
    case KernelEntry::reference:
      return "SG_METHOD_REFERENCE";
    case KernelEntry::staa_temporal:
      return "SG_METHOD_STAA_TEMPORAL";
    case KernelEntry::staa:
      return "SG_METHOD_STAA";
    case KernelEntry::specaa:
      return "SG_METHOD_SPECAA";
    case KernelEntry::microspec:
      return "SG_METHOD_MICROSPEC";
    case KernelEntry::bruneton:
      return "SG_METHOD_BRUNETON";
    case KernelEntry::lean:
      return "SG_METHOD_LEAN";
    case KernelEntry::lean_map:
      return "SG_METHOD_LEAN_MAP";
    case KernelEntry::taa:
      return "SG_METHOD_TAA";
    case KernelEntry::taa_resolve:
      return "SG_METHOD_TAA_RESOLVE";
  }
  return "";
}

std::string kernel_program_header(KernelEntry entry, const ProgramOptions& o) {
  std::string h = std::string("#define ") + entry_define(entry) + "\n#define SG_MAX_SEGMENTS " +
                  std::to_string(o.segments) + "\n";
  if (entry != KernelEntry::reference) h += "#define SG_EXACT_SEGMENTS 1\n";
  if (entry == KernelEntry::reference || entry == KernelEntry::stratified)
    h += "#define SG_LOOP_GUARD " + std::to_string(kLoopGuardWork) + "\n";
  if (entry == KernelEntry::specaa)
    h += std::string("#define SG_SPECAA_QUAD ") + (o.specaa_quad ? "1" : "0") + "\n";
  if (entry == KernelEntry::staa) {
    h += "#define SG_SMOOTH_CELLS " + std::to_string(o.smooth_cells) + "\n";
    h += "#define SG_STAA_KERNELS " + std::to_string(o.kernels) + "\n";
    h += std::string("#define SG_FOLD_CELLS ") + (o.fold_cells ? "1" : "0") + "\n";
    if (o.smooth_terms >= 0)
      h += "#define SG_SMOOTH_TERMS " + std::to_string(o.smooth_terms) + "\n";
    if (o.light_sets >= 0) h += "#define SG_LIGHT_SETS " + std::to_string(o.light_sets) + "\n";
    if (o.swept_cells >= 0) h += "#define SG_SWEPT_CELLS " + std::to_string(o.swept_cells) + "\n";
    h += std::string("#define SG_STAA_FALLBACK_RIEMANN ") + (o.fallback_riemann ? "1" : "0") +
         "\n#define SG_STAA_FALLBACK_ALONG_PATH " + (o.fallback_along_path ? "1" : "0") + "\n";
  }
  return h;
}

gl::Program kernel_program(KernelEntry entry, const ProgramOptions& o) {
  const std::vector<gl::ShaderSource> s = sources();
  return gl::Program::compute(s, kernel_program_header(entry, o));
}

std::string kernel_program_text(KernelEntry entry, const ProgramOptions& o) {
  const std::vector<gl::ShaderSource> s = sources();
  return gl::assemble_shader(s, kernel_program_header(entry, o)).text;
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
