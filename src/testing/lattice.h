// A lattice cascade for tests: every lattice point non-zero (the Nyquist rows and columns
// too), the band the whole lattice, amplitudes 0.1 u / |k| and phases 2 pi u from the
// stream (seed, 9). What the FFTs' and the cascade fields' tests compare against direct sums.
#pragma once

#include <memory>

#include "math/rng.h"
#include "scene/lattice.h"

namespace sg::testing {

inline CascadeDesc full_cascade(int n, double patch, uint64_t seed) {
  CascadeDesc c;
  c.patch_size = patch;
  c.lattice = n;
  c.band_min = 0;
  c.band_max = 1e9;
  auto d = std::make_shared<LatticeData>();
  d->n = n;
  d->amplitude.resize(static_cast<size_t>(n) * n);
  d->phase.resize(static_cast<size_t>(n) * n);
  Pcg32 rng(seed, 9);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const size_t e = static_cast<size_t>(j) * n + i;
      const double k = length(lattice_wave_vector(patch, n, i, j));
      d->amplitude[e] = k > 0 ? 0.1 * rng.uniform() / k : 0.0;
      d->phase[e] = kTwoPi * rng.uniform();
    }
  }
  c.data = d;
  return c;
}

}  // namespace sg::testing
