#include "methods/bruneton.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/error.h"
#include "shading/gaussian_disk.h"
#include "shading/ndf.h"
#include "shading/ocean_brdf.h"
#include "shading/radiance.h"
#include "shading/water_geometry.h"
#include "shading/wave_lod.h"

namespace sg {

void BrunetonMethod::begin_frame(const FrameContext& ctx) {
  begin_host_frame(ctx);
  cascades_.build(ctx);
  if (sorted_model_.load(std::memory_order_acquire) != ctx.model.id ||
      sorted_fields_ != cascades_.active()) {
    // The model's waves, or its explicit ones (the same for every frame of the model).
    sorted_ = std::make_unique<SortedWaves>(cascades_.waves(ctx.model));
    sorted_fields_ = cascades_.active();
    sorted_model_.store(ctx.model.id, std::memory_order_release);
  }
}

const SortedWaves& BrunetonMethod::sorted_waves(const SceneModel& m) const {
  if (sorted_model_.load(std::memory_order_acquire) != m.id) {
    throw Error("bruneton: frame " + std::to_string(m.id) +
                " shaded without begin_frame (methods/method.h)");
  }
  return *sorted_;
}

RadianceWeights BrunetonMethod::weights(const FrameContext& ctx, int i, int j) const {
  const SceneModel& m = ctx.model;
  const double t = ctx.time.end;
  const vec3 o = m.camera.position();
  const vec3 d = normalize(m.camera.direction(i + 0.5, j + 0.5));
  const PixelFootprint rest = rest_plane_footprint(m, i + 0.5, j + 0.5);
  if (!rest.hit) return miss_pixel_weights(m, i, j);

  // 1. Filter weights, w_p = w_n (the grid cell is the pixel), of the waves that can have
  // any (the waves sorted by |k|: a prefix; those past it have w = 0, wave_lod.h).
  const SortedWaves& sorted = sorted_waves(m);
  const mat2 J = rest.xz_jacobian();
  const size_t kept = sorted.filtered_from(J, options_.n_min);
  const WaveField& waves = sorted.prefix(kept);
  thread_local std::vector<double> w, wr;
  wave_lod_weights(waves, J, options_.n_min, options_.n_max, w);

  // 2. Position: the rest plane, or the filtered height field.
  vec3 P = rest.point;
  if (m.displaced()) {
    const RayHit hit = water(ctx).intersect_filtered(w, o, d, t);
    if (!hit.hit) return miss_pixel_weights(m, i, j);
    if (!(hit.s > 0)) return fallback(ctx, i, j);  // the camera is under the surface
    P = hit.point;
  }
  const vec3 v = normalize(o - P);

  // The cascades' mean slope and covariance over the footprint (flat water only).
  const HostCascades::Moments cm = cascades_.moments(P, J);

  // 3. Normal (Eq. 3), mirrored when back-facing.
  vec3 n = normal_from_gradient(waves.gradient_weighted(P.x, P.z, t, w) + cm.mean);
  if (dot(n, v) < 0) n = normalize(n - 2 * dot(n, v) * v);

  // 4. Slope variances of the filtered-out waves (Eq. 4 for sines): the prefix's share
  // 1 - w and the whole of every wave past it (a suffix sum); principal axes, clamp.
  wr.resize(w.size());
  for (size_t k = 0; k < w.size(); ++k)
    wr[k] = 1 - w[k];
  const PrincipalAxes axes = principal_axes(uniform_ndf_covariance(waves, wr) +
                                            sorted.suffix_covariance(waves.size()) + cm.cov);
  const vec2 sigma2(std::max(axes.s1 * axes.s1, options_.min_variance),
                    std::max(axes.s2 * axes.s2, options_.min_variance));
  vec3 major(axes.u.x, 0, axes.u.y);
  vec3 tx = major - dot(major, n) * n;
  if (dot(tx, tx) < 1e-12) tx = vec3(0, 0, 1) - n.z * n;  // n horizontal along the axis
  tx = normalize(tx);
  const vec3 ty = cross(n, tx);
  auto tangent = [&](const vec3& a) { return vec3(dot(a, tx), dot(a, ty), dot(a, n)); };
  const vec3 v_ts = tangent(v), l_ts = tangent(m.light.L);

  // 5. Sun (Eq. 15).
  const double solid_angle = kTwoPi * (1 - m.light.cos_radius);
  const double x = sun_reflectance(v_ts, l_ts, sigma2, solid_angle);
  const FresnelMode mode = m.scene.surface.fresnel;
  const double F_sun = fresnel(mode, dot(v, normalize(v + m.light.L)));

  // 6. Sky and sea (Eqs. 22-28).
  double F_bar = 1;
  if (mode == FresnelMode::schlick) {
    F_bar = options_.fresnel == BrunetonFresnel::fit
                ? effective_fresnel_fit(v_ts.z, std::sqrt(slope_variance_toward(v_ts, sigma2)))
                : effective_fresnel_integral(v_ts, sigma2);
  }
  const double below = below_horizon_fraction(v, n, tx, ty, sigma2);
  // The sun's term replaces the sky in its solid angle: + F x (light - sky(L)).
  const double sky_y = reflect_view(n, v).y;
  return finite_or_fallback(combine_weights(m, F_bar, 0, below, sky_y) +
                                F_sun * x * (light_weights() - sky_weights(m, m.light.L.y)),
                            ctx, i, j);
}

}  // namespace sg
