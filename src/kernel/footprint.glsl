// How a pixel maps onto the water (scene/footprint.h): the point seen through an
// image-plane point, the view direction there, and the derivatives of that point with
// respect to the image-plane coordinates (the camera's ray differentials transferred to
// the surface, Igehy 1999). To first order the pixel square [i, i+1] x [j, j+1] covers the
// parallelogram centre + u dp_dpx + v dp_dpy, u, v in [-1/2, 1/2], on the water.
// On displaced water the differentials are transferred to the tangent plane at the hit.

struct Footprint {
  bool hit;
  vec3 point;   // on the water (camera-relative)
  vec3 view;    // unit, from the point towards the camera
  vec3 dp_dpx;  // d point / d px
  vec3 dp_dpy;  // d point / d py
  real distance;
};

// The footprint of image-plane point (px, py) at dt from the display time; `displaced`
// chooses the height field or the water at rest (y = 0, Bruneton's projected grid).
SG_FN Footprint pixel_footprint(IN(WaveBuffer) waves, IN(Frame) f, real px, real py, real dt,
                                bool displaced) {
  Footprint fp;
  fp.hit = false;
  fp.point = vec3(0.0);
  fp.view = vec3(0.0, 1.0, 0.0);
  fp.dp_dpx = vec3(0.0);
  fp.dp_dpy = vec3(0.0);
  fp.distance = 0.0;
  vec3 d = camera_direction(f.camera, px, py);  // unnormalised: linear in (px, py)
  vec3 o = f.camera.position;
  real len = length(d);
  RayHit hit;
  if (displaced) {
    hit = intersect_displaced(waves, f, o, d / len, dt);
  } else {
    hit = intersect_flat(o, d);
  }
  if (!hit.hit) return fp;
  // intersect_displaced works on the unit direction: its parameter in d's units.
  real s = displaced ? hit.s / len : hit.s;
  vec3 m = vec3(0.0, 1.0, 0.0);
  if (displaced) {
    vec2 g = water_gradient(waves, f, hit.point.x, hit.point.z, dt);
    if (f.cascade_count > 0)
      g += cascade_gradient(waves, f, frame_segments(f), hit.point.x, hit.point.z);
    m = vec3(-g.x, 1.0, -g.y);
  }
  fp.hit = true;
  fp.point = hit.point;
  vec3 to_camera = o - hit.point;
  fp.distance = length(to_camera);
  // With the camera under the displaced surface the ray hits at the camera itself (the
  // spec's convention): the view is the ray's reverse.
  fp.view = fp.distance > 0.0 ? to_camera / fp.distance : -(d / len);
  fp.dp_dpx = transfer_differential(d, s, camera_ddir_dpx(f.camera), m);
  fp.dp_dpy = transfer_differential(d, s, camera_ddir_dpy(f.camera), m);
  return fp;
}

// The 2x2 map from image-plane offsets (px, py) to horizontal offsets (x, z).
SG_FN mat2 footprint_xz_jacobian(IN(Footprint) fp) {
  return mat2(vec2(fp.dp_dpx.x, fp.dp_dpx.z), vec2(fp.dp_dpy.x, fp.dp_dpy.z));
}
