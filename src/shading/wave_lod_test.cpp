// Bruneton's filter as the kernel runs it (kernel/bruneton.glsl: the prefix of the wave
// buffer, sorted by |k|, that a pixel keeps, and the buffer's suffix sums for the rest)
// against the filter over every wave in file order, summed on the host: for the footprints
// of real views of generated spectrum oceans (256 and 1024 waves, the waves shuffled), the
// same filtered gradient, filtered height and filtered-out slope covariance as Sec. 3.2's
// weights applied to all the waves (which holds only if every wave past the prefix has
// weight 0: the prefix is not an approximation).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "kernel/kernel_double.h"
#include "math/rng.h"
#include "ocean/ocean.h"
#include "scene/model.h"
#include "shading/kernel_frame.h"
#include "shading/ndf.h"
#include "shading/water_geometry.h"
#include "shading/wave_lod.h"
#include "testing/direct_waves.h"

namespace sg {
namespace {

Scene shuffled_ocean(int waves, double camera_height, int width) {
  ocean::OceanParams p;
  p.waves = waves;
  p.wind_speed = 10;
  p.seed = 5;
  Scene s = ocean::ocean_scene(ocean::plain_template(), ocean::generate(p), "sea");
  s.camera.position.y = camera_height;
  s.width = width;
  s.height = width * 9 / 16;
  Pcg32 rng(11, 2);
  std::vector<Wave>& w = s.surface.waves;
  for (size_t i = w.size(); i-- > 1;)
    std::swap(w[i], w[rng.next_u32() % (i + 1)]);
  return s;
}

struct Agreement {
  double gradient = 0, height = 0, covariance = 0;  // worst relative differences
  double filtered_share = 0;                        // mean share of waves past the prefix
  int pixels = 0;
};

// Bruneton's N_min, N_max (BrunetonOptions' defaults).
constexpr double kNMin = 1, kNMax = 2.5;

// Sec. 3.2's filter of `waves` for footprint J at (x, z, t): the filtered gradient and
// height (weights w) and the filtered-out slope covariance (weights 1 - w).
struct Filtered {
  vec2 gradient;
  double height;
  mat2 covariance;
};

Filtered filter_waves(const WaveField& waves, const mat2& J, const vec3& p, double t) {
  std::vector<double> w, wr;
  wave_lod_weights(waves, J, kNMin, kNMax, w);
  wr.resize(w.size());
  for (size_t k = 0; k < w.size(); ++k)
    wr[k] = 1 - w[k];
  return {testing::direct_gradient(waves, p.x, p.z, t, w),
          testing::direct_height(waves, p.x, p.z, t, w), uniform_ndf_covariance(waves, wr)};
}

Agreement compare_filters(const Scene& s) {
  const SceneModel m(s);
  const WaveField& all = m.waves;  // file (shuffled) order
  const double t = 0.7;
  KernelInputsD in;
  build_kernel_inputs(m, FrameTime{0, t, t}, 1, 0, in, 0.0);
  const kd::WaveBuffer wb = wave_buffer(in);
  kd::BrunetonParams bp{};
  bp.n_min = kNMin;
  bp.n_max = kNMax;
  const vec3 origin(m.camera.position().x, 0.0, m.camera.position().z);
  Agreement a;
  for (int j = 0; j < s.height; j += 3) {
    for (int i = 0; i < s.width; i += 5) {
      const PixelFootprint f = rest_plane_footprint(m, i + 0.5, j + 0.5);
      if (!f.hit) continue;
      const mat2 J = f.xz_jacobian();
      // Every wave, in file order, against the kernel's prefix and suffix sums.
      const Filtered full = filter_waves(all, J, f.point, t);
      const int kept = kd::lod_filtered_from(wb, in.frame, J, kNMin);
      const vec3 p = f.point - origin;  // the kernel's camera-relative point
      const kd::FilteredSlopes sl = kd::filtered_slopes(wb, in.frame, bp, J, kept, p.x, p.z);
      const glm::dvec4 suffix = kd::wave_suffix_moments(wb, in.frame, kept);
      const vec3 c = sl.m.cov + vec3(suffix.x, suffix.y, suffix.z);
      Filtered cut{sl.g,
                   kd::filtered_height_slope(wb, in.frame, bp, J, kept, p.x, p.z, vec2(1, 0)).x,
                   mat2(vec2(c.x, c.y), vec2(c.y, c.z))};
      // Scales: the full slope and height bounds, the covariance's trace.
      const double cs = full.covariance[0][0] + full.covariance[1][1];
      a.gradient = std::max(a.gradient, length(cut.gradient - full.gradient) / all.slope_bound());
      a.height = std::max(a.height, std::fabs(cut.height - full.height) / all.amplitude_bound());
      for (int r = 0; r < 2; ++r)
        for (int q = 0; q < 2; ++q)
          a.covariance =
              std::max(a.covariance, std::fabs(cut.covariance[r][q] - full.covariance[r][q]) / cs);
      a.filtered_share += 1.0 - double(kept) / double(all.size());
      ++a.pixels;
    }
  }
  a.filtered_share /= std::max(a.pixels, 1);
  return a;
}

void expect_prefix_equals_full_sum(int waves, double camera_height, int width, double min_share) {
  const Agreement a = compare_filters(shuffled_ocean(waves, camera_height, width));
  std::printf(
      "%d waves, camera %.1f m, %d pixels wide: %d pixels, %.1f%% of the waves past the prefix; "
      "worst gradient %.2e, height %.2e, covariance %.2e\n",
      waves, camera_height, width, a.pixels, 100 * a.filtered_share, a.gradient, a.height,
      a.covariance);
  ASSERT_GT(a.pixels, 150);
  // Not vacuous: the suffix sums stand for a real share of the waves.
  EXPECT_GT(a.filtered_share, min_share);
  EXPECT_LT(a.gradient, 1e-12);
  EXPECT_LT(a.height, 1e-12);
  EXPECT_LT(a.covariance, 1e-12);
}

TEST(WaveLod, KernelPrefixEqualsTheFullSumOn256Waves) {
  expect_prefix_equals_full_sum(256, 2.5, 160, 0.02);
  expect_prefix_equals_full_sum(256, 20, 80, 0.1);
}

TEST(WaveLod, KernelPrefixEqualsTheFullSumOn1024Waves) {
  expect_prefix_equals_full_sum(1024, 20, 80, 0.1);
}

TEST(WaveLod, SmallestSingularValueAgainstTheEigenvalues) {
  // sigma_min of J is the square root of the smaller eigenvalue of J^T J.
  Pcg32 rng(4, 9);
  for (int n = 0; n < 1000; ++n) {
    mat2 J;
    for (int c = 0; c < 2; ++c)
      for (int r = 0; r < 2; ++r)
        J[c][r] = 4 * rng.uniform() - 2;
    const mat2 M = transpose(J) * J;
    const double tr = M[0][0] + M[1][1], det = determinant(M);
    const double lmin = 0.5 * (tr - std::sqrt(std::max(tr * tr - 4 * det, 0.0)));
    EXPECT_NEAR(smallest_singular_value(J), std::sqrt(std::max(lmin, 0.0)), 1e-9) << n;
  }
}

}  // namespace
}  // namespace sg
