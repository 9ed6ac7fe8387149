// The GL engine's compute programs: the shading kernel's GLSL (kernel/kernel.glsl, after
// the GLSL prelude and the interface) and the engine's main (gl_engine/shaders/main.glsl),
// embedded in the binary, assembled for one method and compiled. The method and the cap on
// the path's sub-arcs are the header's #defines, so each variant's shader holds only its
// method's code and arrays of the size it needs.
#pragma once

#include <string>

#include "gl/program.h"

namespace sg::gl_engine {

enum class KernelEntry { point, stratified, reference, staa_temporal, staa };

const char* entry_name(KernelEntry e);

// The program of `entry` with at most `segments` sub-arcs (SG_MAX_SEGMENTS).
gl::Program kernel_program(KernelEntry entry, int segments);

// The assembled text of that program, as handed to the driver (for tests and `--dump`).
std::string kernel_program_text(KernelEntry entry, int segments);
// A fingerprint of the shading kernel's sources as built into this binary (both engines
// compute with them): FNV-1a over every embedded file's name and bytes. The study's frame
// cache keys on it, so that frames rendered by another kernel are not reused.
std::string kernel_fingerprint();

}  // namespace sg::gl_engine
