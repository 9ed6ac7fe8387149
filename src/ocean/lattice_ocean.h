// A sea from a directional wave spectrum as lattice cascades (scene/lattice.h), the
// oceans engines simulate by FFT (`sunglint ocean --cascades C --lattice N`).
//
// Amplitudes (Tessendorf 2001, "Simulating Ocean Water", Eq. 42, with the spectrum of
// ocean.h in place of Phillips'): the lattice point k of cascade c carries the variance of
// its cell of side dk = 2 pi / L_c in the wavenumber plane,
//     A^2 / 2 = E(k) dk^2,    E(k) = S(omega) (d omega / d k) D(theta - theta_0; omega) / |k|,
// the directional spectrum S(omega) D(theta) written per unit area of wave-vector plane
// (the Jacobian of (omega, theta) -> k is |k| / (d omega / d k)), at the wave's travel
// direction theta (towards -k, the scene's convention) and omega = omega(|k|) at the
// spectrum's depth; the wind sea's and the swell's densities add. Phases are uniform in
// [0, 2 pi), one PCG32 stream per cascade; amplitudes are the spectrum's (no Rayleigh
// draw), as the explicit sampler's (sampling.h).
//
// The bands. Cascades are ordered from the largest patch L_0 to the smallest; cascade c
// holds |k| in [b_c, b_c+1) with b_0 the spectrum's trimmed low end (sampling.h) and,
// between cascades, b_c = (N / 4) 2 pi / L_c-1: half of the coarser lattice's Nyquist
// wavenumber, where its lattice still has N / 4 points along each axis below the band's
// edge. The finer cascade must resolve that edge too: b_c >= 4 (2 pi / L_c), that is
// L_c-1 / L_c <= N / 16. The last cascade reaches up to its Nyquist (N / 2) 2 pi / L or the
// band's top, whichever is lower. No wavelength is in two cascades.
//
// Default patches (no --patch-sizes): L_0 = 20 peak wavelengths of the longest peak (wind
// or swell), so the peak's width (about 0.14 k_p for JONSWAP's sigma = 0.07) spans several
// cells of dk = k_p / 20; the next ones shrink by one ratio r, the smallest power of two
// that lets the last lattice reach the band's top, and at most N / 16.
#pragma once

#include <string>
#include <vector>

#include "ocean/ocean.h"
#include "scene/lattice.h"

namespace sg::ocean {

inline constexpr Range kCascadesRange{1, 8};  // --cascades

struct CascadeParams {
  int cascades = 4;                 // --cascades
  int lattice = 256;                // --lattice, a power of two in [4, 1024]
  std::vector<double> patch_sizes;  // --patch-sizes, m, decreasing; empty: chosen
};

struct LatticeOcean {
  std::vector<CascadeDesc> cascades;  // data filled; `file` left empty
  double depth = 0;                   // the spectrum's (infinite: deep water)
  double k_min = 0, k_max = 0;        // the band after trimming, rad/m
  double k_reached = 0;               // the last cascade's band top (< k_max: the rest left out)
  double spectrum_variance = 0;       // the spectrum's integral over the cascades' bands, m^2
  double variance = 0;                // sum A^2 / 2 over every cascade, m^2
};

// Validates (naming --cascades, --lattice, --patch-sizes), then fills the lattices.
LatticeOcean generate_lattice(const OceanParams& p, const CascadeParams& c);

}  // namespace sg::ocean
