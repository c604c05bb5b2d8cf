#pragma once
// Fresnel equations as in Mitsuba 3 (include/mitsuba/render/fresnel.h), unpolarized.
#include "core/math.h"

namespace rc {

struct FresnelDielectric {
  float r;         // reflectance
  float cosThetaT; // signed cosine of the transmitted direction (opposite side of cosThetaI)
  float etaIt;     // relative IOR: incident over transmitted side
  float etaTi;     // its reciprocal
};

// cosThetaI: cosine between the incident direction and the normal (negative = from inside);
// eta: interior over exterior IOR. Total internal reflection gives r = 1.
FresnelDielectric fresnelDielectric(float cosThetaI, float eta);

// Exact unpolarized reflectance of a conductor with complex relative IOR eta + i·k
// (K. D. Moeller, "Optics", 1988, as used by Mitsuba).
float fresnelConductor(float cosThetaI, float eta, float k);
Color fresnelConductor(float cosThetaI, const Color& eta, const Color& k);

// Hemispherically averaged (cosine-weighted) dielectric reflectance: Egan–Hilgeman (eta < 1)
// and d'Eon–Irving (eta ≥ 1) polynomial fits, exactly as Mitsuba's fresnel_diffuse_reflectance.
float fresnelDiffuseReflectance(float eta);

// Refraction about the local normal given fresnelDielectric's cosThetaT and etaTi.
inline Vec3 refractZ(const Vec3& wi, float cosThetaT, float etaTi) {
  return Vec3(-etaTi * wi.x, -etaTi * wi.y, cosThetaT);
}

}  // namespace rc
