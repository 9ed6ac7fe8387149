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
// intersection (flat or displaced), normal, reflection, shading.
SG_FN vec4 sample_weights(IN(WaveBuffer) waves, IN(Frame) f, real px, real py, real dt) {
  Camera c = camera_at(f, dt);
  vec3 d = normalize(camera_direction(c, px, py));
  vec3 o = c.position;
  RayHit hit;
  if (f.displaced) {
    hit = intersect_displaced(waves, f, o, d, dt);
  } else {
    hit = intersect_flat(o, d);
  }
  if (!hit.hit) return miss_weights(f, d);
  vec2 g = water_gradient(waves, f, hit.point.x, hit.point.z, dt);
  return water_weights(f, normal_direction(g), -d);
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

SG_FN vec4 stratified_pixel(IN(WaveBuffer) waves, IN(Frame) f, IN(SampleCounts) n, int i, int j) {
  Pcg32 rng = pixel_rng(f.seed, f.frame, i, j);
  SampleTimes times = draw_sample_times(rng, f, n);
  vec4 sum = vec4(0.0);
  for (int cy = 0; cy < n.sy; ++cy) {
    for (int cx = 0; cx < n.sx; ++cx) {
      real px = real(i) + (real(cx) + pcg32_uniform(rng)) / real(n.sx);
      real py = real(j) + (real(cy) + pcg32_uniform(rng)) / real(n.sy);
      for (int q = 0; q < times.count; ++q)
        sum += sample_weights(waves, f, px, py, times.dt[q]);
    }
  }
  return sum / (real(times.count) * real(n.sx) * real(n.sy));
}

// `staa-temporal`: the temporal method of Sec. 3.3 for every pixel: the point at the pixel
// centre, its reflection path over the shutter (every wave resolved), and the fraction of
// the time in the light disk, exact on the sphere for each of the K sub-arcs.
SG_FN vec4 staa_temporal_pixel(IN(WaveBuffer) waves, IN(Frame) f, int i, int j) {
  // A pixel that the horizon crosses: the water's part at its centroid, the sky over the
  // rest (horizon_coverage.glsl).
  PixelWater pw = pixel_water(f.camera, i, j);
  if (pw.share <= 0.0) return miss_pixel_weights(f, i, j);
  Footprint fp = pixel_footprint(waves, f, pw.centre.x, pw.centre.y, 0.0, f.displaced);
  if (!fp.hit) return miss_pixel_weights(f, i, j);
  PathGradients g = path_gradients(waves, f, fp.point);
  return with_sky_part(f, pw, i, j, temporal_shares(f, g, fp.view).weights);
}
