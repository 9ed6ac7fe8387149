// The options of all methods, as one plain struct that the CLI fills and the methods
// read. Each field documents the flag that sets it.
#pragma once

#include <cstdint>
#include <string>

#include "shading/specular_aa.h"

namespace sg {

// --samples SxSxT: S_x by S_y stratified jittered positions in the pixel times T
// stratified jittered times in the shutter.
struct SampleCounts {
  int sx = 8, sy = 8, st = 8;
  long total() const { return static_cast<long>(sx) * sy * st; }
};

// Parses "SxSxT" (e.g. "8x8x8", "6x6x1"); throws sg::Error naming `flag`.
SampleCounts parse_sample_counts(const std::string& text, const std::string& flag);
std::string to_string(const SampleCounts& s);

// microspec (methods/microspec.h).
enum class MicrospecArea {
  exact,   // the area the disk shares with the reflection space, exactly
  approx,  // each shape cut by one line where it meets the other (microspec.h)
};
struct MicrospecOptions {
  MicrospecArea area = MicrospecArea::exact;  // --microspec-area exact|approx
};

// specaa (methods/specaa.h).
enum class SpecaaDerivatives {
  quad,      // finite differences in 2x2 pixel quads, as ddx_fine/ddy_fine on a GPU
  analytic,  // ray differentials and the Hessian of the height field
};
struct SpecaaOptions {
  double sigma2 = 0.25;                                     // --specaa-sigma2: kernel variance
  double kappa = 0.18;                                      // --specaa-kappa: clamp of 2 sigma^2
  SpecaaDerivatives derivatives = SpecaaDerivatives::quad;  // --specaa-derivatives
  KernelShape kernel = KernelShape::rect;                   // --specaa-kernel rect|full
};

// bruneton (methods/bruneton.h).
enum class BrunetonFresnel {
  fit,       // Eq. 26, the paper's fit
  integral,  // Eq. 24 by quadrature
};
struct BrunetonOptions {
  double n_min = 1.0, n_max = 2.5;  // --bruneton-nmin, --bruneton-nmax (Sec. 7.1)
  double min_variance = 2e-5;       // --bruneton-min-variance: slope-variance clamp (Sec. 5.1)
  BrunetonFresnel fresnel = BrunetonFresnel::fit;  // --bruneton-fresnel fit|integral
};

struct MethodOptions {
  SampleCounts samples{8, 8, 8};  // --samples, for reference and supersample
  uint64_t seed = 0;              // --seed: the sampling streams (rng.h)
  MicrospecOptions microspec;
  SpecaaOptions specaa;
  BrunetonOptions bruneton;
};

// Checks the values of the method flags; throws sg::Error naming the flag
// ("--specaa-sigma2: must be > 0").
void validate(const MethodOptions& options);

}  // namespace sg
