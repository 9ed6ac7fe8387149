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

struct MethodOptions {
  SampleCounts samples{8, 8, 8};  // --samples, for reference and supersample
  uint64_t seed = 0;              // --seed: the sampling streams (rng.h)
};

}  // namespace sg
