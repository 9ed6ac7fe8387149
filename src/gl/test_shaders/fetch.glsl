// Copies texels of a buffer texture (RGBA32F) and of a 3D R32F table, read with
// texelFetch, into an SSBO: the test compares them with what was uploaded.
layout(local_size_x = 64) in;
layout(binding = 0) uniform samplerBuffer waves;
layout(binding = 1) uniform sampler3D table;
layout(std430, binding = 2) buffer Texels {
  vec4 texels[];
};
layout(std430, binding = 3) buffer Table {
  float values[];
};
uniform int n_texels;
uniform ivec3 table_size;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i < n_texels) texels[i] = texelFetch(waves, i);
  int n = table_size.x * table_size.y * table_size.z;
  for (int k = i; k < n; k += int(gl_NumWorkGroups.x * gl_WorkGroupSize.x)) {
    ivec3 p = ivec3(k % table_size.x, (k / table_size.x) % table_size.y,
                    k / (table_size.x * table_size.y));
    values[k] = texelFetch(table, p, 0).r;
  }
}
