// The options of all methods, as one plain struct that the CLI fills and the methods
// read. Each field documents the flag that sets it.
#pragma once

#include <cstdint>
#include <string>

namespace sg {

// --samples SxSxT: S_x by S_y stratified jittered positions in the pixel times T
// stratified jittered times in the shutter.
struct SampleCounts {
  int sx = 8, sy = 8, st = 8;
  long total() const { return static_cast<long>(sx) * sy * st; }
};

// Parses "SxSxT" (e.g. "8x8x8", "6x6x1"); throws sg::Error naming `flag`.
SampleCounts parse_sample_counts(const std::string& text, const std::string& flag);
std::string to_string(const SampleCounts& s);

// --precision float|double: the precision the shading kernel computes in on the CPU
// (kernel/: double by default; float is what a GPU computes).
enum class Precision { float32, float64 };

// The aliasing waves' NDF: uniform (Eq. 3), per-pixel (Eqs. 4-7, Appendix A), or by the
// footprint mode (per_pixel_ndf below).
enum class NdfMode { automatic, uniform, per_pixel };
enum class FallbackMode { quadrature, riemann };
// The pixel-footprint term (docs/method.md): none (the paper's method), the footprint as
// a Gaussian added to the RDF, or the exact swept parallelogram for pixels without
// aliasing waves.
enum class FootprintMode { none, gaussian, exact };
// Where the map from normals to the light plane is linearised (kernel/rdf.glsl): at the
// light (exact to first order in the disk's radius), at the NDF's centre (the paper, Eqs.
// 11-16), or by the footprint mode (rdf_at_light below).
enum class RdfAnchor { automatic, light, centre };

// The choices of the paper's method (Podee et al. 2021) that `staa` and `staa-temporal`
// expose; defaults chosen by measurement (docs/results.md).
struct StaaOptions {
  int segments = 1;  // --segments K: sub-arcs of the shutter interval (Sec. 3.5)
  // --ndf uniform|per-pixel: Eq. 3 or Eqs. 4-7 with Appendix A; by default the paper's
  // per-pixel NDF with `--footprint none`, else the uniform (docs/aliasing-study.md).
  NdfMode ndf = NdfMode::automatic;
  // --ndf-mean shift|none: whether the per-pixel mean slope of the aliasing waves (B)
  // shifts the NDF's centre.
  bool ndf_mean_shift = true;
  // --kernels 1|3|5|9: circular Gaussians for the RDF (Sec. 3.5, 3.6); 0: the default of
  // the footprint mode (rdf_kernels below).
  int kernels = 0;
  // --elongation-threshold X: ratio of the RDF's axes past which the fallback renders
  // (0: the paper's threshold, the kernel count, for 3, 5 or 9 kernels; none for the
  // circular approximation of Sec. 3.5, which the paper uses at any elongation).
  double elongation_threshold = 0;
  FallbackMode fallback = FallbackMode::quadrature;  // --fallback quadrature|riemann
  // --fallback-time path|current: the fallback averaged along the reflection path, or at
  // the display time only (the paper: "We ignore the temporal integration in our fallback").
  bool fallback_along_path = true;
  int riemann_cells = 32;  // --riemann-cells N (per disk diameter)
  // --alias-start, --alias-end: the transition region of Eq. 20 in cycles per pixel;
  // negative: the default of the footprint mode (alias_range below).
  double alias_start = -1;
  double alias_end = -1;
  bool nyquist_max_axis = true;                       // --nyquist max|norm (shading/aliasing.h)
  FootprintMode footprint = FootprintMode::gaussian;  // --footprint none|gaussian|exact
  // --curvature-limit X: with a footprint term, a resolved wave whose slope departs from
  // its linearisation across the pixel by more than X disk radii of reflection is handed
  // to the aliasing set (0: never).
  double curvature_limit = 0;
  // --fold-cells X: a lit pixel where a resolved wave's slope departs from its tangent by
  // more than X disk radii across it is shaded as the mean of its four quarters (0: never).
  double fold_cells = 0;
  // --wave-remainder sum|each: the waves that certainly alias fully in a pixel add their
  // covariance from precomputed sums in O(1) (sum), or are visited one by one (each).
  bool wave_remainder = true;
  // --smooth-terms ndf|mean: Fresnel times the sky, and the sea, integrated over the
  // pixel's normals (the NDF, the footprint and the path; kernel/smooth_terms.glsl) or
  // taken at the centre normal (the paper).
  bool smooth_over_normals = true;
  // --smooth-cells N: the pixel cut into N x N cells (1 to 3), each with its own Gaussian of
  // normals, for the smooth terms (kernel/ndf.glsl, box_cells_add).
  int smooth_cells = 3;
  // --rdf-at light|centre: the map from normals to the light plane linearised at the light
  // (kernel/rdf.glsl, light_anchor) or at the NDF's centre (the paper, Eqs. 11-16); by
  // default the paper's with `--footprint none`, which is the paper's method, else the light.
  RdfAnchor rdf_at = RdfAnchor::automatic;
};

// The transition region of Eq. 20 that a `staa` variant uses. Defaults by measurement
// (docs/method.md, "Defaults"): the paper's 0.2 to 0.5 cycles per pixel (Sec. 4) for
// `--footprint none`, which is the paper's method; 0.3 to 0.8 with a footprint term, which
// integrates a resolved wave over the pixel and so can keep it longer.
struct AliasRange {
  double start, end;
};
inline constexpr AliasRange kPaperAliasRange{0.2, 0.5};
inline constexpr AliasRange kFootprintAliasRange{0.3, 0.8};
inline AliasRange alias_range(const StaaOptions& o) {
  const AliasRange d = o.footprint == FootprintMode::none ? kPaperAliasRange : kFootprintAliasRange;
  return {o.alias_start >= 0 ? o.alias_start : d.start, o.alias_end >= 0 ? o.alias_end : d.end};
}

// The RDF's circular kernels that a `staa` variant uses (docs/method.md, "Defaults"): the
// paper's nine (Sec. 3.6) for `--footprint none`, which is the paper's method; three with a
// footprint term, whose images are within 0.4% of nine's and whose GL programs run a third
// of the path integrals (docs/benchmarks.md, "Three kernels by default").
inline constexpr int kPaperKernels = 9;
inline constexpr int kFootprintKernels = 3;
inline int rdf_kernels(const StaaOptions& o) {
  if (o.kernels > 0) return o.kernels;
  return o.footprint == FootprintMode::none ? kPaperKernels : kFootprintKernels;
}

// Whether a `staa` variant takes the per-pixel NDF (docs/method.md, "Defaults").
inline bool per_pixel_ndf(const StaaOptions& o) {
  if (o.ndf != NdfMode::automatic) return o.ndf == NdfMode::per_pixel;
  return o.footprint == FootprintMode::none;
}

// Whether a `staa` variant linearises the RDF at the light (docs/method.md, "The RDF
// linearised at the light"; measured in docs/aliasing-study.md).
inline bool rdf_at_light(const StaaOptions& o) {
  if (o.rdf_at != RdfAnchor::automatic) return o.rdf_at == RdfAnchor::light;
  return o.footprint != FootprintMode::none;
}

// `lean` (methods/lean.h): LEAN mapping of the waves' slopes.
enum class LeanFilter { trilinear, aniso };
struct LeanOptions {
  int size = 4096;                            // --lean-size: texels per side (power of two)
  double far = 0;                             // --lean-far: map's far distance, m (0: auto)
  LeanFilter filter = LeanFilter::trilinear;  // --lean-filter trilinear|aniso
  int max_aniso = 16;                         // --lean-max-aniso: probes per pixel (aniso)
};

// `taa` (methods/taa.h): temporal anti-aliasing with jitter, reprojection and clamping.
enum class TaaClamp { none, minmax, variance };
enum class TaaHistoryFilter { bilinear, catmull_rom };
// What the motion vectors follow: the camera's motion and the surface's (full), or the
// surface's alone, as if the camera stood still (surface: the contrast that shows what
// reprojecting a moving camera buys; the same images on a fixed camera).
enum class TaaMotion { full, surface };
struct TaaOptions {
  int jitter_count = 8;                                   // --taa-jitter-count: Halton cycle
  double alpha = 0.1;                                     // --taa-alpha: current frame's weight
  double gamma = 1.0;                                     // --taa-gamma: variance box width
  TaaClamp clamp = TaaClamp::variance;                    // --taa-clamp none|minmax|variance
  TaaHistoryFilter history = TaaHistoryFilter::bilinear;  // --taa-history bilinear|catmull-rom
  int warmup = 16;                                        // --taa-warmup: frames before F
  TaaMotion motion = TaaMotion::full;                     // --taa-motion full|surface
};

// microspec (methods/microspec.h).
enum class MicrospecArea {
  exact,   // the area the disk shares with the reflection space, exactly
  approx,  // each shape cut by one line where it meets the other (microspec.h)
};
struct MicrospecOptions {
  MicrospecArea area = MicrospecArea::exact;  // --microspec-area exact|approx
};

// specaa (methods/specaa.h).
enum class SpecaaDerivatives {
  quad,      // finite differences in 2x2 pixel quads, as ddx_fine/ddy_fine on a GPU
  analytic,  // ray differentials and the Hessian of the height field
};
// The filtering kernel's shape (kernel/specaa.glsl).
enum class KernelShape {
  rect,  // per axis of the tangent frame, the bounding rectangle of the derivatives (fwidth)
  full,  // the 2x2 covariance of the derivatives
};
struct SpecaaOptions {
  double sigma2 = 0.25;                                     // --specaa-sigma2: kernel variance
  double kappa = 0.18;                                      // --specaa-kappa: clamp of 2 sigma^2
  SpecaaDerivatives derivatives = SpecaaDerivatives::quad;  // --specaa-derivatives
  KernelShape kernel = KernelShape::rect;                   // --specaa-kernel rect|full
};

// bruneton (methods/bruneton.h).
enum class BrunetonFresnel {
  fit,       // Eq. 26, the paper's fit
  integral,  // Eq. 24 by quadrature
};
struct BrunetonOptions {
  double n_min = 1.0, n_max = 2.5;  // --bruneton-nmin, --bruneton-nmax (Sec. 7.1)
  double min_variance = 2e-5;       // --bruneton-min-variance: slope-variance clamp (Sec. 5.1)
  BrunetonFresnel fresnel = BrunetonFresnel::fit;  // --bruneton-fresnel fit|integral
};

class PathTableStore;

struct MethodOptions {
  // The path tables that `staa` reads (shading/path_table_store.h): created by the caller
  // (the CLI's run, a test, an embedding engine) and outliving the methods made with these
  // options. No flag; `staa` refuses to be made without them.
  const PathTableStore* path_tables = nullptr;
  SampleCounts samples{8, 8, 8};  // --samples, for reference and supersample
  bool samples_given = false;     // false: each method's default (reference: its own)
  int batches = 2;                // --batches, for reference
  // reference: render only this batch of the `batches` (its samples exactly those of a
  // render of all batches), or all of them (-1). No flag: a study's reference renders
  // each batch of a frame as its own unit of work (report/plan.h).
  int only_batch = -1;
  bool adaptive = true;                      // --adaptive on|off, for reference
  int quiet_samples = 1;                     // --quiet-samples N, for reference
  uint64_t seed = 0;                         // --seed: the sampling streams (rng.h)
  Precision precision = Precision::float64;  // --precision, for the kernel methods
  // --intersect-tolerance X: displaced water, the kernel methods' intersection leaves out
  // the shortest waves whose amplitudes sum to at most X pixels of the ray's footprint
  // (kernel/intersect.glsl); 0: every wave. Taken only when given
  // (`intersect_tolerance_given`); else each method's own (intersect_tolerance_for).
  double intersect_tolerance = 0.25;  // staa's: kDefaultIntersectTolerance (catalog.cpp)
  bool intersect_tolerance_given = false;
  // --cascades fields|waves: point, supersample with T = 1, staa-temporal, staa and specaa
  // (flat and displaced water), lean and bruneton (flat water) shade a scene's lattice
  // cascades from their FFT fields (kernel/cascade_grid.glsl, cascade_fields.glsl; a cost
  // per pixel fixed by the cascades), or as their lattice's sines among the waves (exact,
  // a cost that follows the waves). The other methods (reference, supersample with T > 1,
  // taa, microspec) take the sines.
  bool cascade_fields = true;
  // --cascade-fft gpu|host: where the GL engine transforms the cascades' fields each frame:
  // on the GPU, into the wave buffer (gl_engine/cascade_fields_gl.h), or on the host,
  // uploaded with the waves (shading/cascade_fields.h). The CPU engine transforms them on
  // the host.
  bool cascade_fft_gpu = true;
  StaaOptions staa;
  LeanOptions lean;
  TaaOptions taa;
  MicrospecOptions microspec;
  SpecaaOptions specaa;
  BrunetonOptions bruneton;
};

// The intersection tolerance `method` takes on displaced water (pixels; kernel/intersect.glsl),
// per pixel (`supersample` and `reference` divide it per sample cell): --intersect-tolerance
// where given, else 0 (every wave) for the methods whose samples are the scene's radiance
// along a ray (reference, supersample, point, staa-temporal) and kDefaultIntersectTolerance
// for `staa`, whose one hit per pixel is its filter's centre. A wave left out of a
// sample's intersection loses the weighting by projected area that a displaced surface
// gives its slopes in a grazing view (kernel/visible_normals.glsl), whatever its
// amplitude: `point` with 0.25 was 2.6% dark on tests/scenes/displaced-far-sky.json
// (docs/ocean.md); in `staa` the aliasing normals carry that weight, and its centre hit
// moves by at most the tolerance's share of the footprint.
double intersect_tolerance_for(const MethodOptions& o, const std::string& method);

// Checks the values of the method flags; throws sg::Error naming the flag
// ("--specaa-sigma2: must be > 0").
void validate(const MethodOptions& options);

}  // namespace sg
