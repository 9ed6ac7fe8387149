#include "scene/cascade_fft.h"

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

struct CascadeFft::Plan {
  kissfft<double> fft;
  explicit Plan(int n) : fft(static_cast<size_t>(n), true) {}
};

CascadeFft::CascadeFft(int n) : n_(n), plan_(std::make_unique<Plan>(n)) {
  if (n < 1) throw Error("CascadeFft: the lattice must be >= 1");
}

CascadeFft::~CascadeFft() = default;

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

}  // namespace

void CascadeFft::inverse_2d(std::vector<std::complex<double>>& d) const {
  const size_t n = static_cast<size_t>(n_);
  std::vector<std::complex<double>> out(n);
  auto rows = [&] {
    for (size_t q = 0; q < n; ++q) {
      plan_->fft.transform(&d[q * n], out.data());
      std::copy(out.begin(), out.end(), d.begin() + static_cast<std::ptrdiff_t>(q * n));
    }
  };
  rows();  // along p (x)
  transpose(d, n);
  rows();  // along q (z)
  transpose(d, n);
}

CascadeGrid CascadeFft::evaluate(const CascadeDesc& c, const Dispersion& water, double t) const {
  if (!c.data || c.data->n != n_)
    throw Error("CascadeFft: the cascade's lattice is not " + std::to_string(n_));
  using cd = std::complex<double>;
  const int n = n_;
  const size_t count = static_cast<size_t>(n) * n;
  // Z = A e^{i (omega t + phi)}, in double; the spectra by the shared text
  // (kernel/cascade_spectrum.glsl).
  std::vector<kd::vec2> z(count, kd::vec2(0.0));
  for (size_t e = 0; e < count; ++e) {
    const double a = c.data->amplitude[e];
    if (a == 0) continue;
    const vec2 k =
        lattice_wave_vector(c.patch_size, n, static_cast<int>(e % n), static_cast<int>(e / n));
    z[e] = kd::cascade_z(a, water.omega(length(k)) * t + c.data->phase[e]);
  }
  std::vector<cd> a(count), b(count);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const size_t e = static_cast<size_t>(j) * n + i;
      const int im = (n - i) % n, jm = (n - j) % n;
      const size_t m = static_cast<size_t>(jm) * n + static_cast<size_t>(im);
      const vec2 k = lattice_wave_vector(c.patch_size, n, i, j);
      const vec2 km = lattice_wave_vector(c.patch_size, n, im, jm);
      const kd::vec4 s = kd::cascade_spectra(z[e], z[m], kd::vec2(k.x, k.y), kd::vec2(km.x, km.y));
      a[e] = cd(s.x, s.y);
      b[e] = cd(s.z, s.w);
    }
  }
  inverse_2d(a);
  inverse_2d(b);
  CascadeGrid g;
  g.n = n;
  g.patch_size = c.patch_size;
  g.time = t;
  g.height.resize(count);
  g.slope_x.resize(count);
  g.slope_z.resize(count);
  for (size_t e = 0; e < count; ++e) {
    g.slope_x[e] = a[e].real();
    g.height[e] = a[e].imag();
    g.slope_z[e] = b[e].real();
  }
  return g;
}

std::vector<MomentLevel> moment_chain(const CascadeGrid& g) {
  std::vector<MomentLevel> levels;
  MomentLevel l0;
  l0.n = g.n;
  const size_t count = static_cast<size_t>(g.n) * g.n;
  l0.mx = g.slope_x;
  l0.mz = g.slope_z;
  l0.mxx.resize(count);
  l0.mxz.resize(count);
  l0.mzz.resize(count);
  for (size_t e = 0; e < count; ++e) {
    l0.mxx[e] = g.slope_x[e] * g.slope_x[e];
    l0.mxz[e] = g.slope_x[e] * g.slope_z[e];
    l0.mzz[e] = g.slope_z[e] * g.slope_z[e];
  }
  levels.push_back(std::move(l0));
  while (levels.back().n > 1 && levels.back().n % 2 == 0) {
    const MomentLevel& f = levels.back();
    MomentLevel c;
    c.n = f.n / 2;
    const size_t cc = static_cast<size_t>(c.n) * c.n;
    for (auto* v : {&c.mx, &c.mz, &c.mxx, &c.mxz, &c.mzz})
      v->resize(cc);
    auto avg = [&](const std::vector<double>& src, std::vector<double>& dst) {
      for (int q = 0; q < c.n; ++q) {
        for (int p = 0; p < c.n; ++p) {
          const size_t e0 = static_cast<size_t>(2 * q) * f.n + 2 * p;
          dst[static_cast<size_t>(q) * c.n + p] =
              0.25 * (src[e0] + src[e0 + 1] + src[e0 + f.n] + src[e0 + f.n + 1]);
        }
      }
    };
    avg(f.mx, c.mx);
    avg(f.mz, c.mz);
    avg(f.mxx, c.mxx);
    avg(f.mxz, c.mxz);
    avg(f.mzz, c.mzz);
    levels.push_back(std::move(c));
  }
  return levels;
}

}  // namespace sg
