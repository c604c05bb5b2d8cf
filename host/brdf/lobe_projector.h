#pragma once
// Projection of one BRDF lobe onto real SH (ARCHITECTURE.md §Conventions, §Kernels): for a fixed ω_o (local
// frame, z = normal) the lobe g(ω_i) = f_r(ω_i, ω_o)·cos θ_i, zero below the horizon, has
// coefficients F_c,i = ∫ g_c(ω) y_i(ω) dω. Sharp lobes defeat uniform quadrature (a GGX lobe of
// α = 0.05 covers ~0.1% of the hemisphere), so the integral is estimated with multi-sample
// importance sampling: N_b directions from the BSDF's own sample() and N_c cosine-weighted
// directions, combined with the balance heuristic (each sample weighted 1/(N_b·p_b + N_c·p_c)),
// on a deterministic low-discrepancy point set. The cosine samples keep the estimator bounded
// where the BSDF's sampler is poor (diffuse parts, grazing tails).
#include <vector>

#include "bsdf/bsdf.h"

namespace rc {

struct LobeQuadrature {
  int bsdfSamples = 3072;    // N_b
  int cosineSamples = 1024;  // N_c
};

struct LobeProjection {
  std::vector<double> coeffs;  // [3][n2]
  double energy[3] = {0, 0, 0};  // ∫ g_c² dω (the lobe's squared L2 norm, all bands)
};

// Throws rc::Error when order is outside 1..20 or the quadrature has no samples.
void projectLobe(const Bsdf& bsdf, const Vec3& wo, int order, const LobeQuadrature& quad,
                 LobeProjection& out);

}  // namespace rc
