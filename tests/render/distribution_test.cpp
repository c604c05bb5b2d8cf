// Distribution1D's guided search returns the bin of the inverse-CDF definition (upper_bound on the
// cumulative table) for every u, including u on a bin edge, zero-weight bins and lopsided weights;
// PiecewiseConstant2D's flat table returns the cell of a marginal and per-row Distribution1Ds;
// sampleLinear draws from the linear density it claims (a histogram against linearPdf).
#include "render/distribution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
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
  // Tables of up to Distribution1D::kSmallBins bins are searched by counting: both sides of it.
  static_assert(Distribution1D::kSmallBins == 8, "the small tables below straddle kSmallBins");
  expectSameBins({0.0, 1.0});
  expectSameBins({1.0, 0.0});
  expectSameBins({3.0, 1.0});
  expectSameBins({0.0, 0.0, 1.0});
  expectSameBins({1e-7, 1.0, 1e-7});
  expectSameBins({0.0, 2.0, 0.0, 0.0, 1.0, 0.0, 3.0, 0.0});       // eight: counted
  expectSameBins({0.0, 2.0, 0.0, 0.0, 1.0, 0.0, 3.0, 0.0, 1.0});  // nine: guided
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

// The definition of the 2-D sample: the row from a Distribution1D of the row sums, the column from
// a Distribution1D of that row, both with their remapped values.
void expectSameCells(const std::vector<double>& weights, size_t rows, size_t cols) {
  const PiecewiseConstant2D flat(weights, rows, cols);
  EXPECT_EQ(flat.rows(), rows);
  EXPECT_EQ(flat.cols(), cols);
  std::vector<double> rowSums(rows, 0.0);
  std::vector<Distribution1D> perRow;
  for (size_t j = 0; j < rows; ++j) {
    const std::vector<double> row(weights.begin() + j * cols, weights.begin() + (j + 1) * cols);
    for (double w : row) rowSums[j] += w;
    perRow.emplace_back(row);
  }
  const Distribution1D marginal(rowSums);
  auto check = [&](float ux, float uy) {
    float rx = -1.0f, ry = -1.0f;
    const size_t j = marginal.sample(uy, &ry);
    const size_t i = perRow[j].sample(ux, &rx);
    const PiecewiseConstant2D::Cell c = flat.sample(ux, uy);
    ASSERT_EQ(c.row, j) << "u = (" << ux << ", " << uy << ")";
    ASSERT_EQ(c.column, i) << "u = (" << ux << ", " << uy << ")";
    ASSERT_EQ(c.remappedX, rx);
    ASSERT_EQ(c.remappedY, ry);
  };
  Rng rng(5);
  for (int k = 0; k < 20000; ++k) check(rng.nextFloat(), rng.nextFloat());
  // Every row's column edges, at a u.y inside that row, and the ends of [0, 1).
  for (size_t j = 0; j < rows; ++j) {
    const double* cdf = perRow[j].cdf().data();
    float uy = -1.0f;
    for (float v = 0.0f; v < 1.0f && uy < 0.0f; v += 1.0f / 4096.0f)
      if (marginal.sample(v) == j) uy = v;
    if (uy < 0.0f) continue;  // an empty row: no u.y reaches it
    for (size_t i = 0; i <= cols; ++i) {
      const float edge = static_cast<float>(cdf[i]);
      for (float ux : {std::nextafter(edge, 0.0f), edge, std::nextafter(edge, 1.0f)})
        if (ux >= 0.0f && ux < 1.0f) check(ux, uy);
    }
  }
  for (float ux : {0.0f, 0.99999994f})
    for (float uy : {0.0f, 0.99999994f}) check(ux, uy);
}

TEST(PiecewiseConstant2D, FlatTableGivesTheCellsOfPerRowDistributions) {
  expectSameCells({1.0, 2.0, 3.0, 4.0, 5.0, 6.0}, 2, 3);
  expectSameCells({7.0}, 1, 1);
  expectSameCells({1.0, 0.0, 2.0, 5.0}, 4, 1);  // one column: the column is always 0
  expectSameCells({0.0, 0.0, 0.0, 0.0}, 2, 2);  // all black: uniform over the cells
  // A black row between lit ones, empty cells at a row's ends, one bright cell among dim ones.
  expectSameCells({0.0, 3.0, 0.0, 1.0, /**/ 0.0, 0.0, 0.0, 0.0, /**/ 2.0, 0.0, 0.0, 0.0, /**/ 1e-6, 1e-6, 1.0, 1e-6}, 4, 4);
  const size_t rows = 31, cols = 64;  // an envmap-like table with a sun: lopsided rows and columns
  std::vector<double> w(rows * cols);
  for (size_t k = 0; k < w.size(); ++k) w[k] = double(k * k % 89) * 1e-3;
  w[7 * cols + 40] = 500.0;
  expectSameCells(w, rows, cols);
}

TEST(PiecewiseConstant2D, RejectsWeightsOfTheWrongSize) {
  EXPECT_THROW(PiecewiseConstant2D({1.0, 2.0, 3.0}, 2, 2), Error);
  EXPECT_THROW(PiecewiseConstant2D({}, 0, 0), Error);
}

// sampleLinear's histogram against the integral of the linear density over each bin: within 5
// standard errors of a binomial count, for a ramp up, a ramp down, a ramp from 0 and a constant.
TEST(SampleLinear, HistogramMatchesLinearDensity) {
  const float ends[][2] = {{1.0f, 7.0f}, {3.0f, 0.5f}, {0.0f, 2.0f}, {5.0f, 0.0f}, {1.0f, 1.0f}};
  const int bins = 16, n = 64000;
  for (const auto& e : ends) {
    const float a = e[0], b = e[1];
    std::vector<int> count(bins, 0);
    Rng rng(21);
    for (int k = 0; k < n; ++k) {
      const float x = sampleLinear(rng.nextFloat(), a, b);
      ASSERT_GE(x, 0.0f);
      ASSERT_LT(x, 1.0f);
      ++count[std::min(bins - 1, static_cast<int>(x * bins))];
    }
    for (int i = 0; i < bins; ++i) {
      // ∫ over the bin of 2((1 − x)a + xb)/(a + b): the density at the bin's midpoint times its width.
      const double p = linearPdf((i + 0.5f) / bins, a, b) / bins;
      const double se = std::sqrt(n * p * (1.0 - p));
      EXPECT_NEAR(count[i], n * p, 5.0 * se + 1.0) << "a " << a << " b " << b << " bin " << i;
    }
  }
}

// The inverse CDF at its ends and where the density is 0 at one end: x = 0 for u = 0, and the
// CDF (a x + (b − a) x²/2) / ((a + b)/2) of the returned x gives back u.
TEST(SampleLinear, InvertsTheCdf) {
  const float ends[][2] = {{1.0f, 7.0f}, {3.0f, 0.5f}, {0.0f, 2.0f}, {5.0f, 0.0f}, {1e-6f, 1e6f}};
  for (const auto& e : ends) {
    const float a = e[0], b = e[1];
    EXPECT_EQ(sampleLinear(0.0f, a, b), 0.0f);
    for (float u : {0.01f, 0.25f, 0.5f, 0.9f, 0.999f}) {
      const double x = sampleLinear(u, a, b);
      const double cdf = (a * x + (b - a) * x * x / 2.0) / ((a + b) / 2.0);
      EXPECT_NEAR(cdf, u, 2e-6) << "a " << a << " b " << b;
    }
  }
  EXPECT_EQ(sampleLinear(0.3f, 0.0f, 0.0f), 0.3f);  // no density: uniform (never drawn by a warp)
}

}  // namespace
}  // namespace rc
