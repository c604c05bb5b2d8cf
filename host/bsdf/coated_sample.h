#pragma once
// The sample of a glossy coat over a diffuse base (roughplastic, pplastic): a microfacet reflection
// or a cosine-distributed direction, with the BSDF's own mixture pdf() and weight eval()/pdf(), as
// Mitsuba's plastics report them.
#include <cmath>
#include <optional>

#include "bsdf/bsdf.h"
#include "bsdf/microfacet.h"
#include "bsdf/warp.h"

namespace rc {

inline std::optional<BsdfSample> sampleCoatOrBase(const Bsdf& bsdf, const Microfacet& coat, const Vec3& wo, bool sampleCoat,
                                                  const Vec2& u2) {
  if (!(wo.z > 0.0f)) return std::nullopt;
  BsdfSample s;
  if (sampleCoat) {
    s.wi = reflectAbout(wo, coat.sample(wo, u2).first);
    s.lobe = kLobeGlossy;
  } else {
    s.wi = squareToCosineHemisphere(u2);
    s.lobe = kLobeDiffuse;
  }
  const BsdfValue value = bsdf.evalPdf(wo, s.wi);
  s.pdf = value.pdf;
  if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) return std::nullopt;
  s.weight = value.f / s.pdf;
  return s;
}

}  // namespace rc
