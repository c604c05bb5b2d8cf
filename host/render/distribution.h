#pragma once
// Piecewise-constant 1-D distribution over n bins (inverse-CDF sampling), the building block of
// emitter selection, triangle selection and the envmap's 2-D (marginal × conditional) sampling.
#include <algorithm>
#include <cstdint>
#include <vector>

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
    const double uu = u;
    // The last cdf entry ≤ uu (upper_bound − 1, or 0 below the first): the guide table narrows the
    // range to the entries of uu's slice of [0, 1) — whole range where rounding of the slice index
    // could have missed — and a binary search without data-dependent branches finishes.
    const size_t slices = guide_.size(), entries = cdf_.size();
    const size_t k = std::min(slices - 1, static_cast<size_t>((uu > 0.0 ? uu : 0.0) * static_cast<double>(slices)));
    size_t lo = guide_[k], hi = k + 1 < slices ? guide_[k + 1] + 1 : entries;  // [lo, hi) holds it
    if (cdf_[lo] > uu) lo = 0;
    if (hi < entries && cdf_[hi] <= uu) hi = entries;
    const double* base = cdf_.data() + lo;
    for (size_t n = hi - lo; n > 1;) {
      const size_t half = n / 2;
      base = base[half] <= uu ? base + half : base;
      n -= half;
    }
    size_t i = static_cast<size_t>(base - cdf_.data());
    i = std::min(i, size() - 1);
    while (i + 1 < size() && probability(i) == 0.0) ++i;  // never return an empty bin
    if (remapped) {
      const double p = probability(i);
      const double r = p > 0.0 ? (uu - cdf_[i]) / p : 0.5;
      *remapped = static_cast<float>(std::min(std::max(r, 0.0), 0.99999994));
    }
    return i;
  }

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

}  // namespace rc
