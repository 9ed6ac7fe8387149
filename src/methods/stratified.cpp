#include "methods/stratified.h"

#include "kernel/kernel_double.h"
#include "kernel/kernel_float.h"
#include "shading/water_geometry.h"

namespace sg {

RadianceWeights stratified_pixel(const KernelFrameInputs& in, int i, int j,
                                 const StratifiedSettings& s) {
  const kd::SampleCounts n = kernel_sample_counts(s);
  if (in.precision() == Precision::float32) {
    kf::SampleCounts nf;
    nf.sx = n.sx;
    nf.sy = n.sy;
    nf.nt = n.nt;
    nf.time_at_frame = n.time_at_frame;
    return to_weights(kf::float_stratified_pixel(wave_buffer(in.f()), in.f().frame, nf, i, j));
  }
  return kd::stratified_pixel(wave_buffer(in.d()), in.d().frame, n, i, j);
}

RadianceWeights stratified_pixel(const FrameContext& ctx, int i, int j,
                                 const StratifiedSettings& s) {
  KernelFrameInputs in(1, Precision::float64);
  in.build(ctx);
  return stratified_pixel(in, i, j, s);
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
