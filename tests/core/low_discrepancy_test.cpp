// The ldsampler's padded Owen-scrambled Sobol points: the fast form equals the definition, every
// pair of dimensions is a (0,m,2)-net for the first 2^m samples of any pixel, pairs are
// independent, samples are uniform (unbiased), and Rng hands out the prefix as documented.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "core/low_discrepancy.h"
#include "core/rng.h"

namespace rc {
namespace {

double unit(uint32_t v) { return v * (1.0 / 4294967296.0); }

TEST(LowDiscrepancy, TableFormEqualsBitSerialDefinition) {
  Rng r(7, 3);
  for (int k = 0; k < 20000; ++k) {
    const uint32_t i = k < 1024 ? static_cast<uint32_t>(k) : r.nextUint();
    EXPECT_EQ(ld::reverseBits(ld::sobolDim1BitSerial(i)), ld::sobolDim1Reversed(i)) << i;
    EXPECT_EQ(ld::reverseBits(ld::reverseBits(i)), i);
  }
  // The first points of the second dimension, by hand (v1 = .1, v2 = .11, v3 = .101 in binary):
  // 0, 1/2, 3/4, 1/4, 5/8, 1/8.
  const double expect[] = {0.0, 0.5, 0.75, 0.25, 0.625, 0.125};
  for (uint32_t i = 0; i < 6; ++i) EXPECT_DOUBLE_EQ(unit(ld::sobolDim1BitSerial(i)), expect[i]);
}

TEST(LowDiscrepancy, RngPrefixEqualsTheDefinition) {
  for (uint32_t seed : {0u, 1u, 0xDEADBEEFu})
    for (uint32_t index = 0; index < 300; index += 7) {
      Rng rng(1, 2);
      rng.useLowDiscrepancy(seed, index, 12);
      for (uint32_t d = 0; d < 12; ++d) EXPECT_EQ(rng.nextUint(), ld::paddedSobolReference(index, d, seed));
      // Past the prefix: the PCG stream, exactly as without a prefix.
      Rng plain(1, 2);
      EXPECT_EQ(rng.nextUint(), plain.nextUint());
    }
}

// A pixel's hashed seed table gives the same prefix as the seed hashed per draw, whatever mix of
// next2D (which skips to a pair's start) and single draws a sample makes, and the same PCG after.
TEST(LowDiscrepancy, PixelSeedTableGivesTheSameDraws) {
  for (uint32_t seed : {0u, 1u, 0xDEADBEEFu}) {
    const ld::PixelDimensionSeeds table(seed);
    for (uint32_t index = 0; index < 300; index += 7) {
      Rng hashed(3, 4), seeded(3, 4);
      hashed.useLowDiscrepancy(seed, index, Rng::kPixelLowDiscrepancyDims);
      seeded.useLowDiscrepancy(table, index);
      EXPECT_EQ(seeded.lowDiscrepancySeed(), seed);
      for (int k = 0; k < 16; ++k) {
        if (k % 3 == 1) {
          const Vec2 a = hashed.next2D(), b = seeded.next2D();
          ASSERT_EQ(a.x, b.x);
          ASSERT_EQ(a.y, b.y);
        } else {
          ASSERT_EQ(hashed.nextUint(), seeded.nextUint()) << "seed " << seed << " index " << index << " draw " << k;
        }
      }
      EXPECT_EQ(hashed.lowDiscrepancyDim(), seeded.lowDiscrepancyDim());
    }
    // Dimension by dimension against the definition.
    Rng rng(1, 2);
    rng.useLowDiscrepancy(table, 5);
    for (uint32_t d = 0; d < Rng::kPixelLowDiscrepancyDims; ++d) EXPECT_EQ(rng.nextUint(), ld::paddedSobolReference(5, d, seed));
    Rng plain(1, 2);
    EXPECT_EQ(rng.nextUint(), plain.nextUint());
  }
}

// Every elementary interval of area 2^-m (2^a × 2^(m-a) cells) holds exactly one of the first 2^m
// points of each pair — for every pixel seed.
TEST(LowDiscrepancy, EveryPairIsANetForPowersOfTwo) {
  for (uint32_t seed : {0u, 12345u, 0x9E3779B9u})
    for (uint32_t pair = 0; pair < 6; ++pair)
      for (int m = 0; m <= 8; ++m) {
        const uint32_t n = 1u << m;
        for (int a = 0; a <= m; ++a) {
          std::set<std::pair<uint32_t, uint32_t>> cells;
          for (uint32_t i = 0; i < n; ++i) {
            const uint32_t x = ld::paddedSobolReference(i, 2 * pair, seed);
            const uint32_t y = ld::paddedSobolReference(i, 2 * pair + 1, seed);
            const uint32_t cx = a == 0 ? 0 : x >> (32 - a), cy = m - a == 0 ? 0 : y >> (32 - (m - a));
            cells.insert({cx, cy});
          }
          ASSERT_EQ(cells.size(), n) << "seed " << seed << " pair " << pair << " m " << m << " a " << a;
        }
      }
}

// Scrambled points are uniform: the mean over many pixels of f(x, y) = x·y² is 1/6 for every pair
// and sample index (this is what keeps the estimator unbiased), and different pairs of one sample
// are uncorrelated (padding).
TEST(LowDiscrepancy, UniformAndPairsIndependent) {
  const int pixels = 20000;
  for (uint32_t index : {0u, 1u, 5u, 63u}) {
    for (uint32_t pair = 0; pair < 4; ++pair) {
      double sum = 0.0, cross = 0.0;
      for (int p = 0; p < pixels; ++p) {
        const uint32_t seed = static_cast<uint32_t>(hashMix(p, 99));
        const double x = unit(ld::paddedSobolReference(index, 2 * pair, seed));
        const double y = unit(ld::paddedSobolReference(index, 2 * pair + 1, seed));
        const double z = unit(ld::paddedSobolReference(index, 2 * pair + 2, seed));
        sum += x * y * y;
        cross += (x - 0.5) * (z - 0.5);
      }
      // Standard deviation of x·y² is ≈ 0.18, of (x−½)(z−½) 1/12: 5σ bounds.
      EXPECT_NEAR(sum / pixels, 1.0 / 6.0, 5 * 0.18 / std::sqrt(double(pixels))) << index << " " << pair;
      EXPECT_NEAR(cross / pixels, 0.0, 5 * (1.0 / 12.0) / std::sqrt(double(pixels))) << index << " " << pair;
    }
  }
}

// Why the sampler exists: within one pixel, 64 stratified samples estimate a smooth 2-D integral
// far better than 64 independent ones.
TEST(LowDiscrepancy, BeatsIndependentSamplingOnASmooth2DIntegral) {
  auto f = [](float x, float y) { return std::exp(-3.0 * x) * (1.0 + std::sin(5.0 * y)); };
  const double exact = (1.0 - std::exp(-3.0)) / 3.0 * (1.0 + (1.0 - std::cos(5.0)) / 5.0);
  double errLd = 0.0, errIndep = 0.0;
  const int pixels = 400, n = 64;
  for (int p = 0; p < pixels; ++p) {
    double sLd = 0.0, sIn = 0.0;
    for (int i = 0; i < n; ++i) {
      Rng ldRng(hashMix(p, i), 1);
      ldRng.useLowDiscrepancy(static_cast<uint32_t>(hashMix(p, 7)), static_cast<uint32_t>(i), 8);
      ldRng.nextFloat();  // an odd draw first: next2D must still start on a pair
      const Vec2 u = ldRng.next2D();
      sLd += f(u.x, u.y);
      Rng in(hashMix(p, i), 1);
      const float ux = in.nextFloat();
      sIn += f(ux, in.nextFloat());
    }
    errLd += std::pow(sLd / n - exact, 2);
    errIndep += std::pow(sIn / n - exact, 2);
  }
  EXPECT_LT(errLd * 20.0, errIndep) << "ld mse " << errLd / pixels << " independent mse " << errIndep / pixels;
}

}  // namespace
}  // namespace rc
