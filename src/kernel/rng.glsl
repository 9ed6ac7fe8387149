// The sampling streams of the kernel: PCG32 (O'Neill 2014, the pcg32 XSH-RR output
// function) keyed by SplitMix64 (Steele, Lea and Flood 2014), one stream per (seed, frame,
// pixel), exactly as math/rng.h draws them on the host (tested bit for bit). GLSL 4.50 has
// no 64-bit integers, so a 64-bit word is a uvec2 (x: low 32 bits, y: high 32 bits) with
// the few operations below; umulExtended gives the 64-bit product of two 32-bit words.

SG_FN uvec2 u64_add(uvec2 a, uvec2 b) {
  uint lo = a.x + b.x;
  uint carry = lo < a.x ? 1u : 0u;
  return uvec2(lo, a.y + b.y + carry);
}

// The low 64 bits of a * b.
SG_FN uvec2 u64_mul(uvec2 a, uvec2 b) {
  uint hi = 0u;
  uint lo = 0u;
  umulExtended(a.x, b.x, hi, lo);
  return uvec2(lo, hi + a.x * b.y + a.y * b.x);
}

SG_FN uvec2 u64_xor(uvec2 a, uvec2 b) {
  return uvec2(a.x ^ b.x, a.y ^ b.y);
}

// a >> n and a << n for 0 < n < 64.
SG_FN uvec2 u64_shr(uvec2 a, int n) {
  if (n >= 32) return uvec2(a.y >> uint(n - 32), 0u);
  return uvec2((a.x >> uint(n)) | (a.y << uint(32 - n)), a.y >> uint(n));
}
SG_FN uvec2 u64_shl(uvec2 a, int n) {
  if (n >= 32) return uvec2(0u, a.x << uint(n - 32));
  return uvec2(a.x << uint(n), (a.y << uint(n)) | (a.x >> uint(32 - n)));
}

SG_FN uvec2 splitmix64(uvec2 x) {
  x = u64_add(x, uvec2(0x7f4a7c15u, 0x9e3779b9u));
  x = u64_mul(u64_xor(x, u64_shr(x, 30)), uvec2(0x1ce4e5b9u, 0xbf58476du));
  x = u64_mul(u64_xor(x, u64_shr(x, 27)), uvec2(0x133111ebu, 0x94d049bbu));
  return u64_xor(x, u64_shr(x, 31));
}

struct Pcg32 {
  uvec2 state;
  uvec2 inc;
};

SG_FN uint pcg32_next(INOUT(Pcg32) g) {
  uvec2 old = g.state;
  g.state = u64_add(u64_mul(old, uvec2(0x4c957f2du, 0x5851f42du)), g.inc);  // 6364136223846793005
  uint xorshifted = u64_shr(u64_xor(u64_shr(old, 18), old), 27).x;
  uint rot = old.y >> 27u;
  return (xorshifted >> rot) | (xorshifted << ((0u - rot) & 31u));
}

// The stream moved `delta` outputs ahead, as `delta` calls of pcg32_next would, in at most
// 32 steps (Brown 1994, "Random number generation with arbitrary strides": the LCG's
// affine map squared per bit of delta). The reference's passes start mid-stream with it
// (reference.glsl): a loop of one step per skipped output would cost a GPU's time and,
// on llvmpipe, its loop budget (docs/reference-renderer.md).
SG_FN void pcg32_advance(INOUT(Pcg32) g, uint delta) {
  uvec2 acc_mult = uvec2(1u, 0u);
  uvec2 acc_plus = uvec2(0u, 0u);
  uvec2 cur_mult = uvec2(0x4c957f2du, 0x5851f42du);
  uvec2 cur_plus = g.inc;
  for (int bit = 0; bit < 32 && delta != 0u; ++bit) {
    if ((delta & 1u) != 0u) {
      acc_mult = u64_mul(acc_mult, cur_mult);
      acc_plus = u64_add(u64_mul(acc_plus, cur_mult), cur_plus);
    }
    cur_plus = u64_mul(u64_add(cur_mult, uvec2(1u, 0u)), cur_plus);
    cur_mult = u64_mul(cur_mult, cur_mult);
    delta = delta >> 1u;
  }
  g.state = u64_add(u64_mul(acc_mult, g.state), acc_plus);
}

SG_FN Pcg32 pcg32_make(uvec2 seed, uvec2 stream) {
  Pcg32 g;
  g.state = uvec2(0u, 0u);
  g.inc = u64_shl(stream, 1);
  g.inc.x = g.inc.x | 1u;
  pcg32_next(g);
  g.state = u64_add(g.state, seed);
  pcg32_next(g);
  return g;
}

// Uniform in [0, 1): in double the top 53 bits of two outputs (as math/rng.h), in float
// the top 24 bits of one pair's first output, so that a float never rounds up to 1.
SG_FN real pcg32_uniform(INOUT(Pcg32) g) {
  uint hi = pcg32_next(g);
  uint lo = pcg32_next(g);
  if (kDoublePrecision)
    return real(hi) * (1.0 / 4294967296.0) + real(lo >> 11u) * (1.0 / 9007199254740992.0);
  return real(hi >> 8u) * (1.0 / 16777216.0);
}

// The stream of pixel (i, j) of frame `frame` under `seed` (math/rng.h, pixel_rng).
SG_FN Pcg32 pixel_rng(uvec2 seed, int frame, int i, int j) {
  uvec2 f = uvec2(uint(frame), frame < 0 ? 0xffffffffu : 0u);
  uvec2 key = splitmix64(u64_xor(seed, splitmix64(u64_mul(f, uvec2(0x000001b3u, 0x00000100u)))));
  key = splitmix64(u64_xor(key, uvec2(uint(i), uint(j))));
  return pcg32_make(key, splitmix64(u64_add(key, uvec2(1u, 0u))));
}
