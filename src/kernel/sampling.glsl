// Point sampling, supersampling and the reference: the spec's radiance along single camera
// rays, and the stratified estimator of a pixel's box-filtered mean over the pixel square
// and the shutter interval.
//
// `point` (the paper's "No AA") takes one ray through the pixel centre at the display
// time. Every sample's ray is that of the camera at the sample's time (a moving camera,
// camera.glsl). The stratified estimator takes S_x x S_y jittered positions, one per cell of the
// pixel square, times T jittered times, one per stratum of the shutter; every position is
// paired with every time (S_x S_y T samples; unbiased, its error falls with the samples).
// With `time_at_frame` the T times are replaced by the single display time (supersample
// with T = 1: spatial-only supersampling, as MSAA would). Random numbers come from the
// stream of (seed, frame, pixel) (rng.glsl) in a fixed order: the T time jitters, then for
// each cell in row-major order its x and y jitter. Same inputs, same bytes.

// The weights along the ray through image-plane point (px, py) of the camera at dt from
// the display time (camera_at: a moving camera's position and basis at that time):
// intersection (flat or displaced), normal, reflection, shading; with where the ray met
// the water (`hit`) and its unit direction (`dir`): `taa` reprojects that point
// (taa.glsl). Out-parameters rather than a struct returned: `point`'s CPU time was 15%
// longer with the weights returned inside a struct (docs/benchmarks.md).
SG_FN vec4 sample_ray(IN(WaveBuffer) waves, IN(Frame) f, real px, real py, real dt, OUT(RayHit) hit,
                      OUT(vec3) dir) {
  Camera c = camera_at(f, dt);
  dir = normalize(camera_direction(c, px, py));
  vec3 o = c.position;
  if (f.displaced) {
    hit = intersect_displaced(waves, f, o, dir, dt);
  } else {
    hit = intersect_flat(o, dir);
  }
  if (!hit.hit) return miss_weights(f, dir);
  vec2 g = water_gradient(waves, f, hit.point.x, hit.point.z, dt);
  // Cascades shaded from their fields are sampled at the display time only (the host
  // builds fields for `point`, `staa-temporal` and `supersample` with T = 1 alone, whose
  // rays all have dt = 0).
  if (f.cascade_count > 0)
    g += cascade_gradient(waves, f, frame_segments(f), hit.point.x, hit.point.z);
  return water_weights(f, normal_direction(g), -dir);
}

SG_FN vec4 sample_weights(IN(WaveBuffer) waves, IN(Frame) f, real px, real py, real dt) {
  RayHit hit;
  vec3 dir;
  return sample_ray(waves, f, px, py, dt, hit, dir);
}

SG_FN vec4 point_pixel(IN(WaveBuffer) waves, IN(Frame) f, int i, int j) {
  return sample_weights(waves, f, real(i) + 0.5, real(j) + 0.5, 0.0);
}

// The sample times of a pixel, as offsets from the display time: the first T uniforms of
// its stream, one in each of the T equal strata of the shutter.
struct SampleTimes {
  real dt[kMaxTimeSamples];
  int count;
};

SG_FN SampleTimes draw_sample_times(INOUT(Pcg32) rng, IN(Frame) f, IN(SampleCounts) n) {
  SampleTimes t;
  t.count = n.time_at_frame ? 1 : n.nt;
  for (int q = 0; q < kMaxTimeSamples; ++q)
    t.dt[q] = 0.0;
  for (int q = 0; q < t.count; ++q) {
    real u = pcg32_uniform(rng);
    t.dt[q] = n.time_at_frame ? 0.0 : (real(q) + u) / real(t.count) * f.duration - f.duration;
  }
  return t;
}

// The samples of a pixel: S_x S_y cells, each with the T sample times (one at the display
// time when time_at_frame).
SG_FN int stratified_sample_count(IN(SampleCounts) n) {
  return n.sx * n.sy * (n.time_at_frame ? 1 : n.nt);
}

// A sample's loop iterations, estimated after it: the wave sums of each march step and
// refinement and of the normal (the march's steps from `hit`), each over every wave.
SG_FN real sample_work(IN(Frame) f, IN(RayHit) hit) {
  return real(hit.steps + 2) * real(f.wave_count + 1);
}

// The sum of the weights of samples [begin, next) of pixel (i, j), sample c T + q being cell
// c (row-major) at time q; `next` is `end` (or the pixel's count), or earlier where the
// samples' estimated loop iterations (sample_work) spent the platform's budget
// (loop_budget_spent: a GL program's, never elsewhere; at least one sample is taken).
// `next` follows each sample taken: where llvmpipe's limit ends the loops within a sample
// (a single ray that marches past it, docs/gpu.md), that sample is lost, not the rest of
// the pass's. The stream: the T times first, then two
// uniforms per cell (x, y), advanced to the first cell's draws, so that any split of the
// samples into ranges gives the same samples as one range: the GL engine renders a pixel
// in passes of a few samples, each from where the last one stopped (llvmpipe ends every
// loop of an invocation after 65535 iterations in all, docs/gpu.md).
SG_FN vec4 stratified_samples(IN(WaveBuffer) waves, IN(Frame) f, IN(SampleCounts) n, int i, int j,
                              int begin, int end, OUT(int) next) {
  Pcg32 rng = pixel_rng(f.seed, f.frame, i, j);
  SampleTimes times = draw_sample_times(rng, f, n);
  int nt = times.count;
  int last = min(end, n.sx * n.sy * nt);
  vec4 sum = vec4(0.0);
  next = begin;
  if (begin >= last) return sum;
  pcg32_advance(rng, uint(begin / nt) * 4u);
  real px = 0.0;
  real py = 0.0;
  real work = 0.0;
  for (int s = begin; s < last; ++s) {
    if (s > begin && loop_budget_spent(work)) break;
    int q = s % nt;
    if (s == begin || q == 0) {
      int cell = s / nt;
      int cx = cell % n.sx;
      int cy = cell / n.sx;
      px = real(i) + (real(cx) + pcg32_uniform(rng)) / real(n.sx);
      py = real(j) + (real(cy) + pcg32_uniform(rng)) / real(n.sy);
    }
    RayHit hit;
    vec3 dir;
    sum += sample_ray(waves, f, px, py, times.dt[q], hit, dir);
    work += sample_work(f, hit);
    next = s + 1;
  }
  return sum;
}

SG_FN vec4 stratified_pixel(IN(WaveBuffer) waves, IN(Frame) f, IN(SampleCounts) n, int i, int j) {
  int count = stratified_sample_count(n);
  int next;
  return stratified_samples(waves, f, n, i, j, 0, count, next) / real(count);
}

// `staa-temporal`: the temporal method of Sec. 3.3 for every pixel: the point at the pixel
// centre, its reflection path over the shutter (every wave resolved), and the fraction of
// the time in the light disk, exact on the sphere for each of the K sub-arcs. Under a
// moving camera each instant has its own water point and view (reflection_path.glsl,
// PathViews).
SG_FN vec4 staa_temporal_pixel(IN(WaveBuffer) waves, IN(Frame) f, int i, int j) {
  // A pixel that the horizon crosses: the water's part at its centroid, the sky over the
  // rest (horizon_coverage.glsl).
  PixelWater pw = pixel_water(f.camera, i, j);
  if (pw.share <= 0.0) return miss_pixel_weights(f, i, j);
  Footprint fp = pixel_footprint(waves, f, pw.centre.x, pw.centre.y, 0.0, f.displaced);
  if (!fp.hit) return miss_pixel_weights(f, i, j);
  PathViews v = path_views(waves, f, fp, pw.centre.x, pw.centre.y);
  PathGradients g;
  if (v.moving) {
    g = path_gradients_moving(waves, f, v);
  } else {
    g = path_gradients(waves, f, fp.point);
  }
  // Cascades shaded from their fields: point-sampled at each instant's water point.
  for (int k = 0; k <= frame_segments(f); ++k) {
    if (f.cascade_count > 0) {
      vec2 at = v.moving ? v.point[k] : vec2(fp.point.x, fp.point.z);
      g.g[k] += cascade_gradient(waves, f, k, at.x, at.y);
    }
  }
  return with_sky_part(f, pw, i, j, temporal_shares_along(f, g, v).weights);
}
