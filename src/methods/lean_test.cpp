// LEAN mapping (methods/lean.h, lean_map.h, lean_coverage.h).
//  - Moments: constant slopes give their slope and no spread at every level; a two-valued
//    checkerboard gives the analytic mean and (correlated) covariance; a sine wave over
//    whole periods gives Podee Eq. 3 at the coarsest level.
//  - MIP filtering: a level-l texel (the lookup at its centre) equals the brute-force mean
//    of the 2^l x 2^l finest texels it covers; filter weights sum to 1; anisotropic probes
//    follow the box footprint where trilinear over-blurs.
//  - The wave map's texels (the CPU's lanes) are the mapped waves' gradient at their
//    centres and the GL engine's text (kernel/lean.glsl, lean_level0_block: each texel of
//    a block).
//  - Coverage: the map holds the visible water within D; pixels beyond the map get the
//    uniform NDF of Eq. 3 (border moments), as documented.
//  - Calm water against the analytic mirrored disk; the shared scenes and a displaced,
//    Schlick, sky-and-sea variant render without NaN or Inf.
#include "methods/lean.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "base/error.h"
#include "engine/render.h"
#include "math/rng.h"
#include "methods/point.h"
#include "methods/supersample.h"
#include "shading/ndf.h"
#include "shading/radiance.h"
#include "shading/water_geometry.h"
#include "testing/calm_water.h"
#include "testing/testing.h"

namespace sg {
namespace {

double compare_rmse(const Image& a, const Image& b) {
  double se = 0;
  for (size_t k = 0; k < a.size(); ++k)
    se += sqr(double(a.data[k]) - b.data[k]);
  return std::sqrt(se / a.size());
}

void expect_moments_near(const LeanMoments& a, const vec2& B, const mat2& cov, double tol) {
  EXPECT_NEAR(a.B.x, B.x, tol);
  EXPECT_NEAR(a.B.y, B.y, tol);
  const mat2 c = kd::lean_covariance(a);
  EXPECT_NEAR(c[0][0], cov[0][0], tol);
  EXPECT_NEAR(c[1][1], cov[1][1], tol);
  EXPECT_NEAR(c[0][1], cov[0][1], tol);
  EXPECT_NEAR(c[1][0], cov[1][0], tol);
}

TEST(LeanMap, ConstantSlopesHaveNoSpreadAtAnyLevel) {
  LeanMap map;
  map.allocate(64);
  const vec2 b(0.13, -0.07);
  map.fill([&](int, int) { return b; });
  map.build_mips();
  Pcg32 rng(1, 2);
  for (int k = 0; k < 200; ++k) {
    // Inside the map by more than the filters' reach (the border's mean slope is 0).
    const vec2 s(20 + 24 * rng.uniform(), 20 + 24 * rng.uniform());
    const vec2 dx(8 * rng.uniform(), rng.uniform()), dy(-rng.uniform(), 3 * rng.uniform());
    for (LeanFilter f : {LeanFilter::trilinear, LeanFilter::aniso}) {
      // Any filter of constant moments returns them: the weights sum to 1.
      expect_moments_near(map.lookup(s, dx, dy, f, 16), b, mat2(0.0), 1e-7);
    }
    expect_moments_near(map.bilinear(k % 5, s), b, mat2(0.0), 1e-7);
  }
}

TEST(LeanMap, CheckerboardGivesTheAnalyticMeanAndCorrelatedCovariance) {
  // Slopes alternate between b1 and b2: from level 1 on every texel averages two of each,
  // so B = (b1 + b2) / 2 and Sigma = d d^T / 4, d = b1 - b2 (correlated: d is diagonal).
  LeanMap map;
  map.allocate(32);
  const vec2 b1(0.2, 0.1), b2(-0.1, -0.05);
  map.fill([&](int i, int j) { return (i + j) % 2 ? b1 : b2; });
  map.build_mips();
  const vec2 d = b1 - b2;
  const mat2 cov = glm::outerProduct(d, d) / 4.0;
  const vec2 mean = (b1 + b2) / 2.0;
  for (int level = 1; level < map.levels(); ++level) {
    for (int k = 0; k < 3; ++k) {
      const int n = map.level_size(level), i = (k * 5) % n, j = (k * 3) % n;
      expect_moments_near(map.texel(level, i, j), mean, cov, 1e-7);
    }
  }
  // Trilinear at a level >= 1 inside the map.
  expect_moments_near(map.trilinear(vec2(13.3, 17.9), 1.6), mean, cov, 1e-7);
  EXPECT_GT(std::fabs(cov[0][1]), 0.005);
  // Level 0 is a single slope per texel.
  expect_moments_near(map.texel(0, 3, 4), b1, mat2(0.0), 1e-7);
}

TEST(LeanMap, LevelsFollowOneAnotherDownToOneTexel) {
  // The kernel's closed-form layout (lean_level_offset) against the level sizes summed one
  // by one, for every map size the options allow and every level, one past the last
  // included (the chain's size); and the level count (N, N/2, ..., 1).
  for (int size = 1; size <= 8192; size *= 2) {
    int levels = 0;
    for (int n = size; n >= 1; n /= 2)
      ++levels;
    EXPECT_EQ(kd::lean_level_count(size), levels) << size;
    long at = 0;
    for (int level = 0; level <= levels; ++level) {
      EXPECT_EQ(kd::lean_level_offset(size, level), at) << size << " level " << level;
      at += long(size >> level) * (size >> level);
    }
  }
  // The map's storage is the chain: its last texel is level L's one texel.
  LeanMap map;
  map.allocate(64);
  EXPECT_EQ(map.levels(), 7);
  EXPECT_EQ(map.texels().size, long(kd::lean_level_offset(64, 7)) * kd::kLeanTexelFloats);
}

TEST(LeanMap, MipTexelsAreBoxMeansOfTheFinestTexels) {
  LeanMap map;
  map.allocate(128);
  Pcg32 rng(3, 3);
  std::vector<vec2> slopes(128 * 128);
  for (auto& s : slopes)
    s = vec2(rng.uniform() - 0.5, 0.4 * (rng.uniform() - 0.5));
  map.fill([&](int i, int j) { return slopes[j * 128 + i]; });
  map.build_mips();
  for (int level = 1; level < map.levels(); ++level) {
    const int n = map.level_size(level), w = 1 << level;
    for (int k = 0; k < 10; ++k) {
      const int I = static_cast<int>(rng.uniform() * n), J = static_cast<int>(rng.uniform() * n);
      LeanMoments brute{};
      for (int j = J * w; j < (J + 1) * w; ++j) {
        for (int i = I * w; i < (I + 1) * w; ++i) {
          const LeanMoments t = map.texel(0, i, j);  // the stored (float) finest texels
          brute.B += t.B / double(w * w);
          brute.M += t.M / double(w * w);
        }
      }
      // The lookup at the level-l texel centre, level of detail exactly l.
      const vec2 centre((I + 0.5) * w, (J + 0.5) * w);
      const LeanMoments look = map.trilinear(centre, level);
      expect_moments_near(look, brute.B, kd::lean_covariance(brute), 2e-7);
      EXPECT_NEAR(look.M.z, brute.M.z, 2e-7);
    }
  }
}

TEST(LeanMap, AnisotropicProbesFollowTheFootprintWhereTrilinearOverBlurs) {
  // Slopes vary along z only (a sine of period 8 texels); a footprint 16 texels long in x
  // and 1 texel in z. The box mean over the footprint has almost no spread; trilinear
  // filtering at the level of the longer side (16 texels) averages whole periods in z.
  LeanMap map;
  map.allocate(256);
  map.fill([](int, int j) { return vec2(0.0, 0.3 * std::cos(kTwoPi * (j + 0.5) / 8.0)); });
  map.build_mips();
  const vec2 s(100.0, 100.5), dx(16, 0), dy(0, 1);  // the footprint covers texel row 100
  double brute = 0, brute2 = 0;
  int count = 0;
  for (int k = 0; k < 400; ++k) {  // the box footprint, finely sampled along x and z
    const vec2 p = s + ((k % 20 + 0.5) / 20 - 0.5) * dx + ((k / 20 + 0.5) / 20 - 0.5) * dy;
    const double v = 0.3 * std::cos(kTwoPi * (std::floor(p.y) + 0.5) / 8.0);
    brute += v;
    brute2 += v * v;
    ++count;
  }
  const double var = brute2 / count - sqr(brute / count);
  const double tri = kd::lean_covariance(map.lookup(s, dx, dy, LeanFilter::trilinear, 16))[1][1];
  const double ani = kd::lean_covariance(map.lookup(s, dx, dy, LeanFilter::aniso, 16))[1][1];
  EXPECT_NEAR(tri, 0.045, 0.002);  // two whole periods: A^2 / 2
  EXPECT_LT(std::fabs(ani - var), 0.2 * std::fabs(tri - var)) << ani << " " << var << " " << tri;
  // Slopes varying along the footprint's long side (a ramp in x): the 16 probes sit on the
  // 16 texel centres the footprint covers, so aniso gives their variance exactly, where
  // trilinear takes 32 texels (two level-4 texels).
  LeanMap ramp;
  ramp.allocate(256);
  ramp.fill([](int i, int) { return vec2(0.01 * (i + 0.5), 0.0); });
  ramp.build_mips();
  const double ramp_var = sqr(0.01) * (16 * 16 - 1) / 12.0;  // 16 equally spaced values
  const mat2 ac = kd::lean_covariance(ramp.lookup(s, dx, dy, LeanFilter::aniso, 16));
  const mat2 tc = kd::lean_covariance(ramp.lookup(s, dx, dy, LeanFilter::trilinear, 16));
  EXPECT_NEAR(ac[0][0], ramp_var, 1e-6);
  EXPECT_GT(tc[0][0], 2 * ramp_var);
  // An isotropic footprint takes one probe: aniso equals trilinear.
  const LeanMoments a = map.lookup(s, vec2(3, 0), vec2(0, 3), LeanFilter::aniso, 16);
  const LeanMoments t = map.lookup(s, vec2(3, 0), vec2(0, 3), LeanFilter::trilinear, 16);
  EXPECT_EQ(a.B, t.B);
  EXPECT_EQ(a.M, t.M);
}

TEST(LeanWaves, TexelsAreTheGradientAndWholePeriodsGiveEq3) {
  // One wave with whole periods across a 256-texel map: 5 in x and 3 in z; a second one
  // finer than the grid (left to the base term). The CPU's fill (SIMD lanes, angle addition)
  // against the gradient of the mapped wave at every 29th / 37th texel, and against the
  // GL engine's text (lean_level0_block) over the block that starts there.
  const double texel = 0.05, side = 256 * texel;
  const vec2 k(kTwoPi * 5 / side, kTwoPi * 3 / side);
  Scene s = testing::small_scene(
      {Wave{0.02, k, 1.7, 0.4}, Wave{0.001, vec2(kTwoPi / (1.5 * texel), 0.0), 9.0, 0.2}}, 64, 36);
  SceneModel m(s);
  KernelInputsD in;
  build_kernel_inputs(m, frame_time(s, 3), 1, 0, in);
  const kd::WaveBuffer waves = wave_buffer(in);
  LeanMapRegion region;
  region.origin = vec2(-3.0, -40.0);
  region.texel = texel;
  LeanOptions o;
  const kd::LeanParams p =
      lean_frame_params(region, o, 256, kernel_frame_waves(in), vec2(in.origin.x, in.origin.z));
  EXPECT_EQ(p.levels, 9);
  LeanMap map;
  map.allocate(256);
  fill_lean_map(map, p, kernel_frame_waves(in));
  map.build_mips();
  // The mapped wave alone (the buffer is sorted by |k|: it is wave 0).
  const kd::Wave w0 = kd::wave_at(waves, in.frame, 0);
  ASSERT_NEAR(w0.A, 0.02, 1e-15);
  for (int j = 0; j < 256; j += 37) {
    for (int i = 0; i < 256; i += 29) {
      const kd::vec2 xz = kd::lean_texel_centre(p, i, j);
      const kd::vec2 g = kd::wave_gradient_of(w0, xz.x, xz.y, 0.0);
      const LeanMoments t = map.texel(0, i, j);
      EXPECT_NEAR(t.B.x, g.x, 1e-7 + 1e-6 * std::fabs(g.x));
      EXPECT_NEAR(t.B.y, g.y, 1e-7 + 1e-6 * std::fabs(g.y));
      // The GL engine's block from this texel: each of its texels the CPU's.
      const kd::LeanBlock block = kd::lean_level0_block(waves, in.frame, p, i, j);
      for (int r = 0; r < kd::kLeanBlock && j + r < 256; ++r) {
        for (int c = 0; c < kd::kLeanBlock && i + c < 256; ++c) {
          const LeanMoments cpu = map.texel(0, i + c, j + r);
          const LeanMoments gl = kd::lean_moments_of_slope(block.g[r * kd::kLeanBlock + c]);
          EXPECT_NEAR(cpu.B.x, gl.B.x, 1e-7 + 1e-6 * std::fabs(gl.B.x)) << i + c << ", " << j + r;
          EXPECT_NEAR(cpu.B.y, gl.B.y, 1e-7 + 1e-6 * std::fabs(gl.B.y)) << i + c << ", " << j + r;
          EXPECT_NEAR(cpu.M.z, gl.M.z, 1e-8 + 1e-6 * std::fabs(gl.M.z)) << i + c << ", " << j + r;
        }
      }
    }
  }
  const mat2 eq3 = 0.5 * 0.02 * 0.02 * glm::outerProduct(k, k);
  const LeanMoments top = map.texel(map.levels() - 1, 0, 0);
  expect_moments_near(top, vec2(0), eq3, 1e-6 * eq3[1][1]);
  // The border holds Eq. 3 of the mapped wave, the base term the finer wave's.
  EXPECT_NEAR(p.border.x, eq3[0][0], 1e-15);
  EXPECT_NEAR(p.border.y, eq3[1][1], 1e-15);
  EXPECT_NEAR(p.border.z, eq3[0][1], 1e-15);
  EXPECT_NEAR(p.base.x, 0.5 * 1e-6 * sqr(kTwoPi / (1.5 * texel)), 1e-12);
  EXPECT_EQ(p.base.y, 0.0);
}

TEST(LeanCoverage, VisibleWaterBoundsAreTheBoxOfTheVisibleWaterWithinD) {
  // Brute force: a 0.1 m grid of water points, each visible when it projects into the image
  // and lies within D of the camera.
  SceneModel m(testing::project_scene("simple"));
  const double D = 80, step = 0.1;
  vec2 lo, hi;
  ASSERT_TRUE(visible_water_bounds(m, 0.0, D, lo, hi));
  const vec3 C = m.camera.position();
  vec2 blo(1e300), bhi(-1e300);
  for (double z = C.z - D; z <= C.z + D; z += step) {
    for (double x = C.x - D; x <= C.x + D; x += step) {
      if (length(vec2(x - C.x, z - C.z)) > D) continue;
      double px, py;
      if (!m.camera.project(vec3(x, 0, z) - C, px, py)) continue;
      if (px < 0 || py < 0 || px > m.width() || py > m.height()) continue;
      blo = glm::min(blo, vec2(x, z));
      bhi = glm::max(bhi, vec2(x, z));
    }
  }
  // Equal to the grid's spacing (the polygon circumscribes the disk by
  // D (1 / cos(pi / 1024) - 1) = 0.4 mm).
  EXPECT_NEAR(lo.x, blo.x, 1.5 * step);
  EXPECT_NEAR(lo.y, blo.y, 1.5 * step);
  EXPECT_NEAR(hi.x, bhi.x, 1.5 * step);
  EXPECT_NEAR(hi.y, bhi.y, 1.5 * step);
}

TEST(LeanCoverage, AutomaticMapResolvesTheFinestFootprintAndHoldsWaterWithinD) {
  Scene s = testing::project_scene("medium");
  set_image_size(s, 160, 90);
  SceneModel m(s);
  const int N = 1024;
  const LeanMapRegion r = lean_map_region(m, N, 0.0);
  ASSERT_FALSE(r.empty);
  EXPECT_DOUBLE_EQ(r.texel, min_footprint_side(m));
  EXPECT_GT(r.far, 10.0);
  int inside = 0, beyond = 0;
  for (int j = 0; j < m.height(); ++j) {
    for (int i = 0; i < m.width(); ++i) {
      const PixelFootprint fp = pixel_footprint(m, i + 0.5, j + 0.5, 0.0);
      if (!fp.hit) continue;
      // Every footprint side is at least a texel: the level of detail is >= 0.
      EXPECT_GE(length(vec2(fp.dp_dpx.x, fp.dp_dpx.z)), r.texel * (1 - 1e-12));
      EXPECT_GE(length(vec2(fp.dp_dpy.x, fp.dp_dpy.z)), r.texel * (1 - 1e-12));
      const vec2 xz(fp.point.x, fp.point.z), c(m.camera.position().x, m.camera.position().z);
      const vec2 st = r.to_texels(xz);
      const bool in_map = st.x >= 0 && st.y >= 0 && st.x <= N && st.y <= N;
      if (length(xz - c) <= r.far) {
        EXPECT_TRUE(in_map) << i << "," << j;
        ++inside;
      } else {
        beyond += !in_map;
      }
    }
  }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(beyond, 100);  // the horizon lies beyond the map
}

TEST(Lean, WavesTheTexelGridCannotSampleGoToTheBaseRoughness) {
  // Waves above 0.5 cycles per texel (along x or z) are left out of the map; their Eq. 3
  // covariance is the base term. The `high` scene's short waves (down to 8 cm) do not fit
  // a 10 cm texel.
  Scene s = testing::project_scene("high");
  set_image_size(s, 160, 90);
  SceneModel m(s);
  LeanOptions o;
  o.size = 256;
  o.far = 20;
  LeanMethod lean(o);
  FrameContext ctx{m, frame_time(s, 3), 0};
  lean.begin_frame(ctx);
  const double texel = lean.region().texel;
  const kd::LeanParams& p = lean.params();
  const kd::WaveBuffer waves = wave_buffer(lean.inputs());
  const kd::Frame& f = lean.inputs().frame;
  ASSERT_EQ(f.wave_count, static_cast<int>(m.waves.size()));
  int mapped = 0;
  mat2 base(0.0);
  const kd::vec2 xz = kd::lean_texel_centre(p, 10, 20);
  kd::vec2 g(0.0);
  for (int k = 0; k < f.wave_count; ++k) {
    const kd::Wave w = kd::wave_at(waves, f, k);
    const double fr = std::max(std::fabs(w.a), std::fabs(w.b)) * texel / kTwoPi;
    const bool in_map = fr <= 0.5;
    EXPECT_EQ(kd::lean_wave_amplitude(w, texel) != kd::vec2(0.0), in_map) << k;
    mapped += in_map;
    if (in_map) {
      g += kd::wave_gradient_of(w, xz.x, xz.y, 0.0);
    } else {
      base += 0.5 * w.A * w.A * glm::outerProduct(vec2(w.a, w.b), vec2(w.a, w.b));
    }
  }
  EXPECT_GT(mapped, 0);
  EXPECT_LT(mapped, f.wave_count);
  const mat2 got = kd::sym2(p.base);
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b)
      EXPECT_NEAR(got[a][b], base[a][b], 1e-12 * base[1][1] + 1e-18);
  }
  // A texel's slope is the gradient of the mapped waves only.
  EXPECT_NEAR(lean.map().texel(0, 10, 20).B.x, g.x, 1e-6 * (1 + std::fabs(g.x)));
  EXPECT_NEAR(lean.map().texel(0, 10, 20).B.y, g.y, 1e-6 * (1 + std::fabs(g.y)));
}

TEST(Lean, PixelsBeyondTheMapGetTheUniformNdfOfEq3) {
  for (const char* name : {"medium", "high"}) {  // high: a base term as well
    Scene s = testing::project_scene(name);
    set_image_size(s, 160, 90);
    SceneModel m(s);
    LeanOptions o;
    o.size = 256;
    o.far = 20;  // a small map: most of the far water lies beyond it
    LeanMethod lean(o);
    FrameContext ctx{m, frame_time(s, 3), 0};
    lean.begin_frame(ctx);
    std::vector<double> all(m.waves.size(), 1.0);
    const mat2 eq3 = uniform_ndf_covariance(m.waves, all);
    int checked = 0;
    for (int j = 0; j < m.height(); ++j) {
      for (int i = 0; i < m.width(); ++i) {
        const kd::Footprint fp = kd::pixel_footprint(
            wave_buffer(lean.inputs()), lean.inputs().frame, i + 0.5, j + 0.5, 0.0, false);
        if (!fp.hit) continue;
        const vec2 st = (vec2(fp.point.x, fp.point.z) - lean.params().origin) / lean.params().texel;
        // Every tap of the lookup lies outside the map when the footprint centre is further
        // out than the filter's reach (twice the footprint's longer side in texels, plus 2
        // texels of the coarser level's bilinear taps).
        const double side = std::max(length(vec2(fp.dp_dpx.x, fp.dp_dpx.z)),
                                     length(vec2(fp.dp_dpy.x, fp.dp_dpy.z)));
        const double reach = 2 * side / lean.region().texel + 2;
        const double out = std::max({-st.x, -st.y, st.x - o.size, st.y - o.size});
        if (out <= reach) continue;
        const LeanMoments mo = lean.lookup(fp);
        EXPECT_EQ(mo.B, vec2(0.0));
        const mat2 cov = kd::lean_covariance(mo) + kd::sym2(lean.params().base);
        for (int a = 0; a < 2; ++a) {
          for (int b = 0; b < 2; ++b)
            EXPECT_NEAR(cov[a][b], eq3[a][b], 1e-7 * eq3[1][1]);
        }
        EXPECT_NEAR(lean.shade(ctx, i, j),
                    grey_value(m, to_weights(kd::ndf_lobe_weights(lean.inputs().frame, fp.view,
                                                                  vec2(0), eq3))),
                    1e-9);
        ++checked;
      }
    }
    EXPECT_GT(checked, 200) << name;
  }
}

TEST(Lean, CalmWaterIsThePointSampleOfTheMirroredDisk) {
  // All amplitudes 0: the map holds zero slopes and no spread, the NDF is a single normal,
  // and LEAN's value is 1 when the pixel centre's reflection lies in the light's cone, else
  // 0. Within that approximation (no coverage below a pixel), pixels that the analytic
  // mirrored disk covers fully or not at all match exactly, and the window's total matches
  // the disk's area to within the pixels its edge crosses.
  Scene s = testing::small_scene({Wave{0.0, {0.3, -1.2}, 3.4, 0.0}}, 640, 360);
  s.light.angular_radius_deg = 0.6;
  SceneModel m(s);
  LeanOptions o;
  o.size = 512;
  LeanMethod lean(o);
  PointMethod point;
  FrameContext ctx{m, frame_time(s, 3), 0};
  lean.begin_frame(ctx);
  point.begin_frame(ctx);
  double cx, cy;
  ASSERT_TRUE(m.camera.project(vec3(m.light.L.x, -m.light.L.y, m.light.L.z), cx, cy));
  const int i0 = static_cast<int>(cx) - 5, j0 = static_cast<int>(cy) - 5, n = 11;
  double sum = 0, exact_sum = 0;
  int partial = 0;
  for (int j = j0; j < j0 + n; ++j) {
    for (int i = i0; i < i0 + n; ++i) {
      const double v = lean.shade(ctx, i, j), exact = testing::analytic_calm_coverage(m, i, j);
      EXPECT_EQ(v, point.shade(ctx, i, j)) << i << "," << j;
      if (exact < 1e-9 || exact > 1 - 1e-9) {
        EXPECT_NEAR(v, exact, 1e-9) << i << "," << j;
      } else {
        ++partial;
      }
      sum += v;
      exact_sum += exact;
    }
  }
  EXPECT_GT(partial, 8);
  EXPECT_NEAR(sum, exact_sum, 0.5 * partial);
}

TEST(Lean, LongWavesAgreeWithSupersamplingAtTheFrameTime) {
  // Two long waves (7 and 10 m) and a broad light (2 degrees): LEAN's filtered slopes follow
  // the footprints, so it must be much closer than point sampling to spatial supersampling
  // at t_f (12 x 12 samples), the quantity it approximates. The rest is LEAN's Gaussian:
  // glint edges are blurred, and near the horizon, where footprints span wavelengths, its
  // tails reach the light where the bounded slopes of a sine cannot. Measured RMSE: point
  // 0.0216, trilinear 0.0118, aniso 0.0054.
  Scene s = testing::small_scene(
      {Wave{0.06, {0.25, -0.6}, 2.0, 0.3}, Wave{0.03, {-0.5, -0.9}, 2.9, 1.1}}, 160, 90);
  s.light.angular_radius_deg = 2;
  SceneModel m(s);
  StratifiedMethod ss("supersample", StratifiedSettings{{12, 12, 1}, true});
  PointMethod point;
  const Image truth = render_frame(m, ss, 4, RenderSettings{});
  const double point_rmse = compare_rmse(render_frame(m, point, 4, RenderSettings{}), truth);
  double rmse[2];
  for (LeanFilter f : {LeanFilter::trilinear, LeanFilter::aniso}) {
    LeanOptions o;
    o.size = 1024;
    o.filter = f;
    LeanMethod lean(o);
    rmse[f == LeanFilter::aniso] = compare_rmse(render_frame(m, lean, 4, RenderSettings{}), truth);
  }
  std::printf("long waves, RMSE against supersampling: point %.4f, trilinear %.4f, aniso %.4f\n",
              point_rmse, rmse[0], rmse[1]);
  EXPECT_LT(rmse[0], 0.7 * point_rmse);
  EXPECT_LT(rmse[1], 0.35 * point_rmse);
}

TEST(Lean, SharedScenesRenderWithoutNanOrInf) {
  for (const char* name : {"simple", "smooth", "medium", "high"}) {
    for (bool displaced : {false, true}) {
      Scene s = testing::project_scene(name);
      if (displaced) s = testing::displaced_variant(s);
      // Displaced high-frequency water is slow to intersect: a smaller image.
      set_image_size(s, displaced ? 64 : 160, displaced ? 36 : 90);
      SceneModel m(s);
      LeanOptions o;
      o.size = 512;
      o.filter = displaced ? LeanFilter::aniso : LeanFilter::trilinear;
      LeanMethod lean(o);
      double total = 0;
      render_frames(m, lean, 0, 1, RenderSettings{}, [&](int, const Image& img) {
        for (float v : img.data) {
          ASSERT_TRUE(std::isfinite(v)) << name;
          ASSERT_GE(v, 0.0f);
          total += v;
        }
      });
      EXPECT_GT(total, 0.0) << name;
    }
  }
}

TEST(Lean, RejectsBadOptions) {
  LeanOptions o;
  o.size = 1000;
  EXPECT_THROW(LeanMethod lean(o), Error);
  o.size = 1024;
  o.far = -1;
  EXPECT_THROW(LeanMethod lean(o), Error);
}

}  // namespace
}  // namespace sg
