// A cascade's water on its patch's N x N grid at one time, by inverse FFT (scene/lattice.h
// defines the cascade): what the LEAN chain of its slopes' moments is built from
// (kernel/cascade_chain.glsl; shading/cascade_fields.h writes it into the wave buffer).
//
// On the grid x_pq = (p, q) L / N the lattice's phases are k_mn . x_pq = 2 pi (m p + n q) / N,
// so with Z_mn = A_mn exp(i (omega_mn t + phi_mn)) (Tessendorf 2001, "Simulating Ocean
// Water", Sec. 3.4, in the scene's sine form):
//     h(x_pq)      = Im  sum_mn Z_mn e^{2 pi i (m p + n q) / N}          = Im  IDFT[Z]
//     dh/dx(x_pq)  = Re  sum_mn k_x Z_mn e^{...}                         = Re  IDFT[k_x Z]
//     dh/dz(x_pq)  = Re  IDFT[k_z Z]
// (IDFT the unnormalised inverse transform). Two transforms carry the three real fields:
// Re IDFT[Y] = IDFT[E(Y)] and Im IDFT[Y] = IDFT[O(Y)] with E(Y)_k = (Y_k + conj Y_-k) / 2,
// O(Y)_k = (Y_k - conj Y_-k) / 2i (-k modulo N, exact on the grid, the Nyquist row
// included), so IDFT[E(k_x Z) + i O(Z)] = dh/dx + i h and IDFT[E(k_z Z)] = dh/dz. Exact at
// the grid's points to rounding; between them the field is what the renderer interpolates.
//
// The FFT is kissfft's (`kissfft.hh`, Debian's libkissfft-dev: BSD-licensed, so an engine
// that ports sunglint may ship it; templated on the scalar, so the CPU engine runs it in
// double; mixed radix), along rows then columns (a blocked transpose between), the rows
// shared among oneTBB's threads.
#pragma once

#include <complex>
#include <memory>
#include <vector>

#include "scene/dispersion.h"
#include "scene/lattice.h"

namespace sg {

// Height and slopes on the grid, entry q * n + p at x = (p, q) L / n.
struct CascadeGrid {
  int n = 0;
  double patch_size = 0;
  double time = 0;
  std::vector<double> height, slope_x, slope_z;
  // The second derivatives d2h/dx2, d2h/dxdz, d2h/dz2 (evaluate with curvatures only;
  // else empty).
  std::vector<double> curv_xx, curv_xz, curv_zz;
};

class CascadeFft {
 public:
  explicit CascadeFft(int n);
  int n() const { return n_; }
  // Keeps the cascade's non-zero lattice points, their wave vectors and their frequencies
  // at `water`'s depth (its lattice must be n), for the evaluations that follow.
  void set_lattice(const CascadeDesc& c, const Dispersion& water);
  // The height and slopes at time t of the lattice set last, and with `curvatures` the
  // second derivatives too (one more transform: IDFT[E(k_z Z) + i O(-k_x k_z Z)] carries
  // dh/dz and d2h/dxdz, IDFT[O(-k_x^2 Z) + i O(-k_z^2 Z)] the other two;
  // kernel/cascade_spectrum.glsl). The rows and columns of the transform run in parallel
  // (oneTBB); one CascadeFft serves one caller at a time.
  CascadeGrid evaluate(double t, bool curvatures = false);
  // The slopes alone at time t (no height): one transform of E(k_x Z) + i E(k_z Z)
  // (kernel/cascade_spectrum.glsl, cascade_slope_spectrum).
  CascadeGrid evaluate_slopes(double t);
  // The same into `g`, whose storage is kept from call to call (a frame's fields reuse
  // their grids instead of allocating, and the memory's pages, anew).
  void evaluate(double t, bool curvatures, CascadeGrid& g);
  void evaluate_slopes(double t, CascadeGrid& g);
  // set_lattice, then evaluate(t).
  CascadeGrid evaluate(const CascadeDesc& c, const Dispersion& water, double t);
  // The unnormalised inverse 2-D DFT of `data` (n x n, row q holds entries q * n + p), in
  // place: out[q][p] = sum_mn in[n][m] exp(2 pi i (m p + n q) / N).
  void inverse_2d(std::vector<std::complex<double>>& data) const;

 private:
  struct Point {
    size_t index;
    double amplitude, omega, phase;
  };
  // Z at time t, then spectra(e, Z, Z_mirror, k, k_mirror) at each entry e where either is
  // non-zero and zero(e) at the others (defined in cascade_fft.cpp, its only user).
  template <class Spectra, class Zero>
  void spectra_at(double t, Spectra spectra, Zero zero);

  int n_;
  double patch_size_ = 0;
  std::vector<Point> points_;
  std::vector<std::complex<double>> z_, a_, b_, c_;  // scratch of evaluate
};

}  // namespace sg
