// The cost that follows the resolved waves (kernel/waves.glsl's sums, kernel/staa.glsl's
// remainder, kernel/intersect.glsl's tolerance) against the plain sums over every wave,
// on generated spectrum oceans of 256 waves:
//  - the waves sorted once per scene: a shuffled file renders the same pixels;
//  - staa's O(1) remainder equals the explicit sum over its waves (uniform NDF: exactly,
//    every wave of the remainder aliasing fully; per-pixel NDF: within its stated bounds);
//  - the displaced intersection with the shortest waves left out against the full one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"
#include "math/rng.h"
#include "ocean/ocean.h"
#include "shading/kernel_frame.h"
#include "shading/kernel_table.h"
#include "shading/path_table.h"
#include "testing/path_tables.h"

namespace sg {
namespace {

Scene ocean_view(int waves, int width, int height, Geometry geometry) {
  ocean::OceanParams p;
  p.waves = waves;
  p.wind_speed = 10;
  p.seed = 7;
  Scene s = ocean::ocean_scene(ocean::plain_template(), ocean::generate(p), "sea");
  s.width = width;
  s.height = height;
  s.surface.geometry = geometry;
  return s;
}

kd::StaaParams staa_params(bool per_pixel, bool remainder) {
  kd::StaaParams p{};
  p.per_pixel_ndf = per_pixel;
  p.ndf_mean_shift = true;
  p.kernels = 9;
  p.fallback_along_path = true;
  p.riemann_cells = 32;
  p.alias_start = 0.3;
  p.alias_end = 0.8;
  p.nyquist_max = true;
  p.footprint = 1;
  p.wave_remainder = remainder;
  return p;
}

TEST(KernelResolvedWaves, ShuffledWaveFileRendersTheSamePixels) {
  // The inputs sort the waves by |k|: a file with the same waves in another order gives
  // the same staa pixels (per-pixel NDF, remainder on) on displaced water, to rounding.
  const Scene s = ocean_view(256, 64, 36, Geometry::displaced);
  Scene shuffled = s;
  Pcg32 rng(3, 1);
  std::vector<Wave>& w = shuffled.surface.waves;
  for (size_t i = w.size(); i-- > 1;)
    std::swap(w[i], w[rng.next_u32() % (i + 1)]);
  ASSERT_NE(w.front().amplitude, s.surface.waves.front().amplitude);
  const SceneModel ma(s), mb(shuffled);
  KernelInputsD a, b;
  build_kernel_inputs(ma, frame_time(s, 2), 1, 0, a);
  build_kernel_inputs(mb, frame_time(s, 2), 1, 0, b);
  const PathTables& tables = testing::path_tables();
  const KernelFitTexture& fits = kernel_fit_texture();
  const kd::StaaParams p = staa_params(true, true);
  double worst = 0;
  int lit = 0;
  for (int j = 0; j < s.height; ++j) {
    for (int i = 0; i < s.width; ++i) {
      kd::StaaPath pa, pb;
      const kd::StaaResult ra =
          kd::staa_pixel(wave_buffer(a, true), tables.f_texture(), tables.s_texture(),
                         tables.kernel_info(), fits.view(), fits.info, a.frame, p, i, j, pa);
      const kd::StaaResult rb =
          kd::staa_pixel(wave_buffer(b, true), tables.f_texture(), tables.s_texture(),
                         tables.kernel_info(), fits.view(), fits.info, b.frame, p, i, j, pb);
      lit += ra.in_light > 1e-3;
      for (int c = 0; c < 4; ++c)
        worst = std::max(worst, std::fabs(ra.weights[c] - rb.weights[c]));
    }
  }
  std::printf("sorted against shuffled file: max |difference| %.3g, %d lit pixels\n", worst, lit);
  EXPECT_GT(lit, 5);
  EXPECT_LT(worst, 1e-9);
}

TEST(KernelResolvedWaves, RemainderEqualsTheExplicitSum) {
  // A view from 20 m above the sea, where most pixels have a remainder of many waves.
  Scene s = ocean_view(256, 80, 45, Geometry::flat);
  s.camera.position.y = 20;
  const SceneModel m(s);
  KernelInputsD in;
  build_kernel_inputs(m, frame_time(s, 2), 1, 0, in);
  const kd::Frame& f = in.frame;
  const int n = f.wave_count;
  for (bool simd : {true, false}) {
    const kd::WaveBuffer buf = wave_buffer(in, simd);
    for (bool per_pixel : {false, true}) {
      const kd::StaaParams on = staa_params(per_pixel, true), off = staa_params(per_pixel, false);
      int pixels = 0, with_remainder = 0;
      double remainder_waves = 0, worst_cov = 0, worst_mean = 0, worst_path = 0;
      for (int j = 0; j < s.height; ++j) {
        for (int i = 0; i < s.width; ++i) {
          const kd::Footprint fp = kd::pixel_footprint(buf, f, i + 0.5, j + 0.5, 0.0, false);
          if (!fp.hit) continue;
          ++pixels;
          const kd::mat2 J = kd::footprint_xz_jacobian(fp);
          const int c = kd::staa_remainder_start(buf, f, on, J);
          with_remainder += c < n;
          remainder_waves += n - c;
          const kd::PathViews v = kd::path_views_fixed(fp.point, fp.view);
          const kd::StaaSums a = kd::staa_wave_pass(buf, f, on, fp, v);
          const kd::StaaSums b = kd::staa_wave_pass(buf, f, off, fp, v);
          // The remainder's own scales: its trace and its slope amplitudes.
          double trace = 0, slope = 0;
          for (int q = c; q < n; ++q) {
            const kd::Wave w = kd::wave_at(buf, f, q);
            trace += 0.5 * w.A * w.A * (w.a * w.a + w.b * w.b);
            slope += w.A * std::hypot(w.a, w.b);
          }
          const kd::vec3 dc = a.ndf.cov - b.ndf.cov;
          const double cov = std::max({std::fabs(dc.x), std::fabs(dc.y), std::fabs(dc.z)});
          const double mean = length(a.ndf.mean - b.ndf.mean);
          double path = length(a.path.g[0] - b.path.g[0]);
          path = std::max(path, length(a.path.g[1] - b.path.g[1]));
          for (int k = 0; k <= f.segments; ++k) {
            const kd::vec3 dh = a.hess[k] - b.hess[k];
            path = std::max({path, std::fabs(dh.x), std::fabs(dh.y), std::fabs(dh.z)});
          }
          const double total = b.ndf.cov.x + b.ndf.cov.z;
          // Uniform NDF: the remainder is the explicit sum, to the rounding of a sum of
          // hundreds of terms; per-pixel NDF: within the remainder's bounds (staa.glsl).
          worst_cov = std::max(
              worst_cov, per_pixel ? cov / std::max(trace, 1e-300) : cov / std::max(total, 1e-300));
          worst_mean = std::max(worst_mean, per_pixel ? mean / std::max(slope, 1e-300) : mean);
          worst_path = std::max(worst_path, path);
          EXPECT_EQ(a.any_alias, b.any_alias) << i << " " << j;
        }
      }
      std::printf(
          "%s, %s NDF: %d pixels, %d with a remainder (%.1f waves on average); covariance "
          "departure %.3g (of the %s), mean %.3g%s, path and Hessian %.3g\n",
          simd ? "vectorised" : "loops", per_pixel ? "per-pixel" : "uniform", pixels,
          with_remainder, remainder_waves / pixels, worst_cov,
          per_pixel ? "remainder's trace" : "whole trace", worst_mean,
          per_pixel ? " (of the remainder's sum A|k|)" : "", worst_path);
      ASSERT_GT(pixels, 300);
      EXPECT_GT(with_remainder, pixels / 2);
      EXPECT_GT(remainder_waves / pixels, 0.1 * n);
      EXPECT_LT(worst_path, 1e-12);
      if (per_pixel) {
        EXPECT_LT(worst_cov, 0.094);
        EXPECT_LT(worst_mean, 0.125);
      } else {
        EXPECT_LT(worst_cov, 1e-12);
        EXPECT_LT(worst_mean, 1e-12);
      }
    }
  }
}

TEST(KernelResolvedWaves, DescendingRaysHitWhenEveryWaveIsLeftOut) {
  // A 1.4 mm wave seen from 191 m up (a scene of the engines' agreement test,
  // gl_engine/engine_agreement_test.cpp): the tolerance leaves out the only wave, the slab
  // has zero thickness, and f at its floor is positive by rounding on some rays. Every
  // descending ray must hit there (before, 27 of them missed in double and 15 in float, and
  // saw the sky: each engine and precision a different few), in double and in float.
  Scene s = ocean_view(16, 24, 16, Geometry::displaced);
  s.surface.waves = {Wave{}};
  s.surface.waves[0].amplitude = 0.0013760284461597798;
  s.surface.waves[0].wave_vector = vec2(0.42551609416954866, -0.43190425884076883);
  s.surface.waves[0].angular_frequency = 2.4388209981090543;
  s.surface.waves[0].phase = 5.889413164491589;
  s.camera.position = vec3(16902.26990780232, 191.55595834323736, -42594.87822424707);
  s.camera.look_at = vec3(16901.690480595957, 191.02703286334602, -42595.50565047011);
  s.camera.up = vec3(0, 1, 0);
  s.camera.vfov_deg = 67.00150067045146;
  s.surface.fresnel = FresnelMode::schlick;
  const SceneModel m(s);
  KernelInputsD in;
  KernelInputsF inf;
  build_kernel_inputs(m, frame_time(s, 0), 1, 0, in);
  build_kernel_inputs(m, frame_time(s, 0), 1, 0, inf);
  const kd::WaveBuffer b = wave_buffer(in, false);
  const kf::WaveBuffer bf = wave_buffer(inf, false);
  int descending = 0, missed = 0, missed_float = 0;
  for (int j = 0; j < s.height; ++j) {
    for (int i = 0; i < s.width; ++i) {
      const kd::vec3 d = normalize(kd::camera_direction(in.frame.camera, i + 0.5, j + 0.5));
      if (d.y >= -0.01) continue;
      ++descending;
      missed += !kd::intersect_displaced(b, in.frame, in.frame.camera.position, d, 0.0).hit;
      // In float through point's pixel: with Fresnel a hit has a share of the sea, a miss none.
      missed_float += !(kf::float_point_pixel(bf, inf.frame, i, j)[3] > 0.0f);
    }
  }
  EXPECT_GT(descending, 100);
  EXPECT_EQ(missed, 0);
  EXPECT_EQ(missed_float, 0);
}

TEST(KernelResolvedWaves, DisplacedIntersectionWithinItsBoundOfTheFullOne) {
  // kernel/intersect.glsl: with tolerance tau the march sums the first waves only, and
  //  - the hit is within tau eps s (plus the root tolerance) of the full surface, vertically;
  //  - where the ray crosses the surface, the hit moves by at most tau of the pixel's
  //    footprint (first order; a graze may move further or turn a hit into a miss).
  const double tau = 0.25;
  const Scene s = ocean_view(256, 160, 90, Geometry::displaced);
  const SceneModel m(s);
  KernelInputsD full, fewer;
  build_kernel_inputs(m, frame_time(s, 2), 1, 0, full, 0.0);
  build_kernel_inputs(m, frame_time(s, 2), 1, 0, fewer, tau);
  const kd::WaveBuffer bf = wave_buffer(full, true), bl = wave_buffer(fewer, true);
  const kd::Frame& f = full.frame;
  const int n = f.wave_count;
  int hits = 0, disagree = 0, beyond = 0;
  double worst_vertical = 0, worst_shift = 0, summed = 0;
  for (int j = 0; j < s.height; ++j) {
    for (int i = 0; i < s.width; ++i) {
      const kd::vec3 d = normalize(kd::camera_direction(f.camera, i + 0.5, j + 0.5));
      const kd::vec3 o = f.camera.position;
      const kd::RayHit a = kd::intersect_displaced(bf, f, o, d, 0.0);
      const kd::RayHit b = kd::intersect_displaced(bl, fewer.frame, o, d, 0.0);
      if (a.hit != b.hit) ++disagree;
      if (!(a.hit && b.hit)) continue;
      ++hits;
      const double eps = kd::pixel_angle(f.camera, d);
      const double h = kd::water_height(bf, f, b.point.x, b.point.z, 0.0);
      worst_vertical =
          std::max(worst_vertical, std::fabs(b.point.y - h) / (tau * eps * b.s + 1e-9));
      summed += kd::first_wave_below(bl, fewer.frame, tau * eps * b.s);
      const kd::Footprint fp = kd::pixel_footprint(bf, f, i + 0.5, j + 0.5, 0.0, true);
      const double size = length(fp.dp_dpx) + length(fp.dp_dpy);
      const double shift = length(a.point - b.point) / size;
      worst_shift = std::max(worst_shift, shift);
      beyond += shift > tau;
    }
  }
  std::printf(
      "displaced, tolerance %g pixel: %d hits, %d disagree; vertical error %.3g of the bound; "
      "shift > tau footprint at %d hits (worst %.3g footprints); waves summed at the hit "
      "%.1f of %d on average\n",
      tau, hits, disagree, worst_vertical, beyond, worst_shift, summed / std::max(hits, 1), n);
  ASSERT_GT(hits, s.width * s.height / 3);
  EXPECT_LE(worst_vertical, 1.0);
  EXPECT_LE(disagree, hits / 100);
  EXPECT_LE(beyond, hits / 100);
  EXPECT_LT(summed / hits, 0.9 * n);  // the bound leaves waves out
}

}  // namespace
}  // namespace sg
