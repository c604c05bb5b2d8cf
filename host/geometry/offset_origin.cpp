// Self-intersection avoidance for secondary rays. Floating-point error in a hit point is relative to
// the magnitude of the coordinates it was computed from, so the offset scales with max|p| (and with
// the shape's own coordinate magnitude through Hit::pError) and has no absolute floor that would
// swamp tiny scenes — unlike Mitsuba's (1 + max|p|)·ε, which breaks below ~1e-3 scene units.
#include <algorithm>

#include "geometry/accel.h"

namespace rc {

namespace {
// 2^-16 · max|p| ≈ 256 float ulps: well above the few ulps of interpolation/intersection error,
// well below any feature size that matters (1.5e-5 relative).
constexpr float kRelativeOffset = 1.0f / 65536.0f;
// Keeps the offset non-zero for p exactly at the origin of a tiny scene (smallest normal float ×2^20).
constexpr float kAbsoluteFloor = 1e-32f;

inline float maxAbs(const Vec3& p) { return std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}); }

Vec3 offsetBy(const Vec3& p, const Vec3& ng, const Vec3& d, float magnitude) {
  const float side = glm::dot(ng, d) >= 0.0f ? 1.0f : -1.0f;
  return p + ng * (side * magnitude);
}
}  // namespace

Vec3 Accel::offsetOrigin(const Vec3& p, const Vec3& ng, const Vec3& d) {
  return offsetBy(p, ng, d, std::max(kRelativeOffset * maxAbs(p), kAbsoluteFloor));
}

Vec3 Accel::offsetOrigin(const Hit& hit, const Vec3& d) {
  return offsetBy(hit.p, hit.ng, d, std::max({kRelativeOffset * maxAbs(hit.p), 4.0f * hit.pError, kAbsoluteFloor}));
}

Ray Accel::spawnRay(const Hit& hit, const Vec3& d) {
  Ray r;
  r.o = offsetOrigin(hit, d);
  r.d = d;
  return r;
}

Ray Accel::spawnRayTo(const Hit& hit, const Vec3& target) {
  Ray r;
  // The side of the offset is chosen from the direction at p, then the direction is re-aimed from
  // the offset origin: a parallel-shifted ray would miss the target and graze its surface early.
  r.o = offsetOrigin(hit, glm::normalize(target - hit.p));
  r.d = glm::normalize(target - r.o);
  // Stop short of the target by the same relative margin, so the emitter surface itself (when the
  // target lies on one) is not reported as an occluder.
  const float dist = glm::length(target - r.o);
  const float margin = std::max(kRelativeOffset * std::max(maxAbs(target), dist), kAbsoluteFloor);
  r.tMax = std::max(0.0f, dist - margin);
  return r;
}

}  // namespace rc
