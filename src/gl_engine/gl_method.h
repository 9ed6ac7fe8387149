// A method run by the GL engine, as the CPU engine's frame loop sees it (`--engine gl`):
// begin_frame dispatches the frame on the GPU and reads its weights back, and the tiles copy
// them (the radiances applied there, as for every method; `taa`'s output is radiances
// already, its history kept on the GPU: stateful, as the CPU's). The GL context is the process's
// headless one (gl/context.h), made on first use on the calling thread; `sunglint render`,
// `compare` and `bench` call from one thread.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "methods/method.h"

namespace sg::gl_engine {

class GlEngine;

class GlMethod final : public Method {
 public:
  // Throws sg::Error naming the method or flag the GL engine lacks, or gl::Unavailable
  // when no OpenGL 4.5 context can be made.
  GlMethod(const std::string& name, const MethodOptions& options);
  ~GlMethod() override;
  std::string name() const override { return name_; }
  bool stateful() const override { return warmup_ >= 0; }
  int warmup_frames() const override { return warmup_ < 0 ? 0 : warmup_; }
  void reset() override;
  void begin_frame(const FrameContext& ctx) override;
  // A pixel's weights; sg::Error for `taa`, whose output is radiances.
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override;
  void shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                  Image& out) const override;
  // GPU time of the last frame's dispatch, ms (timer queries).
  double last_gpu_ms() const;
  GlEngine& engine() { return *engine_; }

 private:
  std::string name_;
  std::unique_ptr<GlEngine> engine_;
  std::vector<float> weights_;  // or radiances (GlEngine::outputs_radiances)
  int width_ = 0;
  int warmup_ = -1;  // a stateful method's warm-up frames (`taa`); -1: stateless
};

// The process's headless GL context (made once, current on the thread that made it).
void ensure_headless_context();
// Its one-line description: renderer, version, platform.
std::string headless_context_summary();

}  // namespace sg::gl_engine
