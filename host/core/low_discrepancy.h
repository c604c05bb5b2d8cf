#pragma once
// Padded, Owen-scrambled Sobol points for pixel samples (the `ldsampler`).
//
// Each pair of dimensions (0,1), (2,3), … of a pixel's samples is the 2-D Sobol (0,2)-sequence —
// van der Corput in x, the second Sobol dimension in y — Owen-scrambled with a seed of its own
// (Burley 2020, "Practical Hash-based Owen Scrambling"), and its sample index is shuffled by a
// nested scramble of its own so that pairs are independent of each other ("padding"). Why: the
// samples of one pixel then stratify every pair jointly — the first 2^m samples of a pair form a
// (0,m,2)-net — so low-dimensional integrands (pixel footprint, the point on an area light, a BSDF
// direction) converge faster than with independent samples, while each sample stays uniformly
// distributed (the estimate stays unbiased) and pairs stay independent.
#include <cstdint>

namespace rc::ld {

inline uint32_t reverseBits(uint32_t x) {
  x = (x << 16) | (x >> 16);
  x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
  return x;
}

// Laine–Karras style hash on bit-reversed values: every step changes a bit only as a function of
// the bits below it (adding a seed carries upward, multiplying by an even constant shifts upward),
// which is exactly what a nested (Owen) permutation of the reversed digits needs.
inline uint32_t lowToHighHash(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// Owen scrambling of a 32-bit fixed-point value in [0,1): each digit is flipped as a function of
// the digits above it. Applied to a sample index it is a nested shuffle: indices [0, 2^m) map onto
// one aligned block of 2^m indices, so the first 2^m shuffled samples are still a full net.
inline uint32_t owenScramble(uint32_t x, uint32_t seed) {
  return reverseBits(lowToHighHash(reverseBits(x), seed));
}

inline uint32_t sobolDim0(uint32_t i) { return reverseBits(i); }

// Second Sobol dimension: generator matrix = Pascal's triangle mod 2, one direction vector per
// index bit (v_{k+1} = v_k ^ (v_k >> 1)). The bit-serial form is the definition (and the test's
// reference); samples use the byte-table form: the map is linear over GF(2), so the result is the
// XOR of four 256-entry tables, one per index byte (shuffled indices have high bits set, where
// the bit loop would run 32 times per draw).
inline uint32_t sobolDim1BitSerial(uint32_t i) {
  uint32_t r = 0;
  for (uint32_t v = 1u << 31; i != 0; i >>= 1, v ^= v >> 1)
    if (i & 1u) r ^= v;
  return r;
}

// Tables of the bit-reversed second dimension (what the scramble below consumes).
struct SobolDim1Tables {
  uint32_t byte[4][256];
  SobolDim1Tables() {
    for (uint32_t b = 0; b < 4; ++b)
      for (uint32_t x = 0; x < 256; ++x) byte[b][x] = reverseBits(sobolDim1BitSerial(x << (8 * b)));
  }
};

inline uint32_t sobolDim1Reversed(uint32_t i) {
  static const SobolDim1Tables t;
  return t.byte[0][i & 255u] ^ t.byte[1][(i >> 8) & 255u] ^ t.byte[2][(i >> 16) & 255u] ^ t.byte[3][i >> 24];
}

// Per-dimension scramble seeds from the pixel's seed (a 32-bit integer hash, "lowbias32").
inline uint32_t dimensionSeed(uint32_t pixelSeed, uint32_t dim, uint32_t salt) {
  uint32_t h = pixelSeed ^ (dim * 0x9E3779B9u + salt * 0x85EBCA6Bu);
  h ^= h >> 16; h *= 0x7feb352du; h ^= h >> 15; h *= 0x846ca68bu; h ^= h >> 16;
  return h;
}

// The definition: dimension `dim` of sample `index` of the sequence seeded by `pixelSeed` (one
// seed per pixel), as a 32-bit fixed-point number in [0, 1): shuffle the index with the pair's
// seed, take the Sobol dimension, Owen-scramble it with the dimension's seed.
inline uint32_t paddedSobolReference(uint32_t index, uint32_t dim, uint32_t pixelSeed) {
  const uint32_t shuffled = owenScramble(index, dimensionSeed(pixelSeed, dim >> 1, 0x5u));
  const uint32_t raw = (dim & 1u) ? sobolDim1BitSerial(shuffled) : sobolDim0(shuffled);
  return owenScramble(raw, dimensionSeed(pixelSeed, dim, 0xA7u));
}

// The two scramble seeds of a draw: its pair's index shuffle and its own digit scramble.
inline uint32_t pairSeed(uint32_t pixelSeed, uint32_t pair) { return dimensionSeed(pixelSeed, pair, 0x5u); }
inline uint32_t drawSeed(uint32_t pixelSeed, uint32_t dim) { return dimensionSeed(pixelSeed, dim, 0xA7u); }

// The same, in the form samples use (a test checks equality): owenScramble = rev∘hash∘rev, and
// rev(sobolDim0(s)) = s, so most bit reversals cancel; the index arrives reversed (once per
// sample), the pair's shuffled index is shared by its two dimensions, and the seeds come from
// pairSeed / drawSeed (or a pixel's PixelDimensionSeeds, which holds them).
inline uint32_t shuffledIndex(uint32_t reversedIndex, uint32_t pairSeed) {
  return reverseBits(lowToHighHash(reversedIndex, pairSeed));
}
inline uint32_t paddedSobolShuffled(uint32_t shuffled, uint32_t dim, uint32_t drawSeed) {
  const uint32_t reversedRaw = (dim & 1u) ? sobolDim1Reversed(shuffled) : shuffled;
  return reverseBits(lowToHighHash(reversedRaw, drawSeed));
}

// The seeds of the first kSeededDims dimensions of one pixel's sequence: the same for all of the
// pixel's samples, so a pixel hashes them once and its samples read them instead of hashing two
// seeds per draw.
inline constexpr uint32_t kSeededDims = 24;
struct PixelDimensionSeeds {
  uint32_t pixelSeed = 0;
  uint32_t pair[kSeededDims / 2];
  uint32_t dim[kSeededDims];
  explicit PixelDimensionSeeds(uint32_t seed = 0) : pixelSeed(seed) {
    for (uint32_t p = 0; p < kSeededDims / 2; ++p) pair[p] = pairSeed(seed, p);
    for (uint32_t d = 0; d < kSeededDims; ++d) dim[d] = drawSeed(seed, d);
  }
};

}  // namespace rc::ld
