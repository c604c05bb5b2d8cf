#pragma once
// Piecewise-constant 1-D distribution over n bins (inverse-CDF sampling), the building block of
// emitter selection, triangle selection and (as PiecewiseConstant2D) the envmap's 2-D
// (marginal × conditional) sampling.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/error.h"

namespace rc {

class Distribution1D {
 public:
  Distribution1D() = default;
  // Negative or non-finite weights count as 0. All zero → uniform (so sampling never fails).
  explicit Distribution1D(const std::vector<double>& weights) {
    const size_t n = weights.size();
    cdf_.assign(n + 1, 0.0);
    for (size_t i = 0; i < n; ++i) {
      const double w = weights[i] > 0.0 && weights[i] < 1e300 ? weights[i] : 0.0;
      cdf_[i + 1] = cdf_[i] + w;
    }
    total_ = cdf_[n];
    if (!(total_ > 0.0)) {
      for (size_t i = 0; i <= n; ++i) cdf_[i] = static_cast<double>(i);
      total_ = static_cast<double>(n);
      uniform_ = true;
    }
    for (double& c : cdf_) c /= total_;
    cdf_[n] = 1.0;
    buildGuide();
  }
  size_t size() const { return cdf_.empty() ? 0 : cdf_.size() - 1; }
  double total() const { return uniform_ ? 0.0 : total_; }  // sum of the weights given
  double probability(size_t i) const { return cdf_[i + 1] - cdf_[i]; }

  // Bin for u in [0,1); `remapped` gets u rescaled to [0,1) within the bin (sample reuse).
  size_t sample(float u, float* remapped = nullptr) const {
    return sampleTable(cdf_.data(), guide_.data(), size(), u, remapped);
  }

  // The same search over a table of `bins` ≥ 1 bins stored elsewhere (PiecewiseConstant2D's rows):
  // `cdf` has bins + 1 entries and `guide` max(1, bins), laid out as a Distribution1D holds them.
  static size_t sampleTable(const double* cdf, const uint32_t* guide, size_t bins, float u, float* remapped) {
    const double uu = u;
    size_t i;
    if (bins <= kSmallBins) {
      // The last cdf entry ≤ uu among the first `bins` (cdf[0] = 0 ≤ uu): with a non-decreasing cdf
      // that is the count of entries 1 … bins − 1 at or below uu — a few compares without branches,
      // for the small tables (a few emitters, a quad's triangles) a guided search would mispredict on.
      i = 0;
      for (size_t j = 1; j < bins; ++j) i += cdf[j] <= uu ? 1 : 0;
    } else {
      // The last cdf entry ≤ uu (upper_bound − 1, or 0 below the first): the guide table narrows the
      // range to the entries of uu's slice of [0, 1) — whole range where rounding of the slice index
      // could have missed — and a binary search without data-dependent branches finishes.
      const size_t slices = bins, entries = bins + 1;
      const size_t k = std::min(slices - 1, static_cast<size_t>((uu > 0.0 ? uu : 0.0) * static_cast<double>(slices)));
      size_t lo = guide[k], hi = k + 1 < slices ? guide[k + 1] + 1 : entries;  // [lo, hi) holds it
      if (cdf[lo] > uu) lo = 0;
      if (hi < entries && cdf[hi] <= uu) hi = entries;
      const double* base = cdf + lo;
      for (size_t n = hi - lo; n > 1;) {
        const size_t half = n / 2;
        base = base[half] <= uu ? base + half : base;
        n -= half;
      }
      i = std::min(static_cast<size_t>(base - cdf), bins - 1);
    }
    while (i + 1 < bins && cdf[i + 1] - cdf[i] == 0.0) ++i;  // never return an empty bin
    if (remapped) {
      const double p = cdf[i + 1] - cdf[i];
      const double r = p > 0.0 ? (uu - cdf[i]) / p : 0.5;
      *remapped = static_cast<float>(std::min(std::max(r, 0.0), 0.99999994));
    }
    return i;
  }
  // Tables of at most this many bins are searched by counting instead of through the guide.
  static constexpr size_t kSmallBins = 8;
  // The tables sampleTable reads (cdf: size() + 1 entries, guide: max(1, size())).
  const std::vector<double>& cdf() const { return cdf_; }
  const std::vector<uint32_t>& guide() const { return guide_; }

 private:
  // guide_[k]: the last cdf entry ≤ k / n (n = the bin count), so a u in slice [k/n, (k+1)/n) lies
  // between entries guide_[k] and guide_[k+1] (Chen and Asau's guide table): a search over one or
  // two entries instead of a binary search's log n dependent loads over all of them.
  void buildGuide() {
    const size_t slices = std::max<size_t>(1, size());
    guide_.assign(slices, 0);
    size_t i = 0;
    for (size_t k = 0; k < slices; ++k) {
      const double start = static_cast<double>(k) / static_cast<double>(slices);
      while (i + 1 < cdf_.size() && cdf_[i + 1] <= start) ++i;
      guide_[k] = static_cast<uint32_t>(i);
    }
  }

  std::vector<double> cdf_;
  std::vector<uint32_t> guide_;
  double total_ = 0.0;
  bool uniform_ = false;
};

// x ∈ [0, 1) with density ∝ (1 − x)·a + x·b (a, b ≥ 0, not both 0): the inverse of the quadratic CDF
// in the form that loses no precision when a ≈ b or when a or b is 0. Two of these sample a bilinear
// patch (the envmap's density within one cell: the row's linear marginal, then the column given it).
inline float sampleLinear(float u, float a, float b) {
  if (!(a + b > 0.0f)) return u;
  if (u == 0.0f) return 0.0f;  // also where a = 0: the form below would be 0/0
  const float x = u * (a + b) / (a + std::sqrt((1.0f - u) * a * a + u * b * b));
  return std::min(x, 0.99999994f);
}
// Density of sampleLinear's x.
inline float linearPdf(float x, float a, float b) { return a + b > 0.0f ? 2.0f * ((1.0f - x) * a + x * b) / (a + b) : 1.0f; }

// A 2-D piecewise-constant distribution over rows × cols cells (weights row-major, rows, cols ≥ 1):
// a row from the marginal, then a column from that row's conditional. The conditionals' tables are
// stored flat, one row after the other, so a sample reads them at an offset instead of through a
// pointer per row; each row's table is exactly the one a Distribution1D of that row holds, so a
// sample returns the same cell as the marginal and per-row Distribution1Ds would.
class PiecewiseConstant2D {
 public:
  PiecewiseConstant2D() = default;
  PiecewiseConstant2D(const std::vector<double>& weights, size_t rows, size_t cols) : cols_(cols) {
    if (rows == 0 || cols == 0 || weights.size() != rows * cols) throw Error("PiecewiseConstant2D: weights are not rows × cols");
    std::vector<double> rowWeights(rows, 0.0), row(cols);
    cdf_.reserve(rows * (cols + 1));
    guide_.reserve(rows * cols);
    for (size_t j = 0; j < rows; ++j) {
      for (size_t i = 0; i < cols; ++i) rowWeights[j] += (row[i] = weights[j * cols + i]);
      const Distribution1D conditional(row);
      cdf_.insert(cdf_.end(), conditional.cdf().begin(), conditional.cdf().end());
      guide_.insert(guide_.end(), conditional.guide().begin(), conditional.guide().end());
    }
    rows_ = Distribution1D(rowWeights);
  }
  size_t rows() const { return rows_.size(); }
  size_t cols() const { return cols_; }

  struct Cell {
    size_t column = 0, row = 0;
    float remappedX = 0.0f, remappedY = 0.0f;  // (ux, uy) rescaled to [0,1) within the cell
  };
  // The cell for u ∈ [0,1)²: uy picks the row, ux the column within it.
  Cell sample(float ux, float uy) const {
    Cell c;
    c.row = rows_.sample(uy, &c.remappedY);
    c.column = Distribution1D::sampleTable(cdf_.data() + c.row * (cols_ + 1), guide_.data() + c.row * cols_, cols_, ux,
                                           &c.remappedX);
    return c;
  }

 private:
  size_t cols_ = 0;
  Distribution1D rows_;          // marginal over the rows (each row's weight summed)
  std::vector<double> cdf_;      // [rows][cols + 1]
  std::vector<uint32_t> guide_;  // [rows][cols]
};

}  // namespace rc
