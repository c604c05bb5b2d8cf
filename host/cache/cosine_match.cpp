#include "cache/cosine_match.h"

#include <cmath>

#include "core/error.h"
#include "core/math.h"
#include "core/parallel.h"
#include "sh/sh_basis.h"

namespace rc {

void matchCosineIrradianceAtNormal(const ProjectBatch& rays, ProjectResult& projected) {
  if (rays.order != 3) throw Error("matchCosineIrradianceAtNormal: order " + std::to_string(rays.order) + ", not 3");
  constexpr int kCoeffs = 9;
  const int M = rays.M, N = rays.N, S = M * N;
  float y[kCoeffs];
  sh::evalBasis(3, 0.0f, 0.0f, 1.0f, y);
  float A[kCoeffs];
  for (int l = 0; l < 3; ++l)
    for (int m = -l; m <= l; ++m) A[sh::index(l, m)] = sh::kClampedCosineBand[l];
  parallelFor(static_cast<size_t>(rays.records), 64, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) {
      const float* L = rays.radiance.data() + 3 * static_cast<size_t>(S) * b;
      double E[3] = {0.0, 0.0, 0.0};
      for (int s = 0; s < S; ++s) {
        const float* Ls = L + 3 * s;
        if (!std::isfinite(Ls[0]) || !std::isfinite(Ls[1]) || !std::isfinite(Ls[2])) continue;
        const double cosT = 1.0 - ((s / N) + double(rays.pattern[2 * s])) / M;
        for (int c = 0; c < 3; ++c) E[c] += double(Ls[c]) * cosT;
      }
      float* lambda = projected.lambda.data() + 3 * kCoeffs * b;
      for (int c = 0; c < 3; ++c) {
        double bands = 0.0;
        for (int i = 0; i < kCoeffs; ++i) bands += double(A[i]) * lambda[c * kCoeffs + i] * y[i];
        const double exact = E[c] * 2.0 * kPiD / S;
        lambda[c * kCoeffs] += static_cast<float>((exact - bands) / (double(A[0]) * y[0]));
      }
    }
  });
}

}  // namespace rc
