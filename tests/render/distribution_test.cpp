// Distribution1D's guided search returns the bin of the inverse-CDF definition (upper_bound on the
// cumulative table) for every u, including u on a bin edge, zero-weight bins and lopsided weights.
#include "render/distribution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/rng.h"

namespace rc {
namespace {

// The definition: the bin whose cumulative range [c_i, c_{i+1}) holds u, skipping empty bins.
size_t referenceBin(const std::vector<double>& weights, float u) {
  std::vector<double> cdf(weights.size() + 1, 0.0);
  for (size_t i = 0; i < weights.size(); ++i) cdf[i + 1] = cdf[i] + std::max(0.0, weights[i]);
  for (double& c : cdf) c /= cdf.back();
  cdf.back() = 1.0;
  size_t i = static_cast<size_t>(std::upper_bound(cdf.begin(), cdf.end(), double(u)) - cdf.begin());
  i = std::min(i == 0 ? 0 : i - 1, weights.size() - 1);
  while (i + 1 < weights.size() && cdf[i + 1] - cdf[i] == 0.0) ++i;
  return i;
}

void expectSameBins(const std::vector<double>& weights) {
  const Distribution1D d(weights);
  Rng rng(11);
  for (int k = 0; k < 20000; ++k) {
    const float u = rng.nextFloat();
    ASSERT_EQ(d.sample(u), referenceBin(weights, u)) << "u = " << u;
  }
  // Every bin edge and its float neighbours.
  double c = 0.0, total = 0.0;
  for (double w : weights) total += std::max(0.0, w);
  for (double w : weights) {
    c += std::max(0.0, w);
    const float edge = static_cast<float>(c / total);
    for (float u : {std::nextafter(edge, 0.0f), edge, std::nextafter(edge, 1.0f)})
      if (u >= 0.0f && u < 1.0f) ASSERT_EQ(d.sample(u), referenceBin(weights, u)) << "u = " << u;
  }
  EXPECT_EQ(d.sample(0.0f), referenceBin(weights, 0.0f));
  EXPECT_EQ(d.sample(0.99999994f), referenceBin(weights, 0.99999994f));
}

TEST(Distribution1D, GuidedSearchIsTheInverseCdf) {
  expectSameBins({1.0});
  expectSameBins({1.0, 2.0, 3.0, 4.0});
  expectSameBins({0.0, 0.0, 5.0, 0.0, 1.0, 0.0, 0.0, 2.0, 0.0});  // empty bins between and at the ends
  std::vector<double> lopsided(1000, 1e-6);  // one bin holds nearly all: many bins share a slice
  lopsided[500] = 1.0;
  expectSameBins(lopsided);
  std::vector<double> ramp(777);
  for (size_t i = 0; i < ramp.size(); ++i) ramp[i] = double(i * i % 97);
  expectSameBins(ramp);
}

TEST(Distribution1D, RemappedIsUniformWithinTheBin) {
  const Distribution1D d({1.0, 3.0});
  float r = -1.0f;
  EXPECT_EQ(d.sample(0.125f, &r), 0u);
  EXPECT_NEAR(r, 0.5f, 1e-6f);
  EXPECT_EQ(d.sample(0.625f, &r), 1u);
  EXPECT_NEAR(r, 0.5f, 1e-6f);
}

}  // namespace
}  // namespace rc
