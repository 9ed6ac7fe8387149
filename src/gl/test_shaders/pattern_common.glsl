// The known pattern of the pattern test: exact in float (small integers and quarters), so
// the image and buffer read back compare with ==.
vec4 pattern(ivec2 p) {
  return vec4(float(p.x), float(p.y), float(p.x * 1000 + p.y), 0.25 * float(p.x - p.y));
}

uint pattern_word(uint index) {
  return index * 2654435761u ^ 0x9e3779b9u;
}
