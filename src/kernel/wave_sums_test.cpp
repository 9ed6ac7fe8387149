// The CPU engine's sums over the waves in SIMD lanes (kernel/cpu/lane_passes.inc: the
// kernel's per-wave terms compiled over Highway's vectors) against the kernel's loops, the
// definitions (kernel/waves.glsl, reflection_path.glsl, staa.glsl, reference_path.glsl), in
// double and float, and the kernel methods with and without them; with a fixed camera and
// with a moving one (each instant of the path at its own water point). They run the same
// text and differ only in the order of the sums and the sines' last bits.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/cpu/wave_sums.h"
#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"
#include "math/rng.h"
#include "shading/kernel_frame.h"
#include "shading/kernel_table.h"
#include "shading/path_table.h"
#include "testing/path_tables.h"
#include "testing/testing.h"

namespace sg {
namespace {

Scene random_waves_scene(int n, uint64_t seed) {
  Pcg32 rng(seed, 3);
  std::vector<Wave> waves;
  for (int i = 0; i < n; ++i) {
    const double k = 0.2 * std::pow(100.0, rng.uniform()), dir = kTwoPi * rng.uniform();
    waves.push_back(Wave{0.3 / k / std::sqrt(double(n)) * rng.uniform(),
                         {k * std::cos(dir), k * std::sin(dir)},
                         std::sqrt(9.81 * k),
                         kTwoPi * rng.uniform()});
  }
  Scene s = testing::small_scene(waves, 160, 90);
  s.camera.position = vec3(13.7, 3.1, -2.2);  // not at the origin: camera-relative data
  s.animation.t0 = 1234.5;
  return s;
}

// What rounding the phases carry at camera-relative (x, z): 8 rounding units of the
// largest |a x| + |b z| + pi, the phase before its reduction, plus the sine's few units.
double phase_rounding(const Scene& s, double x, double z, double eps) {
  double big = 0;
  for (const Wave& w : s.surface.waves)
    big = std::max(big, std::fabs(w.wave_vector.x * x) + std::fabs(w.wave_vector.y * z) + kPi);
  return 8 * eps * big;
}

TEST(KernelWaveSums, VectorisedSumsEqualTheKernelLoops) {
  for (int n : {1, 5, 16, 17, 64, 100}) {
    const Scene s = random_waves_scene(n, 11 + n);
    const SceneModel m(s);
    KernelInputsD in;
    build_kernel_inputs(m, frame_time(s, 3), 3, 0, in);
    const kd::WaveBuffer simd = wave_buffer(in, true), loop = wave_buffer(in, false);
    kd::Frame f = in.frame;
    f.fresnel = 1;  // Schlick's: the staa pass gathers the smooth terms' cells
    double hscale = 0, gscale = 0, kscale = 0, cscale = 0;
    for (const Wave& w : s.surface.waves) {
      hscale += w.amplitude;
      gscale += w.amplitude * length(w.wave_vector);
      cscale += w.amplitude * length(w.wave_vector) * w.angular_frequency;
      kscale = std::max(kscale, length(w.wave_vector));
    }
    Pcg32 rng(n, 5);
    int differ = 0;  // heights where the lanes and the loop differ in the last bits
    for (int q = 0; q < 50; ++q) {
      const double x = 200 * (rng.uniform() - 0.5), z = -300 * rng.uniform(),
                   dt = -0.03 * rng.uniform();
      // The sums round each phase a x + b z + theta0 in another order (fused multiply-adds):
      // they agree to the phase's rounding times the amplitudes.
      const double tol = phase_rounding(s, x, z, 1.1e-16);
      EXPECT_NEAR(kd::water_height(simd, f, x, z, dt), kd::water_height(loop, f, x, z, dt),
                  tol * hscale);
      differ += kd::water_height(simd, f, x, z, dt) != kd::water_height(loop, f, x, z, dt);
      const vec2 g = kd::water_gradient(simd, f, x, z, dt),
                 h = kd::water_gradient(loop, f, x, z, dt);
      EXPECT_NEAR(g.x, h.x, tol * gscale);
      EXPECT_NEAR(g.y, h.y, tol * gscale);
      // The displaced march's blocks (kernel/intersect.glsl): any range, the lanes outside
      // it masked at both ends; the derivative along u is grad h . u.
      const double ux = rng.uniform() - 0.5, uz = rng.uniform() - 0.5;
      vec2 blocks(0.0);
      for (int lo = 0; lo < n; lo += kd::kMarchBlock) {
        const int hi = std::min(n, lo + kd::kMarchBlock);
        const vec2 a = kd::water_height_slope(simd, f, lo, hi, x, z, dt, ux, uz),
                   b = kd::water_height_slope(loop, f, lo, hi, x, z, dt, ux, uz);
        EXPECT_NEAR(a.x, b.x, tol * hscale) << lo;
        EXPECT_NEAR(a.y, b.y, tol * gscale) << lo;
        blocks += a;
      }
      EXPECT_NEAR(blocks.x, kd::water_height(loop, f, x, z, dt), tol * hscale);
      EXPECT_NEAR(blocks.y, h.x * ux + h.y * uz, tol * gscale);
      const int lo = n / 3, hi = std::min(n, lo + 5);  // a range off the lanes' boundaries
      EXPECT_NEAR(kd::water_height_slope(simd, f, lo, hi, x, z, dt, ux, uz).x,
                  kd::water_height_slope(loop, f, lo, hi, x, z, dt, ux, uz).x, tol * hscale);
      // `bruneton`'s filtered sums (kernel/bruneton.glsl) at the display time, for a
      // footprint that weighs the waves between 0 and 1: the blocks and the pixel's slopes.
      kd::BrunetonParams bp{};
      bp.n_min = 1.0;
      bp.n_max = 2.5;
      const double scale = 2.0 + 4.0 * rng.uniform();
      const mat2 J(vec2(scale, 0.3), vec2(-0.2, 0.5 * scale));
      int weighted = 0;
      for (int i = 0; i < n; ++i) {
        const kd::Wave w = kd::wave_at(loop, f, i);
        const double wt = kd::wave_lod_weight(vec2(w.a, w.b), J, bp.n_min, bp.n_max);
        weighted += wt > 0 && wt < 1;
      }
      const kd::FilteredSums fa = kd::filtered_sums(simd, f, bp, J, lo, hi, x, z, vec2(ux, uz)),
                             fb = kd::filtered_sums(loop, f, bp, J, lo, hi, x, z, vec2(ux, uz));
      EXPECT_NEAR(fa.hs.x, fb.hs.x, tol * hscale) << lo;
      EXPECT_NEAR(fa.hs.y, fb.hs.y, tol * gscale) << lo;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(fa.bounds[c], fb.bounds[c], 1e-12 * (1 + std::fabs(fb.bounds[c]))) << c;
      const kd::FilteredSlopes sa = kd::filtered_slopes(simd, f, bp, J, n, x, z),
                               sb = kd::filtered_slopes(loop, f, bp, J, n, x, z);
      EXPECT_NEAR(sa.g.x, sb.g.x, tol * gscale);
      EXPECT_NEAR(sa.g.y, sb.g.y, tol * gscale);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(sa.m.cov[c], sb.m.cov[c], 1e-12 * (gscale * gscale + 1e-30)) << c;
      if (n >= 16) {
        EXPECT_GT(weighted, 0) << n;  // not every weight 0 or 1
      }
      const kd::PathGradients p = kd::path_gradients(simd, f, vec3(x, 0, z)),
                              r = kd::path_gradients(loop, f, vec3(x, 0, z));
      for (int k = 0; k <= f.segments; ++k) {
        EXPECT_NEAR(p.g[k].x, r.g[k].x, tol * gscale) << k;
        EXPECT_NEAR(p.g[k].y, r.g[k].y, tol * gscale) << k;
      }
      // The reference's path with time derivatives (kernel/reference.glsl), of the window
      // ending at the display time and of one ending dt before it (its last instant is the
      // gradient at dt).
      for (const double w : {0.0, dt}) {
        const kd::PathDerivatives pd = kd::path_derivatives(simd, f, vec3(x, 0, z), w),
                                  rd = kd::path_derivatives(loop, f, vec3(x, 0, z), w);
        for (int k = 0; k <= f.segments; ++k) {
          EXPECT_NEAR(pd.g[k].x, rd.g[k].x, tol * gscale) << k;
          EXPECT_NEAR(pd.g[k].y, rd.g[k].y, tol * gscale) << k;
          EXPECT_NEAR(pd.dg[k].x, rd.dg[k].x, tol * cscale) << k;
          EXPECT_NEAR(pd.dg[k].y, rd.dg[k].y, tol * cscale) << k;
          if (w == 0.0) {
            EXPECT_NEAR(pd.g[k].x, p.g[k].x, tol * gscale) << k;  // the path's instants
          }
        }
        const vec2 last = kd::water_gradient(loop, f, x, z, w);
        EXPECT_NEAR(pd.g[f.segments].x, last.x, tol * gscale);
        EXPECT_NEAR(pd.g[f.segments].y, last.y, tol * gscale);
      }
      // A moving camera: the instants at points of their own (kernel/reflection_path.glsl).
      kd::PathViews v = kd::path_views_fixed(vec3(x, 0, z), vec3(0, 1, 0));
      v.moving = true;
      for (int k = 0; k < f.segments; ++k)
        v.point[k] += vec2(0.9 * (k - 3) + rng.uniform(), 0.5 * (3 - k) - rng.uniform());
      const double tol_m = phase_rounding(s, std::fabs(x) + 5, std::fabs(z) + 5, 1.1e-16);
      const kd::PathGradients pm = kd::path_gradients_moving(simd, f, v),
                              rm = kd::path_gradients_moving(loop, f, v);
      for (int k = 0; k <= f.segments; ++k) {
        EXPECT_NEAR(pm.g[k].x, rm.g[k].x, tol_m * gscale) << k;
        EXPECT_NEAR(pm.g[k].y, rm.g[k].y, tol_m * gscale) << k;
      }
      EXPECT_NEAR(pm.g[f.segments].x, p.g[f.segments].x, tol * gscale);  // the display time's
    }
    // The staa pass at pixel footprints, with each NDF and with the curvature limit, and
    // the smooth terms' cells (1 to 3 per side); variants 3 to 5 as 0 to 2 under a moving
    // camera (the instants' points a few metres apart: the swept footprint).
    for (int variant = 0; variant < 6; ++variant) {
      const bool moving = variant >= 3;
      kd::StaaParams p{};
      p.smooth_cells = variant % 3 + 1;
      p.per_pixel_ndf = variant % 3 != 1;
      p.alias_start = 0.3;
      p.alias_end = 0.8;
      p.nyquist_max = variant % 3 != 2;
      p.footprint = 1;
      p.curvature_limit = variant % 3 == 2 ? 1.0 : 0.0;
      int aliasing = 0;
      for (int j = 0; j < s.height; j += 7) {
        for (int i = 0; i < s.width; i += 13) {
          const kd::Footprint fp = kd::pixel_footprint(simd, f, i + 0.5, j + 0.5, 0.0, false);
          if (!fp.hit) continue;
          kd::PathViews v = kd::path_views_fixed(fp.point, fp.view);
          v.moving = moving;
          for (int k = 0; moving && k < f.segments; ++k)
            v.point[k] += vec2(0.7 * (k - 3) + 0.01 * i, 0.4 * (k - 3) - 0.02 * j);
          const kd::StaaSums a = kd::staa_wave_pass(simd, f, p, fp, v),
                             b = kd::staa_wave_pass(loop, f, p, fp, v);
          const double tol = moving ? phase_rounding(s, std::fabs(fp.point.x) + 5,
                                                     std::fabs(fp.point.z) + 5, 1.1e-16)
                                    : phase_rounding(s, fp.point.x, fp.point.z, 1.1e-16);
          ASSERT_EQ(a.any_alias, b.any_alias) << i << "," << j;
          aliasing += a.any_alias;
          for (int k = 0; k <= f.segments; ++k) {
            EXPECT_NEAR(a.path.g[k].x, b.path.g[k].x, tol * gscale);
            EXPECT_NEAR(a.path.g[k].y, b.path.g[k].y, tol * gscale);
          }
          for (int c = 0; c < 3; ++c) {
            for (int k = 0; k <= f.segments; ++k)
              EXPECT_NEAR(a.hess[k][c], b.hess[k][c], tol * kscale * gscale) << k << " " << c;
            EXPECT_NEAR(a.ndf.cov[c], b.ndf.cov[c], tol * gscale * gscale) << c;
          }
          EXPECT_NEAR(a.ndf.mean.x, b.ndf.mean.x, tol * gscale);
          EXPECT_NEAR(a.ndf.mean.y, b.ndf.mean.y, tol * gscale);
          ASSERT_EQ(kd::staa_smooth_side(f, p), p.smooth_cells);
          for (int q = 0; q < p.smooth_cells * p.smooth_cells; ++q) {
            EXPECT_NEAR(a.cells.m[q].mean.x, b.cells.m[q].mean.x, tol * gscale) << q;
            EXPECT_NEAR(a.cells.m[q].mean.y, b.cells.m[q].mean.y, tol * gscale) << q;
            for (int c = 0; c < 3; ++c)
              EXPECT_NEAR(a.cells.m[q].cov[c], b.cells.m[q].cov[c], tol * gscale * gscale) << q;
          }
        }
      }
      if (n >= 16) {
        EXPECT_GT(aliasing, 0) << "the test must see aliasing waves";
      }
    }
    // The lanes ran, not the loop twice: Highway's sines and the lanes' order of summation
    // round differently from the loop's somewhere in 50 points.
    if (n >= 5) {
      EXPECT_GT(differ, 0) << n;
    }
  }
}

TEST(KernelWaveSums, LeanBlockSlopesAreTheKernelTermsSummedOverTheWaves) {
  // The LEAN map's lanes (lane_passes.inc, LeanBlockPass: rows four at a time, the rest one
  // by one) against the kernel's term (lean_waves.glsl, lean_wave_slope) summed wave by
  // wave, texel by texel: 7 rows (one group of four and three alone) of 2 lane paddings'
  // columns over 37 waves of random amplitudes and phases.
  constexpr int nk = 37, rows = 7, width = 2 * wave_simd::kLanePadding;
  Pcg32 rng(11, 5);
  std::vector<double> amplitude(2 * nk), row(2 * rows * nk), col_c(nk * width), col_s(nk * width);
  for (double& a : amplitude)
    a = rng.uniform() - 0.5;
  for (int r = 0; r < rows; ++r) {
    for (int k = 0; k < nk; ++k) {
      const double t = kTwoPi * rng.uniform();
      row[2 * (r * nk + k)] = std::cos(t);
      row[2 * (r * nk + k) + 1] = std::sin(t);
    }
  }
  for (int e = 0; e < nk * width; ++e) {
    const double t = kTwoPi * rng.uniform();
    col_c[e] = std::cos(t);
    col_s[e] = std::sin(t);
  }
  std::vector<double> out(2 * rows * width, std::nan(""));
  kd::lean_block_slopes(amplitude.data(), nk, row.data(), rows, col_c.data(), col_s.data(), width,
                        out.data());
  for (int r = 0; r < rows; ++r) {
    for (int q = 0; q < width; ++q) {
      kd::vec2 g(0.0);
      for (int k = 0; k < nk; ++k) {
        g += kd::lean_wave_slope(
            kd::vec2(amplitude[2 * k], amplitude[2 * k + 1]),
            kd::vec2(row[2 * (r * nk + k)], row[2 * (r * nk + k) + 1]),
            kd::vec2(col_c[size_t(k) * width + q], col_s[size_t(k) * width + q]));
      }
      EXPECT_NEAR(out[size_t(2 * r) * width + q], g.x, 1e-13) << r << ", " << q;
      EXPECT_NEAR(out[size_t(2 * r + 1) * width + q], g.y, 1e-13) << r << ", " << q;
    }
  }
}

TEST(KernelWaveSums, VectorisedFloatSumsEqualTheFloatKernelLoops) {
  const Scene s = random_waves_scene(64, 3);
  const SceneModel m(s);
  KernelInputsF in;
  build_kernel_inputs(m, frame_time(s, 3), 3, 0, in);
  const kf::WaveBuffer simd = wave_buffer(in, true), loop = wave_buffer(in, false);
  double hscale = 0, gscale = 0, cscale = 0;
  for (const Wave& w : s.surface.waves) {
    hscale += w.amplitude;
    gscale += w.amplitude * length(w.wave_vector);
    cscale += w.amplitude * length(w.wave_vector) * w.angular_frequency;
  }
  Pcg32 rng(9, 5);
  for (int q = 0; q < 200; ++q) {
    const float x = float(200 * (rng.uniform() - 0.5)), z = float(-300 * rng.uniform()),
                dt = float(-0.03 * rng.uniform());
    const double tol = phase_rounding(s, x, z, 6e-8);
    EXPECT_NEAR(kf::float_water_height(simd, in.frame, x, z, dt),
                kf::float_water_height(loop, in.frame, x, z, dt), tol * hscale);
    const kf::vec2 g = kf::float_water_gradient(simd, in.frame, x, z, dt),
                   h = kf::float_water_gradient(loop, in.frame, x, z, dt);
    EXPECT_NEAR(g.x, h.x, tol * gscale);
    EXPECT_NEAR(g.y, h.y, tol * gscale);
    for (int lo : {0, 8, 13, 56}) {
      const int hi = std::min(64, lo + kd::kMarchBlock);  // the same constant in float
      const kf::vec2 a = kf::float_water_height_slope(simd, in.frame, lo, hi, x, z, dt, 0.6f,
                                                      -0.8f),
                     b = kf::float_water_height_slope(loop, in.frame, lo, hi, x, z, dt, 0.6f,
                                                      -0.8f);
      EXPECT_NEAR(a.x, b.x, tol * hscale) << lo;
      EXPECT_NEAR(a.y, b.y, tol * gscale) << lo;
    }
    kf::vec2 pg[kf::kMaxSegments + 1], pd[kf::kMaxSegments + 1], rg[kf::kMaxSegments + 1],
        rd[kf::kMaxSegments + 1];
    kf::float_path_derivatives(simd, in.frame, kf::vec3(x, 0, z), dt, pg, pd);
    kf::float_path_derivatives(loop, in.frame, kf::vec3(x, 0, z), dt, rg, rd);
    for (int k = 0; k <= in.frame.segments; ++k) {
      EXPECT_NEAR(pg[k].x, rg[k].x, tol * gscale) << k;
      EXPECT_NEAR(pg[k].y, rg[k].y, tol * gscale) << k;
      EXPECT_NEAR(pd[k].x, rd[k].x, tol * cscale) << k;
      EXPECT_NEAR(pd[k].y, rd[k].y, tol * cscale) << k;
    }
  }
}

TEST(KernelWaveSums, MovingInstantsKeepTheDisplayTimesPhaseInFloat) {
  // A moving path's instants take their phases from the display time's, turned back in
  // time and on by k . (p_k - p_K) (kernel/path_terms.glsl, path_instant_cos_sin), so
  // that float rounds the display time's phase once for every instant. With the instants'
  // points at p_K the path is the fixed camera's, to the last bits; taken whole at each
  // instant, k . p_k + theta0 + c dt_k, the phases 1.1 km from the camera (up to 2.4e4
  // rad, a float's unit 2e-3 rad) round apart by up to a unit at each instant.
  const Scene s = random_waves_scene(64, 3);
  const SceneModel m(s);
  for (int segments : {1, 4}) {
    KernelInputsF in;
    build_kernel_inputs(m, frame_time(s, 3), segments, 0, in);
    double gscale = 0;
    for (const Wave& w : s.surface.waves)
      gscale += w.amplitude * length(w.wave_vector);
    for (bool lanes : {true, false}) {
      const kf::WaveBuffer waves = wave_buffer(in, lanes);
      Pcg32 rng(segments, 7);
      double largest = 0;
      for (int q = 0; q < 20; ++q) {
        const kf::vec3 p(float(700 + 50 * rng.uniform()), 0.0f, float(-900 - 50 * rng.uniform()));
        kf::vec2 points[kf::kMaxSegments + 1], fixed[kf::kMaxSegments + 1],
            moving[kf::kMaxSegments + 1];
        for (int k = 0; k < segments; ++k)
          points[k] = kf::vec2(p.x, p.z);
        kf::float_path_gradients(waves, in.frame, p, nullptr, fixed);
        kf::float_path_gradients(waves, in.frame, p, points, moving);
        for (int k = 0; k <= segments; ++k)
          largest = std::max({largest, double(std::fabs(moving[k].x - fixed[k].x)),
                              double(std::fabs(moving[k].y - fixed[k].y))});
      }
      EXPECT_LE(largest, 1e-6 * gscale) << segments << " segments, lanes " << lanes;
    }
  }
}

TEST(KernelWaveSums, StaaPixelsWithAndWithoutVectorisedSumsAgree) {
  // staa end to end (its values are smooth in the sums): every pixel with the vectorised
  // sums against the kernel's loops.
  Scene s = testing::project_scene("medium");
  s.width = 96;
  s.height = 54;
  const SceneModel m(s);
  const PathTables& tables = testing::path_tables();
  const KernelFitTexture& fits = kernel_fit_texture();
  for (int footprint : {0, 1}) {
    KernelInputsD in;
    build_kernel_inputs(m, frame_time(s, 2), 1, 0, in);
    kd::StaaParams p{};
    p.per_pixel_ndf = true;
    p.ndf_mean_shift = true;
    p.kernels = 9;
    p.fallback_along_path = true;
    p.riemann_cells = 32;
    p.alias_start = footprint ? 0.3 : 0.2;
    p.alias_end = footprint ? 0.8 : 0.5;
    p.nyquist_max = true;
    p.footprint = footprint;
    p.smooth_cells = 3;
    kd::Frame fr = in.frame;
    fr.fresnel = 1;  // Schlick's, so that the smooth terms' cells are taken
    double worst = 0;
    int lit = 0;
    for (int j = 0; j < s.height; ++j) {
      for (int i = 0; i < s.width; ++i) {
        kd::StaaPath pa, pb;
        const kd::StaaResult a =
            kd::staa_pixel(wave_buffer(in, true), tables.f_texture(), tables.s_texture(),
                           tables.kernel_info(), fits.view(), fits.info, fr, p, i, j, pa);
        const kd::StaaResult b =
            kd::staa_pixel(wave_buffer(in, false), tables.f_texture(), tables.s_texture(),
                           tables.kernel_info(), fits.view(), fits.info, fr, p, i, j, pb);
        lit += a.in_light > 1e-3;
        for (int c = 0; c < 4; ++c)
          worst = std::max(worst, std::fabs(a.weights[c] - b.weights[c]));
      }
    }
    std::printf(
        "staa (footprint %d), vectorised against loop sums: max |difference| %.3g, %d lit\n",
        footprint, worst, lit);
    EXPECT_GT(lit, 10);
    EXPECT_LT(worst, 1e-9);
  }
}

}  // namespace
}  // namespace sg
