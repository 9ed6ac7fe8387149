// The kernel's interface with the host: what is built once per frame and passed in
// (the camera, the light, the frame's settings; the tables' shapes; each method's
// parameters) and what a pixel returns. Only types and integer constants: the host's C++
// includes this file alone to fill and read these structs in either precision
// (kernel/kernel_types.h), and a port sees here everything it must provide.
//
// Coordinates are camera-relative: the camera sits at (0, height, 0) and every
// horizontal position is measured from the camera's (x, z), so that float keeps its
// digits near the camera. Each wave's phase at the camera's (x, z) and the frame's
// display time is reduced modulo 2 pi in double on the host (waves.glsl): float cannot
// hold c t at t = 1 hour (c t ~ 1e4 rad), but it holds a x + b z + theta0 over the visible
// water. Instants of the shutter are reached by rotating the phases by c (end - t), also
// precomputed per wave on the host.

// Compile-time caps: sub-arcs of the shutter, circular kernels, time samples per pixel.
// The preludes set SG_MAX_SEGMENTS: 32 in C++; in GLSL the engine compiles each shader
// with the cap its method needs (arrays of the cap's size cost registers on a GPU).
const int kMaxSegments = SG_MAX_SEGMENTS;
const int kMaxKernels = 9;
const int kMaxTimeSamples = 64;
// `reference`: independent batches per pixel (reference.glsl).
const int kMaxBatches = 8;

// The pinhole camera (scene/camera.h): the ray through image-plane point (px, py) is
// forward + (2 px / width - 1) half_w right + (1 - 2 py / height) half_h up.
struct Camera {
  vec3 position;  // (0, height above the water at rest, 0)
  vec3 forward;
  vec3 right;
  vec3 up;
  real half_w;  // tan(hfov / 2)
  real half_h;  // tan(vfov / 2)
  real width;   // image size in pixels
  real height;
};

// The light disk (scene/light.h): directions within `radius` of the unit vector L, and
// the light plane's frame e1, e2 (e1 horizontal, e2 = L x e1).
struct Light {
  vec3 L;
  vec3 e1;
  vec3 e2;
  real radius;  // angular radius, radians
  real cos_radius;
  real sin_radius;
  real tan_radius;  // the disk's radius on the light plane
  real chord2;      // 4 sin^2(radius / 2): |r - L|^2 for a unit r on the disk's rim
  bool visible;     // drawn in the sky for camera rays that miss the water
};

// A camera that moves during the frame's shutter (format /3; camera.glsl): its keys over
// the shutter, the first at its opening (time -duration) and the last at its end (time
// 0), with the scene's keys in between; positions and look-at points camera-relative (as
// Frame.camera, which holds the camera at the shutter's end). count 0: the camera stands
// still over the shutter, and every ray is Frame.camera's.
const int kMaxCameraKeys = 8;
struct CameraKeys {
  int count;                  // 0, or 2 to kMaxCameraKeys
  real time[kMaxCameraKeys];  // offsets from the display time, increasing
  vec3 position[kMaxCameraKeys];
  vec3 look_at[kMaxCameraKeys];
  vec3 up;  // the scene's camera.up, unit length
};

// Everything per frame that is not per wave (the waves are in the wave buffer, waves.glsl).
struct Frame {
  Camera camera;  // at the display time (the shutter's end)
  CameraKeys camera_keys;
  Light light;
  int fresnel;        // 0: none, 1: Schlick (scene spec 4)
  bool displaced;     // geometry "displaced" (else "flat")
  bool sky_gradient;  // the sky's weight splits between zenith and horizon
  real sky_exponent;
  int wave_count;
  int wave_stride;       // texels per wave in the wave buffer
  real amplitude_bound;  // sum |A_i| (the slab that holds the surface)
  real slope_bound;      // sum |A_i| |k_i| (a bound on |grad h|)
  // Displaced water: the intersection may leave out the shortest waves whose amplitudes
  // sum to at most this many pixels' worth of the ray's footprint (intersect.glsl); 0:
  // every wave.
  real intersect_tolerance;
  real duration;  // the shutter interval is [display time - duration, display time]
  int segments;   // K: the path's instants t_k = end - duration (K - k) / K, k = 0..K
  // The reference on flat water (reference.glsl): W >= 1 windows of the shutter, each
  // duration / W long, integrated exactly with K sub-intervals; the wave buffer's rotations
  // are those of the last window (t_k = end - (duration / W) (K - k) / K). 1 elsewhere.
  int windows;
  // Lattice cascades shaded from their FFT fields (cascade_fields.glsl): how many, and the
  // wave buffer texel where their headers start; 0: none (a cascade ocean's lattices are
  // then among the waves, or the scene has none).
  int cascade_count;
  int cascade_base;
  int frame;   // the frame's index (for the sampling streams)
  uvec2 seed;  // the sampling seed, as a 64-bit word (rng.glsl)
};

// K as the kernel takes it: the constant in a GLSL program compiled for its frames' K
// (SG_EXACT_SEGMENTS, gl_engine/kernel_program.h: every entry but the reference, whose
// frames pick K up to the cap), else the frame's. The pixel's arrays indexed by K (the
// path's instants, centres, gradients) then stay in registers, where an index known only
// at run time sends them through memory (wave_terms.glsl, path_segments; on llvmpipe a
// third of `staa`'s frame on `smooth`, docs/benchmarks.md).
SG_FN int frame_segments(IN(Frame) f) {
#ifndef SG_EXACT_SEGMENTS
  return f.segments;
#else
  return kMaxSegments;
#endif
}

// The path tables' shapes (path_table.glsl, shading/path_table.h).
struct PathTableInfo {
  int n_distance;
  int n_u;
  int n_v;
  int n_sigma;
  real sigma_min;
  real sigma_max;
  real log_q;     // log of the slice ratio: log(sigma_max / sigma_min) / (n_sigma - 2)
  real extent_k;  // R(sigma) = 1 + extent_k sigma
};

// The fitted kernel table's shape (kernel_fit.glsl).
struct KernelFitInfo {
  int intervals;      // rows per count, minus one
  real max_ratio;     // the last row's ratio
  int first_solved3;  // the first fitted row of each count's table
  int first_solved5;
  int first_solved9;
};

// `staa`'s options (methods/options.h, StaaOptions; staa.glsl).
struct StaaParams {
  bool per_pixel_ndf;         // --ndf per-pixel (else uniform)
  bool ndf_mean_shift;        // --ndf-mean shift
  int kernels;                // --kernels 1|3|5|9
  real elongation_threshold;  // axis ratio past which the fallback renders
  bool fallback_riemann;      // --fallback riemann (else quadrature)
  bool fallback_along_path;   // --fallback-time path (else current)
  int riemann_cells;
  real alias_start;  // Eq. 20's transition, cycles per pixel
  real alias_end;
  bool nyquist_max;      // --nyquist max (else norm)
  int footprint;         // 0 none, 1 gaussian, 2 exact (CPU only: host finishes)
  real curvature_limit;  // 0: off
  real fold_cells;  // --fold-cells X: disk radii past which a lit pixel is cut in 2 x 2 (0: off)
  bool wave_remainder;  // the fully aliasing waves' sum in O(1) (else one by one; staa.glsl)
  int smooth_cells;     // Fresnel, sky and sea over the normals of n x n cells (0: at the mean)
  bool rdf_at_light;    // --rdf-at light: Phi linearised at the light (else at the NDF's centre)
};

// `specaa`'s options (methods/options.h, SpecaaOptions; specaa.glsl).
struct SpecaaParams {
  real sigma2;       // --specaa-sigma2: the pixel filter's variance, pixels^2
  real kappa;        // --specaa-kappa: the clamp of the kernel's roughness alpha^2
  bool full_kernel;  // --specaa-kernel full (else rect)
  bool quad;         // --specaa-derivatives quad (else analytic)
};

// What `specaa` knows of one image-plane point (specaa.glsl, specaa_sample): the water
// point and its footprint, the height gradient there and the projected half vector.
// A quad's pixels exchange h_perp (the CPU's tiles, the GL engine's shared memory).
struct SpecaaSample {
  bool hit;
  bool at_camera;  // the camera under the displaced surface: no footprint (Footprint)
  vec3 point;      // camera-relative
  vec3 view;
  vec3 dp_dpx;
  vec3 dp_dpy;
  vec2 g;       // (dh/dx, dh/dz) at the point
  vec2 h_perp;  // the half vector in the normal's shading frame, (h . t, h . b)
};

// `microspec`'s options (methods/options.h, MicrospecOptions; microspec.glsl).
struct MicrospecParams {
  bool exact_area;  // --microspec-area exact (else approx)
};

// `bruneton`'s options (methods/options.h, BrunetonOptions; bruneton.glsl).
struct BrunetonParams {
  real n_min;             // --bruneton-nmin: w = 0 at lambda / l <= n_min (Sec. 3.2)
  real n_max;             // --bruneton-nmax: w = 1 at lambda / l >= n_max
  real min_variance;      // --bruneton-min-variance: the slope variances' clamp (Sec. 5.1)
  bool fresnel_integral;  // --bruneton-fresnel integral (Eq. 24; else the fit, Eq. 26)
};

// `lean` (lean.glsl): where the frame's LEAN map lies and what shading adds to it, from the
// host (methods/lean.h: the map's region, the waves it holds and those it leaves out).
struct LeanParams {
  vec2 origin;    // camera-relative (x, z) of the map's corner, texel coordinates (0, 0)
  real texel;     // metres per level-0 texel
  int size;       // N: level 0's texels a side (a power of two)
  int levels;     // L + 1: N, N / 2, ..., 1
  bool empty;     // no water within the map's reach: every lookup is the border
  bool aniso;     // --lean-filter aniso (else trilinear)
  int max_aniso;  // --lean-max-aniso: the anisotropic filter's most probes
  vec3 border;    // the border's second moments (xx, zz, xz), its mean slope 0
  vec3 base;      // the slope covariance (xx, xz, zz, ndf.glsl's order) of the waves the
                  // map leaves out
};

// `taa`'s frame (taa.glsl): where its sample lies in the pixel and what its motion vectors
// need of the frame before, from the host (methods/taa.h).
struct TaaParams {
  vec2 jitter;               // the sample's offset from the pixel centre, pixels (taa_jitter)
  real dt_prev;              // the previous frame's display time minus this frame's
  bool prev_camera_differs;  // the previous frame's camera is not this one (--taa-motion full)
  Camera prev_camera;        // that camera, in this frame's camera-relative coordinates
};

// A motion that puts the reprojected point off any image: no history.
const real kTaaNoHistory = 1.0e30;

// `taa`'s sample of a pixel (taa.glsl, taa_sample): its weights and its motion vector
// (image-plane pixels, current minus previous position).
struct TaaSample {
  vec4 weights;
  vec2 motion;
};

// A pixel resolved (taa.glsl, taa_resolve_pixel): its channels (those past the image's count
// 0), and whether a blend was not finite (its channel then shows the current sample: the
// method's fallback).
struct TaaResolved {
  vec4 value;
  bool fallback;
};

// `taa`'s resolve (taa.glsl, taa_resolve_pixel): the options (methods/options.h, TaaOptions)
// and the image's size.
const int kTaaClampNone = 0;
const int kTaaClampMinmax = 1;
const int kTaaClampVariance = 2;
struct TaaResolveParams {
  ivec2 size;        // the image's width and height, pixels
  int channels;      // 1 (grey) or 3 (RGB)
  real alpha;        // --taa-alpha: the current sample's share of the blend
  real gamma;        // --taa-gamma: the variance box's half-width in standard deviations
  int clamp;         // --taa-clamp: kTaaClampNone, kTaaClampMinmax or kTaaClampVariance
  bool catmull_rom;  // --taa-history catmull-rom (else bilinear)
};

// The reflection at one pixel corner (microspec.glsl, microspec_corner): the water point
// seen through an image-plane point at the display time, its normal, the mirrored view.
// Neighbouring pixels share their corners (the CPU's tiles, the GL engine's shared memory).
struct CornerReflection {
  bool hit;
  bool at_camera;  // the camera under the surface: the hit is the camera itself
  vec3 r;          // unit reflected direction
  vec3 v;          // unit view direction (towards the camera)
};

// A pixel's four corners, in the order (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1).
struct PixelCorners {
  CornerReflection c[4];
};

// A baseline's pixel (`specaa`, `microspec`, `bruneton`): its weights, and whether its model failed
// there (the camera under the surface, a shading that is not finite) so that it took the
// centre ray's radiance.
struct FallbackResult {
  vec4 weights;
  bool fallback;
};

// `reference` and `supersample`: samples per pixel (sampling.glsl).
struct SampleCounts {
  int sx;
  int sy;
  int nt;              // times, at most kMaxTimeSamples
  bool time_at_frame;  // one sample time, the display time
};

// `reference` (reference.glsl): per batch S_x x S_y spatial strata of T samples each
// (on displaced water T time strata), `batches` independent batches. With `adaptive`, a
// pixel whose pilot finds it far from the light and the horizon (reference_pixel_busy)
// takes quiet_sx x quiet_sy strata instead.
struct ReferenceParams {
  int sx;
  int sy;
  int nt;
  int batches;      // 2 to kMaxBatches (1 for one batch of a study's reference)
  int first_batch;  // the first batch rendered: its samples are those of batch first_batch of
                    // a render of all batches (the draws of the batches before are skipped)
  bool adaptive;
  int quiet_sx;
  int quiet_sy;
  real margin;  // the pilot's margin, in units of the reflection's spread and step
};

// A reference pixel: the mean weights and each batch's (for the variance of the mean).
struct ReferenceResult {
  vec4 weights;
  vec4 batch[kMaxBatches];
  bool busy;  // the pilot's verdict (true without `adaptive`)
};

// The RDF's centres on the light plane at the path's instants.
struct StaaPath {
  vec2 centre[kMaxSegments + 1];
  bool valid[kMaxSegments + 1];
};

// The result of a pixel, with what tests and diagnostics look at.
// `staa`'s smooth terms over the pixel's normals (smooth_terms.glsl): the expectations of
// F 1{above}, F z 1{above}, F h 1{above} and 1{above}, with z and h the sky's zenith and
// horizon shares at r.y (z + h = 1, each summed for its own digits).
struct SmoothTerms {
  real f_above;
  real f_zenith;
  real f_horizon;
  real above;
};

struct StaaResult {
  vec4 weights;
  bool hit;
  bool aliasing;       // some alpha > 0
  bool temporal;       // step 3: the temporal method, exactly
  bool fallback;       // past the elongation threshold
  bool exact_pending;  // --footprint exact on a pixel without aliasing waves: the host
                       // integrates the swept parallelogram (D and the path are in
                       // exact_D and the StaaPath)
  real in_light;
  real below;
  real fresnel;
  real sky_y;  // the height of the centre reflection (the sky's zenith-horizon split)
  mat2 exact_D;
  bool terms_valid;  // the smooth terms integrated over the normals (smooth_cells > 0)
  SmoothTerms terms;
};
