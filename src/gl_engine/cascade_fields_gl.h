// The lattice cascades' FFT fields built on the GPU (docs/ocean.md, "Shading from the
// cascades"): the GL engine's twin of shading/cascade_fields.h, writing the same texels
// (to float rounding; the chain and the height's differences by the same text,
// kernel/cascade_chain.glsl) into the wave buffer where the kernel reads them, so that a
// frame's fields never cross the bus: the host lays out the headers and the bounds
// (build_kernel_inputs with CascadeData::layout), this fills each cascade's data.
//
// Per cascade and frame (the lattice oversampled as on the host, oversampled_cascade):
//   - at the display time t_K, two transforms (gl_engine/cascade_fft_gl.h): (dh/dx, h,
//     dh/dz, d2h/dxdz), then (d2h/dx2, d2h/dz2) paired with the slopes at t_0; the other
//     instants' slopes two to a transform;
//   - each instant's LEAN chain into its place (shaders/cascade_chain.glsl, one dispatch per
//     level); with a zero shutter the display time's chain copied to every instant;
//   - the display time's height maxima (shaders/cascade_bounds.glsl), read back (a wait
//     on the GPU's transforms, a few values) to bound the interpolants on the host
//     (cascade_bounds_from_maxima) as the CPU does.
// The lattices' time origin is the display time rounded down to a multiple of kTimeEpoch,
// so a frame's fields depend on its time alone (the same bytes whatever was rendered
// before) and the float phase omega (t - t0) stays within a few 1e-5 rad.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl_engine/cascade_fft_gl.h"
#include "scene/model.h"
#include "shading/cascade_fields.h"

namespace sg::gl_engine {

inline constexpr double kTimeEpoch = 8.0;  // s

class CascadeFieldsGl {
 public:
  CascadeFieldsGl();  // a GL context must be current
  ~CascadeFieldsGl();

  // Fills frame ft's cascade data (K = segments) into `waves` (the wave buffer's storage)
  // at `layout`'s places and returns each cascade's bounds on its interpolants
  // (set_cascade_bounds in shading/kernel_frame.h takes them): on displaced water alone,
  // whose march reads them (zeros on flat water, as the host's CascadeFields leaves them:
  // no pass, no wait for a read-back). Issues the barrier the kernel's texel fetches need.
  // `reads`: what the method reads (shading/cascade_fields.h), the rest not built.
  std::vector<glm::dvec3> fill(const SceneModel& m, const FrameTime& ft, int segments,
                               const CascadeLayout& layout, const gl::Buffer& waves,
                               CascadeReads reads = CascadeReads::all);

 private:
  void prepare(const SceneModel& m, double t0);
  // An instant's chain into `waves` from texel `at` (shaders/cascade_chain.glsl), in the
  // kernel's modes (kernel/cascade_chain.glsl, kCascadeChain*): Chain::full, the display
  // time's from the transform's fields 0 and 1; Chain::slopes, the slopes in field
  // `field`'s pair `slot` (0: xy, 1: zw); Chain::slopes_height, field 0's
  // slopes and height at level 0, the slopes alone at the levels above (the display time's
  // level 0 under the reduced reads; the other instants on displaced water).
  enum class Chain { slopes = 0, full = 1, slopes_height = 2 };
  void chain(const CascadeFftGl& fft, Chain kind, int field, int slot, size_t at,
             const gl::Buffer& waves, bool levels);

  uint64_t model_ = 0;
  double t0_ = 0;
  std::vector<std::unique_ptr<CascadeFftGl>> ffts_;
  std::vector<CascadeDesc> padded_;
  gl::Program chain_, bounds_;
  gl::Buffer maxima_;
};

}  // namespace sg::gl_engine
