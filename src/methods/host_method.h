// What a host method (the baselines lean, bruneton, taa) keeps of a
// frame: the water's geometry from the kernel (shading/water_geometry.h), built in
// begin_frame as the kernel methods build their inputs, and the count of the frame's
// fallback pixels.
//
// Pixels where a method's model does not apply. Every method returns a finite value on
// every valid scene; where the assumption of its model fails (a camera below the crests,
// a ray that grazes the water, a degenerate pixel footprint, a lobe whose shading is not
// finite), it falls back to a defined value (each method's header says which) and counts
// the pixel here, so that `sunglint render` can report how many pixels of a frame did.
//
// The fallback value is the spec's radiance along the ray through the pixel centre at the
// frame time (what `point` returns): defined wherever the scene is valid, also with the
// camera under the surface (the spec's convention: the ray hits at the camera).
//
// A method derives from HostMethod: it calls begin_host_frame(ctx) in begin_frame (the
// geometry is built, the count reset), reads water(ctx) for the geometry, and calls
// fallback() (any thread) where its model fails, or finite_or_fallback() on its weights.
// `specaa` and `microspec`, on the kernel, count through FallbackCount alone.
// fallback_pixels(method) reads the count of the last frame, or -1 for a method that does not
// count.
#pragma once

#include <atomic>
#include <cmath>

#include "methods/method.h"
#include "shading/water_geometry.h"

namespace sg {

// The radiance weights along the ray through the centre of pixel (i, j) at the frame time.
RadianceWeights centre_ray_weights(const FrameContext& ctx, const WaterGeometry& water, int i,
                                   int j);

// Whether all four weights are finite.
inline bool finite_weights(const RadianceWeights& w) {
  return std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z) && std::isfinite(w.w);
}

// The count of a frame's fallback pixels (any thread adds to it): a host method's, and
// that of a kernel method whose model can fail (`specaa`, `microspec`).
class FallbackCount {
 public:
  virtual ~FallbackCount() = default;
  long fallbacks() const { return fallbacks_.load(std::memory_order_relaxed); }

 protected:
  void reset_fallbacks() { fallbacks_.store(0, std::memory_order_relaxed); }
  void count_fallback() const { fallbacks_.fetch_add(1, std::memory_order_relaxed); }

 private:
  mutable std::atomic<long> fallbacks_{0};
};

class HostMethod : public FallbackCount {
 protected:
  // Builds the frame's water geometry and resets the count (begin_frame, one thread).
  void begin_host_frame(const FrameContext& ctx);
  // The geometry of ctx's frame; sg::Error naming `method` when the frame was not begun
  // (a caller that shades without begin_frame: methods/method.h).
  const WaterGeometry& water(const FrameContext& ctx) const;
  // Counts pixel (i, j) and returns its fallback weights.
  RadianceWeights fallback(const FrameContext& ctx, int i, int j) const {
    count_fallback();
    return centre_ray_weights(ctx, water(ctx), i, j);
  }
  // `w` when all its weights are finite, else the fallback.
  RadianceWeights finite_or_fallback(const RadianceWeights& w, const FrameContext& ctx, int i,
                                     int j) const {
    return finite_weights(w) ? w : fallback(ctx, i, j);
  }

 private:
  WaterGeometry water_;
};

// The fallback pixels of the method's last frame; -1 when the method does not count them.
inline long fallback_pixels(const Method& m) {
  const auto* c = dynamic_cast<const FallbackCount*>(&m);
  return c ? c->fallbacks() : -1;
}

}  // namespace sg
