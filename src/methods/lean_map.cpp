#include "methods/lean_map.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "base/error.h"

namespace sg {

mat2 LeanMoments::covariance() const {
  const double xx = std::max(0.0, M.x - B.x * B.x), zz = std::max(0.0, M.y - B.y * B.y);
  const double lim = std::sqrt(xx * zz);
  const double xz = std::clamp(M.z - B.x * B.y, -lim, lim);
  return mat2(vec2(xx, xz), vec2(xz, zz));
}

LeanMoments LeanMoments::of_slope(const vec2& b) {
  return LeanMoments{b, vec3(b.x * b.x, b.y * b.y, b.x * b.y)};
}

namespace {

LeanTexel to_texel(const LeanMoments& m) {
  return LeanTexel{float(m.B.x), float(m.B.y), float(m.M.x), float(m.M.y), float(m.M.z)};
}

LeanMoments from_texel(const LeanTexel& t) {
  return LeanMoments{vec2(t.bx, t.bz), vec3(t.mxx, t.mzz, t.mxz)};
}

void accumulate(LeanMoments& acc, const LeanMoments& m, double w) {
  acc.B += w * m.B;
  acc.M += w * m.M;
}

}  // namespace

void LeanMap::allocate(int size) {
  if (size < 1 || (size & (size - 1)) != 0) throw Error("LEAN map: size must be a power of two");
  if (size == size_) return;
  size_ = size;
  offsets_.clear();
  size_t total = 0;
  for (int n = size; n >= 1; n /= 2) {
    offsets_.push_back(total);
    total += static_cast<size_t>(n) * n;
  }
  texels_.assign(total, LeanTexel{});
  texels_.shrink_to_fit();
}

void LeanMap::fill(const std::function<vec2(int, int)>& slope) {
  const int n = size_;
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 16), [&](const tbb::blocked_range<int>& r) {
    for (int j = r.begin(); j < r.end(); ++j) {
      for (int i = 0; i < n; ++i)
        texels_[static_cast<size_t>(j) * n + i] = to_texel(LeanMoments::of_slope(slope(i, j)));
    }
  });
}

void LeanMap::build_mips() {
  for (int l = 1; l < levels(); ++l) {
    const int n = level_size(l), np = level_size(l - 1);
    const LeanTexel* src = texels_.data() + offsets_[l - 1];
    LeanTexel* dst = texels_.data() + offsets_[l];
    tbb::parallel_for(tbb::blocked_range<int>(0, n, std::max(1, 2048 / n)),
                      [&](const tbb::blocked_range<int>& r) {
                        for (int j = r.begin(); j < r.end(); ++j) {
                          for (int i = 0; i < n; ++i) {
                            LeanMoments acc;
                            for (int c = 0; c < 4; ++c) {
                              const size_t k =
                                  static_cast<size_t>(2 * j + c / 2) * np + (2 * i + c % 2);
                              accumulate(acc, from_texel(src[k]), 0.25);
                            }
                            dst[static_cast<size_t>(j) * n + i] = to_texel(acc);
                          }
                        }
                      });
  }
}

LeanMoments LeanMap::texel(int level, int i, int j) const {
  const int n = level_size(level);
  if (i < 0 || j < 0 || i >= n || j >= n) return border_;
  return from_texel(texels_[offsets_[level] + static_cast<size_t>(j) * n + i]);
}

LeanMap::Taps LeanMap::bilinear_taps(int level, const vec2& s) {
  // Level-l texel centres sit at (i + 1/2) 2^l in level-0 units.
  const double scale = std::ldexp(1.0, -level);
  const double u = s.x * scale - 0.5, v = s.y * scale - 0.5;
  const double fu = std::floor(u), fv = std::floor(v);
  Taps t;
  t.i0 = static_cast<int>(fu);
  t.j0 = static_cast<int>(fv);
  const double a = u - fu, b = v - fv;
  t.w[0] = (1 - a) * (1 - b);
  t.w[1] = a * (1 - b);
  t.w[2] = (1 - a) * b;
  t.w[3] = a * b;
  return t;
}

LeanMoments LeanMap::bilinear(int level, const vec2& s) const {
  const Taps t = bilinear_taps(level, s);
  LeanMoments acc;
  accumulate(acc, texel(level, t.i0, t.j0), t.w[0]);
  accumulate(acc, texel(level, t.i0 + 1, t.j0), t.w[1]);
  accumulate(acc, texel(level, t.i0, t.j0 + 1), t.w[2]);
  accumulate(acc, texel(level, t.i0 + 1, t.j0 + 1), t.w[3]);
  return acc;
}

LeanMoments LeanMap::trilinear(const vec2& s, double lambda) const {
  const int top = levels() - 1;
  if (!(lambda > 0)) return bilinear(0, s);  // also NaN (a zero footprint)
  if (lambda >= top) return bilinear(top, s);
  const int l0 = static_cast<int>(lambda);
  const double f = lambda - l0;
  LeanMoments acc;
  accumulate(acc, bilinear(l0, s), 1 - f);
  accumulate(acc, bilinear(l0 + 1, s), f);
  return acc;
}

LeanMoments LeanMap::lookup(const vec2& s, const vec2& ds_dpx, const vec2& ds_dpy,
                            LeanFilter filter, int max_aniso) const {
  const double px = length(ds_dpx), py = length(ds_dpy);
  const double pmax = std::max(px, py), pmin = std::min(px, py);
  if (filter == LeanFilter::trilinear || pmax <= 0) return trilinear(s, std::log2(pmax));
  const double ratio = pmin > 0 ? std::ceil(pmax / pmin) : double(max_aniso);
  const int n = static_cast<int>(std::clamp(ratio, 1.0, double(std::max(1, max_aniso))));
  const double lambda = std::log2(pmax / n);
  const vec2 major = px >= py ? ds_dpx : ds_dpy;
  LeanMoments acc;
  for (int k = 0; k < n; ++k)
    accumulate(acc, trilinear(s + ((k + 0.5) / n - 0.5) * major, lambda), 1.0 / n);
  return acc;
}

}  // namespace sg
