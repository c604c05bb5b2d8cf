#pragma once
// PCG32 (O'Neill 2014): small, fast, statistically good, and seekable by stream so that every
// pixel/record gets its own deterministic sequence independent of thread scheduling.
//
// A pixel sample may put a low-discrepancy prefix in front of the stream (useLowDiscrepancy): its
// first dimensions then come from the pixel's padded Owen-scrambled Sobol sequence
// (core/low_discrepancy.h), the rest from PCG. Consumers draw 2-D quantities with next2D(), which
// starts them on a Sobol pair so both coordinates are stratified jointly.
#include <cstdint>

#include "core/low_discrepancy.h"
#include "core/math.h"

namespace rc {

class Rng {
 public:
  explicit Rng(uint64_t seed = 0, uint64_t stream = 0) { seedWith(seed, stream); }

  // Restarts this Rng as a plain PCG stream (any low-discrepancy prefix dropped first, so that the
  // seeding draws below are PCG's whatever the Rng was used for before).
  void seedWith(uint64_t seed, uint64_t stream) {
    ldSeed_ = ldIndex_ = ldReversedIndex_ = ldDim_ = ldDims_ = 0;
    ldSeeds_ = nullptr;
    ldShuffledValid_ = false;
    state_ = 0u;
    inc_ = (stream << 1u) | 1u;
    nextUint();
    state_ += seed;
    nextUint();
  }

  // Draws number `firstDim`, `firstDim`+1, … of sample `index` of the padded Sobol sequence seeded
  // by `seed` until draw `dims` (exclusive), then continues with this PCG stream.
  void useLowDiscrepancy(uint32_t seed, uint32_t index, uint32_t dims, uint32_t firstDim = 0) {
    ldSeed_ = seed;
    ldIndex_ = index;
    ldReversedIndex_ = ld::reverseBits(index);
    ldDim_ = firstDim;
    ldDims_ = dims;
    ldShuffledValid_ = false;
    ldSeeds_ = nullptr;
  }
  // The same prefix (dimensions [0, kPixelLowDiscrepancyDims) of sample `index`) with the seeds
  // read from the pixel's table, which must outlive this Rng's low-discrepancy draws.
  void useLowDiscrepancy(const ld::PixelDimensionSeeds& seeds, uint32_t index) {
    useLowDiscrepancy(seeds.pixelSeed, index, kPixelLowDiscrepancyDims);
    ldSeeds_ = &seeds;
  }
  // Dimensions a pixel sample takes from its low-discrepancy sequence: the camera, then for the
  // first few vertices a light sample and a BSDF sample; deeper vertices gain little from it.
  static constexpr uint32_t kPixelLowDiscrepancyDims = 24;
  static_assert(kPixelLowDiscrepancyDims <= ld::kSeededDims, "a pixel's table holds the seeds of its prefix");
  // Where the low-discrepancy prefix stands (dim == dims: used up or never set), so that a later
  // stage of the same sample can continue it with useLowDiscrepancy(seed, index, dims, dim).
  uint32_t lowDiscrepancySeed() const { return ldSeed_; }
  uint32_t lowDiscrepancyIndex() const { return ldIndex_; }
  uint32_t lowDiscrepancyDim() const { return ldDim_; }
  uint32_t lowDiscrepancyDims() const { return ldDims_; }

  uint32_t nextUint() {
    if (ldDim_ < ldDims_) {
      // Both dimensions of a pair use the same shuffled index: computed at the pair's first.
      const uint32_t dim = ldDim_++;
      if (!(dim & 1u) || !ldShuffledValid_)
        ldShuffled_ = ld::shuffledIndex(ldReversedIndex_, ldSeeds_ ? ldSeeds_->pair[dim >> 1] : ld::pairSeed(ldSeed_, dim >> 1));
      ldShuffledValid_ = !(dim & 1u);
      return ld::paddedSobolShuffled(ldShuffled_, dim, ldSeeds_ ? ldSeeds_->dim[dim] : ld::drawSeed(ldSeed_, dim));
    }
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  // Uniform in [0, 1): 24 random mantissa bits, never returns 1.
  float nextFloat() { return static_cast<float>(nextUint() >> 8) * (1.0f / 16777216.0f); }
  // A 2-D sample; inside the low-discrepancy prefix it starts on a new Sobol pair.
  Vec2 next2D() {
    if ((ldDim_ & 1u) && ldDim_ < ldDims_) ++ldDim_;
    const float x = nextFloat();
    return Vec2(x, nextFloat());
  }
  double nextDouble() {
    const uint64_t hi = nextUint(), lo = nextUint();
    return static_cast<double>(((hi << 21) ^ lo) & ((1ULL << 53) - 1)) * (1.0 / 9007199254740992.0);
  }

 private:
  uint64_t state_ = 0, inc_ = 1;
  uint32_t ldSeed_ = 0, ldIndex_ = 0, ldDim_ = 0, ldDims_ = 0;
  uint32_t ldReversedIndex_ = 0;
  uint32_t ldShuffled_ = 0;       // shuffled index of the current pair
  bool ldShuffledValid_ = false;  // ldShuffled_ belongs to ldDim_'s pair (set at its even dim)
  const ld::PixelDimensionSeeds* ldSeeds_ = nullptr;  // the pixel's hashed seeds, or none: hash per draw
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
