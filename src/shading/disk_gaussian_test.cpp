// F(d, sigma) against direct 2D quadrature of the Gaussian over the disk, on a grid of
// (d, sigma) from sigma = 1e-5 to 100 and d from 0 to 1 + 8 sigma; its limits and branches.
#include "shading/disk_gaussian.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/error.h"
#include "math/vec.h"
#include "testing/quadrature.h"

namespace sg {
namespace {

// The mass of N((d, 0), sigma^2 I) inside the unit disk by nested adaptive Gauss-Kronrod
// quadrature in Cartesian coordinates scaled by sigma: rows y = sigma t, and along each row
// x = d + sigma z over the disk's chord |x| <= w(y) = sqrt(1 - y^2). The density is
// exp(-(z^2 + t^2) / 2) / (2 pi) in (z, t). Both coordinates are cut at 40 (mass beyond
// exp(-800)). Nothing of F's closed form is used. Scaling by sigma keeps the features of
// the integrand of width ~1 for every sigma.
double direct_F(double d, double sigma) {
  auto row = [&](double t) {
    const double y = sigma * t;
    if (std::abs(y) >= 1) return 0.0;
    const double w = std::sqrt(1 - y * y);
    // (w - d) / sigma = ((1 - d) - (1 - w)) / sigma with 1 - w = y^2 / (1 + w), exactly.
    const double hi = std::min(((1 - d) - y * y / (1 + w)) / sigma, 40.0);
    const double lo = std::max((-w - d) / sigma, -40.0);
    if (hi <= lo) return 0.0;
    auto density = [](double z) { return std::exp(-0.5 * z * z); };
    return testing::integrate(density, lo, hi, {}, 1e-13) * std::exp(-0.5 * t * t) / kTwoPi;
  };
  // Even in t. Rows are taken at y = sin(sigma tau), which removes the square-root
  // behaviour of w at the top of the disk and keeps the integrand of order 1:
  // dt = cos(sigma tau) dtau.
  auto outer = [&](double tau) {
    return row(std::sin(sigma * tau) / sigma) * std::cos(sigma * tau);
  };
  const double top = std::asin(std::min(1.0, 40 * sigma)) / sigma;
  return 2 * testing::integrate(outer, 0.0, top, {}, 1e-13);
}

TEST(DiskGaussian, MatchesDirectQuadratureOnAGrid) {
  const double sigmas[] = {1e-5, 1e-4, 1e-3, 3e-3, 1e-2, 0.03, 0.0499, 0.05,
                           0.1,  0.3,  1,    3,    10,   30,   100};
  double worst = 0;
  int n = 0;
  for (double sigma : sigmas) {
    std::vector<double> ds;
    for (int i = 0; i <= 24; ++i)
      ds.push_back((1 + 8 * sigma) * i / 24.0);
    for (double t : {-2.0, -1.0, -0.3, 0.0, 0.3, 1.0, 2.0})
      ds.push_back(std::max(0.0, 1 + t * sigma));
    for (double d : ds) {
      const double f = disk_gaussian(d, sigma);
      const double q = direct_F(d, sigma);
      // Both sides are good to ~1e-14 (the quadrature's tolerance is 1e-13 relative to
      // each row; measured worst difference 1e-15). 1e-12 leaves margin and still catches
      // any formula or branch error, which would show at the 1e-3 level or above.
      ASSERT_NEAR(f, q, 1e-12) << "d = " << d << ", sigma = " << sigma;
      ASSERT_GE(f, 0.0);
      ASSERT_LE(f, 1.0);
      worst = std::max(worst, std::abs(f - q));
      ++n;
    }
  }
  std::printf("F vs 2D quadrature: %d points, worst |difference| = %.3g\n", n, worst);
}

TEST(DiskGaussian, SigmaZeroIsTheIndicator) {
  EXPECT_EQ(disk_gaussian(0.0, 0.0), 1.0);
  EXPECT_EQ(disk_gaussian(0.999, 0.0), 1.0);
  EXPECT_EQ(disk_gaussian(1.0, 0.0), 0.5);
  EXPECT_EQ(disk_gaussian(1.001, 0.0), 0.0);
  // And it is the limit: F(1 + t sigma, sigma) -> Phi(-t), the flat-edge profile, with a
  // curvature correction of -sigma phi(t) / 2 (so 1e-9 at sigma = 1e-9).
  for (double sigma : {1e-6, 1e-9, 1e-12}) {
    for (double t_wanted : {-3.0, -1.0, 0.0, 0.5, 2.0}) {
      // 1 + t sigma rounds to a multiple of 2^-52: use the t of the d actually passed.
      const double t = ((1 + t_wanted * sigma) - 1) / sigma;
      const double phi_t = 0.5 * std::erfc(t / std::sqrt(2.0));
      EXPECT_NEAR(disk_gaussian(1 + t_wanted * sigma, sigma), phi_t, sigma) << sigma << " " << t;
    }
    EXPECT_EQ(disk_gaussian(1 - 50 * sigma, sigma), 1.0);
    EXPECT_EQ(disk_gaussian(1 + 50 * sigma, sigma), 0.0);
  }
}

TEST(DiskGaussian, BranchesAgreeWhereTheyMeet) {
  // sigma = 0.05: the 1D form below, Boost's non-central chi-squared above; 1e3: Boost below,
  // the wide expansion above. Each side is exact to ~1e-14, so a jump above that is a bug.
  for (double d : {0.0, 0.3, 0.9, 1.0, 1.05, 1.2}) {
    const double lo = disk_gaussian(d, std::nextafter(0.05, 0.0));
    const double hi = disk_gaussian(d, 0.05);
    EXPECT_NEAR(lo, hi, 1e-13) << d;
  }
  for (double d : {0.0, 1.0, 500.0, 2000.0, 5000.0}) {
    const double lo = disk_gaussian(d, 1e3);
    const double hi = disk_gaussian(d, std::nextafter(1e3, 2e3));
    EXPECT_NEAR(lo, hi, 1e-14 * std::max(lo, 1e-300) + 1e-30) << d;
  }
}

TEST(DiskGaussian, WideExpansionConvergesLikeSigmaToTheMinusEight) {
  // The three-term expansion's relative error is O(sigma^-6) times a polynomial in d / sigma,
  // and F is O(sigma^-2): its absolute error over d in [0, 1 + 6 sigma] (the tables'
  // extent) falls like sigma^-8. Measured: 3.9e-7 at sigma = 3, 2.6e-11 at 10, i.e. about
  // 2.6e-3 sigma^-8; the bound allows a factor 2.
  for (double sigma : {3.0, 5.0, 8.0, 20.0}) {
    double worst = 0;
    for (int i = 0; i <= 120; ++i) {
      const double d = (1 + 6 * sigma) * i / 120.0;
      worst = std::max(worst, std::abs(disk_gaussian_wide(d, sigma) - disk_gaussian(d, sigma)));
    }
    EXPECT_LT(worst, 5e-3 * std::pow(sigma, -8.0)) << sigma;
  }
  // Huge sigma: F -> exp(-rho^2 / 2) / (2 sigma^2).
  EXPECT_NEAR(disk_gaussian(0, 1e6) * 2e12, 1.0, 1e-12);
  EXPECT_NEAR(disk_gaussian(1e6, 1e6) * 2e12, std::exp(-0.5), 1e-12);
}

TEST(DiskGaussian, BadInputNamesTheArgument) {
  EXPECT_THROW(disk_gaussian(-0.1, 1), Error);
  EXPECT_THROW(disk_gaussian(0.1, -1), Error);
  try {
    disk_gaussian(0.5, NAN);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("sigma must be finite and >= 0"), std::string::npos);
  }
  try {
    disk_gaussian(INFINITY, 1);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("disk_gaussian: d must be"), std::string::npos);
  }
}

}  // namespace
}  // namespace sg
