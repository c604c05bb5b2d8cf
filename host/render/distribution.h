#pragma once
// Piecewise-constant 1-D distribution over n bins (inverse-CDF sampling), the building block of
// emitter selection, triangle selection and the envmap's 2-D (marginal × conditional) sampling.
#include <algorithm>
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
  }
  size_t size() const { return cdf_.empty() ? 0 : cdf_.size() - 1; }
  double total() const { return uniform_ ? 0.0 : total_; }  // sum of the weights given
  double probability(size_t i) const { return cdf_[i + 1] - cdf_[i]; }

  // Bin for u in [0,1); `remapped` gets u rescaled to [0,1) within the bin (sample reuse).
  size_t sample(float u, float* remapped = nullptr) const {
    const double uu = u;
    size_t i = static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), uu) - cdf_.begin());
    i = i == 0 ? 0 : i - 1;
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
  std::vector<double> cdf_;
  double total_ = 0.0;
  bool uniform_ = false;
};

}  // namespace rc
