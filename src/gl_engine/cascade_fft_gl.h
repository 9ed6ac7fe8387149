// A cascade's per-frame FFT on the GPU (docs/ocean.md, "Cascades"): the GL engine's twin of
// scene/cascade_fft.h. Each transform is two compute passes' worth of work on the lattice
// (A, phi, omega): the spectra of two complex fields at the wanted times
// (shaders/cascade_spectrum.glsl, by the same text as the CPU: kernel/cascade_spectrum.glsl),
// then the rows and the columns of the inverse 2-D FFT (shaders/cascade_fft.glsl: radix-4
// Stockham in shared memory, one workgroup per row, each pass writing transposed). Which
// two fields a transform carries is its Pair; gl_engine/cascade_fields_gl.h combines them
// into the kernel's LEAN chains.
//
// Float throughout. The phases are kept accurate over long animations by a time origin t0:
// the host folds omega t0 into each phase in double (set_lattice), and the GPU adds
// omega (t - t0) in float. A field is a storage buffer of vec4 (two complex numbers) per
// grid point, entry q * N + p at x = (p, q) L / N.
#pragma once

#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "scene/cascade_fft.h"
#include "scene/dispersion.h"
#include "scene/lattice.h"

namespace sg::gl_engine {

// A compute program of the cascades' passes: gl_engine/shaders/`main_file` after `header`,
// and after the GLSL prelude and the kernel-subset file `kernel_file` where one is named
// (kernel/cascade_spectrum.glsl, the spectra; kernel/cascade_chain.glsl, the chain's texels
// and the height's differences: the CPU's text too).
gl::Program cascade_program(const char* main_file, const std::string& header = {},
                            const char* kernel_file = nullptr);

class CascadeFftGl {
 public:
  // What one transform carries (shaders/cascade_spectrum.glsl's modes):
  //   full: (dh/dx, h, dh/dz, d2h/dxdz) at t;
  //   curvature_and_slopes: (d2h/dx2, d2h/dz2) at t and (dh/dx, dh/dz) at t1;
  //   two_slopes: (dh/dx, dh/dz) at t and at t1.
  // The second pair is zero where the transform is told it has no t1.
  enum class Pair { full = 0, curvature_and_slopes = 1, two_slopes = 2 };

  // Compiles the two programs for lattices of n (a power of two in [4, 1024]); a GL
  // context must be current.
  explicit CascadeFftGl(int n);
  int n() const { return n_; }

  // Uploads a cascade's lattice (its `lattice` must be n) with its frequencies at `water`'s
  // depth and its phases advanced to t0 (in double).
  void set_lattice(const CascadeDesc& c, const Dispersion& water, double t0);
  double time_origin() const { return t0_; }
  // One transform into field `target` (0 or 1): `pair` at t (and t1 where has_t1); read
  // the field after gl::barrier().
  void transform(Pair pair, double t, double t1, bool has_t1, int target);
  // The height and slopes at time t: transform(Pair::full, t) into field 0.
  void evaluate(double t);

  const gl::Buffer& field(int i) const { return fields_[i]; }
  // Read back (waits for the GPU): field 0 as a CascadeGrid, after evaluate (the height,
  // the slopes and d2h/dxdz in curv_xz; the other curvatures empty).
  CascadeGrid read_field() const;

 private:
  int n_;
  double patch_size_ = 0, t0_ = 0, time_ = 0;
  gl::Program spectrum_, fft_;
  gl::Buffer lattice_, spectra_, scratch_, fields_[2], twiddles_;
};

}  // namespace sg::gl_engine
