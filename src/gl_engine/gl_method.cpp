#include "gl_engine/gl_method.h"

#include <memory>

#include "base/error.h"
#include "gl/context.h"
#include "gl_engine/gl_engine.h"

namespace sg::gl_engine {
namespace {

gl::HeadlessContext& headless() {
  static std::unique_ptr<gl::HeadlessContext> ctx = std::make_unique<gl::HeadlessContext>();
  return *ctx;
}

}  // namespace

void ensure_headless_context() {
  headless().make_current();
}

std::string headless_context_summary() {
  return headless().info().summary();
}

GlMethod::GlMethod(const std::string& name, const MethodOptions& options) : name_(name) {
  gl_variant(name, options);  // refuses what the engine lacks before any GL
  ensure_headless_context();
  engine_ = std::make_unique<GlEngine>(name, options);
  if (engine_->outputs_radiances()) warmup_ = options.taa.warmup;
}

void GlMethod::reset() {
  engine_->reset_history();
}

GlMethod::~GlMethod() = default;

void GlMethod::begin_frame(const FrameContext& ctx) {
  ensure_headless_context();
  engine_->dispatch(ctx);
  weights_ = engine_->read_weights();
  width_ = ctx.model.width();
}

RadianceWeights GlMethod::weights(const FrameContext&, int i, int j) const {
  if (engine_->outputs_radiances())
    throw Error("GlMethod: " + name_ + " on the GL engine outputs radiances, not weights");
  const float* w = &weights_[(static_cast<size_t>(j) * width_ + i) * 4];
  return RadianceWeights(w[0], w[1], w[2], w[3]);
}

void GlMethod::shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                          Image& out) const {
  if (engine_->outputs_radiances()) {
    for (int j = y0; j < y1; ++j)
      for (int i = x0; i < x1; ++i)
        for (int c = 0; c < out.channels; ++c)
          out.at(i, j, c) = weights_[(static_cast<size_t>(j) * width_ + i) * 4 + c];
    return;
  }
  for (int j = y0; j < y1; ++j) {
    for (int i = x0; i < x1; ++i)
      store_pixel(ctx, out, i, j, weights(ctx, i, j));
  }
}

double GlMethod::last_gpu_ms() const {
  return engine_->last_gpu_ms();
}

}  // namespace sg::gl_engine
