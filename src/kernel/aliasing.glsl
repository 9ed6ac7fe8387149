// Spatial-aliasing detection (Podee et al. 2021, Sec. 3.2 and 3.7, Eq. 20).
//
// A wave's phase p = a x + b z changes across the screen at the rate
//     dp/dpx = k . dX/dpx,   dp/dpy = k . dX/dpy     (k = (a, b), X = (x, z) on the water)
// so its projected frequency is |grad_screen p| / 2 pi cycles per pixel. On a square pixel
// grid the Nyquist region is |f_x|, |f_y| < 1/2, so by default the frequency is the larger
// axis frequency ("max"); the Euclidean norm ("norm") is the alternative. Eq. 20's soft
// classification gives the aliasing fraction
//     alpha = clamp((f - f_start) / (f_end - f_start), 0, 1).
// Wave i then contributes alpha A_i to the aliasing waves (the NDF) and (1 - alpha) A_i
// to the resolved ones (the reflection path).

// Projected frequency (cycles per pixel) of wave vector k for a pixel whose footprint
// maps image-plane offsets to horizontal offsets by J (columns dX/dpx, dX/dpy).
SG_FN real projected_frequency(vec2 k, mat2 J, bool max_norm) {
  real fx = abs(dot(k, J[0]));
  real fy = abs(dot(k, J[1]));
  real rad = max_norm ? max(fx, fy) : sqrt(fx * fx + fy * fy);
  return rad * kInvTwoPi;
}

// Eq. 20.
SG_FN real alias_fraction(real frequency, real start, real end) {
  return clamp((frequency - start) / (end - start), 0.0, 1.0);
}

// Under a moving camera the pixel's footprint sweeps over the shutter: the parallelogram
// X + J [-1/2, 1/2]^2 convolved with the water point's motion X_0 -> X_K, the segment
// X + Delta [-1/2, 1/2] (Delta = X_K - X_0; docs/method.md, "A moving camera"). The phase
// then changes along three axes of the swept box, k . J_0, k . J_1 and k . Delta, and the
// projected frequency is that of all three (max or norm as above): a wave whose phase
// turns through a large part of a cycle over the motion is not followed by the path's
// K + 1 instants any more than one across the pixel is by its centre.
SG_FN real swept_frequency(vec2 k, mat2 J, vec2 delta, bool max_norm) {
  real fx = abs(dot(k, J[0]));
  real fy = abs(dot(k, J[1]));
  real fm = abs(dot(k, delta));
  real rad = max_norm ? max(max(fx, fy), fm) : sqrt(fx * fx + fy * fy + fm * fm);
  return rad * kInvTwoPi;
}
