#pragma once
// Image error metrics (ARCHITECTURE.md §Tests and benchmarks), one definition for the CLI, tests and benchmarks.
// relMSE = mean over pixels and channels of (x − r)² / (r² + 0.01).
#include <vector>

#include "core/math.h"

namespace rc {

// One pixel channel's term of relMSE, (x − r)² / (r² + 0.01) with diff = x − r.
inline double relMseTerm(double diff, double reference) { return diff * diff / (reference * reference + 0.01); }

struct ImageError {
  double rmse = 0, relmse = 0, maxAbs = 0;
  size_t nonFinite = 0;  // pixels of the test image that are NaN/Inf (counted, excluded)
};

// Throws rc::Error when sizes differ.
ImageError compareImages(const std::vector<Color>& test, const std::vector<Color>& reference);

// Per-pixel relative squared error (mean over channels), for heat maps.
std::vector<float> relativeErrorMap(const std::vector<Color>& test, const std::vector<Color>& reference);

}  // namespace rc
