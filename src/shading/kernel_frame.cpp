#include "shading/kernel_frame.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <type_traits>

#include "base/error.h"
#include "kernel/cpu/wave_sums.h"
#include "kernel/kernel_double.h"
#include "scene/camera_path.h"

namespace sg {

int wave_stride(int segments) {
  return kd::wave_stride_for(segments);
}
namespace {

// The wave buffer's sums after its n waves (kernel/waves.glsl): from each position q on,
// the suffix's slope moments and squared amplitude, its amplitude, and the prefix's
// amplitude, slope and curvature bounds, in double.
template <class V4>
void write_sums(std::span<const double> A, std::span<const double> a, std::span<const double> b,
                int stride, std::vector<V4>& texels) {
  const int n = static_cast<int>(A.size());
  const size_t base = static_cast<size_t>(kd::wave_sums_index(n, stride, 0));
  texels.resize(base);
  texels.resize(static_cast<size_t>(kd::wave_sums_index(n, stride, n + 1)), V4(0));
  std::vector<double> pre_A(n + 1, 0.0), pre_Ak(n + 1, 0.0), pre_Ak2(n + 1, 0.0);
  for (int q = 0; q < n; ++q) {
    const double k = std::hypot(a[q], b[q]);
    pre_A[q + 1] = pre_A[q] + A[q];
    pre_Ak[q + 1] = pre_Ak[q] + A[q] * k;
    pre_Ak2[q + 1] = pre_Ak2[q] + A[q] * k * k;
  }
  double sxx = 0, sxz = 0, szz = 0, sA2 = 0, sA = 0;
  for (int q = n; q >= 0; --q) {
    if (q < n) {
      const double e = 0.5 * A[q] * A[q];
      sxx += e * a[q] * a[q];
      sxz += e * a[q] * b[q];
      szz += e * b[q] * b[q];
      sA2 += A[q] * A[q];
      sA += A[q];
    }
    const size_t e = static_cast<size_t>(kd::wave_sums_index(n, stride, q));
    texels[e] = V4(kd::wave_pack_suffix(kd::vec3(sxx, sxz, szz), sA2));
    texels[e + 1] = V4(kd::wave_pack_bounds(sA, kd::vec3(pre_A[q], pre_Ak[q], pre_Ak2[q])));
  }
}

// x reduced to [-pi, pi] in double.
double reduce_angle(double x) {
  return std::remainder(x, kTwoPi);
}

// The models' kernel structs (LightModel::kernel_light, CameraModel::kernel_camera: the one
// place each field is filled) in the frame's precision: as they are in double, each field
// rounded in float.
template <class Light>
void fill_light(const LightModel& l, Light& out) {
  const kd::Light d = l.kernel_light();
  if constexpr (std::is_same_v<Light, kd::Light>) {
    out = d;
  } else {
    using R = decltype(out.radius);
    out.L = kf::vec3(d.L);
    out.e1 = kf::vec3(d.e1);
    out.e2 = kf::vec3(d.e2);
    out.radius = R(d.radius);
    out.cos_radius = R(d.cos_radius);
    out.sin_radius = R(d.sin_radius);
    out.tan_radius = R(d.tan_radius);
    out.chord2 = R(d.chord2);
    out.visible = d.visible;
  }
}

template <class Camera>
void fill_camera(const CameraModel& c, Camera& out) {
  const kd::Camera d = c.kernel_camera();
  if constexpr (std::is_same_v<Camera, kd::Camera>) {
    out = d;
  } else {
    using R = decltype(out.width);
    out.position = kf::vec3(d.position);
    out.forward = kf::vec3(d.forward);
    out.right = kf::vec3(d.right);
    out.up = kf::vec3(d.up);
    out.half_w = R(d.half_w);
    out.half_h = R(d.half_h);
    out.width = R(d.width);
    out.height = R(d.height);
  }
}

// A moving camera's keys over the shutter [ft.start, ft.end] (kernel/interface.glsl,
// CameraKeys): its poses at the shutter's ends and the scene's keys in between, relative to
// the display time and to the camera's (x, z) at the end (`origin`). count 0 when the pose
// is the same at every key: the camera stands still over this shutter.
template <class Keys>
void fill_camera_keys(const CameraDesc& c, const FrameTime& ft, const vec3& origin, Keys& out) {
  using R = decltype(out.up.x);
  using V3 = decltype(out.up);
  auto v3 = [](const vec3& v) { return V3(R(v.x), R(v.y), R(v.z)); };
  out = Keys{};
  out.up = v3(normalize(c.up));
  if (!c.moving() || !(ft.duration() > 0)) return;
  std::vector<CameraKey> keys;
  auto add = [&](double t) {
    const CameraPoseAt p = camera_pose(c, t);
    keys.push_back(CameraKey{t, p.position, p.look_at});
  };
  add(ft.start);
  for (const CameraKey& k : c.keyframes) {
    if (k.time > ft.start && k.time < ft.end) keys.push_back(k);
  }
  add(ft.end);
  bool still = true;
  for (const CameraKey& k : keys)
    still = still && k.position == keys[0].position && k.look_at == keys[0].look_at;
  if (still) return;
  if (keys.size() > static_cast<size_t>(kd::kMaxCameraKeys)) {
    throw Error("camera.keyframes: frame " + std::to_string(ft.frame) + "'s shutter holds " +
                std::to_string(keys.size() - 2) + " keyframes, more than the " +
                std::to_string(kd::kMaxCameraKeys - 2) + " a frame can take");
  }
  const vec3 shift(origin.x, 0, origin.z);
  out.count = static_cast<int>(keys.size());
  for (size_t q = 0; q < keys.size(); ++q) {
    out.time[q] = R(keys[q].time - ft.end);
    out.position[q] = v3(keys[q].position - shift);
    out.look_at[q] = v3(keys[q].look_at - shift);
  }
}

// The frame's bounds with the cascades' fields: the explicit waves' and the fields'
// interpolants' (the surface the kernel sees). On flat water neither engine bounds the
// interpolants (the displaced march, kernel/intersect.glsl, is their only reader), and the
// frame keeps the sines' sums that build() set.
template <class In>
void frame_cascade_bounds(const SceneModel& m, In& out) {
  if (!m.displaced()) return;
  using R = decltype(out.frame.duration);
  const WaveField& w = out.cascades->explicit_waves(m);
  const glm::dvec3 cb = out.cascades->interpolant_bounds();
  out.frame.amplitude_bound = R(w.amplitude_bound() + cb.x);
  out.frame.slope_bound = R(w.slope_bound() + cb.y);
}

template <class In>
void build(const SceneModel& m, const FrameTime& ft, int segments, uint64_t seed,
           double intersect_tolerance, int windows, bool cascade_fields, CascadeData data,
           CascadeReads reads, In& out) {
  using Frame = decltype(out.frame);
  using R = decltype(out.frame.duration);
  using V4 = typename decltype(out.texels)::value_type;
  if (segments < 1 || segments > kd::kMaxSegments) {
    throw Error("--segments: must be in [1, " + std::to_string(kd::kMaxSegments) + "] (got " +
                std::to_string(segments) + ")");
  }
  if (windows < 1) throw Error("the reference's windows: must be at least 1");
  Frame& f = out.frame;
  // The camera at the display time; a moving one's from its keys (the frame's model holds
  // it already, frame_model in scene/camera_path.h; a model of the whole scene does not).
  const CameraModel c = m.scene.camera.moving()
                            ? CameraModel(camera_at(m.scene.camera, ft.end), m.width(), m.height())
                            : m.camera;
  fill_camera_keys(m.scene.camera, ft, c.position(), f.camera_keys);
  out.origin = glm::dvec3(c.position().x, 0.0, c.position().z);
  fill_camera(c, f.camera);
  fill_light(m.light, f.light);
  f.fresnel = m.scene.surface.fresnel == FresnelMode::none ? 0 : 1;
  f.displaced = m.displaced();
  f.sky_gradient = m.scene.sky.gradient;
  f.sky_exponent = R(m.scene.sky.exponent);
  const bool fields = cascade_fields && cascade_fields_apply(m);
  if (fields && !out.cascades) out.cascades = std::make_shared<CascadeFields>();
  const WaveField& w = fields ? out.cascades->explicit_waves(m) : m.waves;
  const int n = static_cast<int>(w.size());
  f.wave_count = n;
  f.wave_stride = wave_stride(segments);
  f.amplitude_bound = R(w.amplitude_bound() + (fields ? out.cascades->amplitude_sum(m) : 0.0));
  f.slope_bound = R(w.slope_bound() + (fields ? out.cascades->slope_sum(m) : 0.0));
  f.cascade_count = 0;
  f.cascade_base = 0;
  f.intersect_tolerance = R(intersect_tolerance);
  f.duration = R(ft.duration());
  f.segments = segments;
  f.windows = windows;
  f.frame = ft.frame;
  f.seed = {static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32)};

  out.order.resize(n);
  std::iota(out.order.begin(), out.order.end(), 0);
  std::stable_sort(out.order.begin(), out.order.end(), [&](int p, int q) {
    return std::hypot(w.a[p], w.b[p]) < std::hypot(w.a[q], w.b[q]);
  });
  const int stride = f.wave_stride;
  out.texels.assign(static_cast<size_t>(kd::wave_texel_index(stride, n)), V4(0));
  // The arrays are padded with waves of amplitude 0 to a multiple of the widest vector.
  const int lanes = wave_simd::kLanePadding;
  const int np = (n + lanes - 1) / lanes * lanes;
  for (auto* v : {&out.A, &out.a, &out.b, &out.theta0, &out.c, &out.k, &out.slope})
    v->assign(np, R(0));
  out.rot_c.assign(static_cast<size_t>(np) * segments, R(0));
  out.rot_s.assign(static_cast<size_t>(np) * segments, R(0));
  const double xc = c.position().x, zc = c.position().z, t = ft.end;
  for (int q = 0; q < n; ++q) {
    const int i = out.order[q];
    const double k = std::hypot(w.a[i], w.b[i]);
    const double theta0 =
        reduce_angle(w.a[i] * xc + w.b[i] * zc + reduce_angle(w.c[i] * t) + reduce_angle(w.phi[i]));
    // The wave in the precision of the frame, packed by the kernel's layout (waves.glsl).
    kd::Wave wave;
    wave.A = R(w.A[i]);
    wave.a = R(w.a[i]);
    wave.b = R(w.b[i]);
    wave.theta0 = R(theta0);
    wave.c = R(w.c[i]);
    wave.k = R(k);
    wave.slope = R(w.A[i] * k);
    out.texels[kd::wave_texel_index(stride, q)] = V4(kd::wave_pack_phase(wave));
    out.texels[kd::wave_texel_index(stride, q) + 1] = V4(kd::wave_pack_motion(wave));
    out.A[q] = R(wave.A);
    out.a[q] = R(wave.a);
    out.b[q] = R(wave.b);
    out.theta0[q] = R(wave.theta0);
    out.c[q] = R(wave.c);
    out.k[q] = R(wave.k);
    out.slope[q] = R(wave.slope);
    for (int s = 0; s < segments; ++s) {
      const double delta =
          reduce_angle(w.c[i] * (ft.duration() / windows * (segments - s) / segments));
      const R rc = R(std::cos(delta)), rs = R(std::sin(delta));
      V4& r = out.texels[kd::wave_rotation_index(stride, q, s)];
      r = V4(kd::wave_pack_rotation(kd::vec4(r), s, kd::vec2(rc, rs)));
      out.rot_c[static_cast<size_t>(s) * np + q] = rc;
      out.rot_s[static_cast<size_t>(s) * np + q] = rs;
    }
  }
  // The sums from each position on (kernel/waves.glsl), in double, in buffer order.
  std::vector<double> sA(n), sa(n), sb(n);
  for (int q = 0; q < n; ++q) {
    const int i = out.order[q];
    sA[q] = w.A[i];
    sa[q] = w.a[i];
    sb[q] = w.b[i];
  }
  write_sums(sA, sa, sb, stride, out.texels);
  // The cascades' fields after the sums (kernel/cascade_fields.glsl).
  if (fields) {
    f.cascade_count = static_cast<int>(m.scene.surface.cascades.size());
    if (data == CascadeData::layout) {
      // The engine transforms them and sets the bounds (set_cascade_bounds).
      f.cascade_base = out.cascades->append_layout(m, ft, segments, xc, zc, out.texels);
    } else {
      f.cascade_base = out.cascades->append(m, ft, segments, xc, zc, out.texels, reads);
      frame_cascade_bounds(m, out);
    }
  }
}

}  // namespace

void write_wave_sums(std::span<const double> A, std::span<const double> a,
                     std::span<const double> b, int stride, std::vector<kd::vec4>& texels) {
  write_sums(A, a, b, stride, texels);
}

kd::Footprint kernel_footprint(const SceneModel& m, const PixelFootprint& fp) {
  kd::Footprint k;
  k.hit = fp.hit;
  k.point = to_camera_relative(m, fp.point);
  k.view = fp.view;
  k.dp_dpx = fp.dp_dpx;
  k.dp_dpy = fp.dp_dpy;
  k.distance = fp.distance;
  return k;
}

kd::Frame widen(const kf::Frame& f) {
  kd::Frame d;
  auto v3 = [](const kf::vec3& v) { return kd::vec3(v); };
  d.camera_keys.count = f.camera_keys.count;
  d.camera_keys.up = v3(f.camera_keys.up);
  for (int k = 0; k < kd::kMaxCameraKeys; ++k) {
    d.camera_keys.time[k] = f.camera_keys.time[k];
    d.camera_keys.position[k] = v3(f.camera_keys.position[k]);
    d.camera_keys.look_at[k] = v3(f.camera_keys.look_at[k]);
  }
  d.camera.position = v3(f.camera.position);
  d.camera.forward = v3(f.camera.forward);
  d.camera.right = v3(f.camera.right);
  d.camera.up = v3(f.camera.up);
  d.camera.half_w = f.camera.half_w;
  d.camera.half_h = f.camera.half_h;
  d.camera.width = f.camera.width;
  d.camera.height = f.camera.height;
  d.light.L = v3(f.light.L);
  d.light.e1 = v3(f.light.e1);
  d.light.e2 = v3(f.light.e2);
  d.light.radius = f.light.radius;
  d.light.cos_radius = f.light.cos_radius;
  d.light.sin_radius = f.light.sin_radius;
  d.light.tan_radius = f.light.tan_radius;
  d.light.chord2 = f.light.chord2;
  d.light.visible = f.light.visible;
  d.fresnel = f.fresnel;
  d.displaced = f.displaced;
  d.sky_gradient = f.sky_gradient;
  d.sky_exponent = f.sky_exponent;
  d.wave_count = f.wave_count;
  d.wave_stride = f.wave_stride;
  d.amplitude_bound = f.amplitude_bound;
  d.slope_bound = f.slope_bound;
  d.intersect_tolerance = f.intersect_tolerance;
  d.duration = f.duration;
  d.segments = f.segments;
  d.windows = f.windows;
  d.cascade_count = f.cascade_count;
  d.cascade_base = f.cascade_base;
  d.frame = f.frame;
  d.seed = f.seed;
  return d;
}

void build_kernel_inputs(const SceneModel& m, const FrameTime& ft, int segments, uint64_t seed,
                         KernelInputsD& out, double intersect_tolerance, int windows,
                         bool cascade_fields, CascadeData data, CascadeReads reads) {
  build(m, ft, segments, seed, intersect_tolerance, windows, cascade_fields, data, reads, out);
}
void build_kernel_inputs(const SceneModel& m, const FrameTime& ft, int segments, uint64_t seed,
                         KernelInputsF& out, double intersect_tolerance, int windows,
                         bool cascade_fields, CascadeData data, CascadeReads reads) {
  build(m, ft, segments, seed, intersect_tolerance, windows, cascade_fields, data, reads, out);
}

void set_cascade_bounds(const SceneModel& m, const std::vector<glm::dvec3>& each,
                        KernelInputsF& out) {
  if (!out.cascades) throw Error("set_cascade_bounds: the frame has no cascade fields");
  out.cascades->set_bounds(each, out.texels);
  frame_cascade_bounds(m, out);
}

}  // namespace sg
