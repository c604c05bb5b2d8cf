#pragma once
// Per-16-px-block agreement of several renders (independent seeds) with a high-spp reference: each
// block's mean over the renders within 5 standard errors (from the renders' spread plus the
// reference's own, refSpp/spp times smaller in variance; floor 0.1 % of the block) plus `relSlack`
// of the block (a known bias allowance, 0 for unbiased estimators).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/integrator.h"

namespace rc::test {

inline double blockMean(const Image& img, int width, int bx, int by, int c) {
  double sum = 0.0;
  for (int y = by * 16; y < by * 16 + 16; ++y)
    for (int x = bx * 16; x < bx * 16 + 16; ++x) sum += img.pixels[static_cast<size_t>(y) * width + x][c];
  return sum / 256.0;
}

// The largest excess of |mean − reference| over what is allowed, over the blocks and channels
// (≤ 0: all agree); each failing block is reported as a test failure when `expect`.
inline double blockExcess(const std::vector<Image>& renders, int spp, const Image& ref, int refSpp, int width,
                          int height, double relSlack, const std::string& what, bool expect) {
  const double n = static_cast<double>(renders.size());
  double worst = -INFINITY;
  for (int by = 0; by < height / 16; ++by)
    for (int bx = 0; bx < width / 16; ++bx)
      for (int c = 0; c < 3; ++c) {
        double mean = 0.0, sq = 0.0;
        for (const Image& img : renders) mean += blockMean(img, width, bx, by, c) / n;
        for (const Image& img : renders) sq += std::pow(blockMean(img, width, bx, by, c) - mean, 2.0);
        const double variance = sq / (n - 1.0);
        const double se = std::sqrt(variance / n + variance * spp / refSpp);
        const double r = blockMean(ref, width, bx, by, c);
        if (!(r > 0.0)) continue;
        const double allowed = 5.0 * std::max(se, 1e-3 * r) + relSlack * r;
        worst = std::max(worst, std::fabs(mean - r) - allowed);
        if (expect) EXPECT_LT(std::fabs(mean - r), allowed) << what << " block " << bx << "," << by << " channel " << c;
      }
  return worst;
}

inline void expectBlocksAgree(const std::vector<Image>& renders, int spp, const Image& ref, int refSpp, int width,
                              int height, double relSlack, const std::string& what) {
  blockExcess(renders, spp, ref, refSpp, width, height, relSlack, what, true);
}

}  // namespace rc::test
