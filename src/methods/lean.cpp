#include "methods/lean.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "base/error.h"
#include "math/simd_trig.h"
#include "shading/aliasing.h"
#include "shading/ndf.h"
#include "shading/ndf_radiance.h"
#include "shading/radiance.h"

namespace sg {

LeanMethod::LeanMethod(const LeanOptions& o, bool cascade_fields)
    : options_(o), cascades_(cascade_fields) {
  if (o.size < 2 || o.size > 8192 || (o.size & (o.size - 1)) != 0) {
    throw Error("--lean-size: must be a power of two in [2, 8192] (got " + std::to_string(o.size) +
                ")");
  }
  if (!(o.far >= 0) || !std::isfinite(o.far)) {
    throw Error("--lean-far: must be a finite distance >= 0 (0: automatic)");
  }
  if (o.max_aniso < 1 || o.max_aniso > 64) throw Error("--lean-max-aniso: must be in [1, 64]");
}

void fill_lean_map_from_waves(LeanMap& map, const LeanMapRegion& region, const WaveField& w,
                              std::span<const double> weights, double t) {
  const int n = map.size();
  // The mapped waves, with their weights folded into the amplitudes.
  std::vector<double> Aa, Ab, a, b, c, phi;
  for (size_t k = 0; k < w.size(); ++k) {
    const double A = weights[k] * w.A[k];
    if (A == 0) continue;
    Aa.push_back(A * w.a[k]);
    Ab.push_back(A * w.b[k]);
    a.push_back(w.a[k]);
    b.push_back(w.b[k]);
    c.push_back(w.c[k]);
    phi.push_back(w.phi[k]);
  }
  const size_t nk = a.size();
  LeanTexel* texels = map.level0();
  if (nk == 0) {
    std::fill(texels, texels + static_cast<size_t>(n) * n, LeanTexel{});
    return;
  }
  // Columns in blocks of `bw`: cos(a_k x_i), sin(a_k x_i) as [block][k][i in block], so that
  // one block's table (at most 24 KiB) stays in the L1 cache while the rows of a task run
  // over it.
  int bw = 8;
  while (bw < 128 && static_cast<size_t>(2 * bw) * nk * 2 * sizeof(double) <= 24576)
    bw *= 2;
  bw = std::min(n, bw);
  const int blocks = n / bw;
  std::vector<double> cos_x(nk * n), sin_x(nk * n);
  tbb::parallel_for(0, blocks, [&](int blk) {
    std::vector<double> arg(nk * bw);
    for (size_t k = 0; k < nk; ++k) {
      for (int q = 0; q < bw; ++q) {
        const double x = region.origin.x + (blk * bw + q + 0.5) * region.texel;
        arg[k * bw + q] = a[k] * x;
      }
    }
    const size_t off = static_cast<size_t>(blk) * nk * bw;
    sincos_array(arg.data(), sin_x.data() + off, cos_x.data() + off, nk * bw);
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 32), [&](const tbb::blocked_range<int>& r) {
    const int rows = r.end() - r.begin();
    // Per row: theta_j = b z_j + c t + phi and the coefficients A a cos theta, A a sin theta,
    // A b cos theta, A b sin theta.
    std::vector<double> theta(nk), st(nk), ct(nk);
    std::vector<double> coef(static_cast<size_t>(rows) * 4 * nk);
    for (int jr = 0; jr < rows; ++jr) {
      const double z = region.origin.y + (r.begin() + jr + 0.5) * region.texel;
      for (size_t k = 0; k < nk; ++k)
        theta[k] = b[k] * z + c[k] * t + phi[k];
      sincos_array(theta.data(), st.data(), ct.data(), nk);
      double* cf = &coef[static_cast<size_t>(jr) * 4 * nk];
      for (size_t k = 0; k < nk; ++k) {
        cf[k] = Aa[k] * ct[k];
        cf[nk + k] = Aa[k] * st[k];
        cf[2 * nk + k] = Ab[k] * ct[k];
        cf[3 * nk + k] = Ab[k] * st[k];
      }
    }
    std::vector<double> gx(bw), gz(bw);
    for (int blk = 0; blk < blocks; ++blk) {
      const size_t off = static_cast<size_t>(blk) * nk * bw;
      for (int jr = 0; jr < rows; ++jr) {
        const double* cf = &coef[static_cast<size_t>(jr) * 4 * nk];
        // dh/dx = sum A a cos(theta_j + a x_i), by angle addition (simd_trig.h).
        shifted_cosine_sums(cf, cf + nk, cf + 2 * nk, cf + 3 * nk, cos_x.data() + off,
                            sin_x.data() + off, nk, bw, gx.data(), gz.data());
        LeanTexel* row = texels + static_cast<size_t>(r.begin() + jr) * n + blk * bw;
        for (int q = 0; q < bw; ++q) {
          row[q] = LeanTexel{float(gx[q]), float(gz[q]), float(gx[q] * gx[q]), float(gz[q] * gz[q]),
                             float(gx[q] * gz[q])};
        }
      }
    }
  });
}

void LeanMethod::begin_frame(const FrameContext& ctx) {
  begin_host_frame(ctx);
  const SceneModel& m = ctx.model;
  cascades_.build(ctx);
  const WaveField& w = cascades_.waves(m);
  region_ = lean_map_region(m, options_.size, options_.far);
  // Waves the texel grid samples (<= 0.5 cycles per texel on both axes) go into the map.
  mapped_.assign(w.size(), 0.0);
  std::vector<double> base(w.size(), 0.0);
  const mat2 grid(region_.texel);  // texel offsets -> metres
  for (size_t k = 0; k < w.size(); ++k) {
    const double f = projected_frequency(vec2(w.a[k], w.b[k]), grid, FrequencyNorm::max);
    (f <= 0.5 ? mapped_ : base)[k] = 1.0;
  }
  base_cov_ = uniform_ndf_covariance(w, base);
  const mat2 border = uniform_ndf_covariance(w, mapped_);
  map_.allocate(options_.size);
  map_.set_border(LeanMoments{vec2(0), vec3(border[0][0], border[1][1], border[1][0])});
  if (region_.empty) return;  // no visible water: the map is never looked up
  fill_lean_map_from_waves(map_, region_, w, mapped_, ctx.time.end);
  map_.build_mips();
}

LeanMoments LeanMethod::lookup(const PixelFootprint& fp) const {
  if (region_.empty) return map_.border();
  const vec2 s = region_.to_texels(vec2(fp.point.x, fp.point.z));
  const vec2 ds_dpx = vec2(fp.dp_dpx.x, fp.dp_dpx.z) / region_.texel;
  const vec2 ds_dpy = vec2(fp.dp_dpy.x, fp.dp_dpy.z) / region_.texel;
  return map_.lookup(s, ds_dpx, ds_dpy, options_.filter, options_.max_aniso);
}

RadianceWeights LeanMethod::weights(const FrameContext& ctx, int i, int j) const {
  const SceneModel& m = ctx.model;
  const PixelFootprint fp = water(ctx).footprint(i + 0.5, j + 0.5, ctx.time.end);
  if (!fp.hit) return miss_pixel_weights(m, i, j);
  if (fp.at_camera) return fallback(ctx, i, j);
  const LeanMoments mo = lookup(fp);
  // The cascades' filtered moments (host_cascades.h; zero without cascade fields).
  const HostCascades::Moments cm = cascades_.moments(fp.point, fp.xz_jacobian());
  return finite_or_fallback(
      shade_gaussian_ndf(m, fp.view, -(mo.B + cm.mean), mo.covariance() + base_cov_ + cm.cov)
          .weights,
      ctx, i, j);
}

}  // namespace sg
