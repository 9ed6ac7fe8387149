// The viewer's still-frame reference: while the view is paused, the GL engine's
// `reference` (gl_engine/gl_engine.h, the estimator of `render --method reference`, with
// the command line's --samples, --batches, --adaptive and --quiet-samples) renders the
// frame again and again, batch k with seed `seed + k`, and the view shows the running mean
// of the batches' linear images, or its absolute difference to the method's image, scaled.
// The first batch is exactly `render --method reference --engine gl --seed seed` of the
// frame; each further batch is an independent estimate, so the mean's noise falls as
// 1 / sqrt(batches). The owner restarts it whenever the frame, the camera, the scene's
// edits or the method change.
#pragma once

#include <memory>
#include <vector>

#include "gl_engine/gl_engine.h"
#include "image/image.h"
#include "methods/method.h"
#include "methods/options.h"

namespace sg::viewer {

class ReferenceView {
 public:
  // Throws sg::Error when the options do not make a reference.
  explicit ReferenceView(const MethodOptions& options);

  // Drops the batches.
  void restart() { batches_ = 0; }
  // One more batch of ctx's frame (its seed replaced by the options' seed + batches()).
  void add_batch(const FrameContext& ctx);
  int batches() const { return batches_; }
  // Samples per pixel in the mean so far: busy pixels (the pilot's verdict) and quiet ones.
  long busy_samples() const { return batches_ * per_batch_busy_; }
  long quiet_samples() const { return batches_ * per_batch_quiet_; }
  // The running mean (the first batch's image after one batch); empty before any.
  const Image& mean() const { return mean_; }
  double last_gpu_ms() const { return engine_->last_gpu_ms(); }

 private:
  MethodOptions options_;
  std::unique_ptr<gl_engine::GlEngine> engine_;
  std::vector<double> sum_;
  Image mean_;
  int batches_ = 0;
  long per_batch_busy_ = 0, per_batch_quiet_ = 0;
};

// |a - b| * scale, channel by channel (same size and channels).
Image difference_image(const Image& a, const Image& b, double scale);

}  // namespace sg::viewer
