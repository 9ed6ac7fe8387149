// The cascades' FFT fields in the shading kernel (kernel/cascade_fields.glsl, built by
// shading/cascade_fields.h) against the direct sums of the lattices' sines, on a generated
// two-cascade sea of 32 x 32 lattices (2 x 1024 waves):
//  - every texel the host writes (the LEAN chain, kernel/cascade_chain.glsl) against direct
//    averaging of the grid over its block, and a CascadeFields kept from frame to frame
//    against a fresh one;
//  - at the coarser grid's points (which are the finer's too) the point-sampled slope is
//    the direct sum at every path instant, to rounding;
//  - between them, Catmull-Rom's error, measured and bounded;
//  - the chain's second moments, averaged over the water, are the lattices' slope variance
//    at every level (the texels' layout and the bilinear weights);
//  - `staa`'s share: a footprint wider than both patches is the whole covariance and no
//    mean; a footprint far below a texel is the point sample and no covariance;
//  - the baselines' share: the Hessian at grid points is the direct sum; the moments over
//    a footprint (LEAN's filter of the chain) against the direct sum's mean and covariance
//    over the footprint's parallelogram, measured and bounded;
//  - displaced water: the height at grid points is the direct sum, the interpolant's
//    gradient its finite differences, the interpolant within its bounds at random points,
//    and the march's hits on the interpolated surface, the ray above it before them;
//  - the fields a method builds for what it reads (CascadeReads): `point`, `supersample`
//    with T = 1 and `staa-temporal` shade the same, to rounding, as from the whole fields;
//  - a still camera's shutter start read along the display time's pass: the same share, to
//    the bit, as a pass of its own;
//  - the host baselines' fields (the display time's chain alone): the whole fields' display
//    time, texel for texel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"
#include "math/rng.h"
#include "ocean/lattice_ocean.h"
#include "ocean/ocean.h"
#include "shading/kernel_frame.h"

namespace sg {
namespace {

struct Sea {
  Scene scene;
  std::vector<Wave> waves;  // the cascades' sines
  double slope_sum = 0;     // sum A |k|
  double variance = 0;      // sum A^2 |k|^2 / 2
};

Sea cascade_sea(double shutter = 1.0, int lattice = 32) {
  ocean::OceanParams p;
  p.wind_speed = 8;
  p.seed = 5;
  ocean::CascadeParams c;
  c.cascades = 2;
  c.lattice = lattice;
  const ocean::LatticeOcean lat = ocean::generate_lattice(p, c);
  Sea sea;
  p.waves = 16;
  sea.scene = ocean::ocean_scene(ocean::plain_template(), ocean::generate(p), "sea");
  sea.scene.surface.waves.clear();
  sea.scene.surface.cascades = lat.cascades;
  sea.scene.width = 64;
  sea.scene.height = 36;
  sea.scene.camera.position = vec3(1234.5, 6.0, -876.25);
  sea.scene.camera.look_at = vec3(1234.5, 0.0, -856.25);
  sea.scene.animation.shutter = shutter;
  sea.waves = surface_waves(sea.scene.surface);
  for (const Wave& w : sea.waves) {
    const double k = length(w.wave_vector);
    sea.slope_sum += w.amplitude * k;
    sea.variance += 0.5 * w.amplitude * w.amplitude * k * k;
  }
  return sea;
}

// One frame of a sea's fields: its model, time and the kernel's inputs in double (the
// cascades as fields).
struct Fields {
  Fields(const Scene& s, int frame, int segments, double intersect_tolerance)
      : model(s), ft(frame_time(s, frame)) {
    build_kernel_inputs(model, ft, segments, 0, in, intersect_tolerance, 1, true);
  }
  SceneModel model;
  FrameTime ft;
  KernelInputsD in;
};

vec2 direct_gradient(const std::vector<Wave>& waves, double x, double z, double t) {
  vec2 g(0.0);
  for (const Wave& w : waves) {
    const double th = w.wave_vector.x * x + w.wave_vector.y * z + w.angular_frequency * t + w.phase;
    g += w.amplitude * std::cos(th) * w.wave_vector;
  }
  return g;
}

double instant_time(const FrameTime& ft, int K, int k) {
  return ft.end - ft.duration() * (K - k) / K;
}

// The grid the host transforms cascade c of m to at time t (what CascadeFields::append
// evaluates: the lattice oversampled, at the scene's depth): with the curvatures, or the
// slopes alone.
CascadeGrid host_grid(const SceneModel& m, size_t c, double t, bool curvatures) {
  const CascadeDesc padded = oversampled_cascade(m.scene.surface.cascades[c]);
  CascadeFft fft(padded.lattice);
  fft.set_lattice(padded, Dispersion{m.scene.surface.depth});
  return curvatures ? fft.evaluate(t, true) : fft.evaluate_slopes(t);
}

TEST(CascadeFields, ChainIsTheBlockAverageOfTheGrid) {
  // Every data texel CascadeFields::append writes against the grid averaged directly over
  // the texel's aligned 2^l x 2^l block (Olano and Baker's LEAN moments), for each method's
  // reads (CascadeReads), K = 2, a non-zero and a zero shutter (every instant the display
  // time's): at the display time of the whole fields a = (E[s_x], E[s_z], E[h_xx],
  // E[h_zz]), b = (E[h_xz], E[s_x^2], E[s_x s_z], E[s_z^2]) with level 0's b.y the height
  // and its b.zw instant 0's slopes (flat water);
  // at the other instants (s_x, s_z) and the rest 0; the reads other than `all` level 0
  // alone, (s_x, s_z, 0, 0), (0, h, 0, 0) at the display time, (s_x, s_z, 0, 0), 0 at the
  // instants they build; every texel not built 0. Within 1e-13 of each component's largest
  // value.
  const int K = 2;
  for (const double shutter : {1.0, 0.0}) {
    const Sea sea = cascade_sea(shutter);
    const SceneModel m(sea.scene);
    const FrameTime ft = frame_time(sea.scene, 3);
    ASSERT_EQ(ft.duration() > 0, shutter > 0);
    const vec3 cam = sea.scene.camera.position;
    for (const CascadeReads reads :
         {CascadeReads::all, CascadeReads::instants_level0, CascadeReads::display_level0}) {
      CascadeFields fields;
      std::vector<glm::dvec4> texels;
      fields.append(m, ft, K, cam.x, cam.z, texels, reads);
      const CascadeLayout& lay = fields.layout();
      ASSERT_EQ(texels.size(), lay.end);
      double worst = 0;
      for (size_t c = 0; c < lay.data.size(); ++c) {
        const int n = lay.grid[c];
        const CascadeGrid first = host_grid(m, c, cascade_instant(ft, K, 0), false);
        for (int k = 0; k <= K; ++k) {
          // A zero shutter: every instant the display time's (whole fields only).
          const bool display = k == K || (reads == CascadeReads::all && shutter == 0);
          const bool built = reads != CascadeReads::display_level0 || k == K;
          const bool full = display && reads == CascadeReads::all;
          const CascadeGrid g = host_grid(m, c, cascade_instant(ft, K, display ? K : k), display);
          // Each component's want at every texel of every level, then its largest value.
          std::vector<glm::dvec4> want;
          for (int side = n, level = 0; side >= 1; side /= 2, ++level) {
            const int block = n / side;
            for (int q = 0; q < side; ++q) {
              for (int p = 0; p < side; ++p) {
                glm::dvec4 a(0.0), b(0.0);
                for (int y = 0; y < block; ++y) {
                  for (int x = 0; x < block; ++x) {
                    const size_t e = static_cast<size_t>(q * block + y) * n + p * block + x;
                    const double sx = g.slope_x[e], sz = g.slope_z[e];
                    a += glm::dvec4(sx, sz, full ? g.curv_xx[e] : 0.0, full ? g.curv_zz[e] : 0.0);
                    if (full && level == 0) {
                      b +=
                          glm::dvec4(g.curv_xz[e], g.height[e], first.slope_x[e], first.slope_z[e]);
                    } else if (full) {
                      b += glm::dvec4(g.curv_xz[e], sx * sx, sx * sz, sz * sz);
                    } else if (display && level == 0) {
                      b += glm::dvec4(0.0, g.height[e], 0.0, 0.0);
                    }
                  }
                }
                const bool here = built && (level == 0 || reads == CascadeReads::all);
                const double inv = here ? 1.0 / (block * block) : 0.0;
                want.push_back(inv * a);
                want.push_back(inv * b);
              }
            }
          }
          ASSERT_EQ(want.size(), static_cast<size_t>(kd::cascade_instant_texels(n)));
          glm::dvec4 scale[2] = {glm::dvec4(0.0), glm::dvec4(0.0)};
          for (size_t i = 0; i < want.size(); ++i)
            scale[i % 2] = glm::max(scale[i % 2], glm::abs(want[i]));
          const size_t at = lay.data[c] + static_cast<size_t>(k) * want.size();
          for (size_t i = 0; i < want.size(); ++i) {
            for (int j = 0; j < 4; ++j) {
              const double d = std::fabs(texels[at + i][j] - want[i][j]);
              const double sc = scale[i % 2][j];
              ASSERT_LE(d, 1e-13 * sc)
                  << "reads " << int(reads) << " shutter " << shutter << " cascade " << c
                  << " instant " << k << " texel " << i << "." << j;
              worst = std::max(worst, sc > 0 ? d / sc : d);
            }
          }
        }
      }
      std::printf(
          "reads %d, shutter %.1f: largest |texel - block average| %.3g of the "
          "component's largest\n",
          int(reads), shutter, worst);
    }
  }
}

TEST(CascadeFields, KeptFieldsWriteTheFreshTexels) {
  // One CascadeFields appends frame after frame (its grids kept, whatever the reads and
  // the instants before): every texel the fresh one's, bit for bit.
  const Sea sea = cascade_sea(0.5);
  const SceneModel m(sea.scene);
  const vec3 cam = sea.scene.camera.position;
  CascadeFields kept;
  const CascadeReads order[] = {CascadeReads::all, CascadeReads::display_level0, CascadeReads::all,
                                CascadeReads::instants_level0, CascadeReads::all};
  for (int f = 0; f < 5; ++f) {
    const FrameTime ft = frame_time(sea.scene, 2 + f);
    const int K = 1 + f % 3;
    std::vector<glm::dvec4> a, b;
    kept.append(m, ft, K, cam.x, cam.z, a, order[f]);
    CascadeFields fresh;
    fresh.append(m, ft, K, cam.x, cam.z, b, order[f]);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_TRUE(a == b) << "frame " << f;
  }
}

TEST(CascadeFields, GridPointsAreTheDirectSum) {
  const Sea sea = cascade_sea();
  ASSERT_GT(sea.waves.size(), 500u);
  const SceneModel m(sea.scene);
  const FrameTime ft = frame_time(sea.scene, 3);
  const int K = 2;
  KernelInputsD in;
  KernelInputsF inf;
  build_kernel_inputs(m, ft, K, 0, in, kDefaultIntersectTolerance, 1, true);
  build_kernel_inputs(m, ft, K, 0, inf, kDefaultIntersectTolerance, 1, true);
  ASSERT_EQ(in.frame.cascade_count, 2);
  ASSERT_EQ(in.frame.wave_count, 0);
  const CascadeDesc& c0 = sea.scene.surface.cascades[0];
  const double h = c0.patch_size / c0.lattice;
  const vec3 cam = sea.scene.camera.position;
  Pcg32 rng(3, 1);
  double worst = 0;
  for (int s = 0; s < 60; ++s) {
    const int k = s % (K + 1);
    const double t = instant_time(ft, K, k);
    // A grid point near the camera (camera-relative coordinates are small).
    const double x = (std::floor(cam.x / h) + std::floor(40 * rng.uniform() - 20)) * h;
    const double z = (std::floor(cam.z / h) + std::floor(40 * rng.uniform())) * h;
    const vec2 want = direct_gradient(sea.waves, x, z, t);
    const kd::vec2 got = kd::cascade_gradient(wave_buffer(in), in.frame, k, x - cam.x, z - cam.z);
    worst = std::max(worst, length(vec2(got) - want));
  }
  std::printf("grid points: |fields - direct| %.3g; sum A|k| %.3g\n", worst, sea.slope_sum);
  EXPECT_LT(worst, 1e-11 * sea.slope_sum);
  // The float frame holds the same layout (its fields in float).
  EXPECT_EQ(inf.frame.cascade_count, 2);
  EXPECT_EQ(inf.frame.cascade_base, in.frame.cascade_base);
  EXPECT_EQ(inf.texels.size(), in.texels.size());
}

TEST(CascadeFields, CubicInterpolationErrorBetweenGridPoints) {
  const Sea sea = cascade_sea();
  const Fields fields(sea.scene, 1, 1, kDefaultIntersectTolerance);
  const FrameTime& ft = fields.ft;
  const KernelInputsD& in = fields.in;
  const vec3 cam = sea.scene.camera.position;
  Pcg32 rng(4, 1);
  double err2 = 0, ref2 = 0;
  const int n = 400;
  for (int s = 0; s < n; ++s) {
    const double x = cam.x + 60 * rng.uniform() - 30, z = cam.z + 60 * rng.uniform();
    const vec2 want = direct_gradient(sea.waves, x, z, ft.end);
    const kd::vec2 got = kd::cascade_gradient(wave_buffer(in), in.frame, 1, x - cam.x, z - cam.z);
    err2 += dot(vec2(got) - want, vec2(got) - want);
    ref2 += dot(want, want);
  }
  const double rel = std::sqrt(err2 / ref2);
  std::printf("between grid points: RMS |fields - direct| / RMS slope = %.4f\n", rel);
  // Measured 0.0003 on this sea with the fields' grid 8 times the lattice's
  // (cascade_oversampling), 0.0248 with it twice, 0.2465 on the lattice's own grid (the
  // top octave sampled 2 to 4 times a period); a bilinear blend or a misplaced texel
  // centre gives 0.1 or more.
  EXPECT_LT(rel, 0.002);
  EXPECT_GT(rel, 0.0);
}

TEST(CascadeFields, LargeLatticesOversampleTheLastCascadeAlone) {
  // Two cascades of 256: the first's band ends at half its Nyquist wavenumber, so its own
  // grid holds its shortest waves 4 points a period, as the last cascade's grid twice its
  // lattice holds its own (cascade_oversampling): the first transformed on 256^2, the last
  // on 512^2, and the bicubic between grid points near the direct sum, as with both
  // twice their lattice.
  const Sea sea = cascade_sea(1.0, 256);
  const Fields fields(sea.scene, 1, 1, kDefaultIntersectTolerance);
  const KernelInputsD& in = fields.in;
  const kd::WaveBuffer b = wave_buffer(in);
  EXPECT_EQ(kd::cascade_at(b, in.frame, 0).n, 256);
  EXPECT_EQ(kd::cascade_at(b, in.frame, 1).n, 512);
  const vec3 cam = sea.scene.camera.position;
  Pcg32 rng(4, 2);
  double err2 = 0, ref2 = 0;
  for (int s = 0; s < 100; ++s) {
    const double x = cam.x + 60 * rng.uniform() - 30, z = cam.z + 60 * rng.uniform();
    const vec2 want = direct_gradient(sea.waves, x, z, fields.ft.end);
    const kd::vec2 got = kd::cascade_gradient(b, in.frame, 1, x - cam.x, z - cam.z);
    err2 += dot(vec2(got) - want, vec2(got) - want);
    ref2 += dot(want, want);
  }
  const double rel = std::sqrt(err2 / ref2);
  std::printf("256 lattices between grid points: RMS |fields - direct| / RMS slope = %.4f\n", rel);
  // Measured 0.0147 (0.0125 with the first cascade on 512^2 too; 0.1315 with both on
  // their own 256^2).
  EXPECT_LT(rel, 0.02);
}

TEST(CascadeFields, ChainResolvesAWaveAsEq20sRamp) {
  // One sine in a cascade (16 m patch), seen through square footprints of f cycles per
  // pixel: the share of its slope that staa's chain filter keeps in the resolved gradient
  // (the regression of the filtered slope on the wave's over a period), averaged over nine
  // wavelengths (1.2 to 3.2 m: the chain's levels fall at every fraction), against Eq. 20's
  // ramp, 1 - alias_fraction(f) (resolved in full below 0.3 cycles a pixel, aliased in
  // full past 0.8): half at the ramp's middle (kernel/cascade_fields.glsl,
  // cascade_resolving_scale). Measured 0.946, 0.797, 0.480, 0.237, 0.050 at the f below
  // (the filter's tail is longer than the ramp's); with the boxes of the scale alias_end
  // (before) 0.821, 0.465, 0.100, 0.019, 0.004.
  const double freqs[] = {0.15, 0.3, 0.55, 0.8, 1.2};
  double share[5] = {0, 0, 0, 0, 0};
  const int n = 32, ms[] = {5, 6, 7, 8, 9, 10, 11, 12, 13};
  for (const int m : ms) {
    Sea sea = cascade_sea();
    const double L = 16, k = kTwoPi * m / L, A = 0.01;
    auto data = std::make_shared<LatticeData>();
    data->n = n;
    data->amplitude.assign(n * n, 0.0);
    data->phase.assign(n * n, 0.0);
    data->amplitude[m] = A;
    data->phase[m] = 0.4;
    CascadeDesc c;
    c.file = "one.npy";
    c.patch_size = L;
    c.lattice = n;
    c.band_min = 0.5;
    c.band_max = n * kPi / L;
    c.data = data;
    sea.scene.surface.cascades = {c};
    const Fields fields(sea.scene, 0, 1, kDefaultIntersectTolerance);
    const kd::WaveBuffer b = wave_buffer(fields.in);
    const kd::Frame& f = fields.in.frame;
    const kd::Cascade cc = kd::cascade_at(b, f, 0);
    kd::StaaParams p{};
    p.alias_start = 0.3;
    p.alias_end = 0.8;
    for (int q = 0; q < 5; ++q) {
      const double sigma = kTwoPi * freqs[q] / k;
      double gt = 0, tt = 0;
      for (int s = 0; s < 64; ++s) {
        kd::Footprint fp;
        fp.hit = true;
        fp.point = kd::vec3(0.37 + (s + 0.5) / 64 * (kTwoPi / k), 0.0, 1.3 + 0.1 * s);
        fp.view = kd::vec3(0.0, 1.0, 0.0);
        fp.dp_dpx = kd::vec3(sigma, 0.0, 0.0);
        fp.dp_dpy = kd::vec3(0.0, 0.0, sigma);
        fp.distance = 10;
        const kd::PathViews v = kd::path_views_fixed(fp.point, fp.view);
        const kd::CascadeShare sh = kd::cascade_staa_share(b, f, p, fp, v, cc);
        const double truth = kd::cascade_gradient(b, f, f.segments, fp.point.x, fp.point.z).x;
        gt += sh.g[f.segments].x * truth;
        tt += truth * truth;
      }
      share[q] += gt / tt / std::size(ms);
    }
  }
  for (int q = 0; q < 5; ++q) {
    const double ramp = 1 - kd::alias_fraction(freqs[q], 0.3, 0.8);
    std::printf("f %.2f cycles a pixel: the chain keeps %.3f of the slope, Eq. 20 %.3f\n", freqs[q],
                share[q], ramp);
    EXPECT_NEAR(share[q], ramp, q == 2 ? 0.05 : 0.25) << freqs[q];
  }
}

TEST(CascadeFields, ChainSecondMomentsAverageToTheSlopeVariance) {
  const Sea sea = cascade_sea();
  const Fields fields(sea.scene, 0, 1, kDefaultIntersectTolerance);
  const FrameTime& ft = fields.ft;
  const KernelInputsD& in = fields.in;
  const kd::WaveBuffer b = wave_buffer(in);
  for (int c = 0; c < 2; ++c) {
    const kd::Cascade cc = kd::cascade_at(b, in.frame, c);
    const CascadeDesc& d = sea.scene.surface.cascades[c];
    EXPECT_EQ(cc.n, 32 * cascade_oversampling(d));
    EXPECT_EQ(cc.n, 256);
    EXPECT_EQ(cc.levels, 9);
    EXPECT_DOUBLE_EQ(cc.size, d.patch_size);
    double var = 0;
    for (const Wave& w : cascade_waves(d, Dispersion{}))
      var += 0.5 * w.amplitude * w.amplitude * dot(w.wave_vector, w.wave_vector);
    EXPECT_NEAR(cc.cov.x + cc.cov.z, var, 1e-12 * var);
    // The top texel: the grid's mean of s s^T, the direct sum's on the grid (which is not
    // sum A^2 k^2 / 2: counter-running waves k, -k beat in space).
    double top = 0;
    {
      const std::vector<Wave> cw = cascade_waves(d, Dispersion{});
      const int g = cc.n;
      for (int q = 0; q < g; ++q) {
        for (int p = 0; p < g; ++p) {
          const vec2 s = direct_gradient(cw, p * d.patch_size / g, q * d.patch_size / g, ft.end);
          top += dot(s, s) / (g * g);
        }
      }
      const kd::CascadeTexel t = kd::cascade_filtered(b, cc, kd::cascade_read(1, true, false),
                                                      cc.levels - 1, kd::vec2(0.0));
      EXPECT_NEAR(t.b.y + t.b.w, top, 1e-9 * top) << "cascade " << c;
    }
    for (double level : {1.0, 2.5, 4.0, 5.0}) {
      // A regular grid of positions over the patch: the bilinear weights sum each texel's
      // share equally, so the mean of E[s s^T] is the patch's.
      double tr = 0;
      const int g = 64;
      for (int q = 0; q < g; ++q) {
        for (int p = 0; p < g; ++p) {
          const kd::vec2 u((p + 0.5) * cc.n / g, (q + 0.5) * cc.n / g);
          const kd::CascadeTexel t =
              kd::cascade_filtered(b, cc, kd::cascade_read(1, true, false), level, u);
          tr += (t.b.y + t.b.w) / (g * g);
        }
      }
      EXPECT_NEAR(tr, top, 1e-9 * top) << "cascade " << c << " level " << level;
    }
  }
}

kd::StaaParams params() {
  kd::StaaParams p{};
  p.per_pixel_ndf = true;
  p.alias_start = 0.3;
  p.alias_end = 0.8;
  p.nyquist_max = true;
  p.footprint = 1;
  return p;
}

kd::Footprint footprint_of(double x, double z, double metres_per_pixel) {
  kd::Footprint fp{};
  fp.hit = true;
  fp.point = kd::vec3(x, 0, z);
  fp.view = normalize(kd::vec3(0, 1, -1));
  fp.dp_dpx = kd::vec3(metres_per_pixel, 0, 0);
  fp.dp_dpy = kd::vec3(0, 0, metres_per_pixel);
  return fp;
}

TEST(CascadeFields, StaaShareLimits) {
  const Sea sea = cascade_sea();
  const Fields fields(sea.scene, 2, 1, kDefaultIntersectTolerance);
  const KernelInputsD& in = fields.in;
  const kd::WaveBuffer b = wave_buffer(in);
  const kd::StaaParams p = params();
  for (int c = 0; c < 2; ++c) {
    const kd::Cascade cc = kd::cascade_at(b, in.frame, c);
    // Wider than the patch: all of it aliases.
    const kd::Footprint wide = footprint_of(3, 7, 2 * cc.size);
    const kd::CascadeShare sw = kd::cascade_staa_share(
        b, in.frame, p, wide, kd::path_views_fixed(wide.point, wide.view), cc);
    EXPECT_EQ(sw.cov, cc.cov);
    EXPECT_EQ(sw.g[1], kd::vec2(0.0));
    // Far below a texel: the point sample, and no covariance (a grid point has no spread).
    const kd::Footprint tiny = footprint_of(3, 7, 1e-5 * cc.size / cc.n);
    const kd::CascadeShare st = kd::cascade_staa_share(
        b, in.frame, p, tiny, kd::path_views_fixed(tiny.point, tiny.view), cc);
    const kd::vec4 a = kd::cascade_bicubic(b, cc, kd::cascade_read(1, false, false),
                                           kd::cascade_grid_coord(cc, kd::vec2(3, 7)))
                           .a;
    EXPECT_NEAR(st.g[1].x, a.x, 1e-14);
    EXPECT_NEAR(st.g[1].y, a.y, 1e-14);
    EXPECT_LT(st.cov.x + st.cov.z, 1e-12 * (cc.cov.x + cc.cov.z));
  }
}

// A camera that holds still reads the path's two ends at one water point: the display
// time's pass over the filter's texels takes the shutter start's slopes along
// (cascade_fields.glsl, CascadeRead.start). The share must be the one that a pass of the
// shutter start's own gives (PathViews marked moving with every instant's point the same
// takes that pass), to the bit: every slope, Hessian and the covariance, over footprints
// from below a texel to past the patch, elongated and turned, for 1 and 3 sub-arcs; and the
// start's slopes must differ from the display time's (the shutter is not zero).
TEST(CascadeFields, ShutterStartTakenAlongEqualsItsOwnPass) {
  const Sea sea = cascade_sea();
  const kd::StaaParams p = params();
  for (int K : {1, 3}) {
    const Fields fields(sea.scene, 2, K, kDefaultIntersectTolerance);
    const KernelInputsD& in = fields.in;
    const kd::WaveBuffer b = wave_buffer(in);
    std::mt19937 rng(7 + K);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    int differ = 0, read = 0;
    for (int c = 0; c < 2; ++c) {
      const kd::Cascade cc = kd::cascade_at(b, in.frame, c);
      for (int trial = 0; trial < 60; ++trial) {
        kd::Footprint fp = footprint_of(40 * u01(rng) - 20, 40 * u01(rng) - 20,
                                        std::pow(10.0, 4 * u01(rng) - 3) * cc.size / cc.n);
        const double turn = kTwoPi * u01(rng), stretch = 1 + 9 * u01(rng);
        fp.dp_dpx = kd::vec3(std::cos(turn), 0, std::sin(turn)) * fp.dp_dpx.x;
        fp.dp_dpy = kd::vec3(-std::sin(turn), 0, std::cos(turn)) * (fp.dp_dpy.z * stretch);
        const kd::PathViews still = kd::path_views_fixed(fp.point, fp.view);
        kd::PathViews own = still;
        own.moving = true;
        const kd::CascadeShare a = kd::cascade_staa_share(b, in.frame, p, fp, still, cc);
        const kd::CascadeShare o = kd::cascade_staa_share(b, in.frame, p, fp, own, cc);
        for (int k = 0; k <= K; ++k) {
          EXPECT_EQ(a.g[k], o.g[k]) << "K " << K << " cascade " << c << " trial " << trial;
          EXPECT_EQ(a.hess[k], o.hess[k]) << "K " << K << " instant " << k;
        }
        EXPECT_EQ(a.cov, o.cov);
        if (a.g[K] != kd::vec2(0.0)) ++read;
        if (a.g[0] != a.g[K]) ++differ;
      }
    }
    // Most footprints read the chain (the rest average a cascade out whole), and there the
    // two ends' slopes differ.
    EXPECT_GT(read, 60) << "K " << K;
    EXPECT_EQ(differ, read) << "K " << K;
  }
}

kd::vec3 direct_hessian(const std::vector<Wave>& waves, double x, double z, double t) {
  kd::vec3 h(0.0);
  for (const Wave& w : waves) {
    const double th = w.wave_vector.x * x + w.wave_vector.y * z + w.angular_frequency * t + w.phase;
    const double s = -w.amplitude * std::sin(th);
    const vec2 k = w.wave_vector;
    h += s * kd::vec3(k.x * k.x, k.x * k.y, k.y * k.y);
  }
  return h;
}

TEST(CascadeFields, HessianAtGridPointsIsTheDirectSum) {
  const Sea sea = cascade_sea();
  const Fields fields(sea.scene, 1, 1, kDefaultIntersectTolerance);
  const FrameTime& ft = fields.ft;
  const KernelInputsD& in = fields.in;
  const CascadeDesc& c0 = sea.scene.surface.cascades[0];
  const double h = c0.patch_size / c0.lattice;
  const vec3 cam = sea.scene.camera.position;
  double curv = 0;  // sum A |k|^2
  for (const Wave& w : sea.waves)
    curv += w.amplitude * dot(w.wave_vector, w.wave_vector);
  Pcg32 rng(6, 1);
  double worst = 0;
  for (int s = 0; s < 40; ++s) {
    const double x = (std::floor(cam.x / h) + std::floor(40 * rng.uniform() - 20)) * h;
    const double z = (std::floor(cam.z / h) + std::floor(40 * rng.uniform())) * h;
    const kd::vec3 want = direct_hessian(sea.waves, x, z, ft.end);
    const kd::vec3 got = kd::cascade_hessian(wave_buffer(in), in.frame, x - cam.x, z - cam.z);
    worst = std::max(worst, length(got - want));
  }
  std::printf("Hessian at grid points: |fields - direct| %.3g; sum A|k|^2 %.3g\n", worst, curv);
  EXPECT_LT(worst, 1e-11 * curv);
}

// The direct sum's slope mean and covariance over the parallelogram centre + u J_x + v J_z,
// u, v in [-1/2, 1/2] (a g x g midpoint grid).
struct Direct {
  vec2 mean{0};
  mat2 cov{0};
};
Direct direct_moments(const std::vector<Wave>& waves, vec2 centre, mat2 J, double t, int g) {
  Direct d;
  mat2 second(0.0);
  for (int q = 0; q < g; ++q) {
    for (int p = 0; p < g; ++p) {
      const vec2 at = centre + J * vec2((p + 0.5) / g - 0.5, (q + 0.5) / g - 0.5);
      const vec2 s = direct_gradient(waves, at.x, at.y, t);
      d.mean += s / double(g * g);
      second += glm::outerProduct(s, s) / double(g * g);
    }
  }
  d.cov = second - glm::outerProduct(d.mean, d.mean);
  return d;
}

TEST(CascadeFields, FootprintMomentsAreTheSlopesOverTheFootprint) {
  const Sea sea = cascade_sea();
  const Fields fields(sea.scene, 1, 1, kDefaultIntersectTolerance);
  const FrameTime& ft = fields.ft;
  const KernelInputsD& in = fields.in;
  const kd::WaveBuffer b = wave_buffer(in);
  const vec3 cam = sea.scene.camera.position;
  // The finer cascade's texel (its field's grid): footprints from a quarter of it to a
  // quarter of the coarser patch, square and 4:1 at random angles.
  const kd::Cascade c1 = kd::cascade_at(b, in.frame, 1);
  const double texel = c1.size / c1.n;
  Pcg32 rng(7, 1);
  double mean_err2 = 0, cov_err2 = 0, cov_ref2 = 0, var_sum = 0;
  int count = 0;
  for (double size : {0.25, 1.0, 4.0, 16.0, 64.0}) {
    for (int s = 0; s < 6; ++s) {
      const double angle = 6.283 * rng.uniform();
      const double aspect = s % 2 == 0 ? 1.0 : 4.0;
      const vec2 u(std::cos(angle), std::sin(angle)), w(-u.y, u.x);
      const mat2 J(u * size * texel * aspect, w * size * texel);
      const vec2 centre(cam.x + 40 * rng.uniform() - 20, cam.z + 40 * rng.uniform());
      const Direct want = direct_moments(sea.waves, centre, J, ft.end, 96);
      const kd::CascadeMoments got = kd::cascade_footprint_moments(
          b, in.frame, kd::vec2(centre.x - cam.x, centre.y - cam.z), kd::mat2(J));
      const vec2 dm = vec2(got.mean) - want.mean;
      const vec3 wc(want.cov[0][0], want.cov[0][1], want.cov[1][1]);
      const vec3 dc = vec3(got.cov) - wc;
      mean_err2 += dot(dm, dm);
      cov_err2 += dc.x * dc.x + 2 * dc.y * dc.y + dc.z * dc.z;
      cov_ref2 += wc.x * wc.x + 2 * wc.y * wc.y + wc.z * wc.z;
      var_sum += wc.x + wc.z;
      ++count;
    }
  }
  const double mean_rel = std::sqrt(mean_err2 / count / sea.variance);
  const double cov_rel = std::sqrt(cov_err2 / cov_ref2);
  std::printf(
      "footprint moments over %d footprints: RMS mean error / RMS slope %.4f, covariance "
      "error / covariance (Frobenius, RMS) %.4f; mean footprint variance / whole %.3f\n",
      count, mean_rel, cov_rel, var_sum / count / sea.variance);
  // Measured 0.0812 and 0.147 on the grid twice the lattice's, 0.0912 and 0.191 on the
  // 8x grid (the boxes are the grid's, not the parallelogram); the whole covariance and no
  // mean everywhere give 0.64 and more.
  EXPECT_LT(mean_rel, 0.12);
  EXPECT_LT(cov_rel, 0.25);
}

double direct_height(const std::vector<Wave>& waves, double x, double z, double t) {
  double h = 0;
  for (const Wave& w : waves)
    h += w.amplitude *
         std::sin(w.wave_vector.x * x + w.wave_vector.y * z + w.angular_frequency * t + w.phase);
  return h;
}

TEST(CascadeFields, HeightAndItsInterpolantsBounds) {
  Sea sea = cascade_sea();
  sea.scene.surface.geometry = Geometry::displaced;
  const Fields fields(sea.scene, 2, 1, kDefaultIntersectTolerance);
  const FrameTime& ft = fields.ft;
  const KernelInputsD& in = fields.in;
  ASSERT_EQ(in.frame.cascade_count, 2);
  const kd::WaveBuffer b = wave_buffer(in);
  const vec3 cam = sea.scene.camera.position;
  const CascadeDesc& c0 = sea.scene.surface.cascades[0];
  const double h = c0.patch_size / c0.lattice;
  double amp = 0;
  for (const Wave& w : sea.waves)
    amp += w.amplitude;
  // At the coarser lattice's points (grid points of both fields): the direct sum.
  Pcg32 rng(8, 1);
  double worst = 0;
  for (int s = 0; s < 40; ++s) {
    const double x = (std::floor(cam.x / h) + std::floor(40 * rng.uniform() - 20)) * h;
    const double z = (std::floor(cam.z / h) + std::floor(40 * rng.uniform())) * h;
    const double got = kd::cascade_height_gradient(b, in.frame, x - cam.x, z - cam.z).x;
    worst = std::max(worst, std::abs(got - direct_height(sea.waves, x, z, ft.end)));
  }
  std::printf("height at grid points: |fields - direct| %.3g; sum A %.3g\n", worst, amp);
  EXPECT_LT(worst, 1e-11 * amp);
  // Between them: the gradient is the interpolant's own (central differences), and the
  // interpolant stays within the frame's bounds: height, slope along a direction and
  // second derivative along one.
  const kd::vec3 cb = kd::cascade_bounds(b, in.frame);
  EXPECT_LT(cb.x, amp) << "the interpolant's bound is tighter than the sines' sum A";
  double grad_err = 0, grad_ref = 0, peak_h = 0, peak_s = 0, peak_c = 0;
  const double e = 1e-4;
  for (int s = 0; s < 400; ++s) {
    const double x = 60 * rng.uniform() - 30, z = 60 * rng.uniform();
    const kd::vec3 at = kd::cascade_height_gradient(b, in.frame, x, z);
    auto hh = [&](double dx, double dz) {
      return kd::cascade_height_gradient(b, in.frame, x + dx, z + dz).x;
    };
    const vec2 fd((hh(e, 0) - hh(-e, 0)) / (2 * e), (hh(0, e) - hh(0, -e)) / (2 * e));
    grad_err = std::max(grad_err, length(vec2(at.y, at.z) - fd));
    grad_ref = std::max(grad_ref, length(fd));
    const double angle = 6.283 * rng.uniform();
    const vec2 u(std::cos(angle), std::sin(angle));
    const double dd = 1e-3;
    const double second =
        (hh(dd * u.x, dd * u.y) - 2 * at.x + hh(-dd * u.x, -dd * u.y)) / (dd * dd);
    peak_h = std::max(peak_h, std::abs(at.x));
    peak_s = std::max(peak_s, std::abs(at.y * u.x + at.z * u.y));
    peak_c = std::max(peak_c, std::abs(second));
  }
  std::printf(
      "interpolant: gradient vs differences %.3g of %.3g; peaks / bounds: height %.3g / %.3g, "
      "slope %.3g / %.3g, curvature %.3g / %.3g\n",
      grad_err, grad_ref, peak_h, cb.x, peak_s, cb.y, peak_c, cb.z);
  EXPECT_LT(grad_err, 1e-6 * grad_ref);
  EXPECT_LE(peak_h, cb.x);
  EXPECT_LE(peak_s, cb.y);
  EXPECT_LE(peak_c, cb.z);
  // The frame's bounds are the fields' (no explicit waves here).
  EXPECT_DOUBLE_EQ(in.frame.amplitude_bound, cb.x);
  EXPECT_DOUBLE_EQ(in.frame.slope_bound, cb.y);
}

TEST(CascadeFields, MarchHitsTheInterpolatedSurface) {
  Sea sea = cascade_sea();
  sea.scene.surface.geometry = Geometry::displaced;
  const Fields fields(sea.scene, 2, 1, 0.0);
  const KernelInputsD& in = fields.in;
  const kd::WaveBuffer b = wave_buffer(in);
  const kd::Frame& f = in.frame;
  int hits = 0;
  double worst_surface = 0, worst_above = 0;
  for (int j = 0; j < 36; j += 3) {
    for (int i = 0; i < 64; i += 3) {
      const kd::vec3 d = normalize(kd::camera_direction(f.camera, i + 0.5, j + 0.5));
      const kd::RayHit hit = kd::intersect_displaced(b, f, f.camera.position, d, 0.0);
      if (!hit.hit) continue;
      ++hits;
      // The ray's own point at the hit's parameter (the hit's y is set to the surface's).
      const kd::vec3 on_ray = f.camera.position + hit.s * d;
      const double surface = kd::cascade_height_gradient(b, f, on_ray.x, on_ray.z).x;
      worst_surface = std::max(worst_surface, std::abs(on_ray.y - surface));
      // Before the hit the ray is above the surface (200 looks along it).
      for (int q = 1; q < 200; ++q) {
        const kd::vec3 p = f.camera.position + (hit.s * q / 200.0) * d;
        const double below = kd::cascade_height_gradient(b, f, p.x, p.z).x - p.y;
        worst_above = std::max(worst_above, below);
      }
    }
  }
  std::printf("march on the fields: %d hits, |y - h| at the hit %.3g, deepest dip before %.3g\n",
              hits, worst_surface, worst_above);
  EXPECT_GT(hits, 100);
  EXPECT_LT(worst_surface, 1e-6);
  EXPECT_LE(worst_above, 1e-6);
}

// On displaced water the path's points follow the water as it rises and falls over the
// shutter (reflection_path.glsl, path_views): each instant's point lies on the pixel's ray
// and on the water of that instant, to the Newton step's second order. Over the fields
// (whose other instants hold their heights on displaced water) and over the same waves as
// sines, K = 2; the fields' heights at the instants are the direct sum's.
TEST(CascadeFields, PathPointsFollowTheRisingWater) {
  Sea sea = cascade_sea();
  sea.scene.surface.geometry = Geometry::displaced;
  Scene sines = sea.scene;
  sines.surface.cascades.clear();
  sines.surface.waves = sea.waves;
  const int K = 2;
  const vec3 cam = sea.scene.camera.position;
  for (const bool fields : {true, false}) {
    const Fields in_f(fields ? sea.scene : sines, 2, K, 0.0);
    const KernelInputsD& in = in_f.in;
    const kd::WaveBuffer b = wave_buffer(in);
    const kd::Frame& f = in.frame;
    double moved = 0, off = 0, off_direct = 0;
    int points = 0;
    for (int j = 0; j < 36; j += 3) {
      for (int i = 0; i < 64; i += 3) {
        const kd::Footprint fp = kd::pixel_footprint(b, f, i + 0.5, j + 0.5, 0.0, true);
        if (!fp.hit) continue;
        const kd::PathViews v = kd::path_views(b, f, fp, i + 0.5, j + 0.5);
        ASSERT_TRUE(v.moving);
        ASSERT_FALSE(v.camera_moves);
        const kd::vec3 d = -fp.view;
        for (int k = 0; k < K; ++k) {
          const double dt = kd::path_instant_dt(f, k), t = instant_time(in_f.ft, K, k);
          auto water = [&](kd::vec2 p) {
            return kd::water_height_slope_at_instant(b, f, k, p.x, p.y, dt, kd::vec2(0.0)).x;
          };
          // The instant's point on the ray: p_K + s d, s from its horizontal offset.
          const kd::vec2 shift = v.point[k] - kd::vec2(fp.point.x, fp.point.z);
          const double s =
              dot(shift, kd::vec2(d.x, d.z)) / dot(kd::vec2(d.x, d.z), kd::vec2(d.x, d.z));
          EXPECT_LT(length(shift - s * kd::vec2(d.x, d.z)), 1e-12) << "off the ray";
          const double y = fp.point.y + s * d.y;
          moved += std::abs(water(kd::vec2(fp.point.x, fp.point.z)) - fp.point.y);
          off += std::abs(water(v.point[k]) - y);
          off_direct +=
              std::abs(direct_height(sea.waves, v.point[k].x + cam.x, v.point[k].y + cam.z, t) - y);
          EXPECT_LT(length(v.view[k] - fp.view), 1e-12);
          ++points;
        }
      }
    }
    std::printf(
        "%s: the water moves %.3g m at the held point on average, the moved point is %.3g m "
        "off its instant's water (%.3g m off the direct sum)\n",
        fields ? "fields" : "sines", moved / points, off / points, off_direct / points);
    EXPECT_GT(points, 100);
    EXPECT_GT(moved / points, 0.005);  // the water does move over the shutter
    EXPECT_LT(off, 0.02 * moved);
    EXPECT_LT(off_direct, 0.05 * moved);
  }
}

// The tolerance leaves out the last cascades where the rest fits tau eps s (intersect.glsl):
// every hit lies within that of the whole interpolated surface, vertically, the ray never
// dips further below it before the hit, and far rays do march fewer cascades.
TEST(CascadeFields, MarchWithinItsToleranceOfTheWholeSurface) {
  Sea sea = cascade_sea();
  sea.scene.surface.geometry = Geometry::displaced;
  sea.scene.camera.look_at = vec3(1234.5, 0.0, -676.25);  // 200 m ahead: far rays
  const double tau = 1.0;
  const Fields fields(sea.scene, 2, 1, tau), whole(sea.scene, 2, 1, 0.0);
  const KernelInputsD& in = fields.in;
  const kd::WaveBuffer b = wave_buffer(in);
  const kd::Frame& f = in.frame;
  const kd::WaveBuffer bw = wave_buffer(whole.in);
  ASSERT_EQ(f.cascade_count, 2);
  int hits = 0, fewer = 0, moved = 0;
  double worst_surface = 0, worst_dip = 0;  // in units of the tolerance at that point
  for (int j = 0; j < 36; j += 2) {
    for (int i = 0; i < 64; i += 3) {
      const kd::vec3 d = normalize(kd::camera_direction(f.camera, i + 0.5, j + 0.5));
      const double eps = kd::pixel_angle(f.camera, d);
      const kd::RayHit hit = kd::intersect_displaced(b, f, f.camera.position, d, 0.0);
      if (!hit.hit) continue;
      ++hits;
      if (kd::first_cascade_below(b, f, tau * eps * hit.s) < f.cascade_count) ++fewer;
      const kd::RayHit w = kd::intersect_displaced(bw, whole.in.frame, f.camera.position, d, 0.0);
      if (!w.hit || std::abs(w.s - hit.s) > 1e-6 * hit.s) ++moved;
      const kd::vec3 on_ray = f.camera.position + hit.s * d;
      const double surface = kd::cascade_height_gradient(b, f, on_ray.x, on_ray.z).x;
      worst_surface =
          std::max(worst_surface, (std::abs(on_ray.y - surface) - 1e-6) / (tau * eps * hit.s));
      for (int q = 1; q < 200; ++q) {
        const double sq = hit.s * q / 200.0;
        const kd::vec3 p = f.camera.position + sq * d;
        const double below = kd::cascade_height_gradient(b, f, p.x, p.z).x - p.y;
        worst_dip = std::max(worst_dip, (below - 1e-6) / (tau * eps * sq));
      }
    }
  }
  std::printf(
      "march with tolerance %.2g: %d hits, %d with the last cascade left out, %d moved from "
      "the whole surface's; |y - h| at the hit %.3g and the deepest dip before %.3g of the "
      "tolerance there\n",
      tau, hits, fewer, moved, worst_surface, worst_dip);
  EXPECT_GT(hits, 100);
  EXPECT_GT(fewer, hits / 20) << "far rays leave the finest cascade out";
  EXPECT_GT(moved, 0) << "the march leaves it out";
  EXPECT_LE(worst_surface, 1.0);
  EXPECT_LE(worst_dip, 1.0);
}

TEST(CascadeFields, ReducedReadsShadeTheSameAsTheWholeFields) {
  // Flat and displaced, double and float, K = 1 to 3 (the slopes two to a transform on the
  // GL engine, one left over at K = 2): every pixel of `point`, `supersample 2x2x1` and
  // `staa-temporal` from the fields its method builds against the same pixel from the
  // whole fields. Were a method to read a texel its reads leave out (a later level, the
  // curvatures, an instant), the pixels would differ: the reduced texels are 0 there.
  Sea sea = cascade_sea(0.5);
  // Schlick's Fresnel and a sky gradient: every pixel's weights follow its normal.
  sea.scene.surface.fresnel = FresnelMode::schlick;
  sea.scene.sky = SkyDesc{Rgb(0.02), Rgb(0.1), 0.5, true};
  int lit = 0;  // pixels that a read texel changes
  for (const Geometry geometry : {Geometry::flat, Geometry::displaced}) {
    sea.scene.surface.geometry = geometry;
    const SceneModel m(sea.scene);
    const FrameTime ft = frame_time(sea.scene, 3);
    for (int K = 1; K <= 3; ++K) {
      KernelInputsD all, display, instants;
      KernelInputsF all_f, display_f, instants_f;
      build_kernel_inputs(m, ft, K, 0, all, 0.25, 1, true);
      build_kernel_inputs(m, ft, K, 0, display, 0.25, 1, true, CascadeData::host,
                          CascadeReads::display_level0);
      build_kernel_inputs(m, ft, K, 0, instants, 0.25, 1, true, CascadeData::host,
                          CascadeReads::instants_level0);
      build_kernel_inputs(m, ft, K, 0, all_f, 0.25, 1, true);
      build_kernel_inputs(m, ft, K, 0, display_f, 0.25, 1, true, CascadeData::host,
                          CascadeReads::display_level0);
      build_kernel_inputs(m, ft, K, 0, instants_f, 0.25, 1, true, CascadeData::host,
                          CascadeReads::instants_level0);
      // Not vacuous: the reduced fields leave texels 0 that the whole fields fill, and the
      // comparison sees a texel that is read: the display time's slopes of cascade 0 made
      // 0 change the pixels.
      size_t differ = 0;
      for (size_t e = 0; e < all.texels.size(); ++e)
        differ += all.texels[e] != display.texels[e];
      ASSERT_GT(differ, all.texels.size() / 2);
      KernelInputsD broken = display;
      const CascadeLayout& lay = display.cascades->layout();
      const size_t at =
          lay.data[0] + static_cast<size_t>(K) * kd::cascade_instant_texels(lay.grid[0]);
      for (size_t e = 0; e < static_cast<size_t>(lay.grid[0]) * lay.grid[0]; ++e)
        broken.texels[at + 2 * e] = kd::vec4(0.0);
      kd::SampleCounts n{2, 2, 1, true};
      // The same to rounding: the whole fields' display-time slopes come from transforms
      // that carry the curvatures too (scene/cascade_fft.h), a few 1e-16 apart.
      auto same = [](auto a, auto b, double tol) {
        for (int c = 0; c < 4; ++c)
          if (!(std::fabs(double(a[c]) - double(b[c])) <= tol * (1.0 + std::fabs(double(a[c])))))
            return false;
        return true;
      };
      for (int j = 0; j < m.height(); ++j) {
        for (int i = 0; i < m.width(); ++i) {
          const kd::vec4 p = kd::point_pixel(wave_buffer(all), all.frame, i, j);
          ASSERT_TRUE(same(p, kd::point_pixel(wave_buffer(display), display.frame, i, j), 1e-12))
              << i << "," << j;
          ASSERT_TRUE(same(kd::stratified_pixel(wave_buffer(all), all.frame, n, i, j),
                           kd::stratified_pixel(wave_buffer(display), display.frame, n, i, j),
                           1e-12));
          ASSERT_TRUE(same(kd::staa_temporal_pixel(wave_buffer(all), all.frame, i, j),
                           kd::staa_temporal_pixel(wave_buffer(instants), instants.frame, i, j),
                           1e-12));
          ASSERT_TRUE(same(kf::float_point_pixel(wave_buffer(all_f), all_f.frame, i, j),
                           kf::float_point_pixel(wave_buffer(display_f), display_f.frame, i, j),
                           1e-5));
          ASSERT_TRUE(
              same(kf::float_staa_temporal_pixel(wave_buffer(all_f), all_f.frame, i, j),
                   kf::float_staa_temporal_pixel(wave_buffer(instants_f), instants_f.frame, i, j),
                   1e-5));
          lit += !same(p, kd::point_pixel(wave_buffer(broken), broken.frame, i, j), 1e-12);
        }
      }
    }
  }
  std::printf("pixels that the display time's slopes of one cascade change: %d of %d\n", lit,
              6 * sea.scene.width * sea.scene.height);
  EXPECT_GT(lit, sea.scene.width * sea.scene.height);
}

// The baselines (`lean`, `specaa`, `bruneton`) read the
// display time alone; their fields (CascadeReads::display_chain) are the whole fields'
// display time, texel for texel (but level 0's instant 0 slopes, b.zw, which they leave 0),
// the other instants 0, and the baselines' reads of them the same to the bit, at K = 1
// and 3, with a shutter and without.
TEST(CascadeFields, DisplayChainIsTheWholeFieldsDisplayTime) {
  for (const double shutter : {1.0, 0.0}) {
    const Sea sea = cascade_sea(shutter);
    const SceneModel m(sea.scene);
    const FrameTime ft = frame_time(sea.scene, 3);
    for (int K : {1, 3}) {
      KernelInputsD all, display;
      build_kernel_inputs(m, ft, K, 0, all, 0.25, 1, true);
      build_kernel_inputs(m, ft, K, 0, display, 0.25, 1, true, CascadeData::host,
                          CascadeReads::display_chain);
      ASSERT_EQ(all.texels.size(), display.texels.size());
      const CascadeLayout& lay = display.cascades->layout();
      // Every texel before the cascades' data (the waves, headers and bounds) and each
      // cascade's display-time chain the same; the other instants 0 where the whole
      // fields fill them.
      size_t others = 0;
      for (size_t e = 0; e < lay.data[0]; ++e)
        ASSERT_EQ(all.texels[e], display.texels[e]) << e;
      for (size_t c = 0; c < lay.data.size(); ++c) {
        const size_t per = static_cast<size_t>(kd::cascade_instant_texels(lay.grid[c]));
        for (int k = 0; k <= K; ++k) {
          for (size_t e = 0; e < per; ++e) {
            const size_t at = lay.data[c] + static_cast<size_t>(k) * per + e;
            if (k == K && e < 2 * size_t(lay.grid[c]) * lay.grid[c] && e % 2 == 1) {
              // Level 0's second texel: instant 0's slopes left 0.
              const kd::vec4 a = all.texels[at], d = display.texels[at];
              ASSERT_EQ(kd::vec4(a.x, a.y, 0.0, 0.0), d) << "cascade " << c << " texel " << e;
              others += a.z != 0.0;
            } else if (k == K) {
              ASSERT_EQ(all.texels[at], display.texels[at]) << "cascade " << c << " texel " << e;
            } else {
              ASSERT_EQ(display.texels[at], kd::vec4(0.0));
              others += all.texels[at] != kd::vec4(0.0);
            }
          }
        }
      }
      EXPECT_GT(others, 0u) << "shutter " << shutter << " K " << K;
      // What the baselines read: the footprint moments, the slope and the Hessian.
      std::mt19937 rng(K);
      std::uniform_real_distribution<double> u(-30.0, 30.0), s(0.01, 3.0);
      for (int q = 0; q < 200; ++q) {
        const kd::vec2 p(u(rng), u(rng));
        const kd::mat2 J(s(rng), 0.1 * u(rng) / 30, 0.1 * u(rng) / 30, s(rng));
        const kd::CascadeMoments a =
            kd::cascade_footprint_moments(wave_buffer(all), all.frame, p, J);
        const kd::CascadeMoments b =
            kd::cascade_footprint_moments(wave_buffer(display), display.frame, p, J);
        EXPECT_EQ(a.mean, b.mean);
        EXPECT_EQ(a.cov, b.cov);
        EXPECT_EQ(kd::cascade_gradient(wave_buffer(all), all.frame, K, p.x, p.y),
                  kd::cascade_gradient(wave_buffer(display), display.frame, K, p.x, p.y));
        EXPECT_EQ(kd::cascade_hessian(wave_buffer(all), all.frame, p.x, p.y),
                  kd::cascade_hessian(wave_buffer(display), display.frame, p.x, p.y));
      }
    }
  }
}

}  // namespace
}  // namespace sg
