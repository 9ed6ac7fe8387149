// A rendering method computes each pixel's value: the box-filtered mean over the pixel
// square and the frame's shutter interval of the radiance of the scene spec, or an
// approximation of it. Every method of `sunglint render --method` implements this.
//
// A pixel's result is the weights of the scene's four radiances (light, sky zenith, sky
// horizon, sea; shading/radiance.h), not a colour: the radiances are applied once per
// pixel when the tile is stored, so grey and colour scenes cost the same.
//
// The engine calls begin_frame once (single-threaded: per-frame tables, maps), then
// shade_tile from many threads (each tile once), then end_frame once with the whole
// image (stateful methods such as TAA resolve there, on the image's values). Frames of a sequence
// arrive in order; a method that needs its previous frame says so with `stateful()`.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "image/image.h"
#include "methods/options.h"
#include "scene/model.h"

namespace sg {

struct FrameContext {
  const SceneModel& model;
  FrameTime time;
  uint64_t seed = 0;
};

class Method {
 public:
  virtual ~Method() = default;
  virtual std::string name() const = 0;

  // Called once per frame, on one thread, before any pixel of the frame is shaded: what a
  // frame's pixels share is built here (the kernel methods refuse a frame they were not
  // begun with: methods/kernel_inputs.h). Tests shading single pixels call it too
  // (testing/begun.h).
  virtual void begin_frame(const FrameContext&) {}
  // The radiance weights of pixel (i, j). Must be thread-safe and depend on nothing but
  // its arguments and the state set by begin_frame.
  virtual RadianceWeights weights(const FrameContext& ctx, int i, int j) const = 0;
  // The value of pixel (i, j) in channel 0 (a grey scene's value): its weights applied
  // to the scene's radiances.
  double shade(const FrameContext& ctx, int i, int j) const {
    return ctx.model.radiances.apply(weights(ctx, i, j), 0);
  }
  // Pixels [x0, x1) x [y0, y1) into `out`. The default stores weights() of each.
  virtual void shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                          Image& out) const;
  virtual void end_frame(const FrameContext&, Image&) {}
  // A method that estimates its own noise (`reference`): the variance of each pixel's
  // estimate in the last frame rendered (same size as the image); nullptr otherwise.
  virtual const Image* pixel_variance() const { return nullptr; }
  // True when frame f depends on frames before it (history); sequences then render in
  // order and a single frame is rendered after its predecessors (see engine/render.h).
  virtual bool stateful() const { return false; }
  // Stateful methods: the number of frames rendered (and not shown) before the first frame
  // of every sequence, so that its history is full; frame F alone is the output after
  // frames F - N .. F - 1 (engine/render.h, render_frames).
  virtual int warmup_frames() const { return 0; }
  // Stateful methods: drops the history; the next frame is a first frame.
  virtual void reset() {}
};

// Stores pixel (i, j) of `out` from its radiance weights: the radiances applied in each of
// its channels (1 for a grey scene, 3 for colour).
void store_pixel(const FrameContext& ctx, Image& out, int i, int j, const RadianceWeights& w);

struct MethodInfo {
  std::string name;
  std::string summary;
};

// Every method `--method` accepts, in the order `--help` lists them.
const std::vector<MethodInfo>& method_catalog();

// The caller's path tables (options.path_tables) for `method`, loaded on the first request;
// sg::Error naming `method` when none were given.
class PathTables;
const PathTables& required_path_tables(const MethodOptions& options, const std::string& method);

// Builds a method by name; throws sg::Error ("--method: unknown method 'x' (choose ...)").
std::unique_ptr<Method> make_method(const std::string& name, const MethodOptions& options);

}  // namespace sg
