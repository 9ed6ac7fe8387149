// The radiance of the scene spec ("Radiance along a camera ray") as weights of the
// scene's four radiances, vec4(light, sky zenith, sky horizon, sea): every value the spec
// defines is linear in them, so a method computes weights and the radiances (grey or RGB)
// are applied once per pixel on the host. At a water point with unit view direction v
// (towards the camera) and unit normal n:
//   r = 2 (n . v) n - v                                   (mirror reflection)
//   r.y <= 0:  the sea
//   otherwise: F (light if r is in the disk, else the sky in direction r) + (1 - F) sea
//   F = 1 (fresnel "none") or Schlick's R0 + (1 - R0)(1 - n . v)^5, R0 = 0.02;
//   sky(d) = horizon + (zenith - horizon) max(d.y, 0)^exponent.
// A camera ray that hits no water sees the sky, or the light when it is visible.

// The mirror reflection of the unit view v about a normal along `nm` of any length: with
// n = nm / |nm|, 2 (n . v) n - v = 2 (nm . v) / (nm . nm) nm - v, which needs no square
// root and is unit to rounding. Every reflection the kernel and the host take is this one.
SG_FN vec3 reflect_view(vec3 nm, vec3 v) {
  return (2.0 * dot(nm, v) / dot(nm, nm)) * nm - v;
}

// Schlick's approximation; n_dot_v is clamped to [0, 1].
SG_FN real fresnel_schlick(real n_dot_v) {
  real m = 1.0 - clamp(n_dot_v, 0.0, 1.0);
  real m2 = m * m;
  return kSchlickR0 + (1.0 - kSchlickR0) * m2 * m2 * m;
}

SG_FN real fresnel_factor(int mode, real n_dot_v) {
  return mode == 0 ? 1.0 : fresnel_schlick(n_dot_v);
}

// Channel c of a value from its weights: `channel` holds the four radiances' channel c
// (light, sky zenith, sky horizon, sea). The host applies it to every pixel's weights
// (scene/model.h, Radiances); `taa` applies it before its resolve, which works on radiances.
SG_FN real weights_radiance(vec4 w, vec4 channel) {
  return w.x * channel.x + w.y * channel.y + w.z * channel.z + w.w * channel.w;
}

SG_FN vec4 light_weights() {
  return vec4(1.0, 0.0, 0.0, 0.0);
}
SG_FN vec4 sea_weights() {
  return vec4(0.0, 0.0, 0.0, 1.0);
}

// The sky's (zenith, horizon) shares in a direction of height y (scene format: zenith
// max(y, 0)^exponent, horizon the rest), each to its precision's rounding: with
// u = exponent ln y, the zenith e^u and the horizon -(e^u - 1) (special.glsl:
// exp_minus_one). 1 - pow(y, e) would cancel where e |ln y| is small (a flat exponent or
// a high direction): a last-bit difference between two engines' pow became a relative
// difference of 2^-24 / (e |ln y|) in the horizon's share.
SG_FN vec2 sky_shares(IN(Frame) f, real dir_y) {
  if (!(dir_y > 0.0)) return vec2(0.0, 1.0);
  real u = f.sky_exponent * log(min(dir_y, 1.0));
  real e = exp(u);
  // 1 - e^u: exp_minus_one's series near u = 0, else from the one exponential (as
  // exp_minus_one takes it there, bit for bit).
  return vec2(e, abs(u) < 0.25 ? -exp_minus_one(u) : 1.0 - e);
}

// The sky in a direction of height dir_y: zenith max(dir_y, 0)^exponent, horizon the
// rest. A constant sky (zenith == horizon) puts its whole weight on the horizon.
SG_FN vec4 sky_weights(IN(Frame) f, real dir_y) {
  if (!f.sky_gradient) return vec4(0.0, 0.0, 1.0, 0.0);
  vec2 zh = sky_shares(f, dir_y);
  return vec4(0.0, zh.x, zh.y, 0.0);
}

// A camera ray with unit direction `dir` that hits no water.
SG_FN vec4 miss_weights(IN(Frame) f, vec3 dir) {
  if (f.light.visible && light_contains(f.light, dir)) return light_weights();
  return sky_weights(f, dir.y);
}

// The water seen from unit direction v with a normal along `nm` of any length.
SG_FN vec4 water_weights(IN(Frame) f, vec3 nm, vec3 v) {
  vec3 r = reflect_view(nm, v);
  if (r.y <= 0.0) return sea_weights();
  vec4 above = light_contains(f.light, r) ? light_weights() : sky_weights(f, r.y);
  if (f.fresnel == 0) return above;
  real F = fresnel_schlick(dot(nm, v) * inversesqrt(dot(nm, nm)));
  return F * above + (1.0 - F) * sea_weights();
}

// Whether all four weights are finite (NaN fails every comparison): where a baseline's
// model gives no finite value, it falls back (specaa.glsl, microspec.glsl).
SG_FN bool finite_weights(vec4 w) {
  vec4 a = abs(w);
  return a.x <= 1e30 && a.y <= 1e30 && a.z <= 1e30 && a.w <= 1e30;
}

// The weights when a fraction `in_light` of the footprint and shutter reflects into the
// light, `below` below the horizon and the rest into the sky at height `sky_y`; F is the
// Fresnel factor of the part above the horizon.
SG_FN vec4 combine_weights(IN(Frame) f, real F, real in_light, real below, real sky_y) {
  real above = 1.0 - below;
  real sky = max(0.0, above - in_light);
  vec4 s = sky_weights(f, sky_y);
  return vec4(F * in_light, F * sky * s.y, F * sky * s.z, below + (1.0 - F) * above);
}
