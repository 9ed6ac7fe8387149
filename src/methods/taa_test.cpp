// Temporal anti-aliasing (methods/taa.h; its sample and resolve, kernel/taa.glsl).
//  - Halton (2, 3) values and the jitter cycle; history resampling; variance clipping of an
//    outlier history to the neighbourhood box; the resolve of a pixel against its parts.
//  - A constant input converges to itself (exponentially without clamping, at once with
//    variance clipping); with alpha = 1 the output is the current jittered frame.
//  - Warm-up: frame F alone equals frame F of the sequence started at F - N; sequences are
//    deterministic and independent of the threads.
//  - Motion vectors of displaced water point to where the surface point was seen, by the
//    previous frame's camera when the camera moves (format /3).
//  - A panning camera: the history reprojected with the camera's motion is clearly closer to a
//    supersampled image than the history reprojected as if the camera stood still
//    (`--taa-motion surface`).
//  - Calm water against the analytic mirrored disk; the shared scenes and a displaced,
//    Schlick, sky-and-sea variant render without NaN or Inf.
#include "methods/taa.h"

#include <gtest/gtest.h>

#include <cmath>

#include "base/error.h"
#include "engine/render.h"
#include "kernel/kernel_double.h"
#include "methods/method.h"
#include "metrics/metrics.h"
#include "scene/camera_path.h"
#include "shading/radiance.h"
#include "shading/water_geometry.h"
#include "testing/calm_water.h"
#include "testing/path_tables.h"
#include "testing/testing.h"

namespace sg {
namespace {

using kd::halton;
using kd::taa_jitter;

kd::ImagePlanes planes(const Image& img) {
  return kd::ImagePlanes{img.data.data(), img.width, img.channels};
}
kd::ivec2 size_of(const Image& img) {
  return kd::ivec2(img.width, img.height);
}

// Channel 0 of the history at p (kernel/taa.glsl, taa_history).
bool sample_history(const Image& h, const vec2& p, TaaHistoryFilter f, double& v) {
  const kd::TaaHistory r =
      kd::taa_history(planes(h), size_of(h), p, f == TaaHistoryFilter::catmull_rom, 0);
  v = r.value;
  return r.found;
}

int clamp_mode(TaaClamp c) {
  return c == TaaClamp::minmax ? kd::kTaaClampMinmax : kd::kTaaClampVariance;
}

TEST(TaaResolve, HaltonTwoThree) {
  const double h2[] = {0, 1. / 2, 1. / 4, 3. / 4, 1. / 8, 5. / 8, 3. / 8, 7. / 8, 1. / 16};
  const double h3[] = {0, 1. / 3, 2. / 3, 1. / 9, 4. / 9, 7. / 9, 2. / 9, 5. / 9, 8. / 9};
  for (int k = 0; k < 9; ++k) {
    EXPECT_DOUBLE_EQ(halton(k, 2), h2[k]) << k;
    EXPECT_DOUBLE_EQ(halton(k, 3), h3[k]) << k;
  }
  EXPECT_DOUBLE_EQ(halton(11, 2), 13. / 16);  // 1011 -> 0.1101
  EXPECT_DOUBLE_EQ(halton(16, 3), 16. / 27);  // 121 -> 0.121
}

TEST(TaaResolve, JitterCyclesThroughHaltonOffsetsInsideThePixel) {
  for (int f = -20; f < 20; ++f) {
    const vec2 j = taa_jitter(f, 8);
    const int k = ((f % 8) + 8) % 8 + 1;
    EXPECT_EQ(j, vec2(halton(k, 2) - 0.5, halton(k, 3) - 0.5));
    EXPECT_EQ(j, taa_jitter(f + 8, 8));
    EXPECT_GE(j.x, -0.5);
    EXPECT_LT(j.x, 0.5);
    EXPECT_GE(j.y, -0.5);
    EXPECT_LT(j.y, 0.5);
  }
  EXPECT_EQ(taa_jitter(0, 1), taa_jitter(5, 1));
}

TEST(TaaResolve, HistoryResampling) {
  Image h(8, 6);
  for (int j = 0; j < 6; ++j) {
    for (int i = 0; i < 8; ++i)
      h.at(i, j) = static_cast<float>(i + 10 * j);
  }
  double v;
  for (auto f : {TaaHistoryFilter::bilinear, TaaHistoryFilter::catmull_rom}) {
    // Pixel centres return the pixel; between centres the linear ramp is reproduced
    // (Catmull-Rom reproduces linear functions too, away from the clamped edge).
    ASSERT_TRUE(sample_history(h, vec2(2.5, 1.5), f, v));
    EXPECT_DOUBLE_EQ(v, 12.0);
    ASSERT_TRUE(sample_history(h, vec2(3.2, 3.25), f, v));
    EXPECT_NEAR(v, 2.7 + 10 * 2.75, 1e-12);
    // Outside the image: rejected.
    EXPECT_FALSE(sample_history(h, vec2(-0.01, 1.5), f, v));
    EXPECT_FALSE(sample_history(h, vec2(2.0, 6.01), f, v));
    // At the edge the texels clamp.
    ASSERT_TRUE(sample_history(h, vec2(0.0, 0.5), f, v));
    EXPECT_NEAR(v, 0.0, 1e-12);
  }
  // Catmull-Rom is sharper than bilinear on a step and does not ring past its neighbours.
  Image step(8, 1);
  for (int i = 4; i < 8; ++i)
    step.at(i, 0) = 1.0f;
  double b, c;
  sample_history(step, vec2(4.25, 0.5), TaaHistoryFilter::bilinear, b);
  sample_history(step, vec2(4.25, 0.5), TaaHistoryFilter::catmull_rom, c);
  EXPECT_DOUBLE_EQ(b, 0.75);
  EXPECT_GT(c, b);
  EXPECT_LE(c, 1.0);
}

TEST(TaaResolve, VarianceClippingClampsAnOutlierHistoryToTheBox) {
  Image cur(3, 3);
  const float vals[9] = {0.1f, 0.2f, 0.3f, 0.2f, 0.2f, 0.2f, 0.1f, 0.3f, 0.2f};
  for (int k = 0; k < 9; ++k)
    cur.at(k % 3, k / 3) = vals[k];
  double mu = 0, m2 = 0;
  for (float v : vals) {
    mu += double(v) / 9;
    m2 += double(v) * v / 9;
  }
  const double sigma = std::sqrt(m2 - mu * mu);
  const kd::ImagePlanes c = planes(cur);
  const kd::vec2 box = kd::taa_box(c, size_of(cur), 1, 1, clamp_mode(TaaClamp::variance), 1.5, 0);
  EXPECT_NEAR(box.x, mu - 1.5 * sigma, 1e-12);
  EXPECT_NEAR(box.y, mu + 1.5 * sigma, 1e-12);
  const kd::vec2 mm = kd::taa_box(c, size_of(cur), 1, 1, clamp_mode(TaaClamp::minmax), 1.0, 0);
  EXPECT_NEAR(mm.x, 0.1, 1e-7);
  EXPECT_NEAR(mm.y, 0.3, 1e-7);
  // A corner uses its 2 x 2 neighbourhood.
  const kd::vec2 corner = kd::taa_box(c, size_of(cur), 0, 0, clamp_mode(TaaClamp::minmax), 1.0, 0);
  EXPECT_NEAR(corner.x, 0.1, 1e-7);
  EXPECT_NEAR(corner.y, 0.2, 1e-7);
  // The resolve of the centre pixel (motion 0: the history's own texel): an outlier history
  // clipped to the box above and below, kept inside it, kept whole without a clamp, and
  // blended with the current sample at alpha.
  const double now = cur.at(1, 1);
  auto resolve = [&](double history, TaaClamp mode) {
    Image h(3, 3, static_cast<float>(history));
    TaaOptions o;
    o.clamp = mode;
    o.gamma = 1.5;
    o.alpha = 0.25;
    const kd::TaaResolved r = kd::taa_resolve_pixel(c, planes(h), taa_resolve_params(o, 3, 3, 1),
                                                    true, kd::vec2(0.0), 1, 1);
    EXPECT_FALSE(r.fallback);
    return r.value.x;
  };
  EXPECT_NEAR(resolve(5.0, TaaClamp::variance), 0.75 * (mu + 1.5 * sigma) + 0.25 * now, 1e-12);
  EXPECT_NEAR(resolve(-1.0, TaaClamp::variance), 0.75 * (mu - 1.5 * sigma) + 0.25 * now, 1e-12);
  EXPECT_NEAR(resolve(0.21, TaaClamp::variance), 0.75 * double(0.21f) + 0.25 * now, 1e-12);
  EXPECT_NEAR(resolve(7.0, TaaClamp::none), 0.75 * 7.0 + 0.25 * now, 1e-12);
  EXPECT_NEAR(resolve(7.0, TaaClamp::minmax), 0.75 * double(0.3f) + 0.25 * now, 1e-12);
}

TEST(TaaResolve, APixelWithoutHistoryOrWithANonFiniteBlendShowsItsCurrentSample) {
  Image cur(4, 4, 0.5f), hist(4, 4, 0.25f);
  cur.at(2, 2) = 0.75f;
  TaaOptions o;
  o.clamp = TaaClamp::none;
  const kd::TaaResolveParams p = taa_resolve_params(o, 4, 4, 1);
  auto at = [&](const Image& h, bool has, kd::vec2 motion) {
    return kd::taa_resolve_pixel(planes(cur), planes(h), p, has, motion, 2, 2);
  };
  EXPECT_NEAR(at(hist, true, kd::vec2(0.0)).value.x, 0.9 * 0.25 + 0.1 * 0.75, 1e-12);
  // A motion of one pixel fetches the history one pixel to the left.
  hist.at(1, 2) = 1.0f;
  EXPECT_NEAR(at(hist, true, kd::vec2(1.0, 0.0)).value.x, 0.9 * 1.0 + 0.1 * 0.75, 1e-12);
  EXPECT_EQ(at(hist, false, kd::vec2(0.0)).value.x, 0.75);               // no history yet
  EXPECT_EQ(at(hist, true, kd::vec2(kd::kTaaNoHistory)).value.x, 0.75);  // off the image
  EXPECT_EQ(at(hist, true, kd::vec2(2.6, 0.0)).value.x, 0.75);           // x = 2.5 - 2.6 < 0
  hist.at(2, 2) = INFINITY;
  const kd::TaaResolved bad = at(hist, true, kd::vec2(0.0));
  EXPECT_TRUE(bad.fallback);
  EXPECT_EQ(bad.value.x, 0.75);
}

// A scene whose camera sees only sky: every sample is the sky's radiance.
Scene sky_scene(double sky) {
  Scene s = testing::small_scene({Wave{0.05, {0.3, -1.2}, 3.4, 0.0}}, 24, 16);
  s.camera.look_at = vec3(0, 40, -60);  // 34 degrees up, 20 degrees half fov: all sky
  s.sky = SkyDesc::constant(Rgb(sky));
  return s;
}

TEST(Taa, ConstantInputConvergesToIt) {
  for (TaaClamp clamp : {TaaClamp::none, TaaClamp::variance}) {
    TaaOptions o;
    o.clamp = clamp;
    TaaMethod taa(o);
    SceneModel before(sky_scene(0.7)), after(sky_scene(0.3));
    RenderSettings rs;
    Image img = render_frame(before, taa, 0, rs);  // the history holds 0.7
    EXPECT_FLOAT_EQ(img.at(5, 5), 0.7f);
    for (int f = 1; f <= 40; ++f) {
      img = render_frame(after, taa, f, rs);  // the input is now 0.3 everywhere
      const double expected = clamp == TaaClamp::none ? 0.3 + 0.4 * std::pow(0.9, f) : 0.3;
      for (float v : img.data)
        ASSERT_NEAR(v, expected, 1e-6) << f;
    }
    EXPECT_NEAR(img.at(3, 3), 0.3, clamp == TaaClamp::none ? 0.01 : 1e-7);
  }
}

TEST(Taa, AlphaOneOutputsTheCurrentJitteredFrame) {
  Scene s = testing::project_scene("simple");
  set_image_size(s, 160, 90);
  SceneModel m(s);
  TaaOptions o;
  o.alpha = 1.0;
  o.warmup = 3;
  TaaMethod taa(o);
  int lit = 0;
  render_frames(m, taa, 5, 7, RenderSettings{}, [&](int f, const Image& img) {
    const vec2 jit = vec2(taa_jitter(f, 8));
    const WaterGeometry water(m, frame_time(s, f));
    for (int j = 0; j < m.height(); ++j) {
      for (int i = 0; i < m.width(); ++i) {
        const double v =
            grey_value(m, weights_along_ray(water, m.camera.position(),
                                            m.camera.direction(i + 0.5 + jit.x, j + 0.5 + jit.y),
                                            s.frame_time(f)));
        ASSERT_EQ(img.at(i, j), static_cast<float>(v)) << i << "," << j;
        lit += v > 0.5;
      }
    }
  });
  EXPECT_GT(lit, 0);
}

bool same(const Image& a, const Image& b) {
  return a.data == b.data;
}

TEST(Taa, WarmupMakesFrameFAloneEqualToFrameFOfASequenceStartedAtFMinusN) {
  Scene s = testing::project_scene("high");
  set_image_size(s, 96, 54);
  s.light.angular_radius_deg = 3;  // a broad glitter: history visibly changes the frame
  SceneModel m(s);
  const int F = 9, N = 16;
  TaaOptions with, without;
  with.warmup = N;
  without.warmup = 0;
  // Without clamping every frame of the history counts, so a warm-up one frame short shows.
  with.clamp = without.clamp = TaaClamp::none;
  TaaMethod alone(with), seq(without), seq_warm(with);
  Image single, from_seq, first_of_warm_seq, again;
  render_frames(m, alone, F, F, RenderSettings{}, [&](int, const Image& i) { single = i; });
  render_frames(m, seq, F - N, F, RenderSettings{}, [&](int f, const Image& i) {
    if (f == F) from_seq = i;
  });
  render_frames(m, seq_warm, F, F + 2, RenderSettings{}, [&](int f, const Image& i) {
    if (f == F) first_of_warm_seq = i;
  });
  EXPECT_TRUE(same(single, from_seq));
  EXPECT_TRUE(same(single, first_of_warm_seq));
  // The warm-up changed the frame (it has history), and the same method object renders the
  // same frame again after a reset (render_frames resets it).
  TaaMethod cold(without);
  Image no_history;
  render_frames(m, cold, F, F, RenderSettings{}, [&](int, const Image& i) { no_history = i; });
  EXPECT_FALSE(same(single, no_history));
  render_frames(m, alone, F, F, RenderSettings{}, [&](int, const Image& i) { again = i; });
  EXPECT_TRUE(same(single, again));
  // A later sequence whose warm-up starts right after the frame the method rendered last
  // still starts from an empty history (render_frames resets the method).
  Image later, later_fresh;
  render_frames(m, alone, F + N + 1, F + N + 1, RenderSettings{},
                [&](int, const Image& i) { later = i; });
  TaaMethod fresh(with);
  render_frames(m, fresh, F + N + 1, F + N + 1, RenderSettings{},
                [&](int, const Image& i) { later_fresh = i; });
  EXPECT_TRUE(same(later, later_fresh));
}

TEST(Taa, AFrameThatDoesNotFollowThePreviousOneStartsWithoutHistory) {
  Scene s = testing::project_scene("high");
  set_image_size(s, 96, 54);
  s.light.angular_radius_deg = 3;
  SceneModel m(s);
  TaaOptions o;
  o.clamp = TaaClamp::none;
  TaaMethod a(o), b(o);
  render_frame(m, a, 3, RenderSettings{});
  render_frame(m, a, 4, RenderSettings{});
  EXPECT_TRUE(a.has_history());
  const Image cut = render_frame(m, a, 9, RenderSettings{});  // a cut: history dropped
  const Image fresh = render_frame(m, b, 9, RenderSettings{});
  EXPECT_TRUE(same(cut, fresh));
  // Both now continue from the same history.
  EXPECT_TRUE(
      same(render_frame(m, a, 10, RenderSettings{}), render_frame(m, b, 10, RenderSettings{})));
}

TEST(Taa, SequencesAreDeterministicAcrossRunsAndThreads) {
  Scene s = testing::project_scene("smooth");
  set_image_size(s, 80, 45);
  SceneModel m(s);
  TaaOptions o;
  o.warmup = 4;
  auto run = [&](int threads, int tile) {
    TaaMethod taa(o);
    RenderSettings rs;
    rs.threads = threads;
    rs.tile = tile;
    std::vector<Image> out;
    render_frames(m, taa, 2, 6, rs, [&](int, const Image& i) { out.push_back(i); });
    return out;
  };
  const auto a = run(1, 16), b = run(2, 7), c = run(0, 16);
  ASSERT_EQ(a.size(), 5u);
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_TRUE(same(a[k], b[k])) << k;
    EXPECT_TRUE(same(a[k], c[k])) << k;
  }
}

TEST(Taa, DisplacedMotionVectorsPointToWhereTheSurfacePointWasSeen) {
  // One long, fast wave: displaced hits move between frames. For a sample that hit the
  // water at X at t_f, the ray through the reprojected position p - motion at t_{f-1}
  // must hit the surface at X's (x, z) (unless something occludes it).
  Scene s = testing::small_scene({Wave{0.3, {0.0, -0.5}, 3.0, 0.0}}, 64, 36);
  s.surface.geometry = Geometry::displaced;
  SceneModel m(s);
  TaaOptions o;
  TaaMethod taa(o);
  const int f = 4;
  FrameContext ctx{m, frame_time(s, f), 0};
  taa.begin_frame(ctx);
  const vec2 jit = taa.jitter();
  const double t_prev = s.frame_time(f - 1);
  const WaterGeometry water(m, ctx.time);
  int checked = 0, moved = 0;
  for (int j = 14; j < 36; j += 3) {
    for (int i = 2; i < 64; i += 7) {
      const vec2 p = vec2(i + 0.5, j + 0.5) + jit;
      vec2 motion(0);
      Image one(64, 36);
      taa.shade_tile(ctx, i, j, i + 1, j + 1, one);
      motion = taa.motion()[static_cast<size_t>(j) * 64 + i];
      RayHit now = water.intersect(m.camera.position(), m.camera.direction(p.x, p.y), ctx.time.end);
      if (!now.hit) continue;
      const vec2 q = p - motion;
      RayHit then = water.intersect(m.camera.position(), m.camera.direction(q.x, q.y), t_prev);
      ASSERT_TRUE(then.hit);
      if (length(vec2(then.point.x - now.point.x, then.point.z - now.point.z)) < 1e-6) {
        ++checked;
      }
      moved += length(motion) > 0.05;
    }
  }
  EXPECT_GT(checked, 60);
  EXPECT_GT(moved, 20);
}

TEST(Taa, FlatWaterHasNoMotion) {
  Scene s = testing::project_scene("simple");
  set_image_size(s, 64, 36);
  SceneModel m(s);
  TaaMethod taa(TaaOptions{});
  render_frame(m, taa, 3, RenderSettings{});
  for (const vec2& v : taa.motion())
    ASSERT_EQ(v, vec2(0.0));
}

// A camera that flies forward (6 m/s) and turns (about 2 degrees a frame at 30 fps, and a
// little up) over gentle waves, towards a low sun that is drawn in the sky (radius 3
// degrees, radiance 4), with a sky gradient and Schlick's Fresnel: everything in the image
// moves, by about two pixels a frame at 64 x 36, and the sun's disk and the horizon are
// edges that a history in the wrong place smears. Shutter 0: the frames are sharp at their
// display times, as TAA renders them.
Scene panning_scene(Geometry geometry) {
  Scene s =
      testing::small_scene({Wave{0.015, {0.6, -0.9}, 2.4, 0.3}, Wave{0.009, {-1.1, -1.4}, 3.7, 1.1},
                            Wave{0.0045, {2.3, -0.7}, 4.9, 2.0}},
                           64, 36);
  s.surface.geometry = geometry;
  s.surface.fresnel = FresnelMode::schlick;
  s.surface.sea_radiance = Rgb(0.02);
  s.light = LightDesc{{0.3, 0.06, -1}, 3, Rgb(4), true};
  s.sky = SkyDesc{Rgb(0.1), Rgb(1.0), 0.5, true};  // zenith, horizon
  s.camera.keyframes = {{-1.0, {0, 3, 4}, {-60, 0, -60}}, {2.0, {0, 3.5, -14}, {60, 5, -60}}};
  s.animation = AnimationDesc{0, 30, 40, 0.0};
  return s;
}

TEST(Taa, MovingCameraMotionVectorsPointToWhereThePointWasSeenBefore) {
  // For a sample that sees water point X at t_f, the ray of the previous frame's camera
  // through p - motion at t_{f-1} hits the surface at X's (x, z) (unless a crest hides X
  // then); for the sky, its direction is that of the sample's ray.
  const Scene s = panning_scene(Geometry::displaced);
  const int f = 5;
  const FrameTime ft = frame_time(s, f);
  const SceneModel m = frame_model(s, ft);
  const double t_prev = s.frame_time(f - 1);
  const CameraModel prev(camera_at(s.camera, t_prev), s.width, s.height);
  const WaterGeometry geometry(m, ft);
  TaaMethod taa(TaaOptions{});
  FrameContext ctx{m, ft, 0};
  taa.begin_frame(ctx);
  Image img(64, 36);
  taa.shade_tile(ctx, 0, 0, 64, 36, img);
  int water = 0, close = 0, sky = 0;
  for (int j = 1; j < 36; j += 2) {
    for (int i = 1; i < 64; i += 3) {
      const vec2 p = vec2(i + 0.5, j + 0.5) + taa.jitter();
      const vec2 q = p - taa.motion()[static_cast<size_t>(j) * 64 + i];
      ASSERT_GT(length(p - q), 0.3) << i << " " << j;  // everything moves
      const vec3 d = normalize(m.camera.direction(p.x, p.y));
      const RayHit now = geometry.intersect(m.camera.position(), d, ft.end);
      if (now.hit) {
        const RayHit then = geometry.intersect(prev.position(), prev.direction(q.x, q.y), t_prev);
        ASSERT_TRUE(then.hit);
        // A wave crest may hide the point from the previous camera (near the horizon).
        close += length(vec2(then.point.x - now.point.x, then.point.z - now.point.z)) < 1e-6;
        ++water;
      } else {
        EXPECT_LT(length(normalize(prev.direction(q.x, q.y)) - d), 1e-12);
        ++sky;
      }
    }
  }
  EXPECT_GT(water, 100);
  EXPECT_GE(close, 0.97 * water);
  EXPECT_GT(sky, 20);
}

TEST(Taa, AMovingCameraReprojectedBeatsTheHistoryOfAStillCamera) {
  // Frames 10-13 of the pan, each against supersample 4x4x1 of the same frame (the
  // box-filtered image TAA converges to on a still scene). With --taa-motion surface the
  // history is fetched where the point was on a still camera's image, wrong by the
  // camera's motion: the clamp hides part of that, not all of it. Measured (RMSE, flat /
  // displaced): taa 0.0915 / 0.1112, --taa-motion surface 0.2125 / 0.2135, point 0.1945 /
  // 0.1948 (the printout).
  for (Geometry g : {Geometry::flat, Geometry::displaced}) {
    const Scene s = panning_scene(g);
    const SceneModel model(s);
    MethodOptions o;
    o.samples = SampleCounts{4, 4, 1};
    auto run = [&](const std::string& name, const MethodOptions& opts) {
      auto m = make_method(name, testing::with_tables(opts));
      std::vector<Image> frames;
      render_frames(model, *m, 10, 13, RenderSettings{},
                    [&](int, const Image& img) { frames.push_back(img); });
      return frames;
    };
    const std::vector<Image> truth = run("supersample", o);
    MethodOptions surface = o;
    surface.taa.motion = TaaMotion::surface;
    const double full_rmse = compare_sequences(run("taa", o), truth).rmse;
    const double surface_rmse = compare_sequences(run("taa", surface), truth).rmse;
    const double point_rmse = compare_sequences(run("point", o), truth).rmse;
    std::printf(
        "pan, %s: RMSE against supersample 4x4x1: taa %.5f, taa --taa-motion surface %.5f, "
        "point %.5f\n",
        g == Geometry::flat ? "flat" : "displaced", full_rmse, surface_rmse, point_rmse);
    EXPECT_LT(full_rmse, 0.6 * surface_rmse);
    EXPECT_LT(full_rmse, point_rmse);  // and TAA still does its work
  }
}

TEST(Taa, CalmWaterAgainstTheAnalyticMirroredDisk) {
  // Calm water is static: TAA averages the point samples at the Halton offsets with the
  // exponential weights of its blend. Without clamping, pixels that the analytic disk
  // covers fully or not at all are exact. The window's total matches the disk's area to
  // 1%, with or without variance clipping (which moves single edge pixels towards their
  // neighbourhood); measured 0.2% and 0.3% (the printout).
  Scene s = testing::small_scene({Wave{0.0, {0.3, -1.2}, 3.4, 0.0}}, 640, 360);
  s.light.angular_radius_deg = 0.6;
  SceneModel m(s);
  double cx, cy;
  ASSERT_TRUE(m.camera.project(vec3(m.light.L.x, -m.light.L.y, m.light.L.z), cx, cy));
  const int i0 = static_cast<int>(cx) - 5, j0 = static_cast<int>(cy) - 5, n = 11;
  double exact_sum = 0;
  std::vector<double> exact(n * n);
  for (int k = 0; k < n * n; ++k) {
    exact[k] = testing::analytic_calm_coverage(m, i0 + k % n, j0 + k / n);
    exact_sum += exact[k];
  }
  for (TaaClamp clamp : {TaaClamp::none, TaaClamp::variance}) {
    TaaOptions o;
    o.clamp = clamp;
    TaaMethod taa(o);
    Image img;
    render_frames(m, taa, 10, 10, RenderSettings{}, [&](int, const Image& i) { img = i; });
    double sum = 0;
    for (int k = 0; k < n * n; ++k) {
      const double v = img.at(i0 + k % n, j0 + k / n);
      sum += v;
      if (clamp == TaaClamp::none && (exact[k] < 1e-9 || exact[k] > 1 - 1e-9)) {
        EXPECT_NEAR(v, exact[k], 1e-6) << k;
      }
    }
    std::printf("calm water, clamp %s: TAA total %.4f, analytic %.4f\n",
                clamp == TaaClamp::none ? "none" : "variance", sum, exact_sum);
    EXPECT_NEAR(sum, exact_sum, 0.01 * exact_sum);
  }
}

TEST(Taa, SharedScenesRenderWithoutNanOrInf) {
  for (const char* name : {"simple", "smooth", "medium", "high"}) {
    for (bool displaced : {false, true}) {
      Scene s = testing::project_scene(name);
      if (displaced) s = testing::displaced_variant(s);
      // Displaced high-frequency water is slow to intersect: a smaller image.
      set_image_size(s, displaced ? 48 : 160, displaced ? 27 : 90);
      SceneModel m(s);
      TaaOptions o;
      o.warmup = displaced ? 1 : 4;
      o.history = displaced ? TaaHistoryFilter::catmull_rom : TaaHistoryFilter::bilinear;
      TaaMethod taa(o);
      double total = 0;
      render_frames(m, taa, 0, 1, RenderSettings{}, [&](int, const Image& img) {
        for (float v : img.data) {
          ASSERT_TRUE(std::isfinite(v)) << name;
          ASSERT_GE(v, 0.0f);
          total += v;
        }
      });
      if (displaced) {
        EXPECT_GT(total, 0.0) << name;  // the sky's radiance at least
      }
    }
  }
}

TEST(Taa, RejectsBadOptions) {
  TaaOptions o;
  o.alpha = 0;
  EXPECT_THROW(TaaMethod taa(o), Error);
  o = TaaOptions{};
  o.jitter_count = 0;
  EXPECT_THROW(TaaMethod taa(o), Error);
  o = TaaOptions{};
  o.warmup = -1;
  EXPECT_THROW(TaaMethod taa(o), Error);
}

}  // namespace
}  // namespace sg
