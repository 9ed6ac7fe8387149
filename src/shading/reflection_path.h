// The reflection path of a pixel (Podee et al. 2021, Sec. 3.3, Fig. 1 and 4): the point
// of the water seen through the pixel centre, and the reflection of the view direction
// about the normal of the resolved waves at K + 1 instants of the frame's shutter
// interval, t_k = start + k (end - start) / K. Consecutive instants bound the K sub-arcs
// ("dividing the frame time into subintervals", Sec. 3.5); K = 1 is the paper's path from
// the previous frame's reflection to the current one.
//
// The normals come from the waves weighted by w_i (1 for staa-temporal; 1 - alpha_i, the
// resolved share, for staa). On displaced water the point is the first hit at the display
// time t_f and its horizontal position is kept for the whole interval (the paper samples
// "a single point on the water surface corresponding to the pixel center").
//
// temporal_value: the temporal method (Sec. 3.3) on a path: for each sub-arc, the
// fractions of time in the light disk and below the horizon (shading/arc.h, exact for a
// constant-speed great-circle arc), combined into the spec's radiance with the sub-arc's
// mean Fresnel factor, and averaged over the sub-arcs.
#pragma once

#include <span>
#include <vector>

#include "math/vec.h"
#include "scene/footprint.h"
#include "scene/model.h"

namespace sg {

struct ReflectionPath {
  WavePhases phases;              // the waves' phases at the point at the display time
  vec3 view{0};                   // unit, towards the camera
  vec2 xz{0};                     // the surface point
  std::vector<double> times;      // K + 1 instants
  std::vector<vec2> gradients;    // weighted (dh/dx, dh/dz) at each instant
  std::vector<vec3> normals;      // unit normals
  std::vector<vec3> reflections;  // unit reflections of the view
  int segments() const { return static_cast<int>(times.size()) - 1; }
};

// `weights` may be empty (all waves at full amplitude).
void reflection_path(const SceneModel& m, const PixelFootprint& fp, const FrameTime& ft,
                     int segments, std::span<const double> weights, ReflectionPath& path);

// The temporal method's shares for a path (Sec. 3.3): the fractions of the interval in
// the light and below the horizon, and the mean Fresnel factor, over all sub-arcs.
struct PathShares {
  double in_light = 0, below = 0, fresnel = 1;
  RadianceWeights weights{0.0};  // temporal_weights of the path (sub-arcs combined one by one)
};
PathShares temporal_shares(const SceneModel& m, const ReflectionPath& path);

// The temporal method's weights for a path: each sub-arc's shares combined into the
// spec's radiance weights with that sub-arc's Fresnel factor (the sky at the height of
// the sub-arc's mid reflection), averaged over the sub-arcs.
RadianceWeights temporal_weights(const SceneModel& m, const ReflectionPath& path);

}  // namespace sg
