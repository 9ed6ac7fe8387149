// Temporal anti-aliasing (`--method taa`): the accumulation that real-time engines ship,
// the alternative Podee et al. 2021 argue against (Sec. 2.2: reprojection "cannot track the
// movement of the reflection direction"). Karis 2014, "High Quality Temporal
// Supersampling"; Salvi 2016, "An Excursion in Temporal Supersampling" (variance
// clipping); Yang, Liu and Salvi 2020, "A Survey of Temporal Antialiasing Techniques".
// On the shading kernel (kernel/taa.glsl: the sample and the resolve, both engines); here
// the host's part: the frame's parameters and the history.
//
// Frame f (display time t_f):
//  1. Current samples: one camera ray per pixel through (i + 1/2, j + 1/2) + jitter(f), the
//     Halton (2, 3) offset of index (f mod K) + 1 (`--taa-jitter-count` K, default 8),
//     shaded at t_f exactly as `point` shades (kernel/sampling.glsl, sample_ray; the scene's
//     cascades as their sines, so that the motion below can read the height at t_{f-1}).
//  2. Motion vectors (the engine's velocity buffer), per sample: where the point it sees
//     was on the image of the previous frame, whose camera is the camera at the previous
//     display time t_{f-1}. Flat water is the plane y = 0, which does not move (the
//     reflections move, and reprojection cannot follow them: the paper's point). Displaced
//     water is a height field displaced vertically, as a displaced grid mesh: the point
//     (x, h(x, z, t_f), z) was at (x, h(x, z, t_{f-1}), z). That point is projected by the
//     previous frame's camera to p' (the sky, at infinity, by its direction alone: only
//     the camera's turn moves it); motion = p - p', with p the sample's image-plane
//     position. A fixed camera (or one whose pose at t_{f-1} equals that at t_f) is its
//     own previous camera: the sky and flat water then have motion 0, as the static
//     camera of format /1 and /2 gives, bit for bit. A point behind the previous camera
//     has no history. `--taa-motion surface` keeps the surface's motion alone (projected
//     by the current camera, as for a fixed one): the reprojection a moving camera lacks.
//  3. Reprojection: the history (the previous output) is resampled at the pixel centre
//     minus the motion (`--taa-history bilinear|catmull-rom`). A point outside the image
//     has no history: the pixel shows its current sample. There is no depth test for
//     disocclusion: as in Karis 2014, the neighbourhood clamp rectifies stale history.
//  4. Rectification: the history is clipped to the box of the current samples in the 3 x 3
//     pixels around the pixel (`--taa-clamp variance`: mean +- gamma sigma, Salvi 2016,
//     `--taa-gamma` default 1; `minmax`: Karis 2014; `none`).
//  5. Blend: out = lerp(history, current, alpha), `--taa-alpha` default 0.1 (Karis 2014;
//     Survey Sec. 4). out becomes the history of the next frame.
// Steps 3-5 run on each channel of a colour image alone (the clamp's box too), as engines
// that clip in RGB do. The blend is on the spec's linear value; Karis's luminance weighting (1 / (1
// + luma), against bright fireflies) is left out because it biases the linear mean that every
// method here is measured on. No sharpening, no motion-dependent alpha.
//
// Stateful: frames must arrive in order. The first frame after reset() (or after a frame
// that does not follow the previous one: a cut) has no history and shows its current
// samples. Frame F alone is the output after `--taa-warmup` N (default 16) frames F-N..F-1
// rendered first (engine/render.h: render_frames does this for every stateful method, and
// for the first frame of a sequence); with alpha 0.1, 0.9^16 = 19% of the first warm-up
// frame still remains at F, so frames inside a long sequence differ slightly from the same
// frames rendered alone.
#pragma once

#include <vector>

#include "image/image.h"
#include "methods/fallback.h"
#include "methods/kernel_inputs.h"
#include "methods/method.h"

namespace sg {

// The frame's TaaParams (kernel/interface.glsl): the jitter of ft's frame, the previous
// display time, and the previous frame's camera where it is not this frame's (a moving
// camera, --taa-motion full), in the frame's camera-relative coordinates (`origin`: the
// kernel inputs' origin, shading/kernel_frame.h).
kd::TaaParams taa_frame_params(const SceneModel& m, const FrameTime& ft, const TaaOptions& o,
                               const glm::dvec3& origin);
kf::TaaParams taa_params_float(const kd::TaaParams& p);
// The resolve's parameters for an image of width x height and `channels`.
kd::TaaResolveParams taa_resolve_params(const TaaOptions& o, int width, int height, int channels);
kf::TaaResolveParams taa_resolve_params_float(const kd::TaaResolveParams& p);
// Throws sg::Error naming the flag for a bad option.
void validate_taa_options(const TaaOptions& o);

// Fallback (methods/fallback.h): a blended value that is not finite is replaced by the
// current sample and counted.
class TaaMethod final : public Method, public FallbackCount {
 public:
  // Throws sg::Error naming the flag for a bad option. `intersect_tolerance`: the displaced
  // intersection's (methods/options.h, intersect_tolerance_for).
  explicit TaaMethod(const TaaOptions& options, Precision precision = Precision::float64,
                     double intersect_tolerance = 0.0);
  std::string name() const override { return "taa"; }
  bool stateful() const override { return true; }
  int warmup_frames() const override { return options_.warmup; }
  void reset() override;

  void begin_frame(const FrameContext& ctx) override;
  // The current (jittered) sample of pixel (i, j).
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;
  // Current samples and their motion vectors.
  void shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                  Image& out) const override;
  // Reprojection, rectification and blend (kernel/taa.glsl, taa_resolve_pixel); `img` holds
  // the current samples on entry and the output on return.
  void end_frame(const FrameContext& ctx, Image& img) override;

  vec2 jitter() const { return vec2(params_.jitter); }
  // This frame's motion vectors (image-plane pixels, current minus previous position), row
  // by row; written by shade_tile.
  const std::vector<vec2>& motion() const { return motion_; }
  bool has_history() const { return has_history_; }

 private:
  TaaOptions options_;
  KernelFrameInputs inputs_;
  kd::TaaParams params_{};
  kf::TaaParams params_f_{};
  Image history_;
  bool has_history_ = false;
  int last_frame_ = 0;
  // Per-pixel motion of this frame's samples, written by shade_tile (each pixel its own
  // slot, so tiles on different threads never share one).
  mutable std::vector<vec2> motion_;
};

}  // namespace sg
