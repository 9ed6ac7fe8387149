#include "methods/stratified.h"

#include <cmath>
#include <vector>

#include "math/rng.h"
#include "scene/intersect.h"
#include "shading/radiance.h"

namespace sg {
namespace {

struct Scratch {
  std::vector<double> times, cos_ct, sin_ct;  // [wave][time]
  std::vector<double> ac, as, bc, bs;         // per wave, per position
  std::vector<double> gx, gz;                 // per time
};

Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

// Flat water: per position, the wave phases are evaluated once and combined with each
// time's cos/sin(c t).
double flat_pixel(const FrameContext& ctx, int i, int j, const StratifiedSettings& s, Pcg32& rng) {
  const SceneModel& m = ctx.model;
  const WaveField& w = m.waves;
  const size_t nw = w.size();
  Scratch& sc = scratch();
  draw_sample_times(rng, ctx.time, s, sc.times);
  const int nt = static_cast<int>(sc.times.size());
  sc.cos_ct.resize(nw * nt);
  sc.sin_ct.resize(nw * nt);
  for (size_t k = 0; k < nw; ++k) {
    for (int q = 0; q < nt; ++q) {
      double arg = w.c[k] * sc.times[q];
      sc.cos_ct[k * nt + q] = std::cos(arg);
      sc.sin_ct[k * nt + q] = std::sin(arg);
    }
  }
  sc.ac.resize(nw);
  sc.as.resize(nw);
  sc.bc.resize(nw);
  sc.bs.resize(nw);
  sc.gx.resize(nt);
  sc.gz.resize(nt);

  const vec3 origin = m.camera.position();
  double sum = 0;
  for (int cy = 0; cy < s.samples.sy; ++cy) {
    for (int cx = 0; cx < s.samples.sx; ++cx) {
      const double px = i + (cx + rng.uniform()) / s.samples.sx;
      const double py = j + (cy + rng.uniform()) / s.samples.sy;
      const vec3 d = normalize(m.camera.direction(px, py));
      RayHit hit = intersect_flat(origin, d);
      if (!hit.hit) {
        sum += nt * miss_radiance(m, d);
        continue;
      }
      const double x = hit.point.x, z = hit.point.z;
      for (size_t k = 0; k < nw; ++k) {
        const double theta = w.a[k] * x + w.b[k] * z + w.phi[k];
        const double ct = std::cos(theta), st = std::sin(theta);
        sc.ac[k] = w.A[k] * w.a[k] * ct;
        sc.as[k] = w.A[k] * w.a[k] * st;
        sc.bc[k] = w.A[k] * w.b[k] * ct;
        sc.bs[k] = w.A[k] * w.b[k] * st;
      }
      std::fill(sc.gx.begin(), sc.gx.end(), 0.0);
      std::fill(sc.gz.begin(), sc.gz.end(), 0.0);
      for (size_t k = 0; k < nw; ++k) {
        const double* cc = &sc.cos_ct[k * nt];
        const double* ss = &sc.sin_ct[k * nt];
        const double ac = sc.ac[k], as = sc.as[k], bc = sc.bc[k], bs = sc.bs[k];
        for (int q = 0; q < nt; ++q) {  // dh/dx = sum A a cos(theta + c t)
          sc.gx[q] += ac * cc[q] - as * ss[q];
          sc.gz[q] += bc * cc[q] - bs * ss[q];
        }
      }
      const vec3 v = -d;
      for (int q = 0; q < nt; ++q) {
        sum += water_radiance(m, normal_from_gradient(vec2(sc.gx[q], sc.gz[q])), v);
      }
    }
  }
  return sum / (static_cast<double>(nt) * s.samples.sx * s.samples.sy);
}

// Displaced water: the hit point depends on time, so each sample traces its own ray.
double displaced_pixel(const FrameContext& ctx, int i, int j, const StratifiedSettings& s,
                       Pcg32& rng) {
  const SceneModel& m = ctx.model;
  Scratch& sc = scratch();
  draw_sample_times(rng, ctx.time, s, sc.times);
  const int nt = static_cast<int>(sc.times.size());
  double sum = 0;
  for (int cy = 0; cy < s.samples.sy; ++cy) {
    for (int cx = 0; cx < s.samples.sx; ++cx) {
      const double px = i + (cx + rng.uniform()) / s.samples.sx;
      const double py = j + (cy + rng.uniform()) / s.samples.sy;
      const vec3 d = m.camera.direction(px, py);
      for (int q = 0; q < nt; ++q) sum += radiance_along_ray(m, m.camera.position(), d, sc.times[q]);
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

double stratified_pixel(const FrameContext& ctx, int i, int j, const StratifiedSettings& s) {
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
