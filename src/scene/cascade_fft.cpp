#include "scene/cascade_fft.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <kissfft/kissfft.hh>

#include <algorithm>
#include <cmath>

#include "base/error.h"
#include "kernel/cpp_prelude.h"

namespace sg::kd {
#define SG_KERNEL_REAL double
#include "kernel/cpp_types.h"
// (after the types it uses)
#include "kernel/cascade_spectrum.glsl"
#undef SG_KERNEL_REAL
}  // namespace sg::kd

namespace sg {

CascadeFft::CascadeFft(int n) : n_(n) {
  if (n < 1) throw Error("CascadeFft: the lattice must be >= 1");
}

namespace {

// In-place transpose of an n x n matrix in 16 x 16 blocks (a power-of-two stride read
// column by column would map every element to the same cache sets).
void transpose(std::vector<std::complex<double>>& d, size_t n) {
  constexpr size_t kBlock = 16;
  for (size_t b0 = 0; b0 < n; b0 += kBlock) {
    for (size_t a0 = b0; a0 < n; a0 += kBlock) {
      for (size_t b = b0; b < std::min(b0 + kBlock, n); ++b) {
        for (size_t a = std::max(a0, b + 1); a < std::min(a0 + kBlock, n); ++a)
          std::swap(d[b * n + a], d[a * n + b]);
      }
    }
  }
}

// Every row transformed, the rows shared among oneTBB's threads (a plan per chunk: kissfft
// keeps scratch for odd radices).
void inverse_rows(std::vector<std::complex<double>>& d, size_t n) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 16), [&](const tbb::blocked_range<size_t>& r) {
    const kissfft<double> fft(n, true);
    std::vector<std::complex<double>> out(n);
    for (size_t q = r.begin(); q < r.end(); ++q) {
      fft.transform(&d[q * n], out.data());
      std::copy(out.begin(), out.end(), d.begin() + static_cast<std::ptrdiff_t>(q * n));
    }
  });
}

}  // namespace

void CascadeFft::inverse_2d(std::vector<std::complex<double>>& d) const {
  const size_t n = static_cast<size_t>(n_);
  inverse_rows(d, n);  // along p (x)
  transpose(d, n);
  inverse_rows(d, n);  // along q (z)
  transpose(d, n);
}

void CascadeFft::set_lattice(const CascadeDesc& c, const Dispersion& water) {
  if (!c.data || c.data->n != n_)
    throw Error("CascadeFft: the cascade's lattice is not " + std::to_string(n_));
  patch_size_ = c.patch_size;
  points_.clear();
  const size_t count = static_cast<size_t>(n_) * n_;
  for (size_t e = 0; e < count; ++e) {
    const double a = c.data->amplitude[e];
    if (a == 0) continue;
    const vec2 k =
        lattice_wave_vector(c.patch_size, n_, static_cast<int>(e % n_), static_cast<int>(e / n_));
    points_.push_back({e, a, water.omega(length(k)), c.data->phase[e]});
  }
}

CascadeGrid CascadeFft::evaluate(const CascadeDesc& c, const Dispersion& water, double t) {
  set_lattice(c, water);
  return evaluate(t);
}

template <class Spectra, class Zero>
void CascadeFft::spectra_at(double t, Spectra spectra, Zero zero) {
  using cd = std::complex<double>;
  const int n = n_;
  // Z = A e^{i (omega t + phi)}, in double; the spectra by the shared text
  // (kernel/cascade_spectrum.glsl), from Z and its mirror's at each entry.
  z_.assign(static_cast<size_t>(n) * n, cd(0.0));
  for (const Point& p : points_) {
    const kd::vec2 z = kd::cascade_z(p.amplitude, p.omega * t + p.phase);
    z_[p.index] = cd(z.x, z.y);
  }
  const double dk = kTwoPi / patch_size_;
  for (int j = 0; j < n; ++j) {
    const int jm = (n - j) % n;
    for (int i = 0; i < n; ++i) {
      const size_t e = static_cast<size_t>(j) * n + i;
      const int im = (n - i) % n;
      const size_t m = static_cast<size_t>(jm) * n + static_cast<size_t>(im);
      if (z_[e] == cd(0.0) && z_[m] == cd(0.0)) {
        zero(e);
        continue;
      }
      const kd::vec2 k(dk * lattice_frequency(i, n), dk * lattice_frequency(j, n));
      const kd::vec2 km(dk * lattice_frequency(im, n), dk * lattice_frequency(jm, n));
      spectra(e, kd::vec2(z_[e].real(), z_[e].imag()), kd::vec2(z_[m].real(), z_[m].imag()), k, km);
    }
  }
}

CascadeGrid CascadeFft::evaluate(double t, bool curvatures) {
  CascadeGrid g;
  evaluate(t, curvatures, g);
  return g;
}

void CascadeFft::evaluate(double t, bool curvatures, CascadeGrid& g) {
  using cd = std::complex<double>;
  const size_t count = static_cast<size_t>(n_) * n_;
  a_.resize(count);
  b_.resize(count);
  if (curvatures) c_.resize(count);
  spectra_at(
      t,
      [&](size_t e, const kd::vec2& z, const kd::vec2& zm, const kd::vec2& k, const kd::vec2& km) {
        const kd::vec4 s = kd::cascade_spectra(z, zm, k, km);
        a_[e] = cd(s.x, s.y);
        b_[e] = cd(s.z, s.w);
        if (curvatures) {
          const kd::vec4 h = kd::cascade_curvature_spectra(z, zm, k, km);
          b_[e] += cd(h.x, h.y);
          c_[e] = cd(h.z, h.w);
        }
      },
      [&](size_t e) {
        a_[e] = b_[e] = cd(0.0);
        if (curvatures) c_[e] = cd(0.0);
      });
  inverse_2d(a_);
  inverse_2d(b_);
  if (curvatures) inverse_2d(c_);
  g.n = n_;
  g.patch_size = patch_size_;
  g.time = t;
  g.height.resize(count);
  g.slope_x.resize(count);
  g.slope_z.resize(count);
  for (size_t e = 0; e < count; ++e) {
    g.slope_x[e] = a_[e].real();
    g.height[e] = a_[e].imag();
    g.slope_z[e] = b_[e].real();
  }
  if (curvatures) {
    g.curv_xx.resize(count);
    g.curv_xz.resize(count);
    g.curv_zz.resize(count);
    for (size_t e = 0; e < count; ++e) {
      g.curv_xx[e] = c_[e].real();
      g.curv_xz[e] = b_[e].imag();
      g.curv_zz[e] = c_[e].imag();
    }
  } else {
    g.curv_xx.clear();
    g.curv_xz.clear();
    g.curv_zz.clear();
  }
}

CascadeGrid CascadeFft::evaluate_slopes(double t) {
  CascadeGrid g;
  evaluate_slopes(t, g);
  return g;
}

void CascadeFft::evaluate_slopes(double t, CascadeGrid& g) {
  using cd = std::complex<double>;
  const size_t count = static_cast<size_t>(n_) * n_;
  a_.resize(count);
  spectra_at(
      t,
      [&](size_t e, const kd::vec2& z, const kd::vec2& zm, const kd::vec2& k, const kd::vec2& km) {
        const kd::vec2 s = kd::cascade_slope_spectrum(z, zm, k, km);
        a_[e] = cd(s.x, s.y);
      },
      [&](size_t e) { a_[e] = cd(0.0); });
  inverse_2d(a_);
  g.n = n_;
  g.patch_size = patch_size_;
  g.time = t;
  g.height.clear();
  g.curv_xx.clear();
  g.curv_xz.clear();
  g.curv_zz.clear();
  g.slope_x.resize(count);
  g.slope_z.resize(count);
  for (size_t e = 0; e < count; ++e) {
    g.slope_x[e] = a_[e].real();
    g.slope_z[e] = a_[e].imag();
  }
}

}  // namespace sg
