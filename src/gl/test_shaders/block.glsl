// Copies a std140 uniform block into an SSBO member by member, for the layout test.
layout(local_size_x = 1) in;
layout(std140, binding = 0) uniform Frame {
  vec4 camera;
  vec3 light;
  float radius;
  vec2 size;
  int waves;
  uint seed;
  float phases[3];
}
frame;
layout(std430, binding = 1) buffer Copy {
  float copy[];
};

void main() {
  for (int k = 0; k < 4; ++k)
    copy[k] = frame.camera[k];
  for (int k = 0; k < 3; ++k)
    copy[4 + k] = frame.light[k];
  copy[7] = frame.radius;
  copy[8] = frame.size.x;
  copy[9] = frame.size.y;
  copy[10] = float(frame.waves);
  copy[11] = float(frame.seed);
  for (int k = 0; k < 3; ++k)
    copy[12 + k] = frame.phases[k];
}
