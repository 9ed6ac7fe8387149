// The lattice cascades' FFT fields for the shading kernel (kernel/cascade_fields.glsl):
// per frame, each cascade transformed at the path's K + 1 instants (scene/cascade_fft.h,
// slopes and second derivatives), its LEAN chain built (means of s, s s^T and the
// curvatures over aligned 2^l blocks), and all of it appended to the wave buffer after the
// waves' sums, with a two-texel header per cascade and a texel of the displaced march's
// bounds per cascade (kernel/cascade_grid.glsl has the layout). The per-pixel cost is then a few
// fetches per cascade whatever its waves (docs/ocean.md, "Shading from the cascades").
//
// Which methods read them: `point`, `supersample` with T = 1, `staa-temporal` and `staa`
// (both engines, flat and displaced water), `lean`, `specaa` and `bruneton` (CPU engine,
// flat water, through methods/host_cascades.h). Elsewhere (`reference` and `supersample`
// with T > 1, whose rays take other times, the host baselines on displaced water, `taa`,
// `microspec`) the cascades are their lattice sines among the waves, exactly, at a cost
// that follows the waves.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "scene/cascade_fft.h"
#include "scene/model.h"

namespace sg {

// The fields' grid: the lattice's points oversampled (a zero-padded spectrum), so that the
// cubic interpolation between them follows the lattice's top octave: at least 2 times per
// axis, and up to 8 times while the grid stays within 256 points a side (32 -> 256,
// 64 -> 256, 128 -> 256, 256 -> 512). The cubic's slope error falls with the fourth power
// of the spacing (docs/ocean.md: 24.7% of the RMS slope on the lattice's own grid, 2.5%
// at 2 times); on small lattices, whose texels are wide against a pixel, it was of the
// order of the sun's disk.
inline int cascade_oversampling(int lattice) {
  int o = 2;
  while (o < 8 && lattice * o * 2 <= 256)
    o *= 2;
  return o;
}

class CascadeFields {
 public:
  // Appends frame ft's fields (K = segments path sub-arcs, the instants
  // t_k = end - duration (K - k) / K) to `texels` for a camera at world (cam_x, cam_z); the
  // first appended texel's index is returned (Frame.cascade_base). The FFTs' lattices are
  // set once per scene model.
  int append(const SceneModel& m, const FrameTime& ft, int segments, double cam_x, double cam_z,
             std::vector<glm::dvec4>& texels);
  int append(const SceneModel& m, const FrameTime& ft, int segments, double cam_x, double cam_z,
             std::vector<glm::vec4>& texels);
  // The scene's explicit waves alone (the wave buffer's, when the cascades are fields).
  const WaveField& explicit_waves(const SceneModel& m);
  // The cascades' sum A and sum A |k| (bounds of their sines).
  double amplitude_sum(const SceneModel& m);
  double slope_sum(const SceneModel& m);
  // The last append's bounds on the fields' interpolated height, its slope along a
  // horizontal direction and its second derivative along one, summed over the cascades
  // (kernel/cascade_grid.glsl, cascade_interpolant_bounds): what the frame's bounds add
  // for them, far tighter than the sines' sums.
  const glm::dvec3& interpolant_bounds() const { return bounds_; }

 private:
  template <class V4>
  int append_impl(const SceneModel& m, const FrameTime& ft, int segments, double cam_x,
                  double cam_z, std::vector<V4>& texels);
  void prepare(const SceneModel& m);

  uint64_t model_ = 0;
  std::vector<std::unique_ptr<CascadeFft>> ffts_;
  std::vector<int> lattices_;    // each field's grid side (the lattice's, oversampled)
  std::vector<glm::dvec3> cov_;  // each cascade's sum A^2 / 2 k k^T (xx, xz, zz)
  // Each cascade's grid and chain, their storage kept from frame to frame.
  struct Scratch {
    CascadeGrid grid;
    std::vector<MomentLevel> chain;
  };
  std::vector<Scratch> scratch_;
  WaveField explicit_;
  double amplitude_sum_ = 0, slope_sum_ = 0;
  glm::dvec3 bounds_{0.0};
};

// Whether a frame of `m` shades its cascades from fields: it has cascades (flat or
// displaced water: the displaced intersection marches the fields' heights).
inline bool cascade_fields_apply(const SceneModel& m) {
  return !m.scene.surface.cascades.empty();
}

}  // namespace sg
