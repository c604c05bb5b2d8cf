#pragma once
// Mitsuba 3's `spot` emitter profile: full intensity inside `beam_width`, falling linearly in the
// angle to zero at `cutoff_angle`, measured from the emitter's local +z (its to_world frame), times
// its projected `texture`; and the `projector`'s emission (src/emitters/spot.cpp, projector.cpp).
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

// The spot's intensity toward `dirFromLight` relative to `intensity`: the falloff times its
// texture at uv = ½ + ½·(x, y)/(z·tan(cutoff)) of the local direction (Mitsuba's direction_to_uv).
inline Color spotProfile(const Emitter& em, const Vec3& dirFromLight) {
  const float falloff = spotFalloff(em, dirFromLight);
  if (!(falloff > 0.0f) || !em.projection) return Color(falloff);
  const Vec3 local = em.spotWorldToLocal * dirFromLight;
  const float uvFactor = std::tan(em.spotCutoffRad);
  const Vec2 uv(0.5f + 0.5f * local.x / (local.z * uvFactor), 0.5f + 0.5f * local.y / (local.z * uvFactor));
  return falloff * em.projection->eval(TexturePoint(uv));  // an image: no surface point
}

// What a projector delivers at point p (radiance·solid angle, i.e. the light sample's value before
// the selection probability): the irradiance image sits on the local z = 1 plane, mapped like
// Mitsuba's perspective camera (uv = ½ − ½·cot·x/z, ½ − ½·aspect·cot·y/z, zero outside [0, 1]²
// or behind), and is scaled by π·scale / (z² cos θ) so that a constant image projects as constant
// irradiance onto a plane at z = 1 (θ between the axis and the direction to p).
inline Color projectorEmission(const Emitter& em, const Vec3& p) {
  const Vec3 local = em.spotWorldToLocal * (p - em.position);
  if (!(local.z > 0.0f)) return Color(0.0f);
  const Vec2 uv(0.5f - 0.5f * em.projectorCot * local.x / local.z,
                0.5f - 0.5f * em.projectorAspect * em.projectorCot * local.y / local.z);
  if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) return Color(0.0f);
  const Vec3 toPoint = p - em.position;
  const float dist = glm::length(toPoint);
  const Vec3 axis = Vec3(em.toWorld * Vec4(0.0f, 0.0f, 1.0f, 0.0f));
  const float cosTheta = glm::dot(axis, toPoint) / dist;
  if (!(cosTheta > 0.0f)) return Color(0.0f);
  const Color e = em.projection ? em.projection->eval(TexturePoint(uv)) : em.irradiance;
  return e * (kPi * em.scale / (local.z * local.z * cosTheta));
}

}  // namespace rc
