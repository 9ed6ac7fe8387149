// A cascade's per-frame FFT on the GPU (docs/ocean.md, "Cascades"): the GL engine's twin of
// scene/cascade_fft.h. Per frame, three compute passes turn the lattice (A, phi, omega)
// into the height and slopes on the patch's N x N grid: the spectra at the frame's time
// (shaders/cascade_spectrum.glsl, by the same text as the CPU: kernel/cascade_spectrum.glsl),
// then the rows and the columns of the inverse 2-D FFT (shaders/cascade_fft.glsl: radix-2
// Stockham in shared memory, one workgroup per row, each pass writing transposed); then, on
// demand, the LEAN moment chain down to one texel (shaders/cascade_moments.glsl).
//
// Float throughout. The phases are kept accurate over long animations by a time origin t0:
// the host folds omega t0 into each phase in double (set_lattice), and the GPU adds
// omega (t - t0) in float. The field is a storage buffer of vec4 (dh/dx, h, dh/dz, 0) per
// grid point, entry q * N + p at x = (p, q) L / N, for the methods to read.
#pragma once

#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "scene/cascade_fft.h"
#include "scene/dispersion.h"
#include "scene/lattice.h"

namespace sg::gl_engine {

class CascadeFftGl {
 public:
  // Compiles the three programs for lattices of n (a power of two in [4, 1024]); a GL
  // context must be current.
  explicit CascadeFftGl(int n);
  int n() const { return n_; }

  // Uploads a cascade's lattice (its `lattice` must be n) with its frequencies at `water`'s
  // depth and its phases advanced to t0 (in double).
  void set_lattice(const CascadeDesc& c, const Dispersion& water, double t0);
  // The field at time t (three dispatches); read it after gl::barrier().
  void evaluate(double t);
  // The moment chain of the last field (log2 n + 1 levels; dispatches, one per level).
  void build_moments();

  const gl::Buffer& field() const { return field_; }
  const gl::Buffer& moments() const { return moments_; }
  // Read back (waits for the GPU): the field as a CascadeGrid, the chain as levels.
  CascadeGrid read_field() const;
  std::vector<MomentLevel> read_moments() const;

 private:
  int n_;
  double patch_size_ = 0, t0_ = 0, time_ = 0;
  gl::Program spectrum_, fft_, chain_;
  gl::Buffer lattice_, spectra_, scratch_, field_, twiddles_, moments_;
};

}  // namespace sg::gl_engine
