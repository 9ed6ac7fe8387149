// Deterministic random numbers for sampling: one independent stream per (seed, frame,
// pixel), so a pixel's samples never depend on the thread that renders it or on the order
// of the tiles. Same inputs, same seed, same bytes.
//
// The generator is PCG32 (O'Neill 2014, "PCG: A family of simple fast space-efficient
// statistically good algorithms for random number generation", the pcg32 XSH-RR output
// function); the stream key is mixed with SplitMix64 (Steele, Lea, Flood 2014). Both are a
// few lines and fixed by their papers, so other renderers can reproduce a stream bit for
// bit; std::uniform_real_distribution is implementation-defined and cannot.
#pragma once

#include <cstdint>

namespace sg {

inline uint64_t splitmix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

class Pcg32 {
 public:
  Pcg32(uint64_t seed, uint64_t stream) : inc_((stream << 1u) | 1u) {
    next_u32();
    state_ += seed;
    next_u32();
  }

  uint32_t next_u32() {
    uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
  }

  // Uniform in [0, 1): the top 53 bits of two outputs.
  double uniform() {
    uint64_t hi = next_u32(), lo = next_u32();
    return static_cast<double>(((hi << 32) | lo) >> 11) * 0x1.0p-53;
  }

 private:
  uint64_t state_ = 0;
  uint64_t inc_;
};

// The stream of pixel (i, j) of frame `frame` under `seed`.
inline Pcg32 pixel_rng(uint64_t seed, int64_t frame, int i, int j) {
  uint64_t key = splitmix64(seed ^ splitmix64(static_cast<uint64_t>(frame) * 0x100000001b3ULL));
  key = splitmix64(
      key ^ (static_cast<uint64_t>(static_cast<uint32_t>(j)) << 32 | static_cast<uint32_t>(i)));
  return Pcg32(key, splitmix64(key + 1));
}

}  // namespace sg
