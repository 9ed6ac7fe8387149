// The web page's one vertex shader: a triangle that covers the viewport (vertices 0, 1, 2
// at (-1, -1), (3, -1), (-1, 3)), so every pass is one fragment per output texel.
void main() {
  vec2 p = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
  gl_Position = vec4(p * 4.0 - 1.0, 0.0, 1.0);
}
