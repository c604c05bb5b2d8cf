// Self-intersection avoidance for secondary rays (the constants and Accel::spawnRay, inline, in
// accel.h). Floating-point error in a hit point is relative to
// the magnitude of the coordinates it was computed from, so the offset scales with max|p| (and with
// the shape's own coordinate magnitude through Hit::pError) and has no absolute floor that would
// swamp tiny scenes — unlike Mitsuba's (1 + max|p|)·ε, which breaks below ~1e-3 scene units and,
// being ~6× larger at |p| ≈ 1, jumps layers thinner than itself (an air gap inside a glass object
// renders differently in the two; bench/RESULTS.md, agree18).
#include <algorithm>

#include "geometry/accel.h"

namespace rc {

namespace {
using offset::kAbsoluteFloor;
using offset::kRelativeOffset;
}  // namespace

Vec3 Accel::offsetOrigin(const Vec3& p, const Vec3& ng, const Vec3& d) {
  return offset::offsetBy(p, ng, d, std::max(kRelativeOffset * maxAbs(p), kAbsoluteFloor));
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
