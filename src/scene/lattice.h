// Lattice oceans (format /3, docs/scene-format.md "Cascades"): the water as engines make
// it, square patches whose waves sit on a lattice of wave vectors, beside the explicit
// waves. A cascade of side L and lattice N holds one sine wave per lattice point
//     k_mn = (2 pi m / L, 2 pi n / L),   m, n in [-N/2, N/2),
// of the scene's form A sin(k . x + omega t + phi) (a crest travels along -k, as the
// explicit waves sunglint ocean writes), with its own amplitude A_mn >= 0 and phase phi_mn
// read from a sidecar file, and omega = omega(|k|) from the dispersion relation at the
// surface's depth (scene/dispersion.h). The surface is exactly the sum of every cascade's
// sines and the explicit waves, so that any renderer reproduces it; that sum, evaluated
// on the patch's N x N grid, is one inverse FFT (scene/cascade_fft.h).
//
// The sidecar is a NumPy `.npy` file (format 1.0) of shape (N, N, 2), little-endian
// float64 (or float32), C order: entry [j][i] = (A, phi) of the lattice point with
//     m = i (i < N/2), i - N (i >= N/2);   n likewise from j,
// the order of an FFT's frequencies (numpy.fft.fftfreq), so `numpy.load` reads it and
// `numpy.fft.ifft2` evaluates it. Each cascade states the band [band_min, band_max) of
// |k| it covers; every non-zero amplitude lies in it and the bands of a surface's
// cascades never overlap, so no wavelength is counted twice.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "math/vec.h"
#include "scene/dispersion.h"

namespace sg {

struct Wave;
struct SurfaceDesc;

// A cascade's amplitudes and phases, n x n, entry j * n + i as in the file.
struct LatticeData {
  int n = 0;
  std::vector<double> amplitude, phase;
  uint64_t fingerprint = 0;  // FNV-1a of the file's bytes (frame cache keys)
};

struct CascadeDesc {
  std::string file;       // the sidecar as the scene names it (relative to the scene's folder)
  double patch_size = 0;  // L, m
  int lattice = 0;        // N: a power of two in [kMinLattice, kMaxLattice]
  double band_min = 0;    // |k|, rad/m: the band [band_min, band_max) the cascade holds
  double band_max = 0;
  std::shared_ptr<const LatticeData> data;
};

inline constexpr int kMinLattice = 4;
inline constexpr int kMaxLattice = 1024;

// The integer wave number of lattice index i (FFT order).
inline int lattice_frequency(int i, int n) {
  return i < n / 2 ? i : i - n;
}
// The wave vector of entry (i, j): (2 pi m / L, 2 pi n / L).
vec2 lattice_wave_vector(double patch_size, int n, int i, int j);

// Reads and checks a sidecar against the cascade it belongs to (shape N x N x 2, finite
// values, amplitudes >= 0, zero outside the band and at k = 0, each sine below Stokes'
// steepness limit, phases within the scene's range). Every error names `key` (the scene's
// key path) and the file: "surface.cascades[1].file (sea.c1.npy): truncated: ...".
std::shared_ptr<const LatticeData> read_lattice(const std::string& path, const CascadeDesc& c,
                                                const std::string& key);
// Writes a sidecar (float64), whole (temp file and rename).
void write_lattice(const std::string& path, const LatticeData& data);
// The file's bytes as write_lattice writes them.
std::string lattice_npy_bytes(const LatticeData& data);

// The cascade's waves with non-zero amplitude as explicit scene waves (angular frequency
// omega(|k|) at `water`'s depth), in lattice order.
std::vector<Wave> cascade_waves(const CascadeDesc& c, const Dispersion& water);
// Every wave of a surface: the explicit ones, then each cascade's (cascade_waves).
std::vector<Wave> surface_waves(const SurfaceDesc& s);
// A cascade's variance sum A^2 / 2 (its significant wave height is 4 sqrt of it).
double cascade_variance(const CascadeDesc& c);

}  // namespace sg
