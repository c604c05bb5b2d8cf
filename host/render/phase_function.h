#pragma once
// Phase functions of media (Mitsuba 3 src/phase/isotropic.cpp, hg.cpp). Directions as Mitsuba
// writes them: wi points back along the arriving ray (−ray.d), wo is where the light goes on, and
// the value equals the sampling density (both sample exactly).
#include "core/frame.h"
#include "core/math.h"
#include "scene/medium.h"

namespace rc {

// Henyey–Greenstein with cosTheta = dot(wo, wi): (1 − g²) / (4π (1 + g² + 2g·cosTheta)^{3/2}), so
// g > 0 favours wo ≈ −wi (forward scattering).
inline float henyeyGreenstein(float g, float cosTheta) {
  const float temp = 1.0f + g * g + 2.0f * g * cosTheta;
  return (1.0f - g * g) / (4.0f * kPi * temp * std::sqrt(temp));
}

inline float phaseValue(const PhaseFunction& phase, const Vec3& wi, const Vec3& wo) {
  if (phase.type == PhaseFunction::Type::Isotropic) return 1.0f / (4.0f * kPi);
  return henyeyGreenstein(phase.g, glm::dot(wo, wi));
}

struct PhaseSample {
  Vec3 wo;
  float pdf;  // = phaseValue(wi, wo): the sample's weight is 1
};

// Isotropic: uniform on the sphere (z = 1 − 2u.x). HG: Mitsuba's inversion, cosθ measured from −wi.
inline PhaseSample samplePhase(const PhaseFunction& phase, const Vec3& wi, const Vec2& u) {
  const float g = phase.type == PhaseFunction::Type::Isotropic ? 0.0f : phase.g;
  float cosTheta;
  if (std::fabs(g) < 1e-7f) {
    cosTheta = 1.0f - 2.0f * u.x;
  } else {
    const float sqrTerm = (1.0f - g * g) / (1.0f - g + 2.0f * g * u.x);
    cosTheta = (1.0f + g * g - sqrTerm * sqrTerm) / (2.0f * g);
  }
  cosTheta = glm::clamp(cosTheta, -1.0f, 1.0f);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = 2.0f * kPi * u.y;
  const Vec3 wo = Frame::fromNormal(wi).toWorld(Vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), -cosTheta));
  return {wo, phaseValue(phase, wi, wo)};
}

}  // namespace rc
