// Writes pattern() into an RGBA32F image and pattern_word() into an SSBO, one invocation
// per pixel, skipping those outside the image (the grid is rounded up to the groups).
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba32f, binding = 0) uniform writeonly image2D image;
layout(std430, binding = 1) buffer Words {
  uint words[];
};
uniform ivec2 size;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= size.x || p.y >= size.y) return;
  imageStore(image, p, pattern(p));
  uint index = uint(p.y * size.x + p.x);
  words[index] = pattern_word(index);
}
