#include "methods/lean_map.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "base/error.h"

namespace sg {

static_assert(sizeof(LeanTexel) == kd::kLeanTexelFloats * sizeof(float),
              "a texel is the kernel's five floats");

LeanTexel to_texel(const LeanMoments& m) {
  return LeanTexel{float(m.B.x), float(m.B.y), float(m.M.x), float(m.M.y), float(m.M.z)};
}

void LeanMap::allocate(int size) {
  if (size < 1 || (size & (size - 1)) != 0) throw Error("LEAN map: size must be a power of two");
  if (size == size_) return;
  size_ = size;
  levels_ = kd::lean_level_count(size);
  // The kernel's layout (kernel/lean.glsl, lean_level_offset): level after level, down to
  // one texel; its offset past the last level is the chain's size.
  texels_.assign(static_cast<size_t>(kd::lean_level_offset(size, levels_)), LeanTexel{});
  texels_.shrink_to_fit();
}

void LeanMap::fill(const std::function<vec2(int, int)>& slope) {
  const int n = size_;
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 16), [&](const tbb::blocked_range<int>& r) {
    for (int j = r.begin(); j < r.end(); ++j) {
      for (int i = 0; i < n; ++i)
        texels_[static_cast<size_t>(j) * n + i] = to_texel(kd::lean_moments_of_slope(slope(i, j)));
    }
  });
}

void LeanMap::build_mips() {
  const kd::MapTexels view = texels();
  for (int l = 1; l < levels(); ++l) {
    const int n = level_size(l), np = level_size(l - 1);
    const size_t src = static_cast<size_t>(kd::lean_level_offset(size_, l - 1));
    LeanTexel* dst = texels_.data() + kd::lean_level_offset(size_, l);
    tbb::parallel_for(
        tbb::blocked_range<int>(0, n, std::max(1, 2048 / n)),
        [&](const tbb::blocked_range<int>& r) {
          for (int j = r.begin(); j < r.end(); ++j) {
            for (int i = 0; i < n; ++i) {
              const int c = static_cast<int>(src) + 2 * j * np + 2 * i;
              dst[static_cast<size_t>(j) * n + i] = to_texel(kd::lean_parent(
                  kd::lean_map_texel(view, c), kd::lean_map_texel(view, c + 1),
                  kd::lean_map_texel(view, c + np), kd::lean_map_texel(view, c + np + 1)));
            }
          }
        });
  }
}

kd::MapTexels LeanMap::texels() const {
  return kd::MapTexels{reinterpret_cast<const float*>(texels_.data()),
                       static_cast<long>(texels_.size()) * kd::kLeanTexelFloats};
}

kd::LeanParams LeanMap::params(LeanFilter filter, int max_aniso) const {
  kd::LeanParams p{};
  p.texel = 1;
  p.size = size_;
  p.levels = levels();
  p.aniso = filter == LeanFilter::aniso;
  p.max_aniso = max_aniso;
  p.border = border_;
  return p;
}

LeanMoments LeanMap::texel(int level, int i, int j) const {
  return kd::lean_texel(texels(), params(), level, i, j);
}

LeanMoments LeanMap::bilinear(int level, const vec2& s) const {
  return kd::lean_bilinear(texels(), params(), level, s);
}

LeanMoments LeanMap::trilinear(const vec2& s, double lambda) const {
  return kd::lean_trilinear(texels(), params(), s, lambda);
}

LeanMoments LeanMap::lookup(const vec2& s, const vec2& ds_dpx, const vec2& ds_dpy,
                            LeanFilter filter, int max_aniso) const {
  return kd::lean_lookup(texels(), params(filter, max_aniso), s, ds_dpx, ds_dpy);
}

}  // namespace sg
