#pragma once
// Mitsuba 3's `spot` emitter profile: full intensity inside `beam_width`, falling linearly in the
// angle to zero at `cutoff_angle`, measured from the emitter's local +z (its to_world frame).
#include <cmath>

#include "core/math.h"
#include "scene/scene.h"

namespace rc {

// The factor in [0, 1] the spot's intensity is multiplied by toward world direction `dirFromLight`.
inline float spotFalloff(const Emitter& em, const Vec3& dirFromLight) {
  // The direction in the emitter's frame, as Mitsuba: inverse linear part, then normalised (a
  // scaled to_world changes the angle a world direction makes with the axis).
  const Vec3 local = em.spotWorldToLocal * dirFromLight;
  const float len = glm::length(local);
  if (!(len > 0.0f)) return 0.0f;
  const float cosTheta = local.z / len;
  if (!(cosTheta > em.spotCosCutoff)) return 0.0f;
  if (cosTheta >= em.spotCosBeam) return 1.0f;
  const float theta = std::acos(std::min(1.0f, cosTheta));
  return std::max(0.0f, (em.spotCutoffRad - theta) / (em.spotCutoffRad - em.spotBeamRad));
}

}  // namespace rc
