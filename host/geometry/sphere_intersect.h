#pragma once
// Exact ray–sphere intersection with a numerically robust quadratic (Haines et al., "Precision
// Improvements for Ray/Sphere Intersection", Ray Tracing Gems ch. 7): the discriminant is computed
// from the perpendicular distance of the centre to the ray, and the smaller root from c/q, so neither
// catastrophic cancellation nor a far-away ray origin loses the hit.
#include "core/math.h"

namespace rc {

// Nearest root t in (tMin, tMax) of |o + t d − c| = r; returns false when there is none.
bool intersectSphere(const Vec3& o, const Vec3& d, const Vec3& center, float radius, float tMin, float tMax,
                     float& tHit);

}  // namespace rc
