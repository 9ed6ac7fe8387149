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
struct TaaOptions {
  int jitter_count = 8;                                   // --taa-jitter-count: Halton cycle
  double alpha = 0.1;                                     // --taa-alpha: current frame's weight
  double gamma = 1.0;                                     // --taa-gamma: variance box width
  TaaClamp clamp = TaaClamp::variance;                    // --taa-clamp none|minmax|variance
  TaaHistoryFilter history = TaaHistoryFilter::bilinear;  // --taa-history bilinear|catmull-rom
  int warmup = 16;                                        // --taa-warmup: frames before F
};

struct MethodOptions {
  SampleCounts samples{8, 8, 8};  // --samples, for reference and supersample
  uint64_t seed = 0;              // --seed: the sampling streams (rng.h)
  LeanOptions lean;
  TaaOptions taa;
};

}  // namespace sg
