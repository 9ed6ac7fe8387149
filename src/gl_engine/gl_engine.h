// The GL engine: the shading kernel run as an OpenGL 4.5 compute shader, one invocation per
// pixel, in float (docs/gpu.md). It runs `point`, `supersample`, `reference`,
// `staa-temporal`, `staa` (both NDFs, `--footprint none|gaussian`, every kernel count
// and fallback) and the baselines `specaa` and `microspec` with the CPU engine's estimators
// and seeds, the baselines `bruneton` and `lean` (its map built on the GPU,
// gl_engine/lean_map_gl.h), and `taa` (its samples, then its resolve against the history it
// keeps on the GPU; its output is radiances, not weights); anything else
// is refused with a message naming the method or flag, never rendered elsewhere. Its `reference` is
// the CPU engine's estimator (kernel/reference.glsl, its K per frame from the waves and the
// shutter) but does not report its noise: the batches' spread stays on the GPU.
//
// Per frame, on the host: the kernel's inputs in float (shading/kernel_frame.h: the phases
// reduced in double at the frame's time, camera-relative, the waves sorted), uploaded as
// the wave buffer texture and the kernel's structs as uniforms (gl_engine/uniforms.h); a
// scene's cascades transformed on the GPU into the same buffer (gl_engine/cascade_fields_gl.h;
// `--cascade-fft host`: on the host, uploaded); one
// dispatch (the sampling methods: passes of a few samples each, see pass_samples; the
// reference's first pass runs its pilot); the weights stay in an RGBA32F image on the GPU until
// read back. The tables (path tables, kernel fits) are uploaded once, as textures. Needs a current
// GL context.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/texture_buffer.h"
#include "gl/timer.h"
#include "gl_engine/cascade_fields_gl.h"
#include "gl_engine/kernel_program.h"
#include "gl_engine/lean_map_gl.h"
#include "gl_engine/program_notice.h"
#include "methods/method.h"
#include "methods/options.h"
#include "shading/kernel_frame.h"

namespace sg::gl_engine {

// What the GL engine runs for a method and its options; throws sg::Error naming the method
// or the flag the engine lacks.
struct GlVariant {
  KernelEntry entry = KernelEntry::point;
  int segments = 1;
  kf::SampleCounts counts{};
  kf::ReferenceParams reference{};  // `reference`: segments is the cap, each frame picks K
  kf::StaaParams params{};
  kf::SpecaaParams specaa{};
  kf::MicrospecParams microspec{};
  kf::BrunetonParams bruneton{};
  LeanOptions lean{};              // `lean`: the map's options (its parameters are the frame's)
  TaaOptions taa{};                // `taa`: its options (its parameters are the frame's)
  double intersect_tolerance = 0;  // --intersect-tolerance (shading/kernel_frame.h)
  // --cascades fields: point, staa-temporal, staa and specaa read a scene's cascades from their
  // FFT fields in the wave buffer (shading/cascade_fields.h, built on the host).
  bool cascade_fields = false;
  // --cascade-fft gpu: those fields transformed on the GPU (gl_engine/cascade_fields_gl.h).
  bool cascade_fft_gpu = true;
  // What the entry reads of them (shading/cascade_fields.h), as the CPU's method does.
  CascadeReads cascade_reads = CascadeReads::all;
};
GlVariant gl_variant(const std::string& method, const MethodOptions& options);

// What the variant's program fixes in its text (gl_engine/kernel_program.h).
ProgramOptions program_options(const GlVariant& v);

// The methods the GL engine runs, for messages and help.
const char* gl_methods();

// The samples per pixel of one pass of the GL engine's `reference` and `supersample` for a
// frame of `waves` waves, K path sub-intervals (the reference on flat water; 0 otherwise),
// flat or displaced water: chosen so that an invocation's loop iterations stay near
// kPassIterations, far below llvmpipe's 65535 per invocation, past which llvmpipe ends
// every loop of the invocation and the samples after that point are lost (the GL
// reference's former bias, docs/reference-renderer.md). The estimate per sample is the
// wave sums (waves x (K + 2) on flat water, waves x 48 march and refinement steps on
// displaced water) plus the crossing search (300 per sub-interval), plus the cascades
// read from their fields (`cascades` of them).
inline constexpr int kPassIterations = 8000;
int pass_samples(int waves, int segments, bool displaced, int cascades = 0);

class GlEngine {
 public:
  GlEngine(const std::string& method, const MethodOptions& options);
  ~GlEngine();

  // Builds the frame's inputs and dispatches; the weights are then in output_texture().
  void dispatch(const FrameContext& ctx);
  // Whether the output is radiances (`taa`: (r, g, b, 0) per pixel, grey in r) rather than
  // weights.
  bool outputs_radiances() const { return v_.entry == KernelEntry::taa; }
  // The output of the last dispatch, row 0 at the top: the weights (light, zenith, horizon,
  // sea) per pixel, or the radiances (outputs_radiances); waits for the GPU.
  std::vector<float> read_weights() const;
  const gl::Texture& output_texture() const;
  // `taa`: forgets the history (the next frame starts a sequence). A frame that does not
  // follow the last one, or of another size or channel count, forgets it too.
  void reset_history() { taa_history_ = false; }
  // `repeats` whole frames of ctx after `warmup` dispatches: per frame the GPU time of its
  // dispatch (timer queries) and the wall time of the whole frame around it (upload,
  // dispatch, read-back), so that a frame's GPU time never exceeds its wall time; the
  // medians of each, in ms.
  struct FrameTimes {
    double gpu_ms = 0, frame_ms = 0;
  };
  FrameTimes time_frames(const FrameContext& ctx, int warmup, int repeats);
  // GPU time of the last dispatch in ms.
  double last_gpu_ms() const { return last_ms_; }
  // The program of the last frame (staa's is compiled at its first frame: before it, none).
  const gl::Program& program() const { return program_; }
  // `taa`'s resolve program (none for the other methods).
  const gl::Program& taa_resolve_program() const { return taa_resolve_; }

 private:
  void upload(const FrameContext& ctx);
  // `lean`: the frame's map parameters and its map (after the wave buffer's upload).
  void upload_lean(const FrameContext& ctx);
  // `taa`: the frame's parameters, its images and whether the history carries over.
  void upload_taa(const FrameContext& ctx);
  // `taa`'s resolve, after its samples.
  void run_taa_resolve();
  void bind();
  void run();
  // Before the first dispatch: one workgroup dispatched and waited for, where a driver that
  // compiles at first use (llvmpipe) does so, outside any timing (program_notice.h).
  void prepare();

  // The program of `o`, compiled unless it is the current one's.
  void use_program(const ProgramOptions& o);

  std::string method_;
  std::unique_ptr<ProgramWatch> watch_;  // a program's, from its compile to its first dispatch
  GlVariant v_;
  gl::Program program_;
  std::optional<ProgramOptions> program_options_;  // what program_ was compiled for
  gl::Texture table_f_, table_s_, fits_;
  kf::PathTableInfo tinfo_{};
  kf::KernelFitInfo finfo_{};
  gl::TextureBuffer waves_;
  gl::Texture weights_;
  // The sampling methods' pixels between passes: .x the reference's pilot (1 where a pixel
  // is busy), .y the pixel's next sample (shaders/main.glsl).
  gl::Texture pixel_state_;
  gl::Buffer pass_unfinished_;  // one uint: the pixels a pass left unfinished
  int pass_samples_ = 1;        // the samples per pixel per pass, this frame
  gl::GpuTimer timer_;
  int width_ = 0, height_ = 0;
  double last_ms_ = 0;
  std::unique_ptr<KernelInputsF> inputs_;
  std::unique_ptr<CascadeFieldsGl> fields_;  // the cascades' transforms, on the first need
  std::unique_ptr<LeanMapGl> lean_map_;      // `lean`'s map
  kf::LeanParams lean_params_{};             // `lean`: the frame's map parameters
  // `taa`: its resolve's program, the samples' motion, the outputs of the last two frames
  // (the one the frame writes, the history it reads), whether the history is the frame
  // before's, and the frame's resolve parameters.
  gl::Program taa_resolve_;
  gl::Texture taa_motion_, taa_out_[2];
  int taa_write_ = 0;
  bool taa_history_ = false;
  int taa_frame_ = 0;
  int taa_channels_ = 0;
  kf::TaaResolveParams taa_rparams_{};
  std::vector<float> upload_;  // the host's texels, as floats
};

}  // namespace sg::gl_engine
