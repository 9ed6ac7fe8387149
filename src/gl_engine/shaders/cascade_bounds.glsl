// The display time's height grid's maxima (gl_engine/cascade_fields_gl.h), from which the
// host bounds the bicubic interpolant the displaced march reads (shading/cascade_fields.h,
// cascade_bounds_from_maxima): the maxima of the five differences at each point
// (kernel/cascade_chain.glsl, cascade_height_differences, the host's text too), the
// differences wrapping around the periodic patch. Reduced in shared memory, then one
// atomicMax per workgroup and value: non-negative floats order as their bits do, so the
// result does not depend on the order (deterministic).
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 0) readonly buffer FieldA {
  vec4 field_a[];
};
layout(std430, binding = 1) buffer Maxima {
  uint maxima[];
};

uniform int n;     // the grid's side
uniform int base;  // this cascade's first of its 5 maxima

shared uint local_max[5];

float h(int i, int j) {
  return field_a[((j + n) % n) * n + (i + n) % n].y;
}

void main() {
  if (gl_LocalInvocationIndex < 5u) local_max[gl_LocalInvocationIndex] = 0u;
  barrier();
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  if (id.x < n && id.y < n) {
    int i = id.x, j = id.y;
    CascadeHeightDifferences d = cascade_height_differences(
        h(i, j), h(i + 1, j), h(i - 1, j), h(i, j + 1), h(i, j - 1), h(i + 1, j + 1));
    atomicMax(local_max[0], floatBitsToUint(d.height));
    atomicMax(local_max[1], floatBitsToUint(d.step_x));
    atomicMax(local_max[2], floatBitsToUint(d.step_z));
    atomicMax(local_max[3], floatBitsToUint(d.second));
    atomicMax(local_max[4], floatBitsToUint(d.mixed));
  }
  barrier();
  if (gl_LocalInvocationIndex < 5u)
    atomicMax(maxima[base + int(gl_LocalInvocationIndex)], local_max[gl_LocalInvocationIndex]);
}
