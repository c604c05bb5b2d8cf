#pragma once
// Square-to-domain warps used by the BSDFs, as in Mitsuba 3's core/warp.h, so that the same
// random numbers map to the same directions.
#include "core/math.h"

namespace rc {

// Shirley–Chiu concentric map of [0,1)² onto the unit disk, in polar form: the point is
// (r·cos φ, r·sin φ), and the origin where `centre` (r = 0 there, φ undefined). Split from the
// cosine and sine so that a batched caller (render/diffuse_shading.h) computes r and φ in vector
// passes and only the trigonometry per lane, with the same arithmetic as the scalar map below.
struct DiskPolar {
  float r, phi;
  bool centre;
};
inline DiskPolar squareToDiskPolar(const Vec2& s) {
  const float x = 2.0f * s.x - 1.0f, y = 2.0f * s.y - 1.0f;
  const bool quadrant13 = std::fabs(x) < std::fabs(y);
  const float r = quadrant13 ? y : x, rp = quadrant13 ? x : y;
  const float phi = 0.25f * kPi * rp / r;
  return DiskPolar{r, quadrant13 ? 0.5f * kPi - phi : phi, x == 0.0f && y == 0.0f};
}

inline Vec2 squareToUniformDiskConcentric(const Vec2& s) {
  const DiskPolar d = squareToDiskPolar(s);
  if (d.centre) return Vec2(0.0f);
  return Vec2(d.r * std::cos(d.phi), d.r * std::sin(d.phi));
}

// The height over the unit disk's point p of the hemisphere it projects onto.
inline float diskToHemisphereZ(float px, float py) { return std::sqrt(fmaxInline(0.0f, 1.0f - px * px - py * py)); }

inline Vec3 squareToCosineHemisphere(const Vec2& s) {
  const Vec2 p = squareToUniformDiskConcentric(s);
  return Vec3(p.x, p.y, diskToHemisphereZ(p.x, p.y));
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
