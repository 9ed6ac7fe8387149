#include "viewer/view_reference.h"

#include <cmath>

#include "base/error.h"
#include "methods/reference.h"
#include "viewer/view_image.h"

namespace sg::viewer {

ReferenceView::ReferenceView(const MethodOptions& options)
    : options_(options), engine_(std::make_unique<gl_engine::GlEngine>("reference", options)) {
  const ReferenceSettings rs = reference_settings(options);
  const long kernel_batches = rs.batches, t = rs.samples.st;
  per_batch_busy_ = kernel_batches * rs.samples.sx * rs.samples.sy * t;
  per_batch_quiet_ = rs.adaptive ? kernel_batches * rs.quiet * rs.quiet * t : per_batch_busy_;
}

void ReferenceView::add_batch(const FrameContext& ctx) {
  const FrameContext c{ctx.model, ctx.time, options_.seed + static_cast<uint64_t>(batches_)};
  const Image img = render_linear(*engine_, c);
  if (batches_ == 0 || img.data.size() != sum_.size()) {
    sum_.assign(img.data.size(), 0.0);
    batches_ = 0;
  }
  for (size_t k = 0; k < sum_.size(); ++k)
    sum_[k] += img.data[k];
  ++batches_;
  mean_ = img;  // after one batch, its image exactly (a float's sum over 1)
  for (size_t k = 0; k < sum_.size(); ++k)
    mean_.data[k] = static_cast<float>(sum_[k] / batches_);
}

Image difference_image(const Image& a, const Image& b, double scale) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw Error("viewer: the difference's images differ in size");
  Image d = a;
  for (size_t k = 0; k < d.data.size(); ++k)
    d.data[k] = static_cast<float>(std::abs(double(a.data[k]) - double(b.data[k])) * scale);
  return d;
}

}  // namespace sg::viewer
