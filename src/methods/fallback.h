// Pixels where a method's model does not apply. Every method returns a finite value on
// every valid scene; where the assumption of its model fails (a camera below the crests,
// a ray that grazes the water, a degenerate pixel footprint, a lobe whose shading is not
// finite, a TAA blend that is not finite), it falls back to a defined value (each method's
// header says which: the kernel's point_pixel, the spec's radiance along the ray through
// the pixel centre at the frame time, for most) and counts the pixel here, so that
// `sunglint render` can report how many pixels of a frame did. fallback_pixels(method)
// reads the count of the last frame, or -1 for a method that does not count.
#pragma once

#include <atomic>

#include "methods/method.h"

namespace sg {

// The count of a frame's fallback pixels (any thread adds to it), kept by the methods whose
// model can fail (`lean`, `specaa`, `microspec`, `bruneton`, `taa`).
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

// The fallback pixels of the method's last frame; -1 when the method does not count them.
inline long fallback_pixels(const Method& m) {
  const auto* c = dynamic_cast<const FallbackCount*>(&m);
  return c ? c->fallbacks() : -1;
}

}  // namespace sg
