#pragma once
// PCG32 (O'Neill 2014): small, fast, statistically good, and seekable by stream so that every
// pixel/record gets its own deterministic sequence independent of thread scheduling.
#include <cstdint>

namespace rc {

class Rng {
 public:
  explicit Rng(uint64_t seed = 0, uint64_t stream = 0) { seedWith(seed, stream); }

  void seedWith(uint64_t seed, uint64_t stream) {
    state_ = 0u;
    inc_ = (stream << 1u) | 1u;
    nextUint();
    state_ += seed;
    nextUint();
  }

  uint32_t nextUint() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  // Uniform in [0, 1): 24 random mantissa bits, never returns 1.
  float nextFloat() { return static_cast<float>(nextUint() >> 8) * (1.0f / 16777216.0f); }
  double nextDouble() {
    const uint64_t hi = nextUint(), lo = nextUint();
    return static_cast<double>(((hi << 21) ^ lo) & ((1ULL << 53) - 1)) * (1.0 / 9007199254740992.0);
  }

 private:
  uint64_t state_ = 0, inc_ = 1;
};

// Mixes several integers into one well-distributed 64-bit value (for per-pixel streams).
inline uint64_t hashMix(uint64_t a, uint64_t b = 0, uint64_t c = 0) {
  uint64_t h = a * 0x9E3779B97F4A7C15ULL;
  h ^= (b + 0x632BE59BD9B4E019ULL) * 0xD6E8FEB86659FD93ULL;
  h ^= c * 0xC2B2AE3D27D4EB4FULL;
  h ^= h >> 31; h *= 0xBF58476D1CE4E5B9ULL; h ^= h >> 27; h *= 0x94D049BB133111EBULL; h ^= h >> 31;
  return h;
}

}  // namespace rc
