// The web page makes the path table S in the browser (docs/web.md: 8 MiB of floats do not
// fit a 2 MiB page; the fine grids of F they are integrated from take 0.6 MiB) with the
// kernel's own functions (kernel/path_table_gen.glsl), as the host does in
// shading/path_table.cpp, in three passes over each sigma slice (a layer of a 2D array
// texture, drawn one layer at a time):
//   SG_PASS_CELLS     the integral of each u cell [u_i, u_i+1] (all left of u = 0: the table
//                     holds u in [-R, 0]), per row v_j (kernel/path_table.glsl's radial grid);
//   SG_PASS_SCAN      one step of an inclusive prefix sum along u (Hillis and Steele 1986:
//                     shift 1, 2, 4, ...), so that texel i holds the cells 0..i;
//   SG_PASS_ASSEMBLE  S: 0 at u_0, then the prefix sums; slice 0 (sigma = 0) the chord.
// The host sums the cells of a row one after the other in double; here the sums are float,
// in the prefix sum's order: S differs from the host's by float rounding (docs/web.md).
#if defined(SG_PASS_CELLS)
uniform TableLine fine;  // the slices' fine grids of F, one after the other
uniform int fine_offset;
uniform int fine_count;
uniform float fine_step;
uniform float extent;  // R of the slice
uniform int n_u;
uniform int n_v;
uniform int panels;
out vec4 cell_out;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);  // (u cell i, v row j)
  float hu = extent / float(n_u - 1);
  float u0 = -extent * float(n_u - 1 - p.x) / float(n_u - 1);
  float v = table_radial_node(extent, float(p.y) / float(n_v - 1));
  float w = hu / float(panels);
  float sum = 0.0;
  for (int m = 0; m < panels; ++m) {
    float c = u0 + (float(m) + 0.5) * w;
    sum += path_cell_panel(fine, fine_offset, fine_count, fine_step, c, 0.5 * w, v * v);
  }
  cell_out = vec4(sum, 0.0, 0.0, 0.0);
}
#elif defined(SG_PASS_SCAN)
uniform sampler2DArray src;
uniform int layer;
uniform int shift;
out vec4 sum_out;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float s = texelFetch(src, ivec3(p, layer), 0).x;
  if (p.x >= shift) s += texelFetch(src, ivec3(p.x - shift, p.y, layer), 0).x;
  sum_out = vec4(s, 0.0, 0.0, 0.0);
}
#elif defined(SG_PASS_ASSEMBLE)
uniform sampler2DArray prefix;  // texel i: the cells 0..i, i.e. S at u_(i + 1)
uniform int layer;
uniform int n_u;
uniform int n_v;
uniform float extent;
uniform bool chord;  // slice 0
out vec4 s_out;
float S_at(int i, int j) {
  return i == 0 ? 0.0 : texelFetch(prefix, ivec3(i - 1, j, layer), 0).x;
}
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);  // (u node i, v row j)
  if (chord) {
    float u = -extent * float(n_u - 1 - p.x) / float(n_u - 1);
    float v = table_radial_node(extent, float(p.y) / float(n_v - 1));
    s_out = vec4(path_table_chord(u, v), 0.0, 0.0, 0.0);
    return;
  }
  s_out = vec4(S_at(p.x, p.y), 0.0, 0.0, 0.0);
}
#endif
