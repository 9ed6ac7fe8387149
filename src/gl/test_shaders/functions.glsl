// Built-in functions on float inputs, for the precision test: out[4i + f] is function f of
// in[i] (sin, exp, sqrt, a * b + c with a = in[i], b = 1 + 1/3, c = -in[i]).
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In {
  float inputs[];
};
layout(std430, binding = 1) writeonly buffer Out {
  float outputs[];
};
uniform float b;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(inputs.length())) return;
  float x = inputs[i];
  outputs[4u * i + 0u] = sin(x);
  outputs[4u * i + 1u] = exp(x);
  outputs[4u * i + 2u] = sqrt(abs(x));
  outputs[4u * i + 3u] = x * b - x;
}
