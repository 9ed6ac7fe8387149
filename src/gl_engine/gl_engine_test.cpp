// The GL engine against the CPU engine (docs/gpu.md): the same kernel compiled as GLSL and
// run as a compute shader (llvmpipe here and in CI; a GPU where there is one) must give the
// CPU engine's images in float, within bounds set by each method's own error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "engine/render.h"
#include "gl_engine/engines.h"
#include "gl_engine/gl_engine.h"
#include "gl_engine/gl_method.h"
#include "gl_engine/kernel_program.h"
#include "gl_engine/lean_map_gl.h"
#include "gl_engine/uniforms.h"
#include "methods/lean.h"
#include "metrics/metrics.h"
#include "ocean/lattice_ocean.h"
#include "scene/camera_path.h"
#include "testing/gl_context.h"
#include "testing/path_tables.h"
#include "testing/testing.h"

namespace sg {
namespace {

class GlEngineTest : public testing::GlTest {};

std::vector<Image> render(const SceneModel& m, Method& method, int first, int last) {
  std::vector<Image> out;
  for (int f = first; f <= last; ++f)
    out.push_back(render_frame(m, method, f, {}));
  return out;
}

TEST_F(GlEngineTest, EveryProgramCompilesAndItsUniformsAreAllWritten) {
  // Every active uniform of every variant's program is one the engine writes: a field of
  // the kernel's structs that the uploader forgot would be read as 0 on the GPU.
  Scene s = testing::project_scene("simple");
  s.width = 16;
  s.height = 8;
  // staa's programs differ by the water's smooth terms (kernel/staa.glsl,
  // staa_frame_terms): each case runs on water without them and, for staa, with them.
  Scene terms = s;
  terms.surface.fresnel = FresnelMode::schlick;
  terms.sky.gradient = true;
  const SceneModel plain_model(s), terms_model(terms);
  struct Case {
    const char* name;
    MethodOptions o;
    const SceneModel* m;
  };
  // Every program the suite runs (this test is the fixture that compiles them first:
  // src/CMakeLists.txt, gl_programs): the seven methods with the default options, staa's
  // with 2 path segments, specaa's with its analytic derivatives.
  std::vector<Case> cases = {{"point", {}, &plain_model},     {"supersample", {}, &plain_model},
                             {"reference", {}, &plain_model}, {"staa-temporal", {}, &plain_model},
                             {"staa", {}, &plain_model},      {"staa", {}, &terms_model}};
  MethodOptions two;
  two.staa.segments = 2;
  two.staa.ndf = NdfMode::uniform;
  two.staa.footprint = FootprintMode::none;
  cases.push_back({"staa", two, &plain_model});
  cases.push_back({"staa", two, &terms_model});
  cases.push_back({"staa-temporal", two, &plain_model});
  // A moving camera over water with the smooth terms: staa's program with the swept cells
  // (kernel/staa.glsl, staa_frame_swept_cells).
  Scene slide = terms;
  slide.camera.keyframes = {
      CameraKey{-1.0, s.camera.position, s.camera.look_at},
      CameraKey{1.0, s.camera.position + vec3(2, 0, 0), s.camera.look_at + vec3(-5, 0, 0)}};
  const SceneModel slide_model(slide);
  cases.push_back({"staa", {}, &slide_model});
  cases.push_back({"specaa", {}, &plain_model});
  MethodOptions analytic;
  analytic.specaa.derivatives = SpecaaDerivatives::analytic;
  cases.push_back({"specaa", analytic, &plain_model});
  cases.push_back({"microspec", {}, &plain_model});
  cases.push_back({"bruneton", {}, &plain_model});
  MethodOptions small_lean;
  small_lean.lean.size = 64;
  cases.push_back({"lean", small_lean, &plain_model});
  cases.push_back({"taa", {}, &plain_model});
  for (const Case& c : cases) {
    const SceneModel& m = *c.m;
    gl_engine::GlEngine engine(c.name, testing::with_tables(c.o));
    FrameContext ctx{m, frame_time(s, 1), 0};
    engine.dispatch(ctx);  // sets the uniforms
    gl_engine::UniformWriter probe(engine.program());
    // What the engine writes for this variant, recorded by a second writer.
    gl_engine::GlVariant v = gl_engine::gl_variant(c.name, c.o);
    KernelInputsF in;
    build_kernel_inputs(m, ctx.time, v.segments, 0, in);
    probe.set("image_size", kf::ivec2(s.width, s.height));
    gl_engine::set_uniforms(probe, "frame", in.frame);
    gl_engine::set_uniforms(probe, "counts", v.counts);
    gl_engine::set_uniforms(probe, "ref_params", v.reference);
    probe.set("pass_index", 0);  // the sampling methods' passes (GlEngine::run)
    probe.set("pass_samples", 1);
    gl_engine::set_uniforms(probe, "params", v.params);
    gl_engine::set_uniforms(probe, "sparams", v.specaa);
    gl_engine::set_uniforms(probe, "mparams", v.microspec);
    gl_engine::set_uniforms(probe, "bparams", v.bruneton);
    gl_engine::set_uniforms(probe, "lparams", kf::LeanParams{});  // the frame's (upload_lean)
    gl_engine::set_uniforms(probe, "tinfo", kf::PathTableInfo{});
    gl_engine::set_uniforms(probe, "finfo", kf::KernelFitInfo{});
    gl_engine::set_uniforms(probe, "tparams", kf::TaaParams{});  // the frame's (upload)
    for (int k = 0; k < 3; ++k)
      probe.set("radiance_channel[" + std::to_string(k) + "]", kf::vec4(0.0f));
    const std::vector<std::string> active = gl_engine::active_uniforms(engine.program());
    EXPECT_GT(active.size(), 5u) << c.name;
    for (const std::string& name : active)
      EXPECT_TRUE(probe.written().count(name))
          << c.name << ": active uniform " << name << " is not written by the engine";
    if (std::string(c.name) == "taa") {  // and its resolve's program (GlEngine::upload_taa)
      gl_engine::UniformWriter r(engine.taa_resolve_program());
      r.set("image_size", kf::ivec2(0, 0));
      gl_engine::set_uniforms(r, "rparams", kf::TaaResolveParams{});
      r.set("taa_has_history", true);
      const std::vector<std::string> resolve =
          gl_engine::active_uniforms(engine.taa_resolve_program());
      EXPECT_GE(resolve.size(), 5u);
      for (const std::string& name : resolve)
        EXPECT_TRUE(r.written().count(name))
            << "taa's resolve: active uniform " << name << " is not written by the engine";
    }
  }
}

// RMSE over frames 0-2 at 160x90; for `binary` methods also the share of pixels that differ.
struct Comparison {
  double gl_cpu = 0, cpu_ref = 0, gl_ref = 0, differ = 0;
};

// Frames first .. first + ref.size() - 1 of the scene at 160x90, on both engines.
Comparison compare_engines(const std::string& scene, const std::string& method,
                           const MethodOptions& o, const std::vector<Image>& ref, int first = 0) {
  Scene s = testing::project_scene(scene);
  s.width = 160;
  s.height = 90;
  const SceneModel m(s);
  MethodOptions of = o;
  of.precision = Precision::float32;
  std::unique_ptr<Method> cpu = make_method_on(Engine::cpu, method, testing::with_tables(of));
  std::unique_ptr<Method> gl = make_method_on(Engine::gl, method, testing::with_tables(o));
  const int last = first + static_cast<int>(ref.size()) - 1;
  const std::vector<Image> a = render(m, *cpu, first, last), b = render(m, *gl, first, last);
  Comparison c;
  c.gl_cpu = compare_sequences(b, a).rmse;
  c.cpu_ref = compare_sequences(a, ref).rmse;
  c.gl_ref = compare_sequences(b, ref).rmse;
  long differ = 0, total = 0;
  for (size_t k = 0; k < a.size(); ++k) {
    for (size_t p = 0; p < a[k].data.size(); ++p)
      differ += std::fabs(a[k].data[p] - b[k].data[p]) > 1e-4;
    total += static_cast<long>(a[k].data.size());
  }
  c.differ = double(differ) / total;
  std::printf(
      "%-7s %-24s RMSE(GL - CPU float) %.3g, CPU - ref %.3g, GL - ref %.3g, %.3f%% of "
      "pixels differ > 1e-4\n",
      scene.c_str(), method.c_str(), c.gl_cpu, c.cpu_ref, c.gl_ref, 100 * c.differ);
  return c;
}

TEST_F(GlEngineTest, MatchesTheCpuEngineOnTheSharedScenes) {
  for (const char* scene : {"simple", "smooth", "medium", "high"}) {
    Scene s = testing::project_scene(scene);
    s.width = 160;
    s.height = 90;
    const SceneModel m(s);
    MethodOptions ro;  // the reference at its default samples
    std::unique_ptr<Method> reference = make_method("reference", testing::with_tables(ro));
    const std::vector<Image> ref = render(m, *reference, 0, 2);
    MethodOptions none;
    none.staa.footprint = FootprintMode::none;
    MethodOptions per_pixel;
    per_pixel.staa.ndf = NdfMode::per_pixel;
    MethodOptions analytic;
    analytic.specaa.derivatives = SpecaaDerivatives::analytic;
    MethodOptions lean;  // a small map: llvmpipe fills it, one texel an invocation
    lean.lean.size = 256;
    for (const auto& [name, o] :
         std::vector<std::pair<std::string, MethodOptions>>{{"staa", {}},
                                                            {"staa", none},
                                                            {"staa", per_pixel},
                                                            {"staa-temporal", {}},
                                                            {"specaa", {}},
                                                            {"specaa", analytic},
                                                            {"bruneton", {}},
                                                            {"lean", lean},
                                                            {"taa", {}}}) {
      const Comparison c = compare_engines(scene, name, o, ref);
      EXPECT_LE(c.gl_cpu, 0.1 * c.cpu_ref) << scene << " " << name;
    }
    // Binary tests at the disk's rim per sample (or per corner quad): a few flip. The
    // reference on frame 2 only (llvmpipe takes 1-3 s a frame for it here).
    MethodOptions r4;  // other samples than the ground truth's
    r4.samples = {4, 4, 1};
    r4.samples_given = true;
    const std::vector<Image> ref2(ref.begin() + 2, ref.end());
    for (const auto& [name, o] : std::vector<std::pair<std::string, MethodOptions>>{
             {"point", {}}, {"reference", r4}, {"microspec", {}}}) {
      const bool one = name == "reference";
      const Comparison c = compare_engines(scene, name, o, one ? ref2 : ref, one ? 2 : 0);
      EXPECT_LE(c.differ, 0.02) << scene << " " << name;
      EXPECT_NEAR(c.gl_ref, c.cpu_ref, 0.05 * c.cpu_ref) << scene << " " << name;
    }
  }
}

// The CPU's frames first..last of a moving-camera scene with the camera held at each frame's
// shutter end: what an engine that ignored the motion would render.
std::vector<Image> held_camera_frames(const Scene& s, const std::string& method,
                                      const MethodOptions& o, int first, int last) {
  std::vector<Image> held;
  for (int f = first; f <= last; ++f) {
    Scene h = s;
    const CameraPoseAt pose = camera_pose(s.camera, frame_time(s, f).end);
    h.camera = CameraDesc{pose.position, pose.look_at, s.camera.up, s.camera.vfov_deg, {}};
    held.push_back(render_frame(
        SceneModel(h), *make_method_on(Engine::cpu, method, testing::with_tables(o)), f, {}));
  }
  return held;
}

TEST_F(GlEngineTest, MatchesTheCpuEngineUnderAMovingCamera) {
  // A pan (format /3, tests/scenes/pan.json, eight times as fast: 12 m/s and 185 degrees/s)
  // at 160x90, frames 1-2: the methods that take the camera at each sample's time
  // (kernel/camera.glsl, camera_at), GL against the CPU in float. point and the 4x4x2
  // supersample as binary tests per sample (a few flip at the disk's rim); the reference
  // within 1.5 times the RMSE between two CPU seeds, and with the same seed within a quarter
  // of it of the CPU's float reference (the same samples: they differ by float rounding
  // only). Measured on llvmpipe: 0 for the same seed; with the GL engine's camera keys left
  // out (a camera fixed at the shutter's end) 1.43 times the seeds' RMSE, while the binary
  // tests moved by only 0.16% of the pixels (the pan's glints are few).
  // staa and staa-temporal (each instant of the path at its own water point and view,
  // kernel/reflection_path.glsl, PathViews; staa with one and two sub-segments): GL against
  // the CPU in float within a tenth of the CPU's RMSE against the reference, and that
  // agreement at least ten times finer than what the motion changes (the CPU's image with
  // the camera held at each frame's shutter end, what an engine that ignored the motion
  // would render).
  Scene s = load_scene(testing::source_dir() + "/tests/scenes/pan.json");
  for (CameraKey& k : s.camera.keyframes)
    k.time *= 0.125;
  set_image_size(s, 160, 90);
  const SceneModel m(s);
  MethodOptions ss;
  ss.samples = {4, 4, 2};
  ss.samples_given = true;
  for (const auto& [name, o] :
       std::vector<std::pair<std::string, MethodOptions>>{{"point", {}}, {"supersample", ss}}) {
    MethodOptions of = o;
    of.precision = Precision::float32;
    const std::vector<Image> cpu =
        render(m, *make_method_on(Engine::cpu, name, testing::with_tables(of)), 1, 2);
    const std::vector<Image> gl =
        render(m, *make_method_on(Engine::gl, name, testing::with_tables(o)), 1, 2);
    long differ = 0, total = 0;
    for (size_t k = 0; k < cpu.size(); ++k) {
      for (size_t p = 0; p < cpu[k].data.size(); ++p)
        differ += std::fabs(cpu[k].data[p] - gl[k].data[p]) > 1e-4;
      total += static_cast<long>(cpu[k].data.size());
    }
    std::printf("pan %-12s %.3f%% of pixels differ > 1e-4\n", name.c_str(), 100.0 * differ / total);
    EXPECT_LE(double(differ) / total, 0.005) << name;
  }
  MethodOptions a, b;
  b.seed = 7;
  RenderSettings rs_b;
  rs_b.seed = 7;
  std::unique_ptr<Method> cpu_a = make_method("reference", testing::with_tables(a)),
                          cpu_b = make_method("reference", testing::with_tables(b));
  std::unique_ptr<Method> gl = make_method_on(Engine::gl, "reference", testing::with_tables(a));
  MethodOptions af = a;
  af.precision = Precision::float32;
  std::unique_ptr<Method> cpu_f = make_method("reference", testing::with_tables(af));
  std::vector<Image> ia, ib, ig, iff;
  for (int f = 1; f <= 2; ++f) {
    iff.push_back(render_frame(m, *cpu_f, f, {}));
    ia.push_back(render_frame(m, *cpu_a, f, {}));
    ib.push_back(render_frame(m, *cpu_b, f, rs_b));
    ig.push_back(render_frame(m, *gl, f, {}));
  }
  const double seeds = compare_sequences(ia, ib).rmse, engines = compare_sequences(ig, ib).rmse;
  std::printf("pan reference: CPU seed 0 vs seed 7 RMSE %.3g, GL seed 0 vs CPU seed 7 %.3g\n",
              seeds, engines);
  const double same_seed = compare_sequences(ig, iff).rmse;
  std::printf("pan reference, the same seed: GL vs CPU in float %.3g\n", same_seed);
  EXPECT_LE(same_seed, 0.25 * seeds);
  EXPECT_GT(seeds, 0);
  EXPECT_LE(engines, 1.5 * seeds);

  MethodOptions two;
  two.staa.segments = 2;
  for (const auto& [name, o] : std::vector<std::pair<std::string, MethodOptions>>{
           {"staa", {}}, {"staa", two}, {"staa-temporal", {}}}) {
    MethodOptions of = o;
    of.precision = Precision::float32;
    const std::vector<Image> cpu =
        render(m, *make_method_on(Engine::cpu, name, testing::with_tables(of)), 1, 2);
    const std::vector<Image> gl =
        render(m, *make_method_on(Engine::gl, name, testing::with_tables(o)), 1, 2);
    const std::vector<Image> held = held_camera_frames(s, name, of, 1, 2);
    const double gl_cpu = compare_sequences(gl, cpu).rmse,
                 cpu_ref = compare_sequences(cpu, ia).rmse,
                 motion = compare_sequences(held, cpu).rmse;
    std::printf(
        "pan %-14s segments %d: RMSE(GL - CPU float) %.3g, CPU - ref %.3g, held camera %.3g\n",
        name.c_str(), o.staa.segments, gl_cpu, cpu_ref, motion);
    EXPECT_LE(gl_cpu, 0.1 * cpu_ref) << name;
    EXPECT_LE(10 * gl_cpu, motion) << name;
  }

  // staa's smooth terms under a moving camera (tests/scenes/slide-sky.json, 96x54, frames
  // 1-2: a camera sliding over displaced water under a sky gradient, the cells averaged over
  // the shutter, kernel/staa.glsl, staa_frame_swept_cells, the program compiled for it): GL
  // against the CPU in float within 1e-4 of the image's mean and ten times finer than what
  // the motion changes. Measured on llvmpipe: 1.4e-8 RMSE, the image's mean 6.5e-3.
  {
    Scene sl = load_scene(testing::source_dir() + "/tests/scenes/slide-sky.json");
    set_image_size(sl, 96, 54);
    const SceneModel sm(sl);
    MethodOptions of;
    of.precision = Precision::float32;
    const std::vector<Image> cpu =
        render(sm, *make_method_on(Engine::cpu, "staa", testing::with_tables(of)), 1, 2);
    const std::vector<Image> gl =
        render(sm, *make_method_on(Engine::gl, "staa", testing::with_tables({})), 1, 2);
    const std::vector<Image> held = held_camera_frames(sl, "staa", of, 1, 2);
    double mean = 0;
    for (float v : cpu[0].data)
      mean += v / double(cpu[0].data.size());
    const double gl_cpu = compare_sequences(gl, cpu).rmse,
                 motion = compare_sequences(held, cpu).rmse;
    std::printf("slide-sky staa: RMSE(GL - CPU float) %.3g, held camera %.3g, mean %.3g\n", gl_cpu,
                motion, mean);
    EXPECT_LE(gl_cpu, 1e-4 * mean);
    EXPECT_LE(10 * gl_cpu, motion);
  }

  // taa (its motion vectors through the previous frame's camera, its history on the GPU),
  // on the flat pan and on a displaced one (the height at the frame before), with a sky
  // gradient, Schlick's Fresnel and the sun's disk drawn (edges that a history in the wrong
  // place smears; the pan's own dark sky and sea leave the clamp nothing to keep): GL
  // against the CPU in float at least ten times finer than what the camera's reprojection
  // changes (the CPU's image with --taa-motion surface: the history fetched as if the
  // camera stood still).
  for (Geometry g : {Geometry::flat, Geometry::displaced}) {
    Scene d = s;
    d.surface.geometry = g;
    d.surface.fresnel = FresnelMode::schlick;
    d.surface.sea_radiance = Rgb(0.02);
    d.sky = SkyDesc{Rgb(0.1), Rgb(1.0), 0.5, true};  // zenith, horizon
    d.light.visible = true;
    d.light.angular_radius_deg = 3;
    const SceneModel dm(d);
    MethodOptions o, still;
    still.taa.motion = TaaMotion::surface;
    MethodOptions of = o, stillf = still;
    of.precision = stillf.precision = Precision::float32;
    const std::vector<Image> cpu = render(dm, *make_method_on(Engine::cpu, "taa", of), 1, 2);
    const std::vector<Image> gl = render(dm, *make_method_on(Engine::gl, "taa", o), 1, 2);
    const std::vector<Image> held = render(dm, *make_method_on(Engine::cpu, "taa", stillf), 1, 2);
    const double gl_cpu = compare_sequences(gl, cpu).rmse,
                 motion = compare_sequences(held, cpu).rmse;
    std::printf("pan taa, %s: RMSE(GL - CPU float) %.3g, --taa-motion surface %.3g\n",
                g == Geometry::flat ? "flat" : "displaced", gl_cpu, motion);
    EXPECT_LE(10 * gl_cpu, motion);
  }
}

TEST_F(GlEngineTest, CascadeFieldsMatchTheCpuEngine) {
  // A generated two-cascade sea of 32 x 32 lattices (wind 8 m/s) under the shared scenes'
  // camera and light, Schlick's Fresnel and a sky gradient, flat and displaced (the march
  // on the fields' heights), 160x90, frames 0-1: point,
  // supersample 2x2x1, staa-temporal and staa read the cascades
  // from their FFT fields in the wave buffer (kernel/cascade_fields.glsl) on both engines,
  // the GL engine's transformed on the GPU (gl_engine/cascade_fields_gl.h) and on the host;
  // GL against the CPU in float within a tenth of what the fields change against the
  // cascades' sines on flat water (the CPU's --cascades waves image; on displaced water,
  // whose sines cost minutes to march, a hundredth of the largest). Were the GL engine to
  // read no field
  // (the lattices neither as fields nor as waves), its image would miss the sea's glints
  // and the bound would fail.
  ocean::OceanParams p;
  p.wind_speed = 8;
  p.seed = 5;
  ocean::CascadeParams c;
  c.cascades = 2;
  c.lattice = 32;
  c.patch_sizes = {20, 10};
  Scene s = testing::project_scene("smooth");
  s.surface.waves.clear();
  s.surface.cascades = ocean::generate_lattice(p, c).cascades;
  // Schlick's Fresnel and a sky gradient: every pixel's value follows its normal.
  s.surface.fresnel = FresnelMode::schlick;
  s.sky = SkyDesc{Rgb(0.02), Rgb(0.1), 0.5, true};
  set_image_size(s, 160, 90);
  std::map<std::string, double> yardstick;
  for (const Geometry geometry : {Geometry::flat, Geometry::displaced}) {
    s.surface.geometry = geometry;
    // Displaced: looking 27 degrees down, the horizon out of the frame (a ray grazing the
    // far water marches thousands of steps, past llvmpipe's loop limit: docs/gpu.md).
    if (geometry == Geometry::displaced) s.camera.look_at = vec3(0, 0, -5);
    const SceneModel m(s);
    const char* water = geometry == Geometry::flat ? "flat" : "displaced";
    for (const std::string name : {"point", "supersample", "staa-temporal", "staa"}) {
      MethodOptions of;
      of.precision = Precision::float32;
      of.samples = SampleCounts{2, 2, 1};  // supersample: T = 1, the display time's fields
      of.samples_given = true;
      MethodOptions waves = of;
      waves.cascade_fields = false;
      const std::vector<Image> cpu =
          render(m, *make_method_on(Engine::cpu, name, testing::with_tables(of)), 0, 1);
      // The GL engine's fields transformed on the GPU (the default) and on the host.
      MethodOptions og;
      og.samples = of.samples;
      og.samples_given = true;
      const std::vector<Image> gl =
          render(m, *make_method_on(Engine::gl, name, testing::with_tables(og)), 0, 1);
      const double gl_cpu = compare_sequences(gl, cpu).rmse;
      og.cascade_fft_gpu = false;
      const std::vector<Image> gl_host =
          render(m, *make_method_on(Engine::gl, name, testing::with_tables(og)), 0, 1);
      const double gl_host_cpu = compare_sequences(gl_host, cpu).rmse;
      // The yardstick: what the fields change against the sines on flat water (the
      // displaced sines' march over 939 waves would cost minutes here).
      if (geometry == Geometry::flat) {
        const std::vector<Image> sines =
            render(m, *make_method_on(Engine::cpu, name, testing::with_tables(waves)), 0, 1);
        yardstick[name] = compare_sequences(cpu, sines).rmse;
      }
      // Displaced: a hundredth of the largest flat one (the fields' 8x grid leaves some
      // methods' flat images within 1e-5 of the sines').
      double largest = 0;
      for (const auto& [method, y] : yardstick)
        largest = std::max(largest, y);
      const double fields = geometry == Geometry::flat ? yardstick[name] : 0.1 * largest;
      double sum = 0;
      for (const Image& im : cpu)
        for (float v : im.data)
          sum += v;
      std::printf(
          "cascades %-9s %-14s RMSE(GL - CPU float) %.3g (the host's transforms %.3g), CPU "
          "fields - sines (flat) %.3g, sum %.3g\n",
          water, name.c_str(), gl_cpu, gl_host_cpu, fields, sum);
      EXPECT_GT(sum, 0) << water << " " << name;
      EXPECT_GT(fields, 0) << water << " " << name;
      EXPECT_LE(gl_cpu, 0.1 * fields) << water << " " << name;
      EXPECT_LE(gl_host_cpu, 0.1 * fields) << water << " " << name << " (host transforms)";
    }
  }
}

TEST_F(GlEngineTest, SmoothTermsAndTheHorizonMatchTheCpuEngine) {
  // The Fresnel-weighted sky and sea over the pixel's normals (kernel/smooth_terms.glsl)
  // and the horizon's split pixels, which the shared scenes (no Fresnel, constant sky)
  // skip: the GL engine against the CPU in float on frames 0-1 at 160x90, within 2% of the
  // CPU's own RMSE against the reference (the two differ by float rounding only).
  Scene s = load_scene(testing::source_dir() + "/tests/scenes/fresnel-sky.json");
  set_image_size(s, 160, 90);
  const SceneModel m(s);
  MethodOptions ro;
  const std::vector<Image> ref =
      render(m, *make_method("reference", testing::with_tables(ro)), 0, 1);
  for (const char* name : {"staa", "staa-temporal"}) {
    MethodOptions of;
    of.precision = Precision::float32;
    const std::vector<Image> cpu =
        render(m, *make_method_on(Engine::cpu, name, testing::with_tables(of)), 0, 1);
    const std::vector<Image> gl =
        render(m, *make_method_on(Engine::gl, name, testing::with_tables({})), 0, 1);
    const double gl_cpu = compare_sequences(gl, cpu).rmse;
    const double cpu_ref = compare_sequences(cpu, ref).rmse;
    std::printf("fresnel-sky %-14s RMSE(GL - CPU float) %.3g, CPU - ref %.3g\n", name, gl_cpu,
                cpu_ref);
    EXPECT_LE(gl_cpu, 0.02 * cpu_ref) << name;
  }
}

TEST_F(GlEngineTest, StaaProgramFollowsEachFramesSmoothTerms) {
  // staa's program is compiled for whether the frame's water needs the smooth terms
  // (kernel/staa.glsl, staa_frame_terms; gl_engine/kernel_program.h): one engine that
  // shades water with them, without them, and with them again switches its program each
  // time, and each frame is byte for byte what an engine made for that water alone gives.
  // A program kept across the switch would shade the plain water with the terms' code (or
  // the Fresnel water without it).
  Scene terms = load_scene(testing::source_dir() + "/tests/scenes/fresnel-sky.json");
  set_image_size(terms, 64, 36);
  Scene plain = terms;
  plain.surface.fresnel = FresnelMode::none;
  plain.sky = SkyDesc::constant(terms.sky.horizon);
  const SceneModel mt(terms), mp(plain);
  auto frame = [](gl_engine::GlEngine& e, const SceneModel& m) {
    e.dispatch(FrameContext{m, frame_time(m.scene, 0), 0});
    return e.read_weights();
  };
  const MethodOptions o = testing::with_tables({});
  gl_engine::GlEngine alone_t("staa", o), alone_p("staa", o), both("staa", o);
  const std::vector<float> ref_t = frame(alone_t, mt), ref_p = frame(alone_p, mp);
  ASSERT_NE(ref_t, ref_p);
  EXPECT_EQ(frame(both, mt), ref_t);
  EXPECT_EQ(frame(both, mp), ref_p);
  EXPECT_EQ(frame(both, mt), ref_t);
}

TEST_F(GlEngineTest, EachFallbackIntegratorMatchesTheCpuEngine) {
  // staa's program holds one fallback integrator, fixed in its text
  // (gl_engine/kernel_program.h, ProgramOptions): two programs that set each of its two
  // switches the other way from the default (the default's program is every other GL
  // test's) against the CPU in float on high (the shared scene with the most fallback
  // pixels), frames 0-1 at 160x90. The yardstick is how far the integrator's image lies
  // from the default's on the CPU: a program that ran another integrator than the one its
  // options name would differ from the CPU by about that much.
  Scene s = testing::project_scene("high");
  set_image_size(s, 160, 90);
  const SceneModel m(s);
  MethodOptions base;
  base.precision = Precision::float32;
  const std::vector<Image> cpu_default =
      render(m, *make_method_on(Engine::cpu, "staa", testing::with_tables(base)), 0, 1);
  for (const auto& [riemann, along_path] :
       std::vector<std::pair<bool, bool>>{{true, true}, {false, false}}) {
    MethodOptions o;
    o.staa.fallback = riemann ? FallbackMode::riemann : FallbackMode::quadrature;
    o.staa.fallback_along_path = along_path;
    MethodOptions of = o;
    of.precision = Precision::float32;
    const std::vector<Image> cpu =
        render(m, *make_method_on(Engine::cpu, "staa", testing::with_tables(of)), 0, 1);
    const std::vector<Image> gl =
        render(m, *make_method_on(Engine::gl, "staa", testing::with_tables(o)), 0, 1);
    const double gl_cpu = compare_sequences(gl, cpu).rmse;
    const double yardstick = compare_sequences(cpu, cpu_default).rmse;
    std::printf(
        "high staa --fallback %s --fallback-time %s: RMSE(GL - CPU float) %.3g, CPU - "
        "CPU default %.3g\n",
        riemann ? "riemann" : "quadrature", along_path ? "path" : "current", gl_cpu, yardstick);
    EXPECT_GT(yardstick, 0) << riemann << along_path;
    EXPECT_LE(gl_cpu, 0.1 * yardstick) << riemann << along_path;
  }
}

TEST_F(GlEngineTest, FoldCellsMatchTheCpuEngine) {
  // `staa --fold-cells`: a lit pixel whose resolved waves fold across it shaded as the mean
  // of its quarters (kernel/staa.glsl, staa_pixel), on flat water with Fresnel and a sky
  // (the fold scene), on displaced water (the quarters' own intersections) and under a
  // moving camera (the quarters' own rays along the shutter), frames 0-1,
  // against the CPU in float. The yardstick is how far the cut image lies from the uncut on
  // the CPU: a program that did not cut, or cut elsewhere, would differ by about that much.
  Scene fold = load_scene(testing::source_dir() + "/tests/scenes/fold-glint.json");
  Scene swell = load_scene(testing::source_dir() + "/tests/scenes/displaced-swell.json");
  Scene pan = load_scene(testing::source_dir() + "/tests/scenes/pan.json");
  set_image_size(swell, 96, 54);
  set_image_size(pan, 96, 54);
  for (const Scene& s : {fold, swell, pan}) {
    const SceneModel m(s);
    MethodOptions o;
    o.staa.fold_cells = 1;
    MethodOptions of = o, uncut;
    of.precision = Precision::float32;
    uncut.precision = Precision::float32;
    const std::vector<Image> cpu =
        render(m, *make_method_on(Engine::cpu, "staa", testing::with_tables(of)), 0, 1);
    const std::vector<Image> cpu_uncut =
        render(m, *make_method_on(Engine::cpu, "staa", testing::with_tables(uncut)), 0, 1);
    const std::vector<Image> gl =
        render(m, *make_method_on(Engine::gl, "staa", testing::with_tables(o)), 0, 1);
    const double gl_cpu = compare_sequences(gl, cpu).rmse;
    const double yardstick = compare_sequences(cpu, cpu_uncut).rmse;
    std::printf("%s staa --fold-cells 1: RMSE(GL - CPU float) %.3g, cut - uncut on the CPU %.3g\n",
                s.name.c_str(), gl_cpu, yardstick);
    EXPECT_GT(yardstick, 0) << s.name;
    EXPECT_LE(gl_cpu, 0.1 * yardstick) << s.name;
  }
}

TEST_F(GlEngineTest, GlReferenceIsWithinTheNoiseOfTwoCpuSeeds) {
  // The GL reference against the CPU reference with another seed (both at their default
  // samples): within 1.5 times the RMSE between two CPU seeds. 96x54, one frame: llvmpipe
  // takes about 5 s for it (12.6 s a frame at 160x90).
  Scene s = testing::project_scene("medium");
  s.width = 96;
  s.height = 54;
  const SceneModel m(s);
  MethodOptions a, b;
  b.seed = 7;
  std::unique_ptr<Method> cpu_a = make_method("reference", testing::with_tables(a)),
                          cpu_b = make_method("reference", testing::with_tables(b));
  std::unique_ptr<Method> gl = make_method_on(Engine::gl, "reference", testing::with_tables(a));
  RenderSettings rs_b;
  rs_b.seed = 7;
  std::vector<Image> ia, ib, ig;
  for (int f = 1; f < 2; ++f) {
    ia.push_back(render_frame(m, *cpu_a, f, {}));
    ib.push_back(render_frame(m, *cpu_b, f, rs_b));
    ig.push_back(render_frame(m, *gl, f, {}));
  }
  const double seeds = compare_sequences(ia, ib).rmse, engines = compare_sequences(ig, ib).rmse;
  std::printf("reference: CPU seed 0 vs seed 7 RMSE %.3g, GL seed 0 vs CPU seed 7 %.3g\n", seeds,
              engines);
  EXPECT_GT(seeds, 0);
  EXPECT_LE(engines, 1.5 * seeds);
}

double image_mean(const Image& im) {
  double sum = 0;
  for (float v : im.data)
    sum += v;
  return sum / double(im.data.size());
}

TEST_F(GlEngineTest, GlReferenceMeanMatchesTheCpuOffTheSharedScenes) {
  // The scenes on which the GL reference was biased (llvmpipe ended the loops of
  // a pixel's invocation after 65535 iterations, so its busy pixels lost their later
  // samples; tests/scenes/gl-reference/): the sun 60 degrees to the side over 64 waves,
  // and Schlick Fresnel under a constant sky with sea and sun. The GL reference's image
  // mean (seed 7) against the CPU's (seed 0) within 4 standard errors of their difference,
  // the standard error from the CPU's batches (the GL's estimator is the same, its
  // variance the CPU's). 12x12x1 samples: the CPU's default 8x8x1 lost no samples on the
  // Fresnel scene's 16 waves. Measured before the fix: GL/CPU 0.345 on side-sun (7.9
  // standard errors off) and 0.918 on fresnel-light (533); after: 1.15 (1.8) and 1.000 (0.04).
  // long-shutter: a 10 s shutter that the reference cuts into windows (kernel/reference.glsl),
  // each sample integrating a window drawn at random; every pixel busy, so 4x4x1 there.
  for (const char* name : {"side-sun", "fresnel-light", "long-shutter"}) {
    Scene s = load_scene(testing::source_dir() + "/tests/scenes/gl-reference/" + name + ".json");
    set_image_size(s, 96, 54);
    const SceneModel m(s);
    MethodOptions o;
    const int strata = std::string(name) == "long-shutter" ? 4 : 12;
    o.samples = {strata, strata, 1};
    o.samples_given = true;
    std::unique_ptr<Method> cpu = make_method("reference", testing::with_tables(o));
    const Image a = render_frame(m, *cpu, 0, {});
    const Image* variance = cpu->pixel_variance();
    ASSERT_TRUE(variance);
    double v = 0;
    for (float x : variance->data)
      v += x;
    const double n = double(variance->data.size());
    const double se = std::sqrt(2 * v) / n;  // of the difference of two independent means
    MethodOptions og = o;
    og.seed = 7;
    RenderSettings rs;
    rs.seed = 7;
    std::unique_ptr<Method> gl = make_method_on(Engine::gl, "reference", testing::with_tables(og));
    const Image b = render_frame(m, *gl, 0, rs);
    const double ca = image_mean(a), gb = image_mean(b);
    std::printf(
        "%-13s reference mean: CPU %.5g, GL %.5g (GL/CPU %.4f), difference %.2f standard "
        "errors (%.3g)\n",
        name, ca, gb, gb / ca, (gb - ca) / se, se);
    EXPECT_GT(se, 0) << name;
    EXPECT_LE(std::fabs(gb - ca), 4 * se) << name;
  }
}

TEST_F(GlEngineTest, SamplingPassesGoOnWhereAGrazingMarchOutrunsTheirEstimate) {
  // Random scene 12 of the engines' agreement run, seed 163 (tests/scenes/gl-reference/
  // far-grazing.json): a camera 66 m above displaced water (swells of 60 m and 2.4 m) looks
  // at the horizon, where a ray marches up to hundreds of steps, against the 48 a pass of
  // samples is sized for (gl_engine.h, pass_samples). llvmpipe ends an invocation's loops
  // after 65535 iterations: the pass's later samples were lost, the horizon's row 20% dark
  // under `supersample --samples 8x8x1` (GL/CPU row mean 0.80, image 0.987) and the
  // reference 1.4% dark. Each pixel now takes its samples from where its last pass
  // stopped, and an invocation stops once its samples' estimated work passes the budget
  // (kLoopGuardWork): the GL's samples are the CPU's float samples, one by one.
  Scene s = load_scene(testing::source_dir() + "/tests/scenes/gl-reference/far-grazing.json");
  const SceneModel m(s);
  MethodOptions o;
  o.samples = {8, 8, 1};
  o.samples_given = true;
  o.precision = Precision::float32;
  std::unique_ptr<Method> cpu = make_method("supersample", o);
  std::unique_ptr<Method> gl = make_method_on(Engine::gl, "supersample", o);
  const Image a = render_frame(m, *cpu, 1, {});
  const Image b = render_frame(m, *gl, 1, {});
  double row_a = 0, row_b = 0;
  for (int i = 0; i < a.width; ++i) {
    for (int c = 0; c < a.channels; ++c) {
      row_a += a.at(i, 6, c);
      row_b += b.at(i, 6, c);
    }
  }
  const double image = image_mean(b) / image_mean(a), row = row_b / row_a;
  std::printf("far-grazing supersample 8x8x1: GL/CPU image mean %.5f, the horizon's row %.4f\n",
              image, row);
  EXPECT_NEAR(row, 1.0, 0.01);
  EXPECT_NEAR(image, 1.0, 1e-3);
  // The reference (8 batches of 8x8x1, the same streams on both engines): its mean within
  // 0.2% of the CPU's float (1.4% below it before; six CPU seeds' means spread over 0.14%).
  o.batches = 8;
  std::unique_ptr<Method> cpu_ref = make_method("reference", testing::with_tables(o));
  std::unique_ptr<Method> gl_ref = make_method_on(Engine::gl, "reference", testing::with_tables(o));
  const double ref =
      image_mean(render_frame(m, *gl_ref, 1, {})) / image_mean(render_frame(m, *cpu_ref, 1, {}));
  std::printf("far-grazing reference 8x8x1, 8 batches: GL/CPU image mean %.5f\n", ref);
  EXPECT_NEAR(ref, 1.0, 2e-3);
}

TEST_F(GlEngineTest, LeanMapIsTheCpusInAnyBands) {
  // `medium` at 64x36 with a 128 x 128 map, its waves in float (the GL engine's): the GPU's
  // map (level 0 one texel an invocation, the chain one texel of a level each) against the
  // CPU's (the same terms in SIMD lanes in double, stored as float), every float of every
  // level; then the GPU's again through an 8 KiB storage window (bands of a few rows, as a
  // context whose storage blocks are smaller than the map's levels writes them): the same
  // bytes.
  Scene s = testing::project_scene("medium");
  set_image_size(s, 64, 36);
  const SceneModel m(s);
  const FrameContext ctx{m, frame_time(s, 2), 0};
  LeanOptions o;
  o.size = 128;
  LeanMethod cpu(o, Precision::float32);
  cpu.begin_frame(ctx);
  ASSERT_FALSE(cpu.params().empty);
  KernelInputsF in;
  build_kernel_inputs(m, ctx.time, 1, 0, in);
  std::vector<float> texels;
  for (const kf::vec4& t : in.texels)
    texels.insert(texels.end(), {t.x, t.y, t.z, t.w});
  const gl::TextureBuffer waves(texels);
  gl_engine::LeanMapGl gpu;
  gpu.fill(waves, in.frame, lean_params_float(cpu.params()));
  const std::vector<float> a = gpu.texels().buffer().read<float>();
  EXPECT_EQ(gpu.passes(), cpu.params().levels);
  const kd::MapTexels c = cpu.map().texels();
  ASSERT_EQ(long(a.size()), c.size);
  double worst = 0, peak = 0;
  for (long k = 0; k < c.size; ++k) {
    worst = std::max(worst, double(std::fabs(a[size_t(k)] - c.data[k])));
    peak = std::max(peak, double(std::fabs(c.data[k])));
  }
  std::printf("LEAN map, GPU against CPU: largest difference %.3g (largest value %.3g)\n", worst,
              peak);
  EXPECT_GT(peak, 0.01);
  EXPECT_LT(worst, 2e-4 * peak);
  gpu.set_window_bytes(8192);
  gpu.fill(waves, in.frame, lean_params_float(cpu.params()));
  EXPECT_GT(gpu.passes(), 4 * cpu.params().levels);
  const std::vector<float> b = gpu.texels().buffer().read<float>();
  EXPECT_TRUE(a == b) << "the bands wrote other values";
}

TEST_F(GlEngineTest, LeanMapPastTheBufferLimitIsRefusedNamingTheFlag) {
  // An 8192 map is 447 million floats: past GL_MAX_TEXTURE_BUFFER_SIZE where that is 2^27
  // (llvmpipe), refused with the flag's name before any allocation.
  // (A context that holds it allocates it.)
  const long floats = 5L * (8192L * 8192L * 4 / 3 + 1);
  const bool holds = floats <= long(gl::max_texture_buffer_texels());
  gl_engine::LeanMapGl map;
  try {
    map.allocate(8192);
    EXPECT_TRUE(holds) << "an 8192 map was allocated past the limit";
  } catch (const Error& e) {
    EXPECT_FALSE(holds) << e.what();
    EXPECT_NE(std::string(e.what()).find("--lean-size 8192"), std::string::npos) << e.what();
  }
  map.allocate(64);  // a map within the limit still is
  EXPECT_EQ(map.texels().texels(),
            size_t(5 * (64 * 64 + 32 * 32 + 16 * 16 + 8 * 8 + 4 * 4 + 2 * 2 + 1)));
}

TEST_F(GlEngineTest, DisplacedMarchAdvancesFarFromTheCameraInFloat) {
  // tests/scenes/gl-reference/far-float-march.json (the engines' agreement run, seed 7,
  // scene 96): 347 displaced waves seen from 2954 m up, the water 3.7 km along the rays,
  // where a float position's rounding unit (2.4e-4 m) is larger than the march's smallest
  // step near the surface (1e-4 m / Lip): s + step was s, the march stood until its step
  // limit (20 s for 384 pixels on the CPU in float), and llvmpipe, whose loop limit cut it,
  // returned a miss: GL image mean 0 against the CPU's 0.0839, the glint of 16.1 lost.
  // Now every step moves s by at least two of its rounding units.
  Scene s = load_scene(testing::source_dir() + "/tests/scenes/gl-reference/far-float-march.json");
  const SceneModel m(s);
  MethodOptions of;
  of.precision = Precision::float32;
  const Image d = render_frame(m, *make_method("point", testing::with_tables({})), 4, {});
  const Image f = render_frame(m, *make_method("point", testing::with_tables(of)), 4, {});
  const Image g =
      render_frame(m, *make_method_on(Engine::gl, "point", testing::with_tables({})), 4, {});
  double peak = 0;
  long off_f = 0, off_g = 0;
  for (size_t p = 0; p < d.data.size(); ++p)
    peak = std::max(peak, double(d.data[p]));
  for (size_t p = 0; p < d.data.size(); ++p) {
    off_f += std::fabs(f.data[p] - d.data[p]) > 1e-3 * peak;
    off_g += std::fabs(g.data[p] - f.data[p]) > 1e-3 * peak;
  }
  std::printf("far float march: peak %.4g, means double %.5g, float %.5g, GL %.5g\n", peak,
              image_mean(d), image_mean(f), image_mean(g));
  EXPECT_GT(peak, 1.0) << "the glint must be in the picture";
  EXPECT_LE(off_f, 1) << "CPU float against double";
  EXPECT_LE(off_g, 1) << "GL against CPU float";
  EXPECT_NEAR(image_mean(g), image_mean(d), 0.02 * image_mean(d));
}

TEST(GlEngine, RefusesWhatItLacksNamingIt) {
  MethodOptions o;
  EXPECT_NO_THROW(gl_engine::gl_variant("taa", o));
  for (const char* m : {"nonsense"}) {
    try {
      gl_engine::gl_variant(m, o);
      ADD_FAILURE() << m << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("--method ") + m), std::string::npos)
          << e.what();
    }
  }
  o.staa.footprint = FootprintMode::exact;
  try {
    gl_engine::gl_variant("staa", o);
    ADD_FAILURE() << "--footprint exact accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--footprint exact"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sg
