#include "methods/specaa.h"

#include <vector>

#include "shading/gaussian_disk.h"
#include "shading/radiance.h"
#include "shading/rdf.h"

namespace sg {
namespace {

// Centre reflections further than acos(kMinLightCos) from the light have no light-plane
// image worth linearising (see specaa.h).
constexpr double kMinLightCos = 0.05;

}  // namespace

SpecaaSample specaa_sample(const WaterGeometry& water, double px, double py, double t,
                           const HostCascades* cascades) {
  const SceneModel& m = water.model();
  SpecaaSample s;
  s.footprint = water.footprint(px, py, t);
  if (!s.footprint.hit) return s;
  s.hit = true;
  const vec3& P = s.footprint.point;
  if (cascades != nullptr && cascades->active()) {
    s.g = cascades->waves(m).gradient(P.x, P.z, t) + cascades->gradient(P);
  } else {
    s.g = water.gradient(P.x, P.z, t);
  }
  s.frame = water_shading_frame(s.g);
  s.h_perp = projected_half_vector(s.frame, s.footprint.view, m.light.L);
  return s;
}

void specaa_analytic_derivatives(const WaterGeometry& water, const SpecaaSample& s, double t,
                                 vec2& ddx, vec2& ddy, const HostCascades* cascades) {
  const SceneModel& m = water.model();
  const vec3& P = s.footprint.point;
  Hessian H;
  if (cascades != nullptr && cascades->active()) {
    H = cascades->waves(m).hessian(P.x, P.z, t);
    const Hessian c = cascades->hessian(P);
    H = Hessian{H.xx + c.xx, H.xz + c.xz, H.zz + c.zz};
  } else {
    H = water.hessian(P.x, P.z, t);
  }
  ddx = projected_half_vector_derivative(m.camera.position(), P, s.g, H, s.footprint.dp_dpx,
                                         m.light.L);
  ddy = projected_half_vector_derivative(m.camera.position(), P, s.g, H, s.footprint.dp_dpy,
                                         m.light.L);
}

RadianceWeights specaa_weights(const SceneModel& m, const SpecaaSample& s, const vec2& ddx,
                               const vec2& ddy, const SpecaaOptions& o) {
  const LightModel& light = m.light;
  const vec3& v = s.footprint.view;
  // The kernel as a covariance of tangent slopes, then of NDF-plane points.
  const mat2 cov_ts = filtering_kernel_covariance(ddx, ddy, o.sigma2, o.kappa, o.kernel);
  const mat2 JG = tangent_slope_to_ndf_plane(s.frame);
  const mat2 cov_ndf = JG * cov_ts * glm::transpose(JG);
  const vec2 nc(-s.g.x, -s.g.y);  // the centre normal on the NDF plane
  const vec3 rc = reflect_about_ndf_point(nc, v);
  double in_light = 0, below = rc.y <= 0 ? 1.0 : 0.0;
  if (dot(rc, light.L) >= kMinLightCos) {
    const vec2 mean = ndf_to_light_plane(nc, v, light);
    const mat2 cov_r = rdf_covariance(ndf_to_light_plane_jacobian(nc, v, light), cov_ndf);
    in_light = gaussian_disk_mass(mean, cov_r, light.tan_radius);
    below = gaussian_half_plane_mass(mean, cov_r, vec2(light.e1.y, light.e2.y), light.L.y);
  }
  const double F = fresnel(m.scene.surface.fresnel, dot(s.frame.n, v));
  return combine_weights(m, F, in_light, below, rc.y);
}

RadianceWeights SpecaaMethod::shade_pixel(const FrameContext& ctx, int i, int j,
                                          const SpecaaSample& own, const SpecaaSample& nx,
                                          const SpecaaSample& ny) const {
  const SceneModel& m = ctx.model;
  if (!own.hit) {
    return miss_pixel_weights(m, i, j);
  }
  if (own.footprint.at_camera) return fallback(ctx, i, j);
  vec2 ddx, ddy;
  if (options_.derivatives == SpecaaDerivatives::quad && nx.hit && ny.hit &&
      !nx.footprint.at_camera && !ny.footprint.at_camera) {
    // Within the quad the difference runs from the even to the odd pixel.
    ddx = (i & 1) ? own.h_perp - nx.h_perp : nx.h_perp - own.h_perp;
    ddy = (j & 1) ? own.h_perp - ny.h_perp : ny.h_perp - own.h_perp;
  } else {
    specaa_analytic_derivatives(water(ctx), own, ctx.time.end, ddx, ddy, &cascades_);
  }
  return finite_or_fallback(specaa_weights(m, own, ddx, ddy, options_), ctx, i, j);
}

RadianceWeights SpecaaMethod::weights(const FrameContext& ctx, int i, int j) const {
  const double t = ctx.time.end;
  const SpecaaSample own = specaa_sample(water(ctx), i + 0.5, j + 0.5, t, &cascades_);
  if (options_.derivatives == SpecaaDerivatives::analytic) {
    return shade_pixel(ctx, i, j, own, SpecaaSample{}, SpecaaSample{});
  }
  const SpecaaSample nx = specaa_sample(water(ctx), (i ^ 1) + 0.5, j + 0.5, t, &cascades_);
  const SpecaaSample ny = specaa_sample(water(ctx), i + 0.5, (j ^ 1) + 0.5, t, &cascades_);
  return shade_pixel(ctx, i, j, own, nx, ny);
}

void SpecaaMethod::shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1,
                              Image& out) const {
  if (options_.derivatives == SpecaaDerivatives::analytic) {
    Method::shade_tile(ctx, x0, y0, x1, y1, out);
    return;
  }
  // The quads that hold the tile: [x0 & ~1, (x1 - 1) | 1] x [y0 & ~1, (y1 - 1) | 1].
  const int qx0 = x0 & ~1, qy0 = y0 & ~1, qx1 = ((x1 - 1) | 1) + 1, qy1 = ((y1 - 1) | 1) + 1;
  const int w = qx1 - qx0;
  thread_local std::vector<SpecaaSample> grid;
  grid.resize(static_cast<size_t>(w) * (qy1 - qy0));
  for (int j = qy0; j < qy1; ++j) {
    for (int i = qx0; i < qx1; ++i)
      grid[(j - qy0) * w + (i - qx0)] =
          specaa_sample(water(ctx), i + 0.5, j + 0.5, ctx.time.end, &cascades_);
  }
  auto at = [&](int i, int j) -> const SpecaaSample& { return grid[(j - qy0) * w + (i - qx0)]; };
  for (int j = y0; j < y1; ++j) {
    for (int i = x0; i < x1; ++i) {
      store_pixel(ctx, out, i, j, shade_pixel(ctx, i, j, at(i, j), at(i ^ 1, j), at(i, j ^ 1)));
    }
  }
}

}  // namespace sg
