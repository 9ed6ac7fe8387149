// The web page's kernel pass (GLSL ES 3.00 fragment shader): one fragment per pixel runs
// the kernel's per-pixel function of the method this shader was compiled for (SG_METHOD_*
// and SG_MAX_SEGMENTS, set by the host in the header, as gl_engine/kernel_program.cpp sets
// them) and writes the pixel's radiance weights (light, sky zenith, sky horizon, sea) to an
// RGBA32F texture whose texel (i, j) is pixel (i, j), row 0 on top. The same uniforms as
// the GL engine's compute shader (gl_engine/shaders/main.glsl), the waves a 2D texture
// (kernel/glsl_es_prelude.glsl).
uniform sampler2D waves;
uniform sampler2D table_f;
uniform sampler2DArray table_s;
uniform sampler2D fits;

uniform Frame frame;
#if defined(SG_METHOD_STRATIFIED)
uniform SampleCounts counts;
#endif
#if defined(SG_METHOD_STAA)
uniform StaaParams params;
uniform PathTableInfo tinfo;
uniform KernelFitInfo finfo;
#endif

out vec4 weights_out;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 w = vec4(0.0);
#if defined(SG_METHOD_POINT)
  w = point_pixel(waves, frame, p.x, p.y);
#elif defined(SG_METHOD_STRATIFIED)
  w = stratified_pixel(waves, frame, counts, p.x, p.y);
#elif defined(SG_METHOD_STAA_TEMPORAL)
  w = staa_temporal_pixel(waves, frame, p.x, p.y);
#elif defined(SG_METHOD_STAA)
  StaaPath path;
  StaaResult r =
      staa_pixel(waves, table_f, table_s, tinfo, fits, finfo, frame, params, p.x, p.y, path);
  w = r.weights;
#endif
  weights_out = w;
}
