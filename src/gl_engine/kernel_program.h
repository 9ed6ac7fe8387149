// The GL engine's compute programs: the shading kernel's GLSL (kernel/kernel.glsl, after
// the GLSL prelude and the interface) and the engine's main (gl_engine/shaders/main.glsl),
// embedded in the binary, assembled for one method and compiled. The method, the cap on
// the path's sub-arcs and staa's fallback integrator are the header's #defines, so each
// variant's shader holds only its method's code and arrays of the size it needs.
#pragma once

#include <string>

#include "gl/program.h"

namespace sg::gl_engine {

enum class KernelEntry {
  point,
  stratified,
  reference,
  staa_temporal,
  staa,
  specaa,
  microspec,
  bruneton,
  lean,
  lean_map,    // `lean`'s map: level 0 from the waves, then the MIP chain (gl_engine/lean_map_gl.h)
  taa,         // `taa`'s samples: each pixel's radiances and motion vector
  taa_resolve  // `taa`'s resolve: the history reprojected, rectified and blended
};

const char* entry_name(KernelEntry e);

// The #define of `entry`'s method (SG_METHOD_POINT, ...).
const char* entry_define(KernelEntry e);

// What a program fixes in its text; every other option is a uniform. `staa`'s fallback
// integrator selects code (kernel/staa.glsl, staa_fallback_share): a program holds the
// one it runs, since code that never runs still costs a shader (docs/benchmarks.md; on
// llvmpipe every branch's code runs, docs/gpu.md). So do the smooth terms: a scene
// without Fresnel or a sky gradient gets a program without their code.
// The path's sub-arcs: every entry but the reference is compiled for its frames' K
// (SG_MAX_SEGMENTS = K and SG_EXACT_SEGMENTS: the per-wave terms then index their arrays by
// a constant, kernel/wave_terms.glsl, path_segments); the reference's frames pick K up to
// the cap (SG_MAX_SEGMENTS alone).
struct ProgramOptions {
  int segments = 1;                 // the frames' K, or the reference's cap on it
  bool fallback_riemann = false;    // staa: SG_STAA_FALLBACK_RIEMANN
  bool fallback_along_path = true;  // staa: SG_STAA_FALLBACK_ALONG_PATH
  int smooth_cells = 3;             // staa: SG_SMOOTH_CELLS, the smooth terms' cells a side
  bool fold_cells = false;          // staa: SG_FOLD_CELLS, the quarters of --fold-cells
  int kernels = 9;                  // staa: SG_STAA_KERNELS, the RDF's kernels
  // staa: SG_SMOOTH_TERMS, whether the frames' water needs the smooth terms (Fresnel or a
  // sky gradient, kernel/staa.glsl, staa_frame_terms): 0 or 1, a program for those frames
  // alone (the GL engine picks it per frame); -1, no #define: each frame decides.
  int smooth_terms = -1;
  // staa: SG_LIGHT_SETS, whether the frames' light disk reaches below the horizon
  // (kernel/staa.glsl, staa_frame_light_sets): 0, 1, or -1 (each frame decides).
  int light_sets = -1;
  // staa: SG_SWEPT_CELLS, whether the frames' camera moves through a shutter (the smooth
  // terms' cells averaged over it, kernel/staa.glsl, staa_frame_swept_cells): 0, 1, or -1.
  int swept_cells = -1;
  // specaa: SG_SPECAA_QUAD, the quads' derivatives (1) or the analytic ones (0): a program
  // holds the one it runs.
  bool specaa_quad = true;

  bool operator==(const ProgramOptions&) const = default;
};

// The sampling programs' (`supersample`, `reference`) budget of estimated loop iterations
// an invocation and pass (SG_LOOP_GUARD; each sample's estimate from its march's steps,
// kernel/sampling.glsl, sample_work): past it an invocation takes no further sample in that
// pass, and the next pass goes on where it stopped (shaders/main.glsl). A pass is sized to about
// 8000 loop iterations (gl_engine.h, pass_samples); a ray that marches far over displaced water can
// cost hundreds of times its estimate, and llvmpipe ends every loop of an invocation past
// 65535 iterations, so that the samples after that point were lost.
inline constexpr int kLoopGuardWork = 4000;

// The header of `entry`'s program: its #defines, before the kernel's sources (the web
// page's programs take the same, web/web_page.cpp).
std::string kernel_program_header(KernelEntry entry, const ProgramOptions& o);

// The program of `entry` with the options `o`.
gl::Program kernel_program(KernelEntry entry, const ProgramOptions& o);

// The assembled text of that program, as handed to the driver (for tests and `--dump`).
std::string kernel_program_text(KernelEntry entry, const ProgramOptions& o);
// A fingerprint of the shading kernel's sources as built into this binary (both engines
// compute with them): FNV-1a over every embedded file's name and bytes. The study's frame
// cache keys on it, so that frames rendered by another kernel are not reused.
std::string kernel_fingerprint();

}  // namespace sg::gl_engine
