// The radiance of the scene spec ("Radiance along a camera ray"), written once and used
// by every method, the reference renderer and the tests.
//
// At a water point with unit view direction v (towards the camera) and unit normal n:
//   r = 2 (n . v) n - v                                   (mirror reflection)
//   r.y <= 0:  L = sea_radiance
//   otherwise: L = F (radiance if angle(r, L) <= rho else sky(r)) + (1 - F) sea_radiance
//   F = 1 (fresnel "none") or Schlick's R0 + (1 - R0)(1 - n . v)^5 with R0 = 0.02,
//   sky(d) = horizon + (zenith - horizon) max(d.y, 0)^exponent (a constant sky: zenith ==
//   horizon).
// A camera ray that hits no water sees the sky (or the light, when light.visible).
//
// Every value above is linear in the scene's four radiances (light, zenith, horizon,
// sea), so a method computes a pixel as their weights, a vec4 (RadianceWeights below),
// and the radiances, grey or RGB, are applied once at the end (Radiances::apply). The
// pixel's mean over footprint and shutter is then the mean of the samples' weights.
//
// Analytic methods do not shade one direction; they find the fractions of a pixel's
// footprint and shutter whose reflection lands in the light disk, in the sky, or below
// the horizon. `combine_weights` turns such fractions into the same weights.
#pragma once

#include <algorithm>
#include <cmath>

#include "math/vec.h"
#include "scene/model.h"

namespace sg {

struct RayHit;

inline constexpr double kSchlickR0 = 0.02;

// RadianceWeights (scene/model.h): x light, y zenith, z horizon, w sea.

// r = 2 (n . v) n - v
inline vec3 reflect_view(const vec3& n, const vec3& v) {
  return 2.0 * dot(n, v) * n - v;
}

// Schlick's approximation (scene spec 4). n_dot_v is clamped to [0, 1].
inline double fresnel_schlick(double n_dot_v) {
  double m = 1.0 - clamp(n_dot_v, 0.0, 1.0);
  double m2 = m * m;
  return kSchlickR0 + (1.0 - kSchlickR0) * m2 * m2 * m;
}

inline double fresnel(FresnelMode mode, double n_dot_v) {
  return mode == FresnelMode::none ? 1.0 : fresnel_schlick(n_dot_v);
}

// The sky's weights in direction d (d.y the height of the unit direction): zenith
// max(d.y, 0)^exponent, horizon the rest, each share to its own digits (kernel/radiance.glsl:
// sky_shares; here std::expm1).
// A constant sky puts its whole weight on the horizon (zenith == horizon there).
inline RadianceWeights sky_weights(const SceneModel& m, double dir_y) {
  if (!m.scene.sky.gradient) return RadianceWeights(0.0, 0.0, 1.0, 0.0);
  if (!(dir_y > 0)) return RadianceWeights(0.0, 0.0, 1.0, 0.0);
  const double u = m.scene.sky.exponent * std::log(std::min(dir_y, 1.0));
  return RadianceWeights(0.0, std::exp(u), -std::expm1(u), 0.0);
}

inline RadianceWeights light_weights() {
  return RadianceWeights(1.0, 0.0, 0.0, 0.0);
}
inline RadianceWeights sea_weights() {
  return RadianceWeights(0.0, 0.0, 0.0, 1.0);
}

// Weights along a camera ray with unit direction `dir` that hits no water.
inline RadianceWeights miss_weights(const SceneModel& m, const vec3& dir) {
  if (m.light.visible && m.light.contains(dir)) return light_weights();
  return sky_weights(m, dir.y);
}

// Weights reflected at a water point seen from unit direction v, for a normal along `nm`
// of any length (the unit normal is nm / |nm|). With n = nm / |nm| the reflection
// 2 (n . v) n - v equals 2 (nm . v) / (nm . nm) nm - v, which needs no square root; r is
// then unit to rounding, so the cone test r . L >= cos(rho) is exact to 1e-16.
inline RadianceWeights water_weights(const SceneModel& m, const vec3& nm, const vec3& v) {
  const double nv = dot(nm, v), nn = dot(nm, nm);
  const vec3 r = (2.0 * nv / nn) * nm - v;
  if (r.y <= 0) return sea_weights();
  const RadianceWeights above = m.light.contains(r) ? light_weights() : sky_weights(m, r.y);
  if (m.scene.surface.fresnel == FresnelMode::none) return above;
  const double F = fresnel_schlick(nv / std::sqrt(nn));
  return F * above + (1.0 - F) * sea_weights();
}

// The (unnormalised) normal (-dh/dx, 1, -dh/dz) of the scene spec for gradient g.
inline vec3 normal_direction(vec2 g) {
  return vec3(-g.x, 1.0, -g.y);
}

// The expected weights when a fraction `in_light` of the footprint and shutter reflects
// into the light disk, `below` reflects below the horizon and the rest sees the sky in
// directions of height `sky_y` (the split between zenith and horizon); F is the Fresnel
// factor of the part above the horizon.
inline RadianceWeights combine_weights(const SceneModel& m, double F, double in_light, double below,
                                       double sky_y) {
  const double above = 1.0 - below;
  const double sky = std::max(0.0, above - in_light);
  const RadianceWeights s = sky_weights(m, sky_y);
  return RadianceWeights(F * in_light, F * sky * s.y, F * sky * s.z, below + (1.0 - F) * above);
}

// Pixel (i, j) whose centre ray hits no water, for the methods that integrate over the
// pixel: the sky at the centre, and the light over the part of the pixel square that sees
// its disk (kernel/disk_coverage.glsl).
RadianceWeights miss_pixel_weights(const SceneModel& m, int i, int j);

// Weights along the camera ray from `origin` with direction `dir` (any length) at time t:
// intersection (flat or displaced), normal, reflection, shading. When `hit` is given it
// receives the intersection (for motion vectors; hit->s is along the unit direction).
RadianceWeights weights_along_ray(const SceneModel& m, const vec3& origin, const vec3& dir,
                                  double t, RayHit* hit = nullptr);

}  // namespace sg
