#pragma once
// Square-to-domain warps used by the BSDFs, as in Mitsuba 3's core/warp.h, so that the same
// random numbers map to the same directions.
#include "core/math.h"

namespace rc {

// Shirley–Chiu concentric map of [0,1)² onto the unit disk.
inline Vec2 squareToUniformDiskConcentric(const Vec2& s) {
  const float x = 2.0f * s.x - 1.0f, y = 2.0f * s.y - 1.0f;
  if (x == 0.0f && y == 0.0f) return Vec2(0.0f);
  const bool quadrant13 = std::fabs(x) < std::fabs(y);
  const float r = quadrant13 ? y : x, rp = quadrant13 ? x : y;
  float phi = 0.25f * kPi * rp / r;
  if (quadrant13) phi = 0.5f * kPi - phi;
  return Vec2(r * std::cos(phi), r * std::sin(phi));
}

inline Vec3 squareToCosineHemisphere(const Vec2& s) {
  const Vec2 p = squareToUniformDiskConcentric(s);
  const float z = std::sqrt(fmaxInline(0.0f, 1.0f - p.x * p.x - p.y * p.y));
  return Vec3(p.x, p.y, z);
}

inline float squareToCosineHemispherePdf(const Vec3& v) { return kInvPi * v.z; }

inline float safeSqrt(float x) { return std::sqrt(fmaxInline(0.0f, x)); }

// Mirror about the local normal (Mitsuba's reflect(wi)).
inline Vec3 reflectZ(const Vec3& w) { return Vec3(-w.x, -w.y, w.z); }
// Mirror about a microfacet normal m.
inline Vec3 reflectAbout(const Vec3& w, const Vec3& m) { return 2.0f * glm::dot(w, m) * m - w; }

// v with the sign of s applied (Dr.Jit's mulsign: s < 0 flips it).
inline Vec3 mulSign(const Vec3& v, float s) { return s < 0.0f ? -v : v; }

// Half vector of a rough dielectric interface (Walter et al.): normalize(wo + η_r·wi) with η_r = 1
// for reflection, else the relative IOR η seen from wo, turned to the normal's side.
inline Vec3 generalizedHalfVector(const Vec3& wo, const Vec3& wi, bool reflect, float eta) {
  const Vec3 m = glm::normalize(wo + wi * (reflect ? 1.0f : eta));
  return mulSign(m, m.z);
}

}  // namespace rc
