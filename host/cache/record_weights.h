#pragma once
// The interpolation criterion of irradiance/radiance caching (ARCHITECTURE.md §Conventions), in one place:
//   w_i(p) = 1 / (‖p − p_i‖/R_i + √(1 − n·n_i)),  contributes when w_i > 1/a_i and record i is
//   not in front of p: (p − p_i)·(n + n_i)/2 ≥ −ε.
// Every division is guarded: a point exactly at a record (same normal) gets a large finite
// weight, R_i ≤ 0 is treated as the smallest positive radius, opposite normals give w ≤ 1/√2.
#include <algorithm>
#include <cmath>

#include "core/math.h"

namespace rc {

// Largest weight we hand out: 1/kMinWeightDenominator. Big enough that a record at p dominates
// any neighbour (neighbours have w < 1/a·... ≪ 1e6), small enough that Σw stays finite in float.
constexpr float kMinWeightDenominator = 1e-6f;

// ε of the in-front test, relative to R_i: scale-invariant, and small against the influence
// radius a·R_i so that only records clearly in front (on a step, in a crease) are rejected.
constexpr float kInFrontEpsilon = 0.05f;

inline float recordWeight(const Vec3& p, const Vec3& n, const Vec3& pi, const Vec3& ni, float Ri) {
  const float R = std::max(Ri, 1e-30f);
  const float d = glm::length(p - pi);
  const float c = std::sqrt(std::max(0.0f, 1.0f - glm::dot(n, ni)));
  const float den = d / R + c;
  return 1.0f / std::max(den, kMinWeightDenominator);
}

inline bool recordInFront(const Vec3& p, const Vec3& n, const Vec3& pi, const Vec3& ni, float Ri) {
  return glm::dot(p - pi, 0.5f * (n + ni)) < -kInFrontEpsilon * std::max(Ri, 0.0f);
}

// Returns the weight when record i contributes at (p, n), else 0.
inline float contributionWeight(const Vec3& p, const Vec3& n, const Vec3& pi, const Vec3& ni, float Ri, float ai) {
  if (!(glm::dot(n, ni) > 0.0f)) return 0.0f;  // opposite hemispheres never share incoming light
  const float w = recordWeight(p, n, pi, ni, Ri);
  if (!(w > 1.0f / ai)) return 0.0f;
  if (recordInFront(p, n, pi, ni, Ri)) return 0.0f;
  return w;
}

// Neighbour clamping (Křivánek et al. EGSR 2006): R may not exceed a neighbour's R plus the
// distance between them (radius changes at most as fast as distance, the Lipschitz argument).
// Applies to the new record first, then the neighbour is clamped by the (clamped) new one.
inline void clampNeighbourRadii(const Vec3& pNew, float& rNew, const Vec3& pj, float& rj) {
  const float d = glm::length(pNew - pj);
  rNew = std::min(rNew, rj + d);
  rj = std::min(rj, rNew + d);
}

}  // namespace rc
