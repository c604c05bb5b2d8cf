#pragma once
// Tabulated importance function of an isotropic measured BRDF (the merl BSDF's sampler).
// Sampling happens in half-vector space, where measured lobes are compact (a specular peak sits at
// h = n for every view) and where the data itself is tabulated: for each of `thetaOBins` bins of
// the view's polar angle, a 2-D piecewise-constant distribution over (u, v) ∈ [0,1)², with
// θ_h = u²·π/2 (the MERL file's square-root map, fine near the normal) and |φ_h − φ_o| = v·π (an
// isotropic lobe is mirror-symmetric about the plane of ω_o, so one half is tabulated and the
// other reached by a sign). Cell masses integrate the target f·cos θ_i over the cell (2×2 midpoint
// sub-samples) through the Jacobians dω_i = 4 (ω_o·h) dω_h and dω_h = π² u sin θ_h du dv.
// The pdf evaluated for any (ω_o, ω_i) uses the same bin, cell and Jacobians as sample(), so the
// two agree exactly; the bin is piecewise constant in θ_o, which only affects variance.
#include <functional>
#include <optional>
#include <vector>

#include "core/math.h"
#include "render/distribution.h"

namespace rc {

class MerlSampler {
 public:
  // target(ω_o, ω_i) ≥ 0: the density to follow (f_r·cos θ_i, summed over channels).
  using Target = std::function<double(const Vec3& wo, const Vec3& wi)>;
  MerlSampler(const Target& target, int thetaOBins = 32, int uBins = 64, int vBins = 32);

  // ω_i for ω_o (ω_o.z > 0); `mirror` picks the half φ_h < φ_o. Empty when the reflected direction
  // falls below the horizon.
  std::optional<Vec3> sample(const Vec3& wo, bool mirror, const Vec2& u2) const;
  // Solid-angle density of sample() at ω_i (0 below the horizon).
  float pdf(const Vec3& wo, const Vec3& wi) const;

 private:
  int binOf(const Vec3& wo) const;
  int thetaOBins_, uBins_, vBins_;
  std::vector<Distribution1D> rows_;     // [bin]: marginal over u
  std::vector<Distribution1D> columns_;  // [bin][u]: conditional over v
};

}  // namespace rc
