#include "methods/staa.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/footprint.h"
#include "shading/aliasing.h"
#include "shading/gaussian_disk.h"
#include "shading/kernel_fit.h"
#include "shading/ndf.h"
#include "shading/path_table.h"
#include "shading/radiance.h"
#include "shading/rdf.h"
#include "shading/reflection_footprint.h"
#include "shading/reflection_path.h"
#include "shading/swept_footprint.h"

namespace sg {
namespace {

// Reflections further than this from the light (r . L below it) are not projected on the
// light plane: the gnomonic projection diverges at 90 degrees, and an RDF would need a
// spread of more than tan(84 deg) ~ 10 plane units to reach the disk from there.
constexpr double kMinCosToLight = 0.1;

// The standard normal CDF.
double normal_cdf(double x) {
  return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

// The share of N(p, cov) (light-plane coordinates) whose direction lies below the
// horizon. The horizon r.y = 0 is a great circle, so on the light plane it is the line
// L.y + p.x e1.y + p.y e2.y = 0; the share beyond it is a 1D normal tail.
double below_horizon_share(const LightModel& light, const vec2& p, const mat2& cov) {
  const vec2 g(light.e1.y, light.e2.y);
  const double gg = length(g);
  if (gg < 1e-12) return light.L.y > 0 ? 0.0 : 1.0;  // horizon parallel to the plane
  const vec2 n = g / gg;
  const double dist = (light.L.y + dot(p, g)) / gg;  // signed distance, positive above
  const double s = std::sqrt(std::max(0.0, dot(n, cov * n)));
  // Beyond 9 standard deviations the tail is below 1.2e-19: 0 or 1 without the erfc.
  if (dist >= 9 * s) return 0.0;
  if (dist <= -9 * s) return 1.0;
  return normal_cdf(-dist / s);
}

}  // namespace

StaaMethod::StaaMethod(const StaaOptions& o) : o_(o), tables_(&PathTables::shared()) {}

StaaMethod::Shares StaaMethod::shares(const FrameContext& ctx, int i, int j,
                                      ReflectionPath** path_out) const {
  const SceneModel& m = ctx.model;
  const FrameTime& ft = ctx.time;
  Shares out;
  const PixelFootprint fp = pixel_footprint(m, i + 0.5, j + 0.5, ft.end);
  if (!fp.hit) return out;
  out.hit = true;

  thread_local std::vector<double> alpha, resolved;
  const mat2 J = fp.xz_jacobian();
  const AliasRange range = alias_range(o_);
  AliasingParams ap{range.start, range.end,
                    o_.nyquist_max_axis ? FrequencyNorm::max : FrequencyNorm::norm};
  alias_fractions(m.waves, J, ap, alpha);
  const bool footprint = o_.footprint != FootprintMode::none;
  if (footprint && o_.curvature_limit > 0) {
    // Where the linearisation breaks: a resolved wave of phase half-width D across the
    // pixel has a slope A |k| cos(theta) that departs from its tangent by up to
    // A |k| D^2 / 2; the reflection moves twice as far. Past `curvature_limit` disk radii
    // the wave goes to the aliasing set, ramping over a factor of two.
    const double limit = o_.curvature_limit * m.light.radius;
    for (size_t k = 0; k < alpha.size(); ++k) {
      const vec2 kv(m.waves.a[k], m.waves.b[k]);
      const double D = footprint_phase_half_width(kv, J);
      const double dev = m.waves.A[k] * length(kv) * D * D;  // 2 * A |k| D^2 / 2
      alpha[k] = std::max(alpha[k], std::clamp(dev / limit - 1.0, 0.0, 1.0));
    }
  }
  bool any = false;
  resolved.resize(alpha.size());
  for (size_t k = 0; k < alpha.size(); ++k) {
    resolved[k] = 1.0 - alpha[k];
    any |= alpha[k] > 0 && m.waves.A[k] > 0;
  }

  thread_local ReflectionPath path;
  reflection_path(m, fp, ft, o_.segments, resolved, path);
  if (path_out) *path_out = &path;
  const FresnelMode fm = m.scene.surface.fresnel;
  if (!any && !footprint) {
    // Step 3: the temporal method, exactly (shade() returns temporal_value for these).
    const PathShares p = temporal_shares(m, path);
    out.temporal = true;
    out.temporal_weights = p.weights;
    out.in_light = p.in_light;
    out.below = p.below;
    out.fresnel = p.fresnel;
    return out;
  }
  out.aliasing = any;

  // Step 4: the NDF of the aliasing waves (none: a point at the resolved normal).
  PlaneGaussian ndf;
  if (any && o_.ndf == NdfMode::uniform) {
    ndf.cov = uniform_ndf_covariance(m.waves, alpha);
  } else if (any) {
    ndf = per_pixel_ndf(m.waves, alpha, path.phases, J);
    if (!o_.ndf_mean_shift) ndf.mean = vec2(0);
  }
  // The NDF's centre at each instant: minus the resolved slope, plus the mean shift.
  const int K = path.segments();
  thread_local std::vector<vec2> centre;
  thread_local std::vector<char> valid;
  centre.resize(K + 1);
  valid.resize(K + 1);
  for (int k = 0; k <= K; ++k) {
    const vec2 nc = -path.gradients[k] + ndf.mean;
    const vec3 r = reflect_about_ndf_point(nc, path.view);
    valid[k] = dot(r, m.light.L) > kMinCosToLight * length(r);
    centre[k] = valid[k] ? m.light.to_plane(r) : vec2(0);
  }
  const vec2 nc_now = -path.gradients[K] + ndf.mean;
  const vec3 n_now = normalize(vec3(nc_now.x, 1, nc_now.y));
  out.fresnel = fresnel(fm, dot(n_now, path.view));
  out.sky_y = reflect_view(n_now, path.view).y;
  if (!valid[K]) {
    // The reflection points away from the light: nothing of the RDF reaches it.
    out.below = dot(reflect_about_ndf_point(nc_now, path.view), vec3(0, 1, 0)) <= 0 ? 1.0 : 0.0;
    return out;
  }
  const mat2 Jc = ndf_to_light_plane_jacobian(nc_now, path.view, m.light);
  mat2 cov_r = rdf_covariance(Jc, ndf.cov);
  const double R = m.light.tan_radius;

  // The pixel-footprint term: the pixel square mapped to the light plane by the resolved
  // reflection's derivatives D (shading/reflection_footprint.h).
  if (footprint) {
    const ReflectionFootprint rf = reflection_footprint(m, fp, resolved, path.phases, ndf.mean);
    if (rf.valid) {
      if (o_.footprint == FootprintMode::exact && !any) {
        out.in_light = swept_parallelogram_share(centre, valid, rf.D, R);
        // The horizon: the parallelogram moment-matched, as for the Gaussian term.
        const mat2 cov_fp = rf.D * glm::transpose(rf.D) / 12.0;
        double below = 0;
        int counted = 0;
        for (int k = 0; k <= K; ++k) {
          if (!valid[k]) continue;
          below += below_horizon_share(m.light, centre[k], cov_fp);
          ++counted;
        }
        out.below = below / counted;
        out.in_light = std::clamp(out.in_light, 0.0, 1.0 - out.below);
        return out;
      }
      // A unit box has variance 1/12 per axis: covariance D D^T / 12, added to the RDF's.
      cov_r += rf.D * glm::transpose(rf.D) / 12.0;
    }
  }

  // The share below the horizon, averaged over the path's instants.
  double below = 0;
  int counted = 0;
  for (int k = 0; k <= K; ++k) {
    if (!valid[k]) continue;
    below += below_horizon_share(m.light, centre[k], cov_r);
    ++counted;
  }
  out.below = below / counted;

  const PrincipalAxes ax = principal_axes(cov_r);
  // Exact cull: when every point of the centres' path is further from the disk than its
  // radius plus 12 major standard deviations, the RDF's mass in the disk is below
  // exp(-144/2) ~ 1e-31 (and the kernels, offset by at most ~3 s1 with stds at most s1,
  // hold less still). Most pixels never reflect the light.
  {
    double nearest = HUGE_VAL;
    for (int k = 0; k < K; ++k) {
      if (!(valid[k] && valid[k + 1])) continue;
      const vec2 a = centre[k], d = centre[k + 1] - centre[k];
      const double dd = dot(d, d);
      const double t = dd > 0 ? std::clamp(-dot(a, d) / dd, 0.0, 1.0) : 0.0;
      nearest = std::min(nearest, length(a + t * d));
    }
    if (valid[K]) nearest = std::min(nearest, length(centre[K]));
    if (nearest > R + 12 * ax.s1) {
      out.in_light = 0;
      return out;
    }
  }
  const double threshold = o_.elongation_threshold > 0 ? o_.elongation_threshold
                           : o_.kernels > 1            ? o_.kernels
                                                       : HUGE_VAL;
  const bool degenerate = !(ax.s2 > 1e-12 * R);
  if (ax.s1 <= 1e-9 * R) {
    // A vanishing RDF: the fraction of the path inside the disk.
    double sum = 0;
    for (int k = 0; k < K; ++k) {
      if (valid[k] && valid[k + 1]) sum += tables_->path_average(centre[k], centre[k + 1], 0.0, R);
    }
    out.in_light = sum / K;
  } else if (degenerate || ax.s1 / ax.s2 > threshold) {
    // Past the elongation threshold: the RDF's mass in the disk (Sec. 3.6), at the display
    // time or averaged along the path by the midpoint rule with samples closer than a third
    // of the width of the mass-versus-position bump (disk radius + RDF spread along the
    // path), at most 32 per sub-segment.
    out.fallback = true;
    auto mass = [&](const vec2& p) {
      return o_.fallback == FallbackMode::riemann
                 ? gaussian_disk_mass_riemann(p, cov_r, R, o_.riemann_cells)
                 : gaussian_disk_mass(p, cov_r, R);
    };
    if (!o_.fallback_along_path) {
      out.in_light = mass(centre[K]);
    } else {
      double sum = 0;
      for (int k = 0; k < K; ++k) {
        if (!(valid[k] && valid[k + 1])) continue;
        const vec2 d = centre[k + 1] - centre[k];
        const double len = length(d);
        const vec2 dir = len > 0 ? d / len : vec2(1, 0);
        const double width = R + std::sqrt(std::max(0.0, dot(dir, cov_r * dir)));
        const int n = std::clamp(static_cast<int>(std::ceil(3 * len / width)), 1, 32);
        double seg = 0;
        for (int q = 0; q < n; ++q)
          seg += mass(centre[k] + ((q + 0.5) / n) * d);
        sum += seg / n;
      }
      out.in_light = sum / K;
    }
  } else {
    const KernelSet ks = elliptical_kernels(o_.kernels, ax.s2, ax.s1);
    double sum = 0;
    for (const CircularKernel& kern : ks.kernels) {
      const vec2 offset = kern.offset * ax.u;
      double along = 0;
      for (int k = 0; k < K; ++k) {
        if (!(valid[k] && valid[k + 1])) continue;
        along += tables_->path_average(centre[k] + offset, centre[k + 1] + offset, kern.sigma, R);
      }
      sum += kern.weight * along / K;
    }
    out.in_light = sum;
  }
  out.in_light = std::clamp(out.in_light, 0.0, 1.0 - out.below);
  return out;
}

RadianceWeights StaaMethod::weights(const FrameContext& ctx, int i, int j) const {
  const Shares s = shares(ctx, i, j);
  if (!s.hit)
    return miss_weights(ctx.model, normalize(ctx.model.camera.direction(i + 0.5, j + 0.5)));
  if (s.temporal) return s.temporal_weights;  // step 3, the temporal method
  return combine_weights(ctx.model, s.fresnel, s.in_light, s.below, s.sky_y);
}

}  // namespace sg
