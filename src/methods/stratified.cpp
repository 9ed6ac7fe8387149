#include "methods/stratified.h"

#include <cmath>
#include <vector>

#include "math/rng.h"
#include "math/simd_trig.h"
#include "scene/intersect.h"
#include "shading/radiance.h"

namespace sg {
namespace {

struct Scratch {
  std::vector<double> times;
  std::vector<double> ct_arg, cos_ct, sin_ct;  // [wave][time]: c t, cos(c t), sin(c t)
  std::vector<vec3> dirs;                      // unit directions of the positions that hit
  std::vector<double> theta, sin_th, cos_th;   // [hit][wave]: a x + b z + phi
  std::vector<double> ac, as, bc, bs;          // per wave: A a cos(theta), ...
  std::vector<double> gx, gz;                  // per time
};

Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

// Flat water: the wave phases of each position and the c t of each time are evaluated
// once (vectorised, math/simd_trig.h) and combined per sample by angle addition.
RadianceWeights flat_pixel(const FrameContext& ctx, int i, int j, const StratifiedSettings& s,
                           Pcg32& rng) {
  const SceneModel& m = ctx.model;
  const WaveField& w = m.waves;
  const size_t nw = w.size();
  Scratch& sc = scratch();
  draw_sample_times(rng, ctx.time, s, sc.times);
  const int nt = static_cast<int>(sc.times.size());
  sc.ct_arg.resize(nw * nt);
  sc.cos_ct.resize(nw * nt);
  sc.sin_ct.resize(nw * nt);
  for (size_t k = 0; k < nw; ++k) {
    for (int q = 0; q < nt; ++q)
      sc.ct_arg[k * nt + q] = w.c[k] * sc.times[q];
  }
  sincos_array(sc.ct_arg.data(), sc.sin_ct.data(), sc.cos_ct.data(), nw * nt);

  // Positions, in the stream's order; those that miss the water see the sky at all times.
  const vec3 origin = m.camera.position();
  RadianceWeights sum(0.0);
  sc.dirs.clear();
  sc.theta.clear();
  for (int cy = 0; cy < s.samples.sy; ++cy) {
    for (int cx = 0; cx < s.samples.sx; ++cx) {
      const double px = i + (cx + rng.uniform()) / s.samples.sx;
      const double py = j + (cy + rng.uniform()) / s.samples.sy;
      const vec3 d = normalize(m.camera.direction(px, py));
      RayHit hit = intersect_flat(origin, d);
      if (!hit.hit) {
        sum += double(nt) * miss_weights(m, d);
        continue;
      }
      sc.dirs.push_back(d);
      for (size_t k = 0; k < nw; ++k) {
        sc.theta.push_back(w.a[k] * hit.point.x + w.b[k] * hit.point.z + w.phi[k]);
      }
    }
  }
  sc.sin_th.resize(sc.theta.size());
  sc.cos_th.resize(sc.theta.size());
  sincos_array(sc.theta.data(), sc.sin_th.data(), sc.cos_th.data(), sc.theta.size());

  sc.gx.resize(nt);
  sc.gz.resize(nt);
  for (auto* v : {&sc.ac, &sc.as, &sc.bc, &sc.bs})
    v->resize(nw);
  for (size_t h = 0; h < sc.dirs.size(); ++h) {
    const double* st_h = &sc.sin_th[h * nw];
    const double* ct_h = &sc.cos_th[h * nw];
    for (size_t k = 0; k < nw; ++k) {
      sc.ac[k] = w.A[k] * w.a[k] * ct_h[k];
      sc.as[k] = w.A[k] * w.a[k] * st_h[k];
      sc.bc[k] = w.A[k] * w.b[k] * ct_h[k];
      sc.bs[k] = w.A[k] * w.b[k] * st_h[k];
    }
    // dh/dx = sum A a cos(theta + c t) = sum A a (cos theta cos ct - sin theta sin ct)
    shifted_cosine_sums(sc.ac.data(), sc.as.data(), sc.bc.data(), sc.bs.data(), sc.cos_ct.data(),
                        sc.sin_ct.data(), nw, nt, sc.gx.data(), sc.gz.data());
    const vec3 v = -sc.dirs[h];
    for (int q = 0; q < nt; ++q) {
      sum += water_weights(m, normal_direction(vec2(sc.gx[q], sc.gz[q])), v);
    }
  }
  return sum / (static_cast<double>(nt) * s.samples.sx * s.samples.sy);
}

// Displaced water: the hit point depends on time, so each sample traces its own ray.
RadianceWeights displaced_pixel(const FrameContext& ctx, int i, int j, const StratifiedSettings& s,
                                Pcg32& rng) {
  const SceneModel& m = ctx.model;
  Scratch& sc = scratch();
  draw_sample_times(rng, ctx.time, s, sc.times);
  const int nt = static_cast<int>(sc.times.size());
  RadianceWeights sum(0.0);
  for (int cy = 0; cy < s.samples.sy; ++cy) {
    for (int cx = 0; cx < s.samples.sx; ++cx) {
      const double px = i + (cx + rng.uniform()) / s.samples.sx;
      const double py = j + (cy + rng.uniform()) / s.samples.sy;
      const vec3 d = m.camera.direction(px, py);
      for (int q = 0; q < nt; ++q)
        sum += weights_along_ray(m, m.camera.position(), d, sc.times[q]);
    }
  }
  return sum / (static_cast<double>(nt) * s.samples.sx * s.samples.sy);
}

}  // namespace

void draw_sample_times(Pcg32& rng, const FrameTime& ft, const StratifiedSettings& s,
                       std::vector<double>& times) {
  const int nt = s.time_at_frame ? 1 : s.samples.st;
  times.resize(nt);
  for (int m = 0; m < nt; ++m) {
    double u = rng.uniform();
    times[m] = s.time_at_frame ? ft.end : ft.start + (m + u) / nt * ft.duration();
  }
}

RadianceWeights stratified_pixel(const FrameContext& ctx, int i, int j,
                                 const StratifiedSettings& s) {
  Pcg32 rng = pixel_rng(ctx.seed, ctx.time.frame, i, j);
  return ctx.model.displaced() ? displaced_pixel(ctx, i, j, s, rng) : flat_pixel(ctx, i, j, s, rng);
}

long stratified_pixel_wave_evaluations(const FrameContext& ctx, int i, int j,
                                       const StratifiedSettings& s) {
  const long nw = static_cast<long>(ctx.model.waves.size());
  const long nt = s.time_at_frame ? 1 : s.samples.st;
  const long positions = static_cast<long>(s.samples.sx) * s.samples.sy;
  if (ctx.model.displaced()) return positions * nt * nw;  // at least one evaluation per sample
  // Count positions that hit water: each evaluates nw phases, then nw * nt updates.
  const SceneModel& m = ctx.model;
  long hits = 0;
  for (int cy = 0; cy < s.samples.sy; ++cy) {
    for (int cx = 0; cx < s.samples.sx; ++cx) {
      vec3 d = m.camera.direction(i + (cx + 0.5) / s.samples.sx, j + (cy + 0.5) / s.samples.sy);
      hits += intersect_flat(m.camera.position(), d).hit ? 1 : 0;
    }
  }
  return nw * nt + hits * nw * (1 + nt);
}

}  // namespace sg
