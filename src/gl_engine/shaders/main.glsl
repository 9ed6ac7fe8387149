// The GL engine's compute shader: one invocation per pixel runs the kernel's per-pixel
// function of the method this shader was compiled for (SG_METHOD_*, set by the engine in
// the header, gl_engine/kernel_program.cpp) and stores the pixel's radiance weights
// (light, sky zenith, sky horizon, sea) in an RGBA32F image, row 0 at the top (`taa`, whose
// resolve works on radiances: the pixel's radiances there). The frame's
// data are uniforms of the kernel's own structs (kernel/interface.glsl), the waves a buffer
// texture, the tables textures read with texelFetch.
//
// The sampling methods run in passes (gl_engine/gl_engine.cpp): each pass adds up to
// pass_samples samples of every pixel, from where its last pass stopped (pixel_state.y),
// divided by the pixel's sample count, to the weights (the first one stores them); the
// reference's pass 0 runs the pilot into pixel_state.x. A pass of a few samples keeps each
// invocation's loop iterations far below llvmpipe's limit of 65535 per invocation, past
// which it ends every loop (docs/gpu.md, docs/reference-renderer.md); and where the samples
// cost more than the pass was sized for (grazing rays marching far over displaced water), an
// invocation stops after the sample that spends its budget of estimated loop iterations
// (SG_LOOP_GUARD, kernel/sampling.glsl: loop_budget_spent, sample_work), counts itself in
// pass_unfinished, and the next pass goes on from there.
layout(local_size_x = 8, local_size_y = 8) in;

#if defined(SG_METHOD_REFERENCE) || defined(SG_METHOD_STRATIFIED)
layout(rgba32f, binding = 0) uniform image2D weights_out;
uniform int pass_index;
uniform int pass_samples;
layout(rgba32f, binding = 5) uniform image2D pixel_state;  // .x the pilot's busy, .y next sample
layout(std430, binding = 8) buffer PassUnfinished {
  uint pass_unfinished;
};

// Where the pixel's samples stand after a pass: `next` of `total`.
void pass_record(ivec2 p, real busy, int next, int total) {
  imageStore(pixel_state, p, vec4(busy, real(next), 0.0, 0.0));
  if (next < total) atomicAdd(pass_unfinished, 1u);
}
#else
layout(rgba32f, binding = 0) uniform writeonly image2D weights_out;
#endif
layout(binding = 1) uniform samplerBuffer waves;
layout(binding = 2) uniform sampler2D table_f;
layout(binding = 3) uniform sampler2DArray table_s;
layout(binding = 4) uniform sampler2D fits;

uniform ivec2 image_size;
uniform Frame frame;
#if defined(SG_METHOD_STRATIFIED)
uniform SampleCounts counts;
#endif
#if defined(SG_METHOD_REFERENCE)
uniform ReferenceParams ref_params;
#endif
#if defined(SG_METHOD_STAA)
uniform StaaParams params;
uniform PathTableInfo tinfo;
uniform KernelFitInfo finfo;
#endif
#if defined(SG_METHOD_SPECAA)
uniform SpecaaParams sparams;
// `specaa`'s quads: the workgroup's 8 x 8 invocations are 4 x 4 whole 2 x 2 quads (the
// groups start at multiples of 8), and each shares its h_perp and whether its neighbours
// may difference it, as a GPU's quad does for dFdx / dFdy.
shared vec2 quad_h_perp[64];
shared bool quad_usable[64];

// The pixel at p with its quad's neighbours in x and in y: every invocation of the group
// samples (those past the image too, as the CPU's tiles sample their quads' cover) before
// the barrier, which all reach.
vec4 specaa_quad_pixel(ivec2 p) {
  SpecaaSample own = specaa_sample(waves, frame, real(p.x) + 0.5, real(p.y) + 0.5);
  int at = int(gl_LocalInvocationIndex);
  quad_h_perp[at] = own.h_perp;
  quad_usable[at] = specaa_quad_usable(own);
  barrier();
  ivec2 l = ivec2(gl_LocalInvocationID.xy);
  int ax = l.y * 8 + (l.x ^ 1);
  int ay = (l.y ^ 1) * 8 + l.x;
  SpecaaSample nx = specaa_no_sample();
  nx.hit = quad_usable[ax];
  nx.h_perp = quad_h_perp[ax];
  SpecaaSample ny = specaa_no_sample();
  ny.hit = quad_usable[ay];
  ny.h_perp = quad_h_perp[ay];
  return specaa_shade(waves, frame, sparams, own, nx, ny, p.x, p.y).weights;
}
#endif

#if defined(SG_METHOD_BRUNETON)
uniform BrunetonParams bparams;
#endif
#if defined(SG_METHOD_LEAN) || defined(SG_METHOD_LEAN_MAP)
// `lean`'s map (gl_engine/lean_map_gl.h): its texels, five floats each, read with the
// kernel's filters; the map program writes a level through the storage buffer from the
// waves (level 0) or from the level before (read through the texture).
uniform LeanParams lparams;
layout(binding = 6) uniform samplerBuffer lean_map;
#endif
#if defined(SG_METHOD_LEAN_MAP)
// A pass writes the rows [lean_row0, lean_row0 + lean_rows) of level lean_level through a
// window of the map's buffer that starts at float lean_out_base (gl_engine/lean_map_gl.h).
uniform int lean_level;
uniform int lean_row0;
uniform int lean_rows;
uniform int lean_out_base;
layout(std430, binding = 7) writeonly buffer LeanMapOut {
  float lean_out[];
};

// Texel (x, y) of level lean_level, n a side, into the window.
void lean_store(LeanMoments t, int x, int y, int n) {
  int at =
      kLeanTexelFloats * (lean_level_offset(lparams.size, lean_level) + y * n + x) - lean_out_base;
  lean_out[at] = t.B.x;
  lean_out[at + 1] = t.B.y;
  lean_out[at + 2] = t.M.x;
  lean_out[at + 3] = t.M.y;
  lean_out[at + 4] = t.M.z;
}

// Level 0: a block of kLeanBlock x kLeanBlock texels an invocation (lean_level0_block);
// the levels above: a texel an invocation, the mean of its four children.
void lean_map_main() {
  int n = lparams.size >> lean_level;
  if (lean_level == 0) {
    ivec2 b = kLeanBlock * ivec2(gl_GlobalInvocationID.xy);  // within the band's rows
    if (b.x >= n || b.y >= lean_rows) return;
    LeanBlock blk = lean_level0_block(waves, frame, lparams, b.x, b.y + lean_row0);
    for (int r = 0; r < kLeanBlock; ++r) {
      for (int c = 0; c < kLeanBlock; ++c) {
        if (b.x + c < n && b.y + r < lean_rows)
          lean_store(lean_moments_of_slope(blk.g[r * kLeanBlock + c]), b.x + c, b.y + r + lean_row0,
                     n);
      }
    }
    return;
  }
  ivec2 p = ivec2(gl_GlobalInvocationID.xy) + ivec2(0, lean_row0);
  if (p.x >= n || int(gl_GlobalInvocationID.y) >= lean_rows) return;
  int np = 2 * n;
  int c = lean_level_offset(lparams.size, lean_level - 1) + 2 * p.y * np + 2 * p.x;
  lean_store(lean_parent(lean_map_texel(lean_map, c), lean_map_texel(lean_map, c + 1),
                         lean_map_texel(lean_map, c + np), lean_map_texel(lean_map, c + np + 1)),
             p.x, p.y, n);
}
#endif
#if defined(SG_METHOD_TAA)
// `taa`'s samples (kernel/taa.glsl): weights_out takes each pixel's radiances (r, g, b, 0:
// grey in r), from the four radiances' channels (kernel/radiance.glsl, weights_radiance),
// taa_motion_out its motion vector.
uniform TaaParams tparams;
uniform vec4 radiance_channel[3];
layout(rgba32f, binding = 5) uniform writeonly image2D taa_motion_out;
#endif
#if defined(SG_METHOD_TAA_RESOLVE)
// `taa`'s resolve: the samples' radiances and motion of the frame, the history (the last
// frame's output), read with texelFetch; weights_out takes the output's radiances.
uniform TaaResolveParams rparams;
uniform bool taa_has_history;
layout(binding = 2) uniform sampler2D taa_current;
layout(binding = 3) uniform sampler2D taa_previous;
layout(binding = 4) uniform sampler2D taa_motion;
#endif
#if defined(SG_METHOD_MICROSPEC)
uniform MicrospecParams mparams;
// `microspec`'s corners: the workgroup's 8 x 8 pixels have 9 x 9 corners, each traced once
// (the last column's and row's invocations trace the extra ones) and shared.
shared CornerReflection group_corners[81];

vec4 microspec_group_pixel(ivec2 p) {
  ivec2 l = ivec2(gl_LocalInvocationID.xy);
  group_corners[l.y * 9 + l.x] = microspec_corner(waves, frame, real(p.x), real(p.y));
  if (l.x == 7)
    group_corners[l.y * 9 + 8] = microspec_corner(waves, frame, real(p.x + 1), real(p.y));
  if (l.y == 7) group_corners[72 + l.x] = microspec_corner(waves, frame, real(p.x), real(p.y + 1));
  if (l.x == 7 && l.y == 7)
    group_corners[80] = microspec_corner(waves, frame, real(p.x + 1), real(p.y + 1));
  barrier();
  PixelCorners c;
  c.c[0] = group_corners[l.y * 9 + l.x];
  c.c[1] = group_corners[l.y * 9 + l.x + 1];
  c.c[2] = group_corners[(l.y + 1) * 9 + l.x + 1];
  c.c[3] = group_corners[(l.y + 1) * 9 + l.x];
  return microspec_shade(waves, frame, mparams, c, p.x, p.y).weights;
}
#endif

void main() {
#if defined(SG_METHOD_LEAN_MAP)
  lean_map_main();
  return;
#endif
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
#if defined(SG_METHOD_SPECAA) && SG_SPECAA_QUAD
  // Before the image's edge test: the quad's barrier is every invocation's.
  vec4 quad_weights = specaa_quad_pixel(p);
#endif
#if defined(SG_METHOD_MICROSPEC)
  vec4 corner_weights = microspec_group_pixel(p);  // likewise
#endif
  if (p.x >= image_size.x || p.y >= image_size.y) return;
  vec4 w = vec4(0.0);
#if defined(SG_METHOD_POINT)
  w = point_pixel(waves, frame, p.x, p.y);
#elif defined(SG_METHOD_STRATIFIED)
  int total = stratified_sample_count(counts);
  int begin = pass_index == 0 ? 0 : int(imageLoad(pixel_state, p).y);
  if (begin >= total) return;
  int next;
  vec4 sum = stratified_samples(waves, frame, counts, p.x, p.y, begin, begin + pass_samples, next);
  w = sum / real(total);
  if (pass_index > 0) w += imageLoad(weights_out, p);
  pass_record(p, 0.0, next, total);
#elif defined(SG_METHOD_REFERENCE)
  if (pass_index == 0) {
    bool busy = reference_busy(waves, frame, ref_params, p.x, p.y);
    imageStore(pixel_state, p, vec4(busy ? 1.0 : 0.0, 0.0, 0.0, 0.0));
  } else {
    vec4 state = imageLoad(pixel_state, p);
    bool busy = state.x != 0.0;
    int total = ref_params.batches * reference_batch_samples(ref_params, busy);
    int begin = int(state.y);
    if (begin >= total) return;
    int next;
    vec4 sum = reference_samples(waves, frame, ref_params, busy, p.x, p.y, begin,
                                 begin + pass_samples, next);
    w = imageLoad(weights_out, p) + sum / real(total);
    pass_record(p, state.x, next, total);
  }
#elif defined(SG_METHOD_STAA_TEMPORAL)
  w = staa_temporal_pixel(waves, frame, p.x, p.y);
#elif defined(SG_METHOD_STAA)
  StaaPath path;
  StaaResult r =
      staa_pixel(waves, table_f, table_s, tinfo, fits, finfo, frame, params, p.x, p.y, path);
  w = r.weights;
#elif defined(SG_METHOD_SPECAA) && SG_SPECAA_QUAD
  w = quad_weights;
#elif defined(SG_METHOD_SPECAA)
  w = specaa_pixel(waves, frame, sparams, p.x, p.y).weights;
#elif defined(SG_METHOD_MICROSPEC)
  w = corner_weights;
#elif defined(SG_METHOD_BRUNETON)
  w = bruneton_pixel(waves, frame, bparams, p.x, p.y).weights;
#elif defined(SG_METHOD_LEAN)
  w = lean_pixel(waves, frame, lean_map, lparams, p.x, p.y).weights;
#elif defined(SG_METHOD_TAA)
  TaaSample s = taa_sample(waves, frame, tparams, p.x, p.y);
  for (int c = 0; c < 3; ++c)
    w[c] = weights_radiance(s.weights, radiance_channel[c]);
  imageStore(taa_motion_out, p, vec4(s.motion, 0.0, 0.0));
#elif defined(SG_METHOD_TAA_RESOLVE)
  vec2 motion = texelFetch(taa_motion, p, 0).xy;
  TaaResolved r =
      taa_resolve_pixel(taa_current, taa_previous, rparams, taa_has_history, motion, p.x, p.y);
  w = r.value;
#endif
  imageStore(weights_out, p, w);
}
