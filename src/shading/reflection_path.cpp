#include "shading/reflection_path.h"

#include "shading/arc.h"
#include "shading/radiance.h"

namespace sg {

namespace {

// cos and sin of c_i (end - t_k) for the instants of a path: they depend only on the wave
// frequencies, the interval's duration and K, so each thread keeps the last table it made.
// The key is the frequencies themselves, not the field's address: a field built later at
// the address of a destroyed one (a second scene in the same process) must not reuse it.
struct Rotations {
  std::vector<double> freq;
  double duration = -1;
  int K = 0;
  std::vector<std::vector<double>> c, s;  // [k]
};

const Rotations& rotations(const WaveField& w, double duration, int K) {
  thread_local Rotations r;
  if (r.duration != duration || r.K != K || r.c.size() != size_t(K) || r.freq != w.c) {
    r.freq = w.c;
    r.duration = duration;
    r.K = K;
    r.c.assign(K, {});
    r.s.assign(K, {});
    for (int k = 0; k < K; ++k)
      w.rotation(duration * (K - k) / K, r.c[k], r.s[k]);
  }
  return r;
}

}  // namespace

void reflection_path(const SceneModel& m, const PixelFootprint& fp, const FrameTime& ft,
                     int segments, std::span<const double> weights, ReflectionPath& path) {
  const int K = std::max(1, segments);
  path.view = fp.view;
  path.xz = vec2(fp.point.x, fp.point.z);
  path.times.resize(K + 1);
  path.gradients.resize(K + 1);
  path.normals.resize(K + 1);
  path.reflections.resize(K + 1);
  // The phases at the display time, once; earlier instants by angle subtraction.
  m.waves.phases(path.xz.x, path.xz.y, ft.end, path.phases);
  const Rotations& rot = rotations(m.waves, ft.duration(), K);
  thread_local WavePhases earlier;
  for (int k = 0; k <= K; ++k) {
    const double t = ft.start + ft.duration() * k / K;
    vec2 g;
    if (k == K) {
      g = m.waves.gradient(path.phases, weights);
    } else {
      m.waves.shift_phases(path.phases, rot.c[k], rot.s[k], earlier);
      g = m.waves.gradient(earlier, weights);
    }
    path.times[k] = t;
    path.gradients[k] = g;
    path.normals[k] = normal_from_gradient(g);
    path.reflections[k] = reflect_view(path.normals[k], path.view);
  }
}

namespace {

// Sub-arc k: its fractions and its Fresnel factor (the mean of its ends').
ArcFractions sub_arc(const SceneModel& m, const ReflectionPath& path, int k, double& F) {
  const FresnelMode mode = m.scene.surface.fresnel;
  F = 0.5 * (fresnel(mode, dot(path.normals[k], path.view)) +
             fresnel(mode, dot(path.normals[k + 1], path.view)));
  return arc_fractions(path.reflections[k], path.reflections[k + 1], m.light);
}

}  // namespace

PathShares temporal_shares(const SceneModel& m, const ReflectionPath& path) {
  PathShares s;
  s.fresnel = 0;
  const int K = path.segments();
  for (int k = 0; k < K; ++k) {
    double F;
    ArcFractions f = sub_arc(m, path, k, F);
    s.in_light += f.in_light / K;
    s.below += f.below / K;
    s.fresnel += F / K;
    const double sky_y = normalize(path.reflections[k] + path.reflections[k + 1]).y;
    s.weights += combine_weights(m, F, f.in_light, f.below, sky_y) / double(K);
  }
  return s;
}

RadianceWeights temporal_weights(const SceneModel& m, const ReflectionPath& path) {
  return temporal_shares(m, path).weights;
}

}  // namespace sg
