#include "core/image_metrics.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace rc {

ImageError compareImages(const std::vector<Color>& test, const std::vector<Color>& reference) {
  if (test.size() != reference.size())
    throw Error("images differ in size (" + std::to_string(test.size()) + " vs " + std::to_string(reference.size()) +
                " pixels)");
  ImageError e;
  double se = 0, rel = 0;
  size_t n = 0;
  for (size_t i = 0; i < test.size(); ++i) {
    if (!isFinite(test[i]) || !isFinite(reference[i])) {
      ++e.nonFinite;
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      const double x = test[i][c], r = reference[i][c], d = x - r;
      se += d * d;
      rel += relMseTerm(d, r);
      e.maxAbs = std::max(e.maxAbs, std::fabs(d));
      ++n;
    }
  }
  if (n > 0) {
    e.rmse = std::sqrt(se / n);
    e.relmse = rel / n;
  }
  return e;
}

std::vector<float> relativeErrorMap(const std::vector<Color>& test, const std::vector<Color>& reference) {
  if (test.size() != reference.size()) throw Error("images differ in size");
  std::vector<float> out(test.size(), 0.0f);
  for (size_t i = 0; i < test.size(); ++i) {
    double acc = 0;
    for (int c = 0; c < 3; ++c) {
      const double d = double(test[i][c]) - reference[i][c];
      acc += relMseTerm(d, reference[i][c]);
    }
    out[i] = std::isfinite(acc) ? static_cast<float>(acc / 3.0) : INFINITY;
  }
  return out;
}

}  // namespace rc
