#include "gl_engine/gl_engine.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>

#include "base/error.h"
#include "gl/check.h"
#include "gl/dispatch.h"
#include "gl_engine/uniforms.h"
#include "kernel/kernel_float.h"
#include "methods/bruneton.h"
#include "methods/lean.h"
#include "methods/microspec.h"
#include "methods/reference.h"
#include "methods/specaa.h"
#include "methods/staa.h"
#include "methods/supersample.h"
#include "methods/taa.h"
#include "shading/kernel_frame.h"
#include "shading/kernel_table.h"
#include "shading/path_table.h"

namespace sg::gl_engine {

namespace {

// The smallest n' >= n that is not a power of two. llvmpipe compiles a variant of a
// program for each combination of "this image's / buffer's sides are powers of two"
// (its sampler and image keys), and each of the kernel's programs takes up to a minute to
// compile there: the engine's image and wave buffer always get sides that are not, so
// every scene size runs the same compiled variant (and Mesa's shader cache serves it).
// The region past the scene's image is never written or read.
int not_power_of_two(int n) {
  while ((n & (n - 1)) == 0)
    n += 1;
  return n;
}

}  // namespace

int pass_samples(int waves, int segments, bool displaced, int cascades) {
  long per_sample = displaced ? 48L * (waves + 1) + 300
                              : long(waves + 1) * (segments + 2) + 300L * segments + 100;
  // Each cascade read from its fields: a 16-texel cubic per read, one read per sample on
  // flat water, one per march step on displaced water (its steps follow the fields'
  // bounds, looser than the waves': 200 steps counted).
  per_sample += long(cascades) * (displaced ? 16L * 200 : 16L);
  return int(std::clamp<long>(kPassIterations / per_sample, 1, 1 << 20));
}

const char* gl_methods() {
  return "point, supersample, reference, staa-temporal, staa, specaa, microspec, bruneton, lean, "
         "taa";
}

GlVariant gl_variant(const std::string& method, const MethodOptions& o) {
  validate(o);
  GlVariant v;
  v.intersect_tolerance = intersect_tolerance_for(o, method);
  v.cascade_fields =
      o.cascade_fields &&
      (method == "point" || method == "staa-temporal" || method == "staa" || method == "specaa" ||
       method == "bruneton" || method == "lean" || (method == "supersample" && o.samples.st == 1));
  v.cascade_fft_gpu = o.cascade_fft_gpu;
  v.cascade_reads = cascade_reads_of(method);
  if (method == "point") {
    v.entry = KernelEntry::point;
  } else if (method == "reference") {
    const ReferenceSettings rs = reference_settings(o);
    v.entry = KernelEntry::reference;
    v.segments = kf::kMaxSegments;
    v.reference.sx = rs.samples.sx;
    v.reference.sy = rs.samples.sy;
    v.reference.nt = rs.samples.st;
    v.reference.batches = rs.kernel_batches();
    v.reference.first_batch = rs.first_batch();
    v.reference.adaptive = rs.adaptive;
    v.reference.quiet_sx = v.reference.quiet_sy = rs.quiet;
    v.reference.margin = static_cast<float>(rs.margin);
    v.intersect_tolerance =  // per sample cell, as on the CPU (methods/reference.h)
        rs.intersect_tolerance / std::max({rs.samples.sx, rs.samples.sy, 1});
  } else if (method == "supersample") {
    v.entry = KernelEntry::stratified;
    v.counts.sx = o.samples.sx;
    v.counts.sy = o.samples.sy;
    v.counts.nt = o.samples.st;
    v.counts.time_at_frame = method == "supersample" && o.samples.st == 1;
    v.intersect_tolerance = stratified_intersect_tolerance(o);
  } else if (method == "staa-temporal") {
    v.entry = KernelEntry::staa_temporal;
    v.segments = o.staa.segments;
  } else if (method == "staa") {
    if (o.staa.footprint == FootprintMode::exact) {
      throw Error(
          "--footprint exact: not on the GL engine (the swept parallelogram is "
          "integrated on the host: use --engine cpu, or --footprint gaussian|none)");
    }
    v.entry = KernelEntry::staa;
    v.segments = o.staa.segments;
    v.params = staa_kernel_params<kf::StaaParams>(o.staa);
  } else if (method == "specaa") {
    v.entry = KernelEntry::specaa;
    v.specaa = specaa_kernel_params<kf::SpecaaParams>(o.specaa);
  } else if (method == "microspec") {
    v.entry = KernelEntry::microspec;
    v.microspec = microspec_kernel_params<kf::MicrospecParams>(o.microspec);
  } else if (method == "bruneton") {
    v.entry = KernelEntry::bruneton;
    v.bruneton = bruneton_kernel_params<kf::BrunetonParams>(o.bruneton);
  } else if (method == "lean") {
    validate_lean_options(o.lean);
    v.entry = KernelEntry::lean;
    v.lean = o.lean;
  } else if (method == "taa") {
    validate_taa_options(o.taa);
    v.entry = KernelEntry::taa;
    v.taa = o.taa;
  } else {
    throw Error("--method " + method + ": not on the GL engine (it runs " + gl_methods() +
                "; use --engine cpu)");
  }
  return v;
}

ProgramOptions program_options(const GlVariant& v) {
  ProgramOptions o;
  o.segments = v.segments;
  o.fallback_riemann = v.params.fallback_riemann;
  o.fallback_along_path = v.params.fallback_along_path;
  o.smooth_cells = v.params.smooth_cells;
  o.fold_cells = v.params.fold_cells > 0.0;
  o.kernels = v.params.kernels;
  o.specaa_quad = v.specaa.quad;
  return o;
}

namespace {

std::unique_ptr<ProgramWatch> started_watch(const std::string& method) {
  auto w = std::make_unique<ProgramWatch>(method);
  w->resume();
  return w;
}

}  // namespace

GlEngine::GlEngine(const std::string& method, const MethodOptions& o)
    : method_(method), v_(gl_variant(method, o)) {
  // Every program but staa's fixes nothing a frame decides: compiled now. staa's is
  // compiled at the first frame, for whether its water needs the smooth terms (upload).
  if (v_.entry != KernelEntry::staa) {
    use_program(program_options(v_));
    if (v_.entry == KernelEntry::taa) {
      watch_->resume();
      taa_resolve_ = kernel_program(KernelEntry::taa_resolve, program_options(v_));
      watch_->pause();
    }
  } else {
    const PathTables& t = required_path_tables(o, method);
    const kernel_tables::R32Texture2D f = t.f_texture();
    const kernel_tables::R32Texture3D s = t.s_texture();
    table_f_ = gl::Texture::table(GL_TEXTURE_2D, f.width, f.height, 1,
                                  {f.data, size_t(f.width) * f.height});
    table_s_ = gl::Texture::table(GL_TEXTURE_2D_ARRAY, s.width, s.height, s.layers,
                                  {s.data, size_t(s.width) * s.height * s.layers});
    tinfo_ = t.kernel_info_float();
    const KernelFitTexture& k = kernel_fit_texture();
    const kernel_tables::R32Texture2D kv = k.view();
    fits_ = gl::Texture::table(GL_TEXTURE_2D, kv.width, kv.height, 1, k.texels);
    finfo_ = k.info_float;
  }
  inputs_ = std::make_unique<KernelInputsF>();
}

GlEngine::~GlEngine() = default;

void GlEngine::use_program(const ProgramOptions& o) {
  if (program_options_ && *program_options_ == o) return;
  // A program compiled after the first frame's (another frame's smooth terms) is watched
  // as the first one is, until its first dispatch (prepare).
  if (!watch_) watch_ = started_watch(method_);
  watch_->resume();
  program_ = kernel_program(v_.entry, o);
  watch_->pause();
  program_options_ = o;
}

void GlEngine::upload(const FrameContext& ctx) {
  const ReferenceTimeSplit split = v_.entry == KernelEntry::reference
                                       ? reference_time_split(ctx.model, ctx.time.duration())
                                       : ReferenceTimeSplit{v_.segments, 1};
  const int segments = split.segments;
  // A program other than the reference's is compiled for its frames' K (kernel_program.h).
  if (v_.entry != KernelEntry::reference && segments != v_.segments)
    throw Error("GlEngine: a frame of " + std::to_string(segments) + " sub-arcs for a program of " +
                std::to_string(v_.segments));
  // `bruneton` and `lean` take the fields on flat water only (shading/cascade_fields.h).
  const bool fields =
      v_.cascade_fields && ((v_.entry != KernelEntry::bruneton && v_.entry != KernelEntry::lean) ||
                            !ctx.model.displaced());
  const bool gpu_fields = fields && v_.cascade_fft_gpu && cascade_fields_apply(ctx.model);
  build_kernel_inputs(ctx.model, ctx.time, segments, ctx.seed, *inputs_, v_.intersect_tolerance,
                      split.windows, fields, gpu_fields ? CascadeData::layout : CascadeData::host,
                      v_.cascade_reads);
  if (v_.entry == KernelEntry::staa) {
    // The program for this frame's smooth terms, light and camera (kernel/staa.glsl,
    // staa_frame_terms, staa_frame_light_sets, staa_frame_swept_cells).
    ProgramOptions o = program_options(v_);
    o.smooth_terms = kf::float_staa_frame_terms(inputs_->frame) ? 1 : 0;
    o.light_sets = kf::float_staa_frame_light_sets(inputs_->frame) ? 1 : 0;
    o.swept_cells = o.smooth_terms != 0 && kf::float_staa_frame_swept_cells(inputs_->frame) ? 1 : 0;
    use_program(o);
  }
  const int w = ctx.model.width(), h = ctx.model.height();
  if (w != width_ || h != height_) {
    weights_ = gl::Texture::image_2d(not_power_of_two(w), not_power_of_two(h), GL_RGBA32F);
    if (v_.entry == KernelEntry::reference || v_.entry == KernelEntry::stratified) {
      pixel_state_ = gl::Texture::image_2d(not_power_of_two(w), not_power_of_two(h), GL_RGBA32F);
    }
    width_ = w;
    height_ = h;
  }
  // The wave buffer: at least one texel (a scene may have no waves); the host's texels,
  // then, with the GPU's fields, the cascades' data written there.
  const size_t used = gpu_fields ? inputs_->cascades->layout().end : inputs_->texels.size();
  const size_t texels = size_t(not_power_of_two(int(std::max<size_t>(1, used))));
  if (waves_.texels() != texels)
    waves_ = gl::TextureBuffer(std::vector<float>(4 * texels, 0.0f), GL_RGBA32F);
  if (gpu_fields) {
    if (!fields_) fields_ = std::make_unique<CascadeFieldsGl>();
    const std::vector<glm::dvec3> bounds =
        fields_->fill(ctx.model, ctx.time, segments, inputs_->cascades->layout(), waves_.buffer(),
                      v_.cascade_reads);
    set_cascade_bounds(ctx.model, bounds, *inputs_);
  }
  upload_.resize(4 * inputs_->texels.size());
  for (size_t i = 0; i < inputs_->texels.size(); ++i) {
    for (int c = 0; c < 4; ++c)
      upload_[4 * i + c] = inputs_->texels[i][c];
  }
  if (!upload_.empty()) waves_.update(upload_);
  UniformWriter u(program_);
  u.set("image_size", kf::ivec2(w, h));
  set_uniforms(u, "frame", inputs_->frame);
  if (v_.entry == KernelEntry::stratified) {
    set_uniforms(u, "counts", v_.counts);
    u.set("pass_index", 0);
    pass_samples_ = pass_samples(inputs_->frame.wave_count, 0, inputs_->frame.displaced,
                                 inputs_->frame.cascade_count);
  }
  if (v_.entry == KernelEntry::reference) {
    set_uniforms(u, "ref_params", v_.reference);
    u.set("pass_index", 0);
    pass_samples_ = pass_samples(inputs_->frame.wave_count, segments, inputs_->frame.displaced,
                                 inputs_->frame.cascade_count);
  }
  if (v_.entry == KernelEntry::specaa) set_uniforms(u, "sparams", v_.specaa);
  if (v_.entry == KernelEntry::microspec) set_uniforms(u, "mparams", v_.microspec);
  if (v_.entry == KernelEntry::bruneton) set_uniforms(u, "bparams", v_.bruneton);
  if (v_.entry == KernelEntry::lean) {
    upload_lean(ctx);
    set_uniforms(u, "lparams", lean_params_);
  }
  if (v_.entry == KernelEntry::staa) {
    set_uniforms(u, "params", v_.params);
    set_uniforms(u, "tinfo", tinfo_);
    set_uniforms(u, "finfo", finfo_);
  }
  if (v_.entry == KernelEntry::taa) {
    upload_taa(ctx);
    const kd::TaaParams p = taa_frame_params(ctx.model, ctx.time, v_.taa, inputs_->origin);
    set_uniforms(u, "tparams", taa_params_float(p));
    for (int c = 0; c < 3; ++c)
      u.set("radiance_channel[" + std::to_string(c) + "]",
            kf::vec4(ctx.model.radiances.channel(c)));
  }
}

void GlEngine::upload_taa(const FrameContext& ctx) {
  const SceneModel& m = ctx.model;
  const int channels = m.scene.grey() ? 1 : 3;
  if (taa_motion_.id() == 0 || taa_rparams_.size != kf::ivec2(m.width(), m.height())) {
    const int w = not_power_of_two(m.width()), h = not_power_of_two(m.height());
    taa_motion_ = gl::Texture::image_2d(w, h, GL_RGBA32F);
    for (gl::Texture& t : taa_out_)
      t = gl::Texture::image_2d(w, h, GL_RGBA32F);
    taa_history_ = false;
  }
  // A cut: the history belongs to another sequence (methods/taa.h).
  if (ctx.time.frame != taa_frame_ + 1 || channels != taa_channels_) taa_history_ = false;
  taa_frame_ = ctx.time.frame;
  taa_channels_ = channels;
  taa_rparams_ =
      taa_resolve_params_float(taa_resolve_params(v_.taa, m.width(), m.height(), channels));
  UniformWriter r(taa_resolve_);
  r.set("image_size", kf::ivec2(m.width(), m.height()));
  set_uniforms(r, "rparams", taa_rparams_);
}

void GlEngine::run_taa_resolve() {
  gl::barrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  // The samples, then the last output as the history; the output in the other texture.
  const int write = taa_history_ ? 1 - taa_write_ : taa_write_;
  weights_.bind_texture(2);
  taa_out_[1 - write].bind_texture(3);
  taa_motion_.bind_texture(4);
  taa_out_[write].bind_image(0, GL_WRITE_ONLY);
  taa_resolve_.set("taa_has_history", taa_history_ ? 1 : 0);
  gl::dispatch_2d(taa_resolve_, width_, height_);
  taa_write_ = write;
  taa_history_ = true;
}

const gl::Texture& GlEngine::output_texture() const {
  return v_.entry == KernelEntry::taa ? taa_out_[taa_write_] : weights_;
}

void GlEngine::upload_lean(const FrameContext& ctx) {
  // The map's region and its waves (methods/lean.h, as the CPU's method places them), from
  // the frame's float waves.
  const SceneModel& m = ctx.model;
  const std::vector<kd::Wave> waves = kernel_frame_waves(*inputs_);
  const LeanMapRegion region = lean_map_region(m, v_.lean.size, v_.lean.far);
  const kd::LeanParams p = lean_frame_params(region, v_.lean, v_.lean.size, waves,
                                             vec2(inputs_->origin.x, inputs_->origin.z));
  lean_params_ = lean_params_float(p);
  if (!lean_map_) lean_map_ = std::make_unique<LeanMapGl>();
  lean_map_->allocate(v_.lean.size);  // filled in run(), within the frame's GPU time
}

void GlEngine::bind() {
  if (v_.entry == KernelEntry::reference || v_.entry == KernelEntry::stratified) {
    weights_.bind_image(0, GL_READ_WRITE);
  } else {
    weights_.bind_image(0, GL_WRITE_ONLY);
  }
  if (v_.entry == KernelEntry::reference || v_.entry == KernelEntry::stratified) {
    pixel_state_.bind_image(5, GL_READ_WRITE);
    if (pass_unfinished_.id() == 0) pass_unfinished_ = gl::Buffer(sizeof(std::uint32_t));
    pass_unfinished_.bind(GL_SHADER_STORAGE_BUFFER, 8);
  }
  if (v_.entry == KernelEntry::lean) lean_map_->texels().bind(6);
  if (v_.entry == KernelEntry::taa) taa_motion_.bind_image(5, GL_WRITE_ONLY);
  waves_.bind(1);
  if (v_.entry == KernelEntry::staa) {
    table_f_.bind_texture(2);
    table_s_.bind_texture(3);
    fits_.bind_texture(4);
  }
}

void GlEngine::run() {
  // `lean`'s map first (an empty region's map is bound but never read).
  if (v_.entry == KernelEntry::lean && !lean_params_.empty)
    lean_map_->fill(waves_, inputs_->frame, lean_params_);
  bind();
  if (v_.entry != KernelEntry::reference && v_.entry != KernelEntry::stratified) {
    gl::dispatch_2d(program_, width_, height_);
    if (v_.entry == KernelEntry::taa) run_taa_resolve();
    return;
  }
  // The samples in passes of up to pass_samples_ per pixel, each adding to the weights
  // from where the pixel's last pass stopped (shaders/main.glsl); the reference's first
  // pass runs the pilot (and clears the weights). After the passes that would take every
  // sample had no invocation stopped early, the count of unfinished pixels is read back,
  // and passes go on while it is not 0 (each takes at least one sample of every unfinished
  // pixel, so at most `total` passes in all).
  int total = 0;
  int first = 0;
  if (v_.entry == KernelEntry::reference) {
    const kf::ReferenceParams& n = v_.reference;
    total = n.batches * std::max(n.sx * n.sy, n.quiet_sx * n.quiet_sy) * n.nt;
    program_.set("pass_index", 0);
    program_.set("pass_samples", pass_samples_);
    gl::dispatch_2d(program_, width_, height_);
    first = 1;
  } else {
    const kf::SampleCounts& n = v_.counts;
    total = n.sx * n.sy * (n.time_at_frame ? 1 : n.nt);
  }
  const int scheduled = (total + pass_samples_ - 1) / pass_samples_;
  program_.set("pass_samples", pass_samples_);
  for (int pass = 0; pass < total; ++pass) {
    const bool check = pass >= scheduled - 1;
    if (check) pass_unfinished_.fill(0);
    gl::barrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    program_.set("pass_index", first + pass);
    gl::dispatch_2d(program_, width_, height_);
    if (check) {
      gl::barrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      std::uint32_t unfinished = 0;
      pass_unfinished_.read(0, sizeof unfinished, &unfinished);
      if (unfinished == 0) break;
    }
  }
}

void GlEngine::prepare() {
  if (!watch_) return;
  watch_->resume();
  bind();
  // One workgroup, with the frame's own bindings and uniforms (llvmpipe compiles a variant
  // per binding state); the frame's dispatch then writes the same values over it.
  gl::dispatch_2d(program_, 1, 1);
  glFinish();
  watch_->finish();
  watch_.reset();
}

void GlEngine::dispatch(const FrameContext& ctx) {
  upload(ctx);
  prepare();
  timer_.begin();
  run();
  timer_.end();
  gl::barrier();
  last_ms_ = timer_.milliseconds();
  gl::check_errors("GL engine dispatch");
}

std::vector<float> GlEngine::read_weights() const {
  return output_texture().read_region(width_, height_);
}

GlEngine::FrameTimes GlEngine::time_frames(const FrameContext& ctx, int warmup, int repeats) {
  upload(ctx);
  prepare();
  for (int k = 0; k < warmup; ++k)
    run();
  gl::barrier();
  glFinish();
  std::vector<double> gpu, frame;
  for (int k = 0; k < std::max(1, repeats); ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    upload(ctx);
    timer_.begin();
    run();
    timer_.end();
    gl::barrier();
    gpu.push_back(timer_.milliseconds());
    (void)read_weights();
    frame.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  gl::check_errors("GL engine timing");
  // Each frame's GPU time lies within its wall time, so the medians keep that order.
  std::sort(gpu.begin(), gpu.end());
  std::sort(frame.begin(), frame.end());
  last_ms_ = gpu[gpu.size() / 2];
  return {last_ms_, frame[frame.size() / 2]};
}

}  // namespace sg::gl_engine
