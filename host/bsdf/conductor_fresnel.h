#pragma once
// The Fresnel parameters shared by `conductor` and `roughconductor` (Mitsuba 3 semantics):
// material "none" (default) with no eta → eta = 0, k = 1, for which the conductor Fresnel equations
// give exactly F ≡ 1 (an ideal mirror); eta/k given → complex Fresnel with those RGB values
// (k defaults to 1 as in Mitsuba); a named material → its RGB η/k (conductor_presets.h).
#include <string>

#include "bsdf/fresnel.h"
#include "core/properties.h"

namespace rc {

struct ConductorFresnel {
  Color eta{0.0f}, k{1.0f};
  Color specularReflectance{1.0f};

  Color eval(float cosThetaI) const { return specularReflectance * fresnelConductor(cosThetaI, eta, k); }
  std::string key() const;
};

ConductorFresnel readConductorFresnel(const Properties& props);

}  // namespace rc
