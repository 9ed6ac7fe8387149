// The radiance of the scene spec ("Radiance along a camera ray") for host code: the
// kernel's formulas (kernel/radiance.glsl, kernel/light.glsl), written once there, called
// in double on the model's light, Fresnel mode and sky.
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

#include "math/vec.h"
#include "scene/model.h"

namespace sg {

struct RayHit;
class WaterGeometry;

// The formulas are the kernel's (kernel/radiance.glsl, kernel/light.glsl), called in double
// (radiance.cpp) on the model's light, Fresnel mode and sky: these are the host's names
// for them. RadianceWeights (scene/model.h): x light, y zenith, z horizon, w sea.

// Schlick's R0 for water (kernel/constants.glsl).
extern const double kSchlickR0;

// The mirror reflection 2 (n . v) n - v of the unit view v about the normal n = nm / |nm|,
// for `nm` of any length.
vec3 reflect_view(const vec3& nm, const vec3& v);

// Schlick's approximation (scene spec 4). n_dot_v is clamped to [0, 1].
double fresnel_schlick(double n_dot_v);
double fresnel(FresnelMode mode, double n_dot_v);

// The sky's weights in direction d (d.y the height of the unit direction): zenith
// max(d.y, 0)^exponent, horizon the rest, each share to its own digits. A constant sky
// puts its whole weight on the horizon (zenith == horizon there).
RadianceWeights sky_weights(const SceneModel& m, double dir_y);

RadianceWeights light_weights();
RadianceWeights sea_weights();

// Weights along a camera ray with unit direction `dir` that hits no water.
RadianceWeights miss_weights(const SceneModel& m, const vec3& dir);

// Weights reflected at a water point seen from unit direction v, for a normal along `nm`
// of any length (the reflection 2 (nm . v) / (nm . nm) nm - v needs no square root).
RadianceWeights water_weights(const SceneModel& m, const vec3& nm, const vec3& v);

// The (unnormalised) normal (-dh/dx, 1, -dh/dz) of the scene spec for gradient g.
vec3 normal_direction(vec2 g);

// The expected weights when a fraction `in_light` of the footprint and shutter reflects
// into the light disk, `below` reflects below the horizon and the rest sees the sky in
// directions of height `sky_y` (the split between zenith and horizon); F is the Fresnel
// factor of the part above the horizon.
RadianceWeights combine_weights(const SceneModel& m, double F, double in_light, double below,
                                double sky_y);

// Pixel (i, j) whose centre ray hits no water, for the methods that integrate over the
// pixel: the sky at the centre, and the light over the part of the pixel square that sees
// its disk (kernel/disk_coverage.glsl).
RadianceWeights miss_pixel_weights(const SceneModel& m, int i, int j);

// Weights along the camera ray from `origin` with direction `dir` (any length) at time t
// on the water of `water`'s model (shading/water_geometry.h): intersection (flat or
// displaced), normal, reflection, shading. When `hit` is given it receives the
// intersection (for motion vectors; hit->s is along the unit direction).
RadianceWeights weights_along_ray(const WaterGeometry& water, const vec3& origin, const vec3& dir,
                                  double t, RayHit* hit = nullptr);

}  // namespace sg
