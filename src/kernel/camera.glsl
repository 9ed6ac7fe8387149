// Camera rays and their differentials (scene spec; Igehy 1999, "Tracing ray
// differentials"). The direction through image-plane point (px, py) is not normalised: it
// is linear in (px, py), so its derivatives are constant.
//
// The camera at a time (format /3): position and look-at point interpolated linearly
// between the keys around that time (held at the first and last key outside them), and
// the basis from them and `up` as for a fixed camera (camera_basis: the host's CameraModel
// builds every camera through it too). The host evaluates the scene's keys through
// camera_pose_between as well (scene/camera_path.h): one formula.

// The orthonormal frame of a camera at `position` looking at `look_at` with unit `up`:
// columns forward, right, up (right = forward x up normalised, up' = right x forward).
SG_FN mat3 camera_basis(vec3 position, vec3 look_at, vec3 up) {
  vec3 forward = normalize(look_at - position);
  vec3 right = normalize(cross(forward, up));
  return mat3(forward, right, cross(right, forward));
}

// A camera's pose: its position and look-at point.
struct CameraPose {
  vec3 position;
  vec3 look_at;
};

// The pose at time t between keys (t0, p0, a0) and (t1, p1, a1), t0 < t1: linear, held at
// the nearer key outside [t0, t1]. Written a + s (b - a), and b itself at s = 1, so that
// equal keys and the keys' own times give the keys' values exactly.
SG_FN CameraPose camera_pose_between(real t0, vec3 p0, vec3 a0, real t1, vec3 p1, vec3 a1, real t) {
  real s = clamp((t - t0) / (t1 - t0), 0.0, 1.0);
  CameraPose c;
  c.position = s >= 1.0 ? p1 : p0 + s * (p1 - p0);
  c.look_at = s >= 1.0 ? a1 : a0 + s * (a1 - a0);
  return c;
}

// The pose at offset dt from the display time along the frame's keys (count >= 2).
SG_FN CameraPose camera_pose_at(IN(CameraKeys) k, real dt) {
  int i = 0;
  for (int q = 1; q + 1 < kMaxCameraKeys; ++q) {
    if (q + 1 < k.count && dt >= k.time[q]) i = q;
  }
  return camera_pose_between(k.time[i], k.position[i], k.look_at[i], k.time[i + 1],
                             k.position[i + 1], k.look_at[i + 1], dt);
}

// The camera at offset dt from the display time: Frame.camera when it stands still over
// the shutter, else the pose along the keys with its basis (image size and field of view
// unchanged). The web page's prelude sets SG_FIXED_CAMERA: it renders fixed cameras only.
SG_FN Camera camera_at(IN(Frame) f, real dt) {
#ifndef SG_FIXED_CAMERA
  if (f.camera_keys.count > 0) {
    CameraPose p = camera_pose_at(f.camera_keys, dt);
    mat3 b = camera_basis(p.position, p.look_at, f.camera_keys.up);
    Camera c = f.camera;
    c.position = p.position;
    c.forward = b[0];
    c.right = b[1];
    c.up = b[2];
    return c;
  }
#endif
  return f.camera;
}

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

// Where a direction meets the image plane (camera_direction's inverse, up to the
// direction's length): the image-plane point (px, py) in pixel units, and whether the
// direction points into the image plane's half-space at all (seen).
struct ImagePoint {
  bool seen;
  vec2 p;
};

SG_FN ImagePoint camera_project(IN(Camera) c, vec3 dir) {
  ImagePoint q;
  real fw = dot(dir, c.forward);
  q.seen = fw > 0.0;
  q.p = vec2(0.0);
  if (!q.seen) return q;
  real x = dot(dir, c.right) / fw / c.half_w;  // -1..1 across the image
  real y = dot(dir, c.up) / fw / c.half_h;
  q.p = vec2((x + 1.0) * 0.5 * c.width, (1.0 - y) * 0.5 * c.height);
  return q;
}

// Transfer of a ray differential onto a surface (Igehy 1999, Eq. 10 for a plane): for a
// ray p(s) = o + s d hitting, at parameter s, a surface whose tangent plane has normal m,
// the hit point moves by s (dd - d (m . dd) / (m . d)) when the direction moves by dd.
SG_FN vec3 transfer_differential(vec3 d, real s, vec3 dd, vec3 m) {
  return s * (dd - d * (dot(m, dd) / dot(m, d)));
}
