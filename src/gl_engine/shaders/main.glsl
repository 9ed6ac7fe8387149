// The GL engine's compute shader: one invocation per pixel runs the kernel's per-pixel
// function of the method this shader was compiled for (SG_METHOD_*, set by the engine in
// the header, gl_engine/kernel_program.cpp) and stores the pixel's radiance weights
// (light, sky zenith, sky horizon, sea) in an RGBA32F image, row 0 at the top. The frame's
// data are uniforms of the kernel's own structs (kernel/interface.glsl), the waves a buffer
// texture, the tables textures read with texelFetch.
layout(local_size_x = 8, local_size_y = 8) in;

layout(rgba32f, binding = 0) uniform writeonly image2D weights_out;
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

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= image_size.x || p.y >= image_size.y) return;
  vec4 w = vec4(0.0);
#if defined(SG_METHOD_POINT)
  w = point_pixel(waves, frame, p.x, p.y);
#elif defined(SG_METHOD_STRATIFIED)
  w = stratified_pixel(waves, frame, counts, p.x, p.y);
#elif defined(SG_METHOD_REFERENCE)
  w = reference_pixel(waves, frame, ref_params, p.x, p.y).weights;
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
