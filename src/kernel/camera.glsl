// Camera rays and their differentials (scene spec; Igehy 1999, "Tracing ray
// differentials"). The direction through image-plane point (px, py) is not normalised: it
// is linear in (px, py), so its derivatives are constant.

SG_FN vec3 camera_direction(IN(Camera) c, real px, real py) {
  return c.forward + ((2.0 * px / c.width) - 1.0) * c.half_w * c.right +
         (1.0 - (2.0 * py / c.height)) * c.half_h * c.up;
}
SG_FN vec3 camera_ddir_dpx(IN(Camera) c) {
  return (2.0 * c.half_w / c.width) * c.right;
}
SG_FN vec3 camera_ddir_dpy(IN(Camera) c) {
  return (-2.0 * c.half_h / c.height) * c.up;
}

// Transfer of a ray differential onto a surface (Igehy 1999, Eq. 10 for a plane): for a
// ray p(s) = o + s d hitting, at parameter s, a surface whose tangent plane has normal m,
// the hit point moves by s (dd - d (m . dd) / (m . d)) when the direction moves by dd.
SG_FN vec3 transfer_differential(vec3 d, real s, vec3 dd, vec3 m) {
  return s * (dd - d * (dot(m, dd) / dot(m, d)));
}
