// The lattice generator (ocean/lattice_ocean.h): each cascade ocean's significant wave
// height against the spectrum's integral over its bands (the target: within 5%), bands that
// tile the spectrum without overlap, the files the loader accepts, the same bytes for the
// same parameters, and bad flags refused by name.
#include "ocean/lattice_ocean.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "base/atomic_file.h"
#include "base/error.h"
#include "math/rng.h"
#include "math/vec.h"
#include "scene/cascade_fft.h"
#include "scene/scene.h"
#include "testing/paths.h"

namespace sg::ocean {
namespace {

std::string error_of(const OceanParams& p, const CascadeParams& c) {
  try {
    generate_lattice(p, c);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(LatticeOcean, SignificantHeightIsTheSpectrumsWithinFivePerCent) {
  struct Case {
    const char* what;
    OceanParams p;
    CascadeParams c;
  };
  std::vector<Case> cases;
  for (double u : {5.0, 10.0, 15.0}) {
    OceanParams p;
    p.wind_speed = u;
    cases.push_back({"jonswap", p, {}});
  }
  {
    OceanParams p;
    p.spectrum = SpectrumKind::pierson_moskowitz;
    p.wind_speed = 12;
    cases.push_back({"pierson-moskowitz", p, {}});
  }
  {
    OceanParams p;
    p.spectrum = SpectrumKind::tma;
    p.depth = 8;
    cases.push_back({"tma 8 m", p, {}});
  }
  {
    OceanParams p;
    p.swell.enabled = true;
    p.swell.height = 1.5;
    p.swell.period = 11;
    p.swell.direction_deg = 40;
    cases.push_back({"wind and swell", p, {}});
  }
  {
    OceanParams p;
    p.wind_speed = 8;
    CascadeParams c;
    c.cascades = 2;
    c.lattice = 64;
    cases.push_back({"2 x 64", p, c});
  }
  for (const Case& k : cases) {
    const LatticeOcean o = generate_lattice(k.p, k.c);
    const double hs = 4 * std::sqrt(o.variance), hs_spec = 4 * std::sqrt(o.spectrum_variance);
    std::printf("%-18s Hs %.4f m, spectrum %.4f m (%+.2f%%)\n", k.what, hs, hs_spec,
                100 * (hs / hs_spec - 1));
    EXPECT_NEAR(hs / hs_spec, 1, 0.05) << k.what;
    // Bands: contiguous from the trimmed low end, each inside its lattice.
    ASSERT_EQ(static_cast<int>(o.cascades.size()), k.c.cascades);
    EXPECT_DOUBLE_EQ(o.cascades[0].band_min, o.k_min);
    for (size_t c = 0; c < o.cascades.size(); ++c) {
      const CascadeDesc& d = o.cascades[c];
      EXPECT_LT(d.band_min, d.band_max);
      EXPECT_LE(d.band_max, (d.lattice / 2) * kTwoPi / d.patch_size * (1 + 1e-12));
      if (c > 0) {
        EXPECT_EQ(d.band_min, o.cascades[c - 1].band_max);
      }
    }
  }
}

TEST(LatticeOcean, FilesLoadAndRepeatBitForBit) {
  OceanParams p;
  p.wind_speed = 9;
  p.seed = 4;
  CascadeParams c;
  c.cascades = 3;
  c.lattice = 32;
  const LatticeOcean a = generate_lattice(p, c), b = generate_lattice(p, c);
  p.seed = 5;
  const LatticeOcean other = generate_lattice(p, c);
  const std::string dir = sg::testing::binary_dir() + "/test_out/lattice_ocean_test";
  std::filesystem::create_directories(dir);
  Scene s = plain_template();
  s.surface.waves.clear();
  s.surface.depth = a.depth;
  for (size_t k = 0; k < a.cascades.size(); ++k) {
    EXPECT_EQ(lattice_npy_bytes(*a.cascades[k].data), lattice_npy_bytes(*b.cascades[k].data));
    EXPECT_EQ(a.cascades[k].data->amplitude, other.cascades[k].data->amplitude);
    EXPECT_NE(a.cascades[k].data->phase, other.cascades[k].data->phase);
    CascadeDesc d = a.cascades[k];
    d.file = std::string("c").append(std::to_string(k)).append(".npy");
    write_lattice(dir + "/" + d.file, *d.data);
    s.surface.cascades.push_back(d);
  }
  write_file_atomic(dir + "/sea.json", scene_to_json(s));
  const Scene back = load_scene(dir + "/sea.json");
  ASSERT_EQ(back.surface.cascades.size(), 3u);
  for (size_t k = 0; k < 3; ++k)
    EXPECT_EQ(back.surface.cascades[k].data->amplitude, a.cascades[k].data->amplitude);
}

TEST(LatticeOcean, BadFlagsNamed) {
  OceanParams p;
  CascadeParams c;
  c.lattice = 100;
  EXPECT_EQ(error_of(p, c), "--lattice: must be a power of two in [4, 1024] (got 100)");
  c = {};
  c.cascades = 9;
  EXPECT_EQ(error_of(p, c), "--cascades: must be in [1, 8] (got 9)");
  c = {};
  c.lattice = 16;
  EXPECT_EQ(error_of(p, c),
            "--cascades: 4 cascades need --lattice 32 or more (a patch may be at most N / 16 "
            "times the next; with 16 only one cascade)");
  c = {};
  c.patch_sizes = {1000, 100};
  EXPECT_EQ(error_of(p, c), "--patch-sizes: 2 sizes for 4 cascades (--cascades)");
  c.cascades = 2;
  c.patch_sizes = {1000, 10};
  EXPECT_EQ(error_of(p, c),
            "--patch-sizes: must decrease, each at most 16 times the next (N / 16: the finer "
            "lattice resolves its band's edge); got 1000 then 10");
}

}  // namespace
}  // namespace sg::ocean

namespace sg::ocean {
namespace {

// The slope field between the grid's points: what a renderer reading the FFT's grid gets
// with bilinear and with Catmull-Rom bicubic interpolation, against the exact sum of the
// cascade's sines, per cascade of the default 10 m/s sea (four of 256) at random points.
// The figures (printed) are docs/ocean.md's; the bounds hold them.
double periodic(const std::vector<double>& f, int n, int p, int q) {
  p = ((p % n) + n) % n;
  q = ((q % n) + n) % n;
  return f[static_cast<size_t>(q) * n + p];
}

double bilinear(const std::vector<double>& f, int n, double u, double v) {
  const int p = static_cast<int>(std::floor(u)), q = static_cast<int>(std::floor(v));
  const double a = u - p, b = v - q;
  return (1 - a) * (1 - b) * periodic(f, n, p, q) + a * (1 - b) * periodic(f, n, p + 1, q) +
         (1 - a) * b * periodic(f, n, p, q + 1) + a * b * periodic(f, n, p + 1, q + 1);
}

double catmull_rom(double p0, double p1, double p2, double p3, double t) {
  return 0.5 * (2 * p1 + (-p0 + p2) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t * t +
                (-p0 + 3 * p1 - 3 * p2 + p3) * t * t * t);
}

double bicubic(const std::vector<double>& f, int n, double u, double v) {
  const int p = static_cast<int>(std::floor(u)), q = static_cast<int>(std::floor(v));
  double row[4];
  for (int j = 0; j < 4; ++j) {
    row[j] = catmull_rom(periodic(f, n, p - 1, q + j - 1), periodic(f, n, p, q + j - 1),
                         periodic(f, n, p + 1, q + j - 1), periodic(f, n, p + 2, q + j - 1), u - p);
  }
  return catmull_rom(row[0], row[1], row[2], row[3], v - q);
}

TEST(LatticeOcean, InterpolatedSlopesBetweenTheGridsPoints) {
  const LatticeOcean o = generate_lattice(OceanParams{}, CascadeParams{});
  const Dispersion water{o.depth};
  const double t = 1.3;
  // Measured 0.116, 0.074, 0.070, 0.013 (bilinear) and 0.028, 0.018, 0.017, 0.0007.
  const double worst_bilinear = 0.15, worst_bicubic = 0.04;
  for (size_t c = 0; c < o.cascades.size(); ++c) {
    const CascadeDesc& d = o.cascades[c];
    const int n = d.lattice;
    const CascadeGrid g = CascadeFft(n).evaluate(d, water, t);
    const std::vector<Wave> waves = cascade_waves(d, water);
    Pcg32 rng(11, c);
    double e_lin = 0, e_cub = 0, s2 = 0;
    const int points = 200;
    for (int s = 0; s < points; ++s) {
      const double u = n * rng.uniform(), v = n * rng.uniform();
      const double x = u * d.patch_size / n, z = v * d.patch_size / n;
      double sx = 0;
      for (const Wave& w : waves) {
        sx +=
            w.amplitude * w.wave_vector.x *
            std::cos(w.wave_vector.x * x + w.wave_vector.y * z + w.angular_frequency * t + w.phase);
      }
      e_lin += std::pow(bilinear(g.slope_x, n, u, v) - sx, 2);
      e_cub += std::pow(bicubic(g.slope_x, n, u, v) - sx, 2);
      s2 += sx * sx;
    }
    const double lin = std::sqrt(e_lin / s2), cub = std::sqrt(e_cub / s2);
    std::printf(
        "cascade %zu (patch %.4g m): rms slope error / rms slope: bilinear %.4f, "
        "Catmull-Rom %.4f\n",
        c, d.patch_size, lin, cub);
    EXPECT_LT(lin, worst_bilinear);
    EXPECT_LT(cub, worst_bicubic);
    EXPECT_LT(cub, lin);
  }
}

}  // namespace
}  // namespace sg::ocean
