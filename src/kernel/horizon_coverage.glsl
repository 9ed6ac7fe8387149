// The horizon across a pixel: the share of the pixel square whose rays reach the water,
// and where that part lies. Every camera ray that points down meets the water (flat or
// displaced; the camera is above it), every ray that points up misses it, and the
// direction through image-plane point (px, py) is linear in (px, py) (camera.glsl), so its
// height d.y(px, py) is an affine function and the water's part of the pixel is the
// square clipped by the line d.y = 0: an exact polygon (Sutherland and Hodgman's clipping
// against one half-plane; area and centre by the shoelace formula). Methods that shade a
// pixel from its centre give the pixels the horizon crosses their water part's value over
// that share and the sky's over the rest, so that the horizon is anti-aliased as the
// visible light is (disk_coverage.glsl).

struct PixelWater {
  real share;   // the fraction of the pixel square whose rays point down
  vec2 centre;  // the centre of that part (image-plane coordinates)
};

SG_FN PixelWater pixel_water(IN(Camera) c, int i, int j) {
  vec2 q[4];
  q[0] = vec2(real(i), real(j));
  q[1] = vec2(real(i) + 1.0, real(j));
  q[2] = vec2(real(i) + 1.0, real(j) + 1.0);
  q[3] = vec2(real(i), real(j) + 1.0);
  real h[4];
  int below = 0;
  for (int k = 0; k < 4; ++k) {
    h[k] = camera_direction(c, q[k].x, q[k].y).y;
    if (h[k] < 0.0) below += 1;
  }
  PixelWater w;
  w.centre = vec2(real(i) + 0.5, real(j) + 0.5);
  w.share = below == 4 ? 1.0 : 0.0;
  if (below == 0 || below == 4) return w;
  // Clip the square to h < 0: at most 5 vertices.
  vec2 p[5];
  int n = 0;
  for (int k = 0; k < 4; ++k) {
    int l = (k + 1) % 4;
    if (h[k] < 0.0) {
      p[n] = q[k];
      n += 1;
    }
    if ((h[k] < 0.0) != (h[l] < 0.0)) {
      p[n] = q[k] + (h[k] / (h[k] - h[l])) * (q[l] - q[k]);
      n += 1;
    }
  }
  real area2 = 0.0;
  vec2 cen = vec2(0.0);
  for (int k = 0; k < n; ++k) {
    vec2 a = p[k] - q[0];
    vec2 b = p[(k + 1) % n] - q[0];
    real cr = a.x * b.y - a.y * b.x;
    area2 += cr;
    cen += cr * (a + b);
  }
  w.share = clamp(0.5 * area2, 0.0, 1.0);
  if (area2 > 0.0) w.centre = q[0] + cen / (3.0 * area2);
  return w;
}

// The sky's part of a pixel that the horizon crosses, a share `sky` of it: the light over
// the part of the pixel that sees it (at most the sky's share), the sky at the centre ray's
// height over the rest (disk_coverage.glsl, miss_pixel_weights, for a whole pixel).
SG_FN vec4 sky_part_weights(IN(Frame) f, int i, int j, real sky) {
  vec3 d = normalize(camera_direction(f.camera, real(i) + 0.5, real(j) + 0.5));
  real cover = min(light_pixel_coverage(f.camera, f.light, i, j), sky);
  return cover * light_weights() + (sky - cover) * sky_weights(f, d.y);
}

// A pixel's weights from its water part's `water`: the water's share of them and the
// sky's part over the rest (the pixel's water part unchanged when it has no sky).
SG_FN vec4 with_sky_part(IN(Frame) f, IN(PixelWater) pw, int i, int j, vec4 water) {
  if (pw.share >= 1.0) return water;
  return pw.share * water + sky_part_weights(f, i, j, 1.0 - pw.share);
}
