// The GL engine's compute shader: one invocation per pixel runs the kernel's per-pixel
// function of the method this shader was compiled for (SG_METHOD_*, set by the engine in
// the header, gl_engine/kernel_program.cpp) and stores the pixel's radiance weights
// (light, sky zenith, sky horizon, sea) in an RGBA32F image, row 0 at the top. The frame's
// data are uniforms of the kernel's own structs (kernel/interface.glsl), the waves a buffer
// texture, the tables textures read with texelFetch.
//
// The sampling methods run in passes (gl_engine/gl_engine.cpp): each pass adds the samples
// [pass_range.x, pass_range.y) of every pixel, divided by the pixel's sample count, to the
// weights (the first one stores them); the reference's pass 0 (ref_pass) runs the pilot
// into busy_image. A pass of a few samples keeps each invocation's loop iterations far
// below llvmpipe's limit of 65535 per invocation, past which it ends every loop
// (docs/gpu.md, docs/reference-renderer.md).
layout(local_size_x = 8, local_size_y = 8) in;

#if defined(SG_METHOD_REFERENCE) || defined(SG_METHOD_STRATIFIED)
layout(rgba32f, binding = 0) uniform image2D weights_out;
uniform ivec2 pass_range;
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
uniform int ref_pass;
layout(rgba32f, binding = 5) uniform image2D busy_image;
#endif
#if defined(SG_METHOD_STAA)
uniform StaaParams params;
uniform PathTableInfo tinfo;
uniform KernelFitInfo finfo;
#endif

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= image_size.x || p.y >= image_size.y) return;
  vec4 w = vec4(0.0);
#if defined(SG_METHOD_POINT)
  w = point_pixel(waves, frame, p.x, p.y);
#elif defined(SG_METHOD_STRATIFIED)
  vec4 sum = stratified_samples(waves, frame, counts, p.x, p.y, pass_range.x, pass_range.y);
  w = sum / real(stratified_sample_count(counts));
  if (pass_range.x > 0) w += imageLoad(weights_out, p);
#elif defined(SG_METHOD_REFERENCE)
  if (ref_pass == 0) {
    bool busy = reference_busy(waves, frame, ref_params, p.x, p.y);
    imageStore(busy_image, p, vec4(busy ? 1.0 : 0.0));
  } else {
    bool busy = imageLoad(busy_image, p).x != 0.0;
    vec4 sum =
        reference_samples(waves, frame, ref_params, busy, p.x, p.y, pass_range.x, pass_range.y);
    int count = ref_params.batches * reference_batch_samples(ref_params, busy);
    w = imageLoad(weights_out, p) + sum / real(count);
  }
#elif defined(SG_METHOD_STAA_TEMPORAL)
  w = staa_temporal_pixel(waves, frame, p.x, p.y);
#elif defined(SG_METHOD_STAA)
  StaaPath path;
  StaaResult r =
      staa_pixel(waves, table_f, table_s, tinfo, fits, finfo, frame, params, p.x, p.y, path);
  w = r.weights;
#endif
  imageStore(weights_out, p, w);
}
