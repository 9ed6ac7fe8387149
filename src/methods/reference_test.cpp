// The reference estimator (methods/reference.h, kernel/reference.glsl).
//  - Its pieces: the Hermite path within its error bound, the roots of degree-6
//    polynomials, the light's conic equal to the disk test.
//  - Exact time integration against dense time sampling of the same water point, on one-,
//    few- and 64-wave scenes: paths through the disk, paths that enter and leave it many
//    times in one shutter, paths tangent to its rim (inside and outside), paths that cross
//    the horizon, with Fresnel and a sky gradient.
//  - The pixel estimate against the stratified estimator at high sample counts on every
//    shared scene, and against calm water's analytic value, within the standard errors.
//  - Determinism: threads, tiles and seeds.
// The standard error's estimate against 16 seeds is in reference_noise_test.cpp (slow).
#include "methods/reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "base/error.h"
#include "engine/render.h"
#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"
#include "math/rng.h"
#include "methods/kernel_inputs.h"
#include "methods/stratified.h"
#include "shading/kernel_frame.h"
#include "testing/calm_water.h"
#include "testing/testing.h"

namespace sg {
namespace {

// ---------------------------------------------------------------- pieces of the kernel

TEST(ReferenceKernel, PolynomialRootsAreFoundInOrder) {
  // (s - r1)...(s - r6) scaled, with roots in and out of (0, 1), some close together.
  const double sets[][6] = {{0.1, 0.35, 0.5, 0.9, 1.5, -0.2},
                            {0.3, 0.300001, 0.7, 2.0, 3.0, -1.0},
                            {0.25, 0.5, 0.75, 0.125, 0.875, 0.99},
                            {-0.5, 1.2, 1.3, 2.0, 5.0, -3.0}};
  for (const auto& r : sets) {
    kd::Poly6 p;
    for (double& c : p.c)
      c = 0;
    p.c[0] = 1e-5;  // scaled like the conic's values
    for (int k = 0; k < 6; ++k) {
      // multiply by (s - r[k])
      for (int j = 6; j >= 1; --j)
        p.c[j] = p.c[j - 1] - r[k] * p.c[j];
      p.c[0] = -r[k] * p.c[0];
    }
    std::vector<double> want;
    for (double x : r) {
      if (x > 0 && x < 1) want.push_back(x);
    }
    std::sort(want.begin(), want.end());
    const kd::Roots6 got = kd::poly6_roots(p);
    ASSERT_EQ(got.count, static_cast<int>(want.size())) << r[0];
    for (int k = 0; k < got.count; ++k)
      EXPECT_NEAR(got.s[k], want[k], 1e-9) << k;
  }
}

TEST(ReferenceKernel, ConicEqualsTheDiskTest) {
  // Q(g) >= 0 exactly where the reflection of v about g's normal is in the disk, and
  // R(g) > 0 where it is above the horizon, for random views and gradients.
  Pcg32 rng(4, 1);
  kd::Light l;
  for (int q = 0; q < 20000; ++q) {
    const double rho = q % 2 ? 0.0047 : 0.05;
    vec3 L = normalize(vec3(rng.uniform() - 0.5, 0.05 + 0.4 * rng.uniform(), -1.0));
    vec3 v = normalize(vec3(0.3 * (rng.uniform() - 0.5), 0.02 + rng.uniform(), 1.0));
    if (q % 5 == 0) {  // a light at the horizon seen at grazing angles: Q about g = 0
      L = normalize(vec3(0.2 * (rng.uniform() - 0.5), -0.002 * rng.uniform(), -1.0));
      v = normalize(vec3(0.1 * (rng.uniform() - 0.5), 0.001 * rng.uniform(), 1.0));
    }
    l.L = L;
    l.radius = rho;
    l.cos_radius = std::cos(rho);
    l.sin_radius = std::sin(rho);
    l.chord2 = 4 * sqr(std::sin(0.5 * rho));
    const kd::LightConic c = kd::light_conic(l, v);
    // Gradients near the one that mirrors v onto L, and far.
    const double spread = q % 3 == 0 ? 1.0 : 3 * rho;
    const vec2 g = c.centre + spread * vec2(rng.uniform() - 0.5, rng.uniform() - 0.5);
    const vec3 m = kd::normal_direction(g);
    const vec3 r = 2 * dot(m, v) / dot(m, m) * m - v;
    const double d = length(r - L) - std::sqrt(l.chord2);
    if (std::abs(d) > 1e-9) {
      EXPECT_EQ(kd::conic_q(c, g) >= 0, d <= 0) << q;
    }
    if (std::abs(r.y) > 1e-12) {
      EXPECT_EQ(kd::horizon_r(v, g) > 0, r.y > 0) << q;
    }
  }
}

// A frame of `s` with the light moved to direction L and radius rho.
void set_light(kd::Frame& f, const vec3& L, double rho) {
  f.light.L = normalize(L);
  f.light.radius = rho;
  f.light.cos_radius = std::cos(rho);
  f.light.sin_radius = std::sin(rho);
  f.light.tan_radius = std::tan(rho);
  f.light.chord2 = 4 * sqr(std::sin(0.5 * rho));
}

struct PathCase {
  KernelInputsD in;
  vec3 point, view;
};

// The inputs of frame `frame` of `s` with K sub-intervals and the water point seen
// through image point (px, py).
// Aims c at the water point seen through image point (px, py).
void aim(PathCase& c, double px, double py) {
  const vec3 d = normalize(kd::camera_direction(c.in.frame.camera, px, py));
  const kd::RayHit hit = kd::intersect_flat(c.in.frame.camera.position, d);
  EXPECT_TRUE(hit.hit);
  c.point = hit.point;
  c.view = -d;
}

PathCase path_case(const Scene& s, int frame, int K, double px, double py) {
  const SceneModel m(s);
  PathCase c;
  build_kernel_inputs(m, frame_time(s, frame), K, 0, c.in);
  aim(c, px, py);
  return c;
}

// The time average of the weights at c.point by N midpoint samples of the exact gradient.
RadianceWeights dense_average(const PathCase& c, int N) {
  const kd::Frame& f = c.in.frame;
  const kd::WaveBuffer w = wave_buffer(c.in, false);
  RadianceWeights sum(0.0);
  for (int q = 0; q < N; ++q) {
    const double dt = -f.duration + (q + 0.5) / N * f.duration;
    const vec2 g = kd::wave_sum_gradient(w, f, c.point.x, c.point.z, dt);
    sum += kd::water_weights(f, kd::normal_direction(g), c.view);
  }
  return sum / double(N);
}

// The exact one, with the kernel's loops or the vectorised sums.
RadianceWeights exact_average(const PathCase& c, bool vectorised = false) {
  const kd::WaveBuffer w = wave_buffer(c.in, vectorised);
  const kd::PathDerivatives p = kd::path_derivatives(w, c.in.frame, c.point, 0.0);
  return kd::path_time_weights(c.in.frame, c.view, p);
}

// The reflection at c.point at time offset dt.
vec3 reflection_at(const PathCase& c, double dt) {
  const vec2 g =
      kd::wave_sum_gradient(wave_buffer(c.in, false), c.in.frame, c.point.x, c.point.z, dt);
  const vec3 m = kd::normal_direction(g);
  return 2 * dot(m, c.view) / dot(m, m) * m - c.view;
}

// Counts the entries into the disk along the dense samples.
int entries(const PathCase& c, int N) {
  int n = 0;
  bool inside = false;
  for (int q = 0; q < N; ++q) {
    const double dt = -c.in.frame.duration + (q + 0.5) / N * c.in.frame.duration;
    const bool now = kd::light_contains(c.in.frame.light, normalize(reflection_at(c, dt)));
    n += now && !inside;
    inside = now;
  }
  return n;
}

Scene one_wave() {
  return testing::small_scene({Wave{0.05, {0.3, -1.2}, 3.4, 0.4}}, 160, 90);
}
Scene few_waves() {
  return testing::small_scene(
      {Wave{0.05, {0.3, -1.2}, 3.4, 0.4}, Wave{0.02, {-1.5, -0.8}, 4.1, 2.0},
       Wave{0.01, {2.5, -2.5}, 6.0, 5.0}},
      160, 90);
}
Scene many_waves() {
  Scene s = testing::project_scene("smooth");  // 64 waves
  s.width = 160;
  s.height = 90;
  return s;
}

// Light share and the other weights: exact against 400 000 dense samples, whose error is
// at most (crossings + 1) / N on each weight.
void expect_exact_matches_dense(const PathCase& c, const char* what, int min_entries = 1) {
  const int N = 400000;
  const RadianceWeights dense = dense_average(c, N);
  const RadianceWeights exact = exact_average(c);
  const RadianceWeights simd = exact_average(c, true);
  const int n = entries(c, 20000);
  EXPECT_GE(n, min_entries) << what;
  const double tol = 2.0 * (2 * n + 2) / N + 1e-9;
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(exact[k], dense[k], tol) << what << " weight " << k << " entries " << n;
    EXPECT_NEAR(simd[k], exact[k], 1e-9) << what << " weight " << k;
  }
}

TEST(ExactTime, HermitePathIsWithinItsBound) {
  Scene high = testing::project_scene("high");
  high.width = 160;
  high.height = 90;
  for (const Scene& s : {one_wave(), few_waves(), many_waves(), high}) {
    const SceneModel m(s);
    const double D = frame_time(s, 5).duration();
    for (int K : {1, 2, 4, reference_segments(m, D)}) {
      PathCase c = path_case(s, 5, K, 80.3, 40.7);
      const kd::PathDerivatives p =
          kd::path_derivatives(wave_buffer(c.in, false), c.in.frame, c.point, 0.0);
      const double bound = reference_path_error_bound(m, D, K);
      double worst = 0;
      const double h = D / K;
      for (int k = 0; k < K; ++k) {
        const kd::HermitePath H = kd::hermite_path(p.g[k], p.dg[k], p.g[k + 1], p.dg[k + 1], h);
        for (int q = 0; q <= 200; ++q) {
          const double sv = q / 200.0;
          const double dt = -D + (k + sv) * h;
          const vec2 g =
              kd::wave_sum_gradient(wave_buffer(c.in, false), c.in.frame, c.point.x, c.point.z, dt);
          worst = std::max(worst, length(kd::hermite_at(H, sv) - g));
        }
      }
      EXPECT_LE(worst, bound + 1e-13) << s.name << " K " << K;
      EXPECT_GT(worst, 1e-3 * bound) << s.name << " K " << K;  // the bound is not vacuous
    }
  }
}

TEST(ExactTime, ChoosesSegmentsFromTheBound) {
  for (const char* name : {"simple", "smooth", "medium", "high"}) {
    const SceneModel m(testing::project_scene(name));
    const double D = frame_time(m.scene, 0).duration();
    const int K = reference_segments(m, D);
    EXPECT_LE(reference_path_error_bound(m, D, K), kReferencePathTolerance * m.light.radius);
    if (K > 1) {
      EXPECT_GT(reference_path_error_bound(m, D, K - 1), kReferencePathTolerance * m.light.radius);
    }
  }
}

// A shutter of many periods of the waves: kMaxSegments sub-intervals over the whole of it
// cannot meet the bound, so the reference cuts it into the fewest windows that do.
Scene long_shutter() {
  Scene s = few_waves();
  s.animation.fps = 0.05;  // a 20 s shutter: 11 to 19 periods of each wave
  s.animation.shutter = 1.0;
  return s;
}

TEST(ExactTime, SplitsALongShutterIntoWindowsWithinTheBound) {
  const SceneModel m(long_shutter());
  const double D = frame_time(m.scene, 3).duration(),
               tol = kReferencePathTolerance * m.light.radius;
  const ReferenceTimeSplit split = reference_time_split(m, D);
  EXPECT_EQ(split.segments, kd::kMaxSegments);
  ASSERT_GT(split.windows, 1);
  EXPECT_LE(reference_path_error_bound(m, D / split.windows, split.segments), tol);
  EXPECT_GT(reference_path_error_bound(m, D / (split.windows - 1), split.segments), tol);
  // Short shutters take one window; displaced water traces each sample at its own time.
  EXPECT_EQ(reference_time_split(SceneModel(few_waves()), D / 1000).windows, 1);
  EXPECT_EQ(reference_time_split(SceneModel(testing::displaced_variant(long_shutter())), D).windows,
            1);
}

// A light disk centred on the reflection at time offset dt, of radius rho.
void centre_light_on(PathCase& c, double dt, double rho) {
  set_light(c.in.frame, normalize(reflection_at(c, dt)), rho);
}

TEST(ExactTime, MatchesDenseSamplingThroughTheDisk) {
  struct Case {
    Scene s;
    double px, py;
  };
  for (const auto& [s, px, py] :
       {Case{one_wave(), 80.5, 60.5}, Case{few_waves(), 30.2, 50.1},
        Case{many_waves(), 100.7, 70.3}, Case{many_waves(), 20.1, 48.9}}) {
    const SceneModel m(s);
    for (int K : {1, 3, reference_segments(m, frame_time(s, 2).duration())}) {
      PathCase c = path_case(s, 2, K, px, py);
      centre_light_on(c, -0.4 * c.in.frame.duration, 0.0047);
      expect_exact_matches_dense(c, (s.name + " K " + std::to_string(K)).c_str());
    }
  }
}

TEST(ExactTime, MatchesDenseSamplingWithManyEntriesInOneShutter) {
  // One fast wave over a long shutter: the normal swings back and forth along a line
  // through the disk; two waves: Lissajous loops through it.
  for (int waves : {1, 2}) {
    std::vector<Wave> w{Wave{0.004, {1.0, -3.0}, 24.0, 0.3}};
    if (waves == 2) w.push_back(Wave{0.003, {-2.5, -1.0}, 17.0, 1.1});
    Scene s = testing::small_scene(w, 160, 90);
    s.animation.shutter = 1.0;
    s.animation.fps = 2;  // a half-second shutter: several periods
    const double D = frame_time(s, 1).duration();
    s.light.angular_radius_deg = 0.03 * 180 / kPi;
    const int K = reference_segments(SceneModel(s), D);
    PathCase c = path_case(s, 1, K, 80.5, 60.5);
    ASSERT_LE(reference_path_error_bound(SceneModel(s), D, K), kReferencePathTolerance * 0.03);
    centre_light_on(c, -0.5 * D, 0.03);
    expect_exact_matches_dense(c, ("many entries, waves " + std::to_string(waves)).c_str(), 3);
  }
}

TEST(ExactTime, MatchesDenseSamplingTangentToTheRim) {
  // The disk placed so that its rim touches the path at one instant (the path's direction
  // there tangent to the rim), then moved by 1e-3 of its radius inwards and outwards.
  for (const Scene& s : {one_wave(), few_waves(), many_waves()}) {
    for (double shift : {-1e-3, 0.0, 1e-3}) {
      PathCase c = path_case(s, 2, 4, 60.5, 55.5);
      const double D = c.in.frame.duration, dt = -0.55 * D, rho = 0.0047;
      const vec3 r = normalize(reflection_at(c, dt));
      const vec3 dr = normalize(reflection_at(c, dt + 1e-6) - reflection_at(c, dt - 1e-6));
      const vec3 side = normalize(cross(r, dr));  // perpendicular to the path, on the sphere
      const double a = rho * (1 + shift);
      set_light(c.in.frame, std::cos(a) * r + std::sin(a) * side, rho);
      const RadianceWeights dense = dense_average(c, 400000), exact = exact_average(c);
      EXPECT_NEAR(exact.x, dense.x, 2e-5) << s.name << " shift " << shift;
      EXPECT_NEAR(exact.z, dense.z, 2e-5) << s.name << " shift " << shift;
    }
  }
}

TEST(ExactTime, MatchesDenseSamplingWithFresnelSkyGradientAndHorizon) {
  // Far water seen at grazing angles: the reflection dips below the horizon and back.
  for (const Scene& base : {few_waves(), many_waves()}) {
    int crossing = 0;
    for (double py : {40.5, 41.5, 43.5, 47.5}) {
      for (double px : {10.5, 50.5, 90.5, 130.5}) {
        PathCase c = path_case(base, 4, 4, px, py);
        c.in.frame.fresnel = 1;
        c.in.frame.sky_gradient = true;
        c.in.frame.sky_exponent = 0.6;
        centre_light_on(c, -0.3 * c.in.frame.duration, 0.01);
        const RadianceWeights dense = dense_average(c, 200000), exact = exact_average(c);
        crossing += dense.w > 0.01 && dense.w < 0.99 && dense.z > 0.001;
        for (int k = 0; k < 4; ++k)
          EXPECT_NEAR(exact[k], dense[k], 1e-4) << base.name << " " << px << "," << py << " w" << k;
      }
    }
    EXPECT_GT(crossing, 0) << base.name;  // some paths cross the horizon
  }
}

TEST(ExactTime, MatchesDenseSamplingAtRandomPointsOfTheSharedScenes) {
  // Water points of the glitter of each shared scene, at their own light: every point
  // whose path comes near the disk, against 20 000 dense samples.
  for (const char* name : {"simple", "smooth", "medium", "high"}) {
    Scene s = testing::project_scene(name);
    s.width = 160;
    s.height = 90;
    const SceneModel m(s);
    const int K = reference_segments(m, frame_time(s, 6).duration());
    Pcg32 rng(7, 2);
    int lit = 0;
    PathCase c = path_case(s, 6, K, 80, 60);
    for (int q = 0; q < 20000 && lit < 40; ++q) {
      aim(c, 60 + 40 * rng.uniform(), 42 + 48 * rng.uniform());
      const RadianceWeights exact = exact_average(c);
      const RadianceWeights coarse = dense_average(c, 40);
      if (exact.x == 0 && coarse.x == 0) continue;
      ++lit;
      const int N = 20000;
      const RadianceWeights dense = dense_average(c, N);
      const int n = entries(c, N);
      EXPECT_NEAR(exact.x, dense.x, (2.0 * n + 2) / N) << name << " point " << q;
    }
    EXPECT_GE(lit, 10) << name;
  }
}

TEST(ExactTime, FloatKernelAgreesWithDouble) {
  // The whole frame at 160x90: the float images' difference from the double ones is small
  // beside the estimate's own noise (float flips a few samples at the rim, and at the
  // horizon, where the hit points are kilometres away, its phases lose digits).
  for (const char* name : {"smooth", "high"}) {
    Scene s = testing::project_scene(name);
    s.width = 160;
    s.height = 90;
    const SceneModel m(s);
    ReferenceMethod d(ReferenceSettings{{4, 4, 1}, 2}, Precision::float64);
    ReferenceMethod f(ReferenceSettings{{4, 4, 1}, 2}, Precision::float32);
    const Image a = render_frame(m, d, 3, {}), b = render_frame(m, f, 3, {});
    double diff = 0;
    for (size_t k = 0; k < a.size(); ++k)
      diff += sqr(double(a.data[k]) - b.data[k]);
    diff = std::sqrt(diff / a.size());
    const double se = image_standard_error(*d.pixel_variance());
    std::printf("%s: float against double RMSE %.3g, the estimate's standard error %.3g\n", name,
                diff, se);
    EXPECT_GT(se, 0);
    EXPECT_LT(diff, 0.1 * se) << name;
  }
}

// ---------------------------------------------------------------- the pixel estimate

// Mean and variance of the mean of pixel values over seeds.
struct Estimate {
  double mean = 0, var = 0;
};

TEST(ReferenceEstimator, AgreesWithStratifiedSamplingOnTheSharedScenes) {
  // The 16x8 window with the most light of each scene at 160x90: the new estimator at
  // 16x16x1 x 8 batches against the stratified one at 8x8x8 over 8 seeds. Glints make
  // single pixels' distributions skewed and their variance estimates heavy-tailed, so the
  // comparison is on sums over 4x4 blocks: each within 5 combined standard errors, their
  // chi-square below 3 per block (7 degrees of freedom per variance estimate: its mean is
  // about 1.4), and the window's total within 4 standard errors.
  for (const char* name : {"simple", "smooth", "medium", "high"}) {
    Scene s = testing::project_scene(name);
    s.width = 160;
    s.height = 90;
    const SceneModel m(s);
    const FrameContext ctx{m, frame_time(s, 7), 0};
    ReferenceMethod coarse(ReferenceSettings{{2, 2, 1}, 2});
    coarse.begin_frame(ctx);
    int best_i = 0, best_j = 0;
    double best = -1;
    for (int j = 40; j + 8 <= 90; j += 4) {
      for (int i = 0; i + 16 <= 160; i += 8) {
        double sum = 0;
        for (int y = j; y < j + 8; ++y) {
          for (int x = i; x < i + 16; ++x)
            sum += grey_value(m, coarse.weights(ctx, x, y));
        }
        if (sum > best) best = sum, best_i = i, best_j = j;
      }
    }
    ASSERT_GT(best, 0.05) << name;
    ReferenceMethod ref(ReferenceSettings{{16, 16, 1}, 8});
    ref.begin_frame(ctx);
    std::vector<std::unique_ptr<KernelFrameInputs>> strat;
    const int seeds = 8;
    for (int k = 0; k < seeds; ++k) {
      strat.push_back(std::make_unique<KernelFrameInputs>(1, Precision::float64));
      strat.back()->build(FrameContext{m, ctx.time, uint64_t(100 + k)});
    }
    // Sums over 4x4 blocks of pixels (less skewed than single pixels) and the window.
    double chi2 = 0, total = 0, total_var = 0;
    int blocks = 0, lit = 0;
    for (int bj = best_j; bj < best_j + 8; bj += 4) {
      for (int bi = best_i; bi < best_i + 16; bi += 4) {
        double d = 0, var = 0;
        for (int j = bj; j < bj + 4; ++j) {
          for (int i = bi; i < bi + 4; ++i) {
            const ReferencePixel p = ref.pixel(ctx, i, j);
            std::vector<double> v;
            double mean = 0, svar = 0;
            for (int k = 0; k < seeds; ++k) {
              v.push_back(grey_value(
                  m, stratified_pixel(*strat[k], i, j, StratifiedSettings{{8, 8, 8}, false})));
              mean += v.back() / seeds;
            }
            for (double x : v)
              svar += sqr(x - mean) / (seeds * (seeds - 1));
            d += grey_value(m, p.weights) - mean;
            var += p.variance(m.radiances, 0) + svar;
            lit += p.weights.x > 0;
          }
        }
        total += d;
        total_var += var;
        if (var > 0) {
          EXPECT_LT(std::abs(d), 5 * std::sqrt(var) + 1e-7) << name << " block " << bi << "," << bj;
          chi2 += d * d / var;
          ++blocks;
        } else {
          EXPECT_NEAR(d, 0, 1e-9) << name << " block " << bi << "," << bj;
        }
      }
    }
    std::printf(
        "%s: window %d,%d, %d lit pixels: blocks' chi2 %.1f over %d, total difference "
        "%.3g (standard error %.3g)\n",
        name, best_i, best_j, lit, chi2, blocks, total, std::sqrt(total_var));
    EXPECT_GE(lit, 8) << name;
    EXPECT_LT(chi2, 3.0 * blocks) << name;
    EXPECT_LT(std::abs(total), 4 * std::sqrt(total_var)) << name;
  }
}

TEST(ReferenceEstimator, CalmWaterEqualsAnalyticCoverage) {
  Scene s = testing::small_scene({Wave{0.0, {0.3, -1.2}, 3.4, 0.0}}, 640, 360);
  s.light.angular_radius_deg = 0.6;  // a disk about 5 pixels across
  const SceneModel m(s);
  double cx, cy;
  ASSERT_TRUE(m.camera.project(vec3(m.light.L.x, -m.light.L.y, m.light.L.z), cx, cy));
  const int i0 = static_cast<int>(cx) - 5, j0 = static_cast<int>(cy) - 5, n = 11;
  const FrameContext ctx{m, frame_time(s, 3), 0};
  ReferenceMethod ref(ReferenceSettings{{12, 12, 1}, 8});
  ref.begin_frame(ctx);
  double sum = 0, sum_exact = 0, var_sum = 0;
  int partial = 0;
  for (int j = j0; j < j0 + n; ++j) {
    for (int i = i0; i < i0 + n; ++i) {
      const ReferencePixel p = ref.pixel(ctx, i, j);
      const double v = grey_value(m, p.weights), var = p.variance(m.radiances, 0);
      const double exact = testing::analytic_calm_coverage(m, i, j);
      EXPECT_NEAR(v, exact, 5 * std::sqrt(var) + 1e-9) << i << "," << j;
      sum += v;
      sum_exact += exact;
      var_sum += var;
      partial += exact > 0 && exact < 1;
    }
  }
  EXPECT_GT(partial, 8);
  EXPECT_GT(sum_exact, 10);
  EXPECT_NEAR(sum, sum_exact, 5 * std::sqrt(var_sum));
}

// The shutter's windows (kernel/reference.glsl): each sample integrates one window drawn
// at random, which keeps the estimate unbiased. Before the windows the path's Hermite
// interpolation over 32 sub-intervals of many periods swung far past the water's slopes:
// on a random scene of this kind the water came out at 0.2 of its value.
TEST(ReferenceEstimator, LongShutterAgreesWithStratifiedSampling) {
  Scene s = long_shutter();
  s.width = 80;
  s.height = 45;
  s.surface.fresnel = FresnelMode::schlick;
  s.surface.sea_radiance = Rgb(0.05);
  s.sky = SkyDesc{Rgb(1.0), Rgb(0.2), 0.5, true};
  const SceneModel m(s);
  const FrameContext ctx{m, frame_time(s, 3), 0};
  ReferenceMethod ref(ReferenceSettings{{4, 4, 4}, 4});
  ref.begin_frame(ctx);
  KernelFrameInputs in(1, Precision::float64);
  in.build(ctx);
  double sum_ref = 0, sum_strat = 0, var = 0, light = 0;
  for (int j = 23; j < 45; j += 3) {
    for (int i = 0; i < 80; i += 5) {
      const ReferencePixel p = ref.pixel(ctx, i, j);
      sum_ref += grey_value(m, p.weights);
      light += p.weights.x;
      var += p.variance(m.radiances, 0);
      sum_strat += grey_value(m, stratified_pixel(in, i, j, StratifiedSettings{{8, 8, 64}, false}));
    }
  }
  EXPECT_GT(ref.windows(), 1);
  EXPECT_GT(light, 0.01);  // some of the light's glitter is in the sum
  EXPECT_NEAR(sum_ref, sum_strat, 5 * std::sqrt(var) + 2e-3 * sum_strat);
}

TEST(ReferenceEstimator, DisplacedWaterAgreesWithStratifiedSampling) {
  Scene s = testing::displaced_variant(few_waves());
  s.width = 80;
  s.height = 45;
  const SceneModel m(s);
  const FrameContext ctx{m, frame_time(s, 2), 0};
  ReferenceMethod ref(ReferenceSettings{{4, 4, 4}, 4});
  ref.begin_frame(ctx);
  // The same displaced intersection for both (the reference's: every wave), so that only
  // the estimators differ.
  KernelFrameInputs in(1, Precision::float64, 0.0);
  in.build(ctx);
  double sum_ref = 0, sum_strat = 0, var = 0;
  for (int j = 20; j < 45; j += 3) {
    for (int i = 0; i < 80; i += 5) {
      const ReferencePixel p = ref.pixel(ctx, i, j);
      sum_ref += grey_value(m, p.weights);
      var += p.variance(m.radiances, 0);
      sum_strat +=
          grey_value(m, stratified_pixel(in, i, j, StratifiedSettings{{16, 16, 8}, false}));
    }
  }
  EXPECT_GT(sum_ref, 1.0);
  // The stratified total's own noise is far below the reference's at these counts.
  EXPECT_NEAR(sum_ref, sum_strat, 5 * std::sqrt(var) + 1e-3 * sum_strat);
}

// A study's reference renders each batch of a frame alone (ReferenceSettings::only_batch):
// batch b alone has exactly the samples of batch b in a render of all batches, on flat and
// displaced water, in double and float, busy and quiet pixels alike.
TEST(ReferenceEstimator, OneBatchAloneEqualsThatBatchOfTheWhole) {
  for (const bool displaced : {false, true}) {
    Scene s = displaced ? testing::displaced_variant(few_waves()) : few_waves();
    s.width = 40;
    s.height = 24;
    const SceneModel m(s);
    const FrameContext ctx{m, frame_time(s, 2), 5};
    for (const Precision p : {Precision::float64, Precision::float32}) {
      ReferenceMethod all(ReferenceSettings{{2, 2, 2}, 3}, p);
      all.begin_frame(ctx);
      ReferenceSettings one_rs{{2, 2, 2}, 3};
      std::vector<std::unique_ptr<ReferenceMethod>> one;
      for (int b = 0; b < 3; ++b) {
        one_rs.only_batch = b;
        one.push_back(std::make_unique<ReferenceMethod>(one_rs, p));
        one.back()->begin_frame(ctx);
      }
      int busy = 0;
      for (int j = 0; j < s.height; ++j) {
        for (int i = 0; i < s.width; ++i) {
          const ReferencePixel whole = all.pixel(ctx, i, j);
          busy += whole.busy;
          ASSERT_EQ(whole.batches.size(), 3u);
          for (int b = 0; b < 3; ++b) {
            const ReferencePixel alone = one[b]->pixel(ctx, i, j);
            ASSERT_EQ(alone.batches.size(), 1u);
            for (int k = 0; k < 4; ++k) {
              ASSERT_EQ(alone.weights[k], whole.batches[b][k])
                  << "pixel " << i << "," << j << " batch " << b << " displaced " << displaced;
            }
          }
        }
      }
      EXPECT_GT(busy, 0);
      EXPECT_LT(busy, s.width * s.height);
    }
  }
  ReferenceSettings bad{{2, 2, 1}, 2};
  bad.only_batch = 2;
  EXPECT_THROW(ReferenceMethod{bad}, Error);
}

TEST(ReferenceEstimator, DeterministicAcrossThreadsAndSeeds) {
  Scene s = testing::project_scene("medium");
  s.width = 96;
  s.height = 54;
  const SceneModel m(s);
  ReferenceMethod a(ReferenceSettings{{2, 2, 1}, 2}), b(ReferenceSettings{{2, 2, 1}, 2});
  RenderSettings r1, r2;
  r1.threads = 1;
  r1.tile = 16;
  r2.threads = 2;
  r2.tile = 7;
  const Image x = render_frame(m, a, 4, r1), y = render_frame(m, b, 4, r2);
  EXPECT_EQ(x.data, y.data);
  EXPECT_EQ(a.pixel_variance()->data, b.pixel_variance()->data);
  RenderSettings r3 = r1;
  r3.seed = 9;
  const Image z = render_frame(m, a, 4, r3);
  EXPECT_NE(x.data, z.data);
}

}  // namespace
}  // namespace sg
