#pragma once
// The sample of a surface that is not there (Mitsuba's BSDFFlags::Null, one of its Delta flags):
// the ray continues unchanged, weight 1 — shared by the null BSDF and a mask's holes.
#include <optional>

#include "bsdf/bsdf.h"

namespace rc {

inline std::optional<BsdfSample> passThroughSample(const Vec3& wo) {
  if (!std::isfinite(wo.x) || !std::isfinite(wo.y) || !std::isfinite(wo.z)) return std::nullopt;
  BsdfSample s;
  s.wi = -wo;
  s.weight = Color(1.0f);
  s.pdf = 0.0f;
  s.lobe = kLobeDelta | kLobeTransmission | kLobeNull;
  s.eta = 1.0f;
  return s;
}

}  // namespace rc
