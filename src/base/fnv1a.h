// FNV-1a, 64 bits (Fowler, Noll and Vo): the hash of the frame cache's keys and of the
// shading kernel's fingerprint. Not cryptographic; stable across runs and machines.
#pragma once

#include <cstdint>
#include <string_view>

namespace sg {

inline constexpr uint64_t kFnv1aBasis = 0xcbf29ce484222325ull;

// The hash of `bytes` continuing from `h` (kFnv1aBasis to start).
inline uint64_t fnv1a64(std::string_view bytes, uint64_t h = kFnv1aBasis) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ull;  // FNV prime
  }
  return h;
}

}  // namespace sg
