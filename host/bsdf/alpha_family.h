#pragma once
// Materials whose only per-point parameter is an isotropic textured microfacet roughness (a
// roughconductor with a texture on `alpha`, also under a texture factor): the radiance cache
// tabulates them at a few α and picks a table per point (brdf/material_plan.h). A side interface
// of such BSDFs, found by alphaFamilyOf().
#include <utility>

#include "bsdf/bsdf.h"

namespace rc {

class AlphaFamily {
 public:
  virtual ~AlphaFamily() = default;
  virtual bool variesOnlyInAlpha() const = 0;
  // The smallest and the largest α the texture takes (sampled on a fine uv lattice).
  virtual std::pair<float, float> alphaRange() const = 0;
  virtual float alphaAt(const TexturePoint& uv) const = 0;
  // The material with a uniform α (what a table at that α describes; without the texture factor).
  virtual BsdfPtr withAlpha(float alpha) const = 0;
};

inline const AlphaFamily* alphaFamilyOf(const Bsdf& bsdf) {
  const auto* family = dynamic_cast<const AlphaFamily*>(&bsdf);
  return family && family->variesOnlyInAlpha() ? family : nullptr;
}

}  // namespace rc
