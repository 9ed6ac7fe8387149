// `staa`'s smooth terms over a Gaussian of normals (kernel/smooth_terms.glsl), the cells'
// moments over the footprint (kernel/ndf.glsl) and the horizon's share of a pixel
// (kernel/horizon_coverage.glsl) against brute force. The smooth terms against
// brute force: a dense midpoint grid over the same Gaussian in its standard coordinates,
// with the horizon's indicator evaluated at every cell. Views from grazing (2 degrees) to
// steep, round and elongated spreads, spreads and means across the view (what the
// reduction to one dimension approximates), distributions that the horizon cuts through the
// middle, at its edge and not at all; Schlick's factor with gradient skies of exponents
// 0.5 to 2. Float against double.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"
#include "math/vec.h"

namespace sg {
namespace {

kd::Frame smooth_frame(double exponent) {
  kd::Frame f{};
  f.fresnel = 1;
  f.sky_gradient = true;
  f.sky_exponent = exponent;
  f.light.L = kd::vec3(0, 0.2, -0.98);
  return f;
}

kf::Frame narrow_frame(const kd::Frame& d) {
  kf::Frame f{};
  f.fresnel = d.fresnel;
  f.sky_gradient = d.sky_gradient;
  f.sky_exponent = static_cast<float>(d.sky_exponent);
  f.light.L = kf::vec3(d.light.L);
  return f;
}

// E[F 1{above}], E[F z 1{above}], P(above) over N(mu, A A^T) on an n x n grid over
// [-8, 8]^2 standard deviations.
kd::SmoothTerms brute_smooth(const kd::Frame& f, kd::vec2 mu, kd::mat2 A, kd::vec3 v, int n) {
  kd::SmoothTerms s{0, 0, 0, 0};
  const double h = 16.0 / n;
  for (int a = 0; a < n; ++a) {
    const double u = -8 + (a + 0.5) * h;
    const double pu = std::exp(-0.5 * u * u);
    for (int b = 0; b < n; ++b) {
      const double w = -8 + (b + 0.5) * h;
      const double weight = pu * std::exp(-0.5 * w * w) * h * h / (2 * kPi);
      const kd::vec2 sl = mu + A * kd::vec2(u, w);
      const kd::vec3 m(sl.x, 1, sl.y);
      const kd::vec3 r = kd::reflect_view(normalize(m), v);
      if (r.y <= 0) continue;
      const double F = kd::fresnel_schlick(dot(normalize(m), v));
      s.above += weight;
      s.f_above += weight * F;
      s.f_zenith += weight * F * std::pow(r.y, f.sky_exponent);
      s.f_horizon += weight * F * -std::expm1(f.sky_exponent * std::log(r.y));
    }
  }
  return s;
}

struct Case {
  const char* what;
  double view_deg;  // the view's elevation above the water
  double sigma_along, sigma_across;
  double mean_along;  // the mean slope towards the camera (positive: the normal tilts to it)
  double exponent;
  double mean_across = 0.0;  // the mean slope across the view
  // The bound on the expectations of F, F z and F h, and on the share above. The grid's
  // own error at the horizon's cut is about 1.5e-5 at 1600 cells per side (it halves with
  // twice the cells), the rule's about 1e-5; the rest is the reduction to one dimension
  // (b^2 at its conditional mean), which grows with the spread across the view.
  double bound_f = 6e-5;
  double bound_above = 6e-5;
};

TEST(SmoothTerms, MatchesBruteForceOverTheNormals) {
  const Case cases[] = {
      {"grazing, wide, horizon through the middle", 2, 0.15, 0.12, 0.0, 0.5},
      {"grazing, narrow", 2, 0.02, 0.02, 0.0, 0.5},
      {"grazing, tilted away (mostly below)", 3, 0.08, 0.05, -0.05, 1.0},
      {"low, elongated along the view", 5, 0.2, 0.03, 0.02, 0.5},
      {"low, elongated across", 5, 0.03, 0.2, 0.0, 2.0},
      {"medium", 20, 0.1, 0.1, 0.05, 0.5},
      {"steep, far from the horizon", 60, 0.1, 0.07, 0.0, 0.5},
      {"point distribution", 10, 0.0, 0.0, 0.01, 0.5},
      {"grazing, wide across, tilted across", 3, 0.05, 0.3, 0.01, 0.5, 0.15, 1e-4, 2e-4},
      {"low, wide both ways, tilted across", 8, 0.25, 0.25, -0.03, 1.0, -0.2, 8e-4, 6e-5},
      {"steep, wide both ways", 45, 0.3, 0.3, 0.1, 0.5, 0.1, 3e-4, 5e-3},
  };
  for (const Case& c : cases) {
    const double el = c.view_deg * kPi / 180;
    // The camera is along -z from the water point... the view towards it: (0, sin, cos).
    const kd::vec3 v(0, std::sin(el), std::cos(el));
    const double turn = 0.3;  // the spread's axes turned from the view's plane
    const kd::vec2 along(std::sin(turn), std::cos(turn)), across(-along.y, along.x);
    const kd::mat2 A(c.sigma_along * along, c.sigma_across * across);
    const kd::vec2 mu = c.mean_along * kd::vec2(0, 1) + c.mean_across * kd::vec2(1, 0);
    const kd::Frame f = smooth_frame(c.exponent);
    const kd::SmoothTerms got = kd::smooth_terms(f, mu, A * transpose(A), v);
    const kd::SmoothTerms want = brute_smooth(f, mu, A, v, 1600);
    const double e_f = std::fabs(got.f_above - want.f_above);
    const double e_z = std::fabs(got.f_zenith - want.f_zenith);
    const double e_h = std::fabs(got.f_horizon - want.f_horizon);
    const double e_a = std::fabs(got.above - want.above);
    std::printf("%-45s F %.6f (%.1e)  Fz %.6f (%.1e)  above %.6f (%.1e)\n", c.what, got.f_above,
                e_f, got.f_zenith, e_z, got.above, e_a);
    EXPECT_LT(e_a, c.bound_above) << c.what;
    EXPECT_LT(e_f, c.bound_f) << c.what;
    EXPECT_LT(e_z, c.bound_f) << c.what;
    EXPECT_LT(e_h, c.bound_f) << c.what;
    // The shares sum to F: the zenith's and the horizon's expectations to that of F.
    EXPECT_NEAR(got.f_zenith + got.f_horizon, got.f_above, 1e-12) << c.what;
    // Float (what a GPU computes) against double.
    const kf::SmoothTerms fl = kf::float_smooth_terms(narrow_frame(f), kf::vec2(mu),
                                                      kf::mat2(A * transpose(A)), kf::vec3(v));
    EXPECT_NEAR(fl.f_above, got.f_above, 2e-5) << c.what;
    EXPECT_NEAR(fl.f_zenith, got.f_zenith, 2e-5) << c.what;
    EXPECT_NEAR(fl.f_horizon, got.f_horizon, 2e-5) << c.what;
    EXPECT_NEAR(fl.above, got.above, 2e-5) << c.what;
  }
}

// `staa`'s pixel (staa_smooth_terms) takes the smooth terms of its n x n cells' mixture of
// Gaussians in three groups by the cells' mean slope along the view, each moment-matched
// (kernel/staa.glsl). Against the mixture itself (the mean of each cell's own terms, what
// nine evaluations gave): cells whose means follow a long wave across the pixel, along,
// across and oblique to the view, grazing to steep views. The one moment-matched Gaussian
// of the whole mixture (what the pixel takes where the cells agree) is checked to miss by
// more, so that the groups' bound says something: the groups' worst case is a long wave's
// slopes along a grazing view, whose horizon cuts the mixture.
TEST(SmoothTerms, CellGroupsAlongTheViewKeepTheCellsMixture) {
  struct Case {
    const char* what;
    double view_deg, spread, turn, within, exponent;
  };
  const Case cases[] = {
      {"grazing, a wave's slopes along the view", 3, 0.12, 0.0, 0.03, 0.5},
      {"grazing, oblique", 3, 0.12, 0.7, 0.03, 0.5},
      {"grazing, across the view", 3, 0.15, 1.57, 0.03, 2.0},
      {"low, along, narrow cells", 8, 0.1, 0.2, 0.01, 0.5},
      {"low, oblique, wide", 8, 0.2, 1.0, 0.06, 1.0},
      {"medium, along", 25, 0.25, 0.0, 0.05, 0.5},
  };
  for (const Case& c : cases) {
    const double el = c.view_deg * kPi / 180;
    const kd::vec3 v(0, std::sin(el), std::cos(el));  // the view's horizontal along +z
    kd::Frame f = smooth_frame(c.exponent);
    f.segments = 1;
    kd::StaaParams p{};
    p.smooth_cells = 3;
    kd::StaaSums sums = kd::staa_sums_zero(1);
    // A wave of slope amplitude `spread` whose phase runs across the pixel's 3 x 3 cells,
    // its direction `turn` from the view's; each cell's own spread `within`.
    const kd::vec2 dir(std::sin(c.turn), std::cos(c.turn));
    for (int iu = 0; iu < 3; ++iu) {
      for (int iv = 0; iv < 3; ++iv) {
        const double phase = 0.3 + 1.1 * iu + 0.4 * iv;
        sums.cells.m[iu * 3 + iv].mean = (c.spread * std::sin(phase)) * dir + kd::vec2(0.01, 0.02);
        sums.cells.m[iu * 3 + iv].cov =
            kd::vec3(c.within * c.within, 0.1 * c.within * c.within, 0.7 * c.within * c.within);
      }
    }
    sums.remainder = kd::vec3(1e-4, 0, 1e-4);
    const kd::SmoothTerms got = kd::staa_smooth_terms(f, p, sums, v);
    // The mixture: each cell's terms, the mean of the nine; and the one matched Gaussian.
    kd::SmoothTerms want{0, 0, 0, 0};
    kd::vec2 m_bar(0);
    kd::mat2 w_bar(0), b_bar(0);
    for (int q = 0; q < 9; ++q) {
      const kd::mat2 cov = kd::sym2(sums.cells.m[q].cov) + kd::sym2(sums.remainder);
      const kd::SmoothTerms t = kd::smooth_terms(f, sums.cells.m[q].mean, cov, v);
      want.f_above += t.f_above / 9;
      want.f_zenith += t.f_zenith / 9;
      want.f_horizon += t.f_horizon / 9;
      want.above += t.above / 9;
      m_bar += sums.cells.m[q].mean / 9.0;
      w_bar += cov / 9.0;
    }
    for (int q = 0; q < 9; ++q) {
      const kd::vec2 d = sums.cells.m[q].mean - m_bar;
      b_bar += outerProduct(d, d) / 9.0;
    }
    const kd::SmoothTerms one = kd::smooth_terms(f, m_bar, w_bar + b_bar, v);
    const double e_groups =
        std::max({std::fabs(got.f_above - want.f_above), std::fabs(got.f_zenith - want.f_zenith),
                  std::fabs(got.above - want.above)});
    const double e_one =
        std::max({std::fabs(one.f_above - want.f_above), std::fabs(one.f_zenith - want.f_zenith),
                  std::fabs(one.above - want.above)});
    std::printf("%-42s F %.6f  groups off %.1e  one Gaussian off %.1e\n", c.what, want.f_above,
                e_groups, e_one);
    // Measured: the groups off by 7e-7 to 2.6e-3, 0.06 to 0.45 of the one Gaussian's miss.
    EXPECT_LT(e_groups, 3e-3) << c.what;
    EXPECT_LT(e_groups, 0.6 * e_one) << c.what;
  }
}

// One wave's slope A cos(phase) over cell (iu, iv) of n x n on the footprint J, and over
// the shutter where its phase at each point turns by 2 x_t, reaching theta at the end: the
// mean and the mean square by a midpoint grid of G per edge and Gt instants (Gt = 1, x_t =
// 0: the still cell).
kd::vec2 cell_slope_moments(double A, kd::vec2 k, double theta, double x_t, const kd::mat2& J,
                            int n, int iu, int iv, int G, int Gt) {
  double m = 0, m2 = 0;
  for (int a = 0; a < G; ++a) {
    for (int c = 0; c < G; ++c) {
      const double u = (iu + (a + 0.5) / G) / n - 0.5, v = (iv + (c + 0.5) / G) / n - 0.5;
      const double at_cell = theta + dot(k, J * kd::vec2(u, v));
      for (int q = 0; q < Gt; ++q) {
        // Time s in [0, 1] over the shutter, the phase 2 x_t (s - 1) behind its end's.
        const double s = (q + 0.5) / Gt;
        const double slope = A * std::cos(at_cell + 2 * x_t * (s - 1));
        m += slope;
        m2 += slope * slope;
      }
    }
  }
  const double count = double(G) * G * Gt;
  return kd::vec2(m / count, m2 / count);
}

// A cell's moments against the grid's (mean m, mean square m2): NDF-plane coordinates are
// minus the slope, so the mean is -K k and the covariance (J - K^2) k k^T; within `rel`
// of the wave's largest slope A |k| (its square for the covariance).
void expect_cell_moments(const kd::NdfMoments& got, kd::vec2 grid, kd::vec2 k, double A, double rel,
                         int n, int iu, int iv) {
  const double m = grid.x, var = grid.y - grid.x * grid.x, scale = A * length(k);
  EXPECT_NEAR(got.mean.x, -m * k.x, rel * scale) << n << " " << iu << iv;
  EXPECT_NEAR(got.mean.y, -m * k.y, rel * scale) << n << " " << iu << iv;
  EXPECT_NEAR(got.cov.x, var * k.x * k.x, rel * scale * scale) << n << " " << iu << iv;
  EXPECT_NEAR(got.cov.y, var * k.x * k.y, rel * scale * scale) << n << " " << iu << iv;
  EXPECT_NEAR(got.cov.z, var * k.y * k.y, rel * scale * scale) << n << " " << iu << iv;
}

TEST(SmoothTerms, CellMomentsMatchNumericalIntegrationOverTheFootprint) {
  // One wave over an elongated, sheared footprint parallelogram (a grazing view's) cut into
  // n x n cells: each cell's mean slope and covariance (ndf.glsl, box_cells_add) against a
  // 200 x 200 midpoint grid over the cell. A long wave spanning a fraction of a cycle, one
  // oblique to the footprint spanning several, and one along it.
  const kd::mat2 J(kd::vec2(0.45, 0.02), kd::vec2(0.9, 11.0));  // columns: metres per pixel
  struct W {
    double A, kx, kz, theta;
  };
  for (const W w : {W{0.13, 0.05, -0.3, 0.7}, W{0.02, 1.9, 0.8, 2.1}, W{0.05, 0.0, -1.1, -0.4}}) {
    const kd::vec2 k(w.kx, w.kz);
    for (int n = 1; n <= 3; ++n) {
      kd::BoxCells b = kd::box_cells_zero();
      kd::box_cells_add(b, n, w.A, k, std::sin(w.theta), std::cos(w.theta),
                        0.5 * kd::vec2(dot(k, J[0]), dot(k, J[1])));
      for (int iu = 0; iu < n; ++iu) {
        for (int iv = 0; iv < n; ++iv) {
          const kd::vec2 grid = cell_slope_moments(w.A, k, w.theta, 0.0, J, n, iu, iv, 200, 1);
          expect_cell_moments(b.m[iu * n + iv], grid, k, w.A, 1e-4, n, iu, iv);
        }
      }
    }
  }
}

TEST(SmoothTerms, SweptCellMomentsMatchNumericalIntegrationOverTheFootprintAndTheShutter) {
  // A moving camera's pixel slides over the water through the shutter: each cell's moments
  // over the cell and the shutter (ndf.glsl, box_cells_add_swept), the wave's phase at the
  // cell's points turning by 2 x_t over the shutter and reaching theta at its end, against
  // a 60 x 60 x 60 midpoint grid over the cell and the shutter. Sweeps of a fraction of a
  // cycle, of several cycles and backwards; x_t = 0 is the still cell (box_cells_add).
  const kd::mat2 J(kd::vec2(0.45, 0.02), kd::vec2(0.9, 11.0));
  struct W {
    double A, kx, kz, theta, x_t;
  };
  for (const W w : {W{0.13, 0.05, -0.3, 0.7, 0.4}, W{0.02, 1.9, 0.8, 2.1, 9.3},
                    W{0.05, 0.0, -1.1, -0.4, -2.2}, W{0.05, 0.0, -1.1, -0.4, 0.0}}) {
    const kd::vec2 k(w.kx, w.kz);
    const kd::vec2 h = 0.5 * kd::vec2(dot(k, J[0]), dot(k, J[1]));
    for (int n = 1; n <= 3; ++n) {
      kd::BoxCells b = kd::box_cells_zero();
      kd::box_cells_add_swept(b, n, w.A, k, std::sin(w.theta), std::cos(w.theta), h, w.x_t);
      if (w.x_t == 0) {
        kd::BoxCells still = kd::box_cells_zero();
        kd::box_cells_add(still, n, w.A, k, std::sin(w.theta), std::cos(w.theta), h);
        for (int c = 0; c < n * n; ++c) {
          EXPECT_EQ(b.m[c].mean, still.m[c].mean) << n;
          EXPECT_EQ(b.m[c].cov, still.m[c].cov) << n;
        }
      }
      for (int iu = 0; iu < n; ++iu) {
        for (int iv = 0; iv < n; ++iv) {
          const kd::vec2 grid = cell_slope_moments(w.A, k, w.theta, w.x_t, J, n, iu, iv, 60, 60);
          expect_cell_moments(b.m[iu * n + iv], grid, k, w.A, 1e-3, n, iu, iv);
        }
      }
    }
  }
}

TEST(SmoothTerms, HorizonShareMatchesARayGrid) {
  // The water's share of pixels that the horizon crosses (horizon_coverage.glsl) against
  // a 400 x 400 grid of rays per pixel, for a level and a rolled camera; the centroid of
  // the water part likewise.
  for (double roll : {0.0, 0.3}) {
    kd::Camera c{};
    c.position = kd::vec3(0, 2, 0);
    const double pitch = 0.013;  // the horizon through the middle of row 47
    c.forward = kd::vec3(0, std::sin(pitch), -std::cos(pitch));
    const kd::vec3 right0(1, 0, 0), up0 = cross(right0, c.forward);
    c.right = std::cos(roll) * right0 + std::sin(roll) * up0;
    c.up = cross(c.right, c.forward);
    c.half_w = 0.4;
    c.half_h = 0.225;
    c.width = 160;
    c.height = 90;
    int crossed = 0;
    for (int j = 30; j < 60; ++j) {
      for (int i = 0; i < 160; i += 9) {
        const kd::PixelWater w = kd::pixel_water(c, i, j);
        const int G = 400;
        double in = 0, cx = 0, cy = 0;
        for (int a = 0; a < G; ++a) {
          for (int b = 0; b < G; ++b) {
            const double px = i + (a + 0.5) / G, py = j + (b + 0.5) / G;
            if (kd::camera_direction(c, px, py).y < 0) {
              in += 1;
              cx += px;
              cy += py;
            }
          }
        }
        const double share = in / (G * G);
        EXPECT_NEAR(w.share, share, 3e-3) << roll << " " << i << "," << j;
        if (share > 0.01 && share < 0.99) {
          ++crossed;
          EXPECT_NEAR(w.centre.x, cx / in, 5e-3) << roll << " " << i << "," << j;
          EXPECT_NEAR(w.centre.y, cy / in, 5e-3) << roll << " " << i << "," << j;
        }
      }
    }
    EXPECT_GT(crossed, 10) << "the test must see pixels that the horizon crosses";
  }
}

}  // namespace
}  // namespace sg
