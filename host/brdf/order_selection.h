#pragma once
// SH order of a material from its BRDF's bandwidth: the smallest order n whose relative L2
// truncation error of the lobe, e_n = sqrt(1 − Σ_{l<n} Σ_m F_lm² / ‖g‖²) (the fraction of the
// lobe's norm outside bands 0..n−1), worst over ω_o and over colour channels, is ≤ tolerance.
#include <vector>

#include "brdf/lobe_projector.h"
#include "bsdf/bsdf.h"

namespace rc {

struct OrderChoice {
  int order = 0;                     // chosen order, 0 = no order ≤ maxOrder meets the tolerance
  std::vector<double> worstError;    // [maxOrder]: worstError[n−1] = worst e_n over ω_o and channels
};

// "Worst over ω_o" is taken over view directions with θ_o ≤ maxThetaDeg: toward the horizon every
// lobe is clipped into a thin sliver along it (f·cos θ_i rises from 0 within ~α of the horizon),
// whose relative L2 error stays large at any order ≤ 16 even for α = 0.5 (measured: GGX α = 0.5
// needs order 14 at θ_o = 80° for 5%); taking the worst up to 90° would send every glossy
// material to importance sampling. θ_o ≤ 60° is 75% of the projected solid angle of views.
// Planning directions: isotropic: 7 parabolic radii from 0 to tan(maxTheta/2) at φ_o = 0;
// anisotropic: the normal plus 4 radii × 8 azimuths. Directions whose lobe norm is below 1e-6 of
// the largest are skipped (a relative error of a vanishing lobe means nothing).
OrderChoice selectShOrder(const Bsdf& bsdf, double tolerance, int maxOrder, const LobeQuadrature& quad,
                          double maxThetaDeg = 60.0);

}  // namespace rc
