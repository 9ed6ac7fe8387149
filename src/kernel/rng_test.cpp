// The kernel's sampling streams (kernel/rng.glsl, 64-bit words as uvec2) against the host's
// PCG32 and SplitMix64 (math/rng.h): the same numbers, bit for bit.
#include <gtest/gtest.h>

#include "kernel/kernel_double.h"
#include "math/rng.h"

namespace sg {
namespace {

kd::uvec2 words(uint64_t x) {
  return kd::uvec2(static_cast<uint32_t>(x), static_cast<uint32_t>(x >> 32));
}
uint64_t joined(kd::uvec2 w) {
  return uint64_t(w.y) << 32 | w.x;
}

TEST(KernelRng, SixtyFourBitWordsMatchNativeArithmetic) {
  Pcg32 rng(7, 9);
  for (int k = 0; k < 10000; ++k) {
    const uint64_t a = uint64_t(rng.next_u32()) << 32 | rng.next_u32();
    const uint64_t b = uint64_t(rng.next_u32()) << 32 | rng.next_u32();
    ASSERT_EQ(joined(kd::u64_add(words(a), words(b))), a + b);
    ASSERT_EQ(joined(kd::u64_mul(words(a), words(b))), a * b);
    const int n = 1 + k % 63;
    ASSERT_EQ(joined(kd::u64_shr(words(a), n)), a >> n) << n;
    ASSERT_EQ(joined(kd::u64_shl(words(a), n)), a << n) << n;
    ASSERT_EQ(joined(kd::splitmix64(words(a))), splitmix64(a));
  }
}

TEST(KernelRng, PixelStreamsAreTheHostsBitForBit) {
  for (uint64_t seed : {0ull, 1ull, 0x123456789abcdefull}) {
    for (int frame : {-3, 0, 5, 1 << 20}) {
      for (int i : {0, 17, 639}) {
        for (int j : {0, 1, 359}) {
          Pcg32 host = pixel_rng(seed, frame, i, j);
          kd::Pcg32 kernel = kd::pixel_rng(words(seed), frame, i, j);
          for (int q = 0; q < 8; ++q)
            ASSERT_EQ(kd::pcg32_next(kernel), host.next_u32());
          for (int q = 0; q < 8; ++q)
            ASSERT_EQ(kd::pcg32_uniform(kernel), host.uniform());
        }
      }
    }
  }
}

TEST(KernelRng, AdvanceEqualsThatManyDraws) {
  // pcg32_advance(n) leaves the stream where n calls of pcg32_next would (the reference's
  // passes start mid-stream with it), for n of every size up to 2^32 - 1.
  for (uint32_t n : {0u, 1u, 2u, 3u, 7u, 64u, 1000u, 4097u, 65535u, 123457u}) {
    kd::Pcg32 a = kd::pixel_rng(words(99), 3, 5, 8);
    kd::Pcg32 b = a;
    kd::pcg32_advance(a, n);
    for (uint32_t k = 0; k < n; ++k)
      kd::pcg32_next(b);
    ASSERT_EQ(joined(a.state), joined(b.state)) << n;
    ASSERT_EQ(kd::pcg32_next(a), kd::pcg32_next(b)) << n;
  }
  // Advancing in two steps equals one step of the sum (a wrap of 2^32 included).
  kd::Pcg32 a = kd::pixel_rng(words(1), 0, 0, 0), b = a;
  kd::pcg32_advance(a, 0xfffffff0u);
  kd::pcg32_advance(a, 0x20u);
  kd::pcg32_advance(b, 0x10u);
  for (int k = 0; k < 4; ++k)
    kd::pcg32_advance(b, 0x40000000u);
  EXPECT_EQ(joined(a.state), joined(b.state));
}

}  // namespace
}  // namespace sg
