#include "geometry/sphere_intersect.h"

namespace rc {

bool intersectSphere(const Vec3& o, const Vec3& d, const Vec3& center, float radius, float tMin, float tMax,
                     float& tHit) {
  // Double precision costs little here and keeps huge/tiny scales exact enough.
  const glm::dvec3 dd(d), f = glm::dvec3(o) - glm::dvec3(center);
  const double a = glm::dot(dd, dd);
  if (!(a > 0.0)) return false;
  const double r = radius;
  const double bPrime = -glm::dot(f, dd);          // −b/2
  const glm::dvec3 perp = f + (bPrime / a) * dd;    // centre→closest point on the ray line
  const double disc = a * (r * r - glm::dot(perp, perp));
  if (disc < 0.0) return false;
  const double c = glm::dot(f, f) - r * r;
  const double q = bPrime + std::copysign(std::sqrt(disc), bPrime);
  double t0, t1;
  if (q == 0.0) {  // ray through the centre with the origin on the sphere: both roots are 0
    t0 = t1 = 0.0;
  } else {
    t0 = c / q;
    t1 = q / a;
  }
  if (t0 > t1) std::swap(t0, t1);
  if (t0 > tMin && t0 < tMax) {
    tHit = static_cast<float>(t0);
    return true;
  }
  if (t1 > tMin && t1 < tMax) {
    tHit = static_cast<float>(t1);
    return true;
  }
  return false;
}

}  // namespace rc
