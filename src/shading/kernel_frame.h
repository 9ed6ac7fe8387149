// The kernel's inputs for one frame, built on the host from a scene model (the
// begin_frame step of every kernel method and engine): the Frame struct of
// kernel/interface.glsl and the wave buffer, in double (sg::kd) or float (sg::kf).
//
// What is computed here, in double, once per frame, so that the kernel (float on a GPU)
// only sees well-scaled numbers:
//  - camera-relative coordinates: the camera at (0, y, 0);
//  - each wave's phase at the camera's (x, z) and the display time t_f,
//    theta0 = a x_c + b z_c + c t_f + phi, reduced to [-pi, pi] (c t_f alone reaches 1e4
//    rad after an hour);
//  - the rotations to the path's instants, (cos, sin) of c (t_f - t_k), k = 0..K-1;
//  - the waves sorted by |k| (ascending, ties in file order): the order every engine sums
//    them in, so that what a pixel leaves out is a suffix;
//  - the sums from each position of that order on (kernel/waves.glsl: the suffix's slope
//    covariance and amplitude, the prefix's slab and slope bounds), after the waves in the
//    wave buffer: the remainders that staa adds in O(1) and the bounds of the displaced
//    intersection's fewer waves.
// The tables (path tables, kernel fits) are views of host data (shading/path_table.h,
// shading/kernel_table.h).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "kernel/kernel_types.h"
#include "scene/footprint.h"
#include "scene/model.h"
#include "shading/cascade_fields.h"

namespace sg::kd {
struct Footprint;  // kernel/footprint.glsl (kernel/kernel_double.h)
}  // namespace sg::kd

namespace sg {

template <class Frame, class Vec4>
struct KernelInputs {
  using Real = decltype(Frame{}.duration);
  Frame frame{};
  std::vector<Vec4> texels;  // the wave buffer (kernel/waves.glsl: layout)
  std::vector<int> order;    // file index of the wave at each position of the buffer
  // The world point at the origin of the camera-relative coordinates: the camera's (x, z)
  // at the display time (a moving camera's from its keys), y = 0.
  glm::dvec3 origin{0.0};
  // The same waves as arrays (the CPU engine's vectorised sums): amplitude, wave vector,
  // phase at the display time, angular frequency, wavenumber, slope amplitude; rotations
  // [k][wave].
  std::vector<Real> A, a, b, theta0, c, k, slope, rot_c, rot_s;
  // The cascades' fields' builder, kept from frame to frame (its FFTs' lattices), when
  // the frames shade cascades from fields.
  std::shared_ptr<CascadeFields> cascades;
  wave_simd::Arrays<Real> arrays() const {
    wave_simd::Arrays<Real> w;
    w.A = A.data();
    w.a = a.data();
    w.b = b.data();
    w.theta0 = theta0.data();
    w.c = c.data();
    w.k = k.data();
    w.slope = slope.data();
    w.rot_c = rot_c.data();
    w.rot_s = rot_s.data();
    w.count = static_cast<int>(A.size());
    return w;
  }
};
using KernelInputsD = KernelInputs<kd::Frame, kd::vec4>;
using KernelInputsF = KernelInputs<kf::Frame, kf::vec4>;

// Texels per wave for K path segments (kernel/waves.glsl, wave_stride_for: the layout).
int wave_stride(int segments);

// The wave buffer's sums (kernel/waves.glsl) for its first n = A.size() waves, of amplitudes
// A[q] and wave vectors (a[q], b[q]) in buffer order, each `stride` texels: `texels` is
// cut to those waves' texels and the sums from each position on are written after them.
void write_wave_sums(std::span<const double> A, std::span<const double> a,
                     std::span<const double> b, int stride, std::vector<kd::vec4>& texels);

// The kernel's footprint for a host footprint (camera-relative point).
kd::Footprint kernel_footprint(const SceneModel& m, const PixelFootprint& fp);

// A float frame's settings in double (the camera, the light and the flags; no waves).
kd::Frame widen(const kf::Frame& f);

// The displaced intersection's default tolerance (kernel/intersect.glsl): the waves it
// leaves out move the water point a pixel sees by at most this fraction of the pixel's
// footprint, to first order (docs/ocean.md gives it as measured against the full intersection).
inline constexpr double kDefaultIntersectTolerance = 0.25;

// Builds the inputs of frame `ft` with K = `segments` path segments (1 to kMaxSegments),
// the sampling `seed`, the displaced intersection's tolerance (pixels; 0: every wave) and
// the reference's windows of the shutter (kernel/interface.glsl, Frame::windows; the
// rotations are the last window's). `cascade_fields`: a scene's cascades go to the wave
// buffer as FFT fields where cascade_fields_apply (shading/cascade_fields.h), else as
// their lattice's sines among the waves. `data`: the fields transformed here
// (CascadeData::host), or only their layout laid out, the engine filling their data and
// calling set_cascade_bounds (CascadeData::layout: the GL engine's transforms on the GPU,
// gl_engine/cascade_fields_gl.h). `reads`: what the method's kernel reads of them
// (shading/cascade_fields.h), the rest not built.
enum class CascadeData { host, layout };
void build_kernel_inputs(const SceneModel& m, const FrameTime& ft, int segments, uint64_t seed,
                         KernelInputsD& out,
                         double intersect_tolerance = kDefaultIntersectTolerance, int windows = 1,
                         bool cascade_fields = false, CascadeData data = CascadeData::host,
                         CascadeReads reads = CascadeReads::all);
void build_kernel_inputs(const SceneModel& m, const FrameTime& ft, int segments, uint64_t seed,
                         KernelInputsF& out,
                         double intersect_tolerance = kDefaultIntersectTolerance, int windows = 1,
                         bool cascade_fields = false, CascadeData data = CascadeData::host,
                         CascadeReads reads = CascadeReads::all);
// After a build with CascadeData::layout: the cascades' bounds texels and the frame's
// amplitude and slope bounds from each cascade's interpolant bounds (the display time's,
// cascade_bounds_from_maxima), as the host's build sets them.
void set_cascade_bounds(const SceneModel& m, const std::vector<glm::dvec3>& each,
                        KernelInputsF& out);

// The wave buffer of `in` for the kernel; `vectorised`: with the arrays, so that the CPU
// engine's vectorised sums run (else the kernel's own loops, the definitions).
inline kd::WaveBuffer wave_buffer(const KernelInputsD& in, bool vectorised = true) {
  return kd::WaveBuffer{in.texels.data(), static_cast<int>(in.texels.size()),
                        vectorised ? in.arrays() : wave_simd::Arrays<double>{}};
}
inline kf::WaveBuffer wave_buffer(const KernelInputsF& in, bool vectorised = true) {
  return kf::WaveBuffer{in.texels.data(), static_cast<int>(in.texels.size()),
                        vectorised ? in.arrays() : wave_simd::Arrays<float>{}};
}

// A host point (world coordinates) in the kernel's camera-relative coordinates, and back.
inline vec3 to_camera_relative(const SceneModel& m, const vec3& p) {
  return vec3(p.x - m.camera.position().x, p.y, p.z - m.camera.position().z);
}
inline vec3 from_camera_relative(const SceneModel& m, const vec3& p) {
  return vec3(p.x + m.camera.position().x, p.y, p.z + m.camera.position().z);
}

}  // namespace sg
