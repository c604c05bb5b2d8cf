#pragma once
// Brute-force integration over the upper hemisphere for validating the tables: a midpoint product
// grid in a frame around the mirror direction of ω_o, polar angle θ' = π·u² (u uniform), so the
// grid is fine where sharp lobes live (spacing ~2πu/n_u rad) yet covers the whole sphere. It
// shares nothing with the importance-sampled projection (no BSDF sampling, no pdf).
#include <cmath>
#include <mutex>
#include <vector>

#include "bsdf/bsdf.h"
#include "core/parallel.h"

namespace rc::test {

// Calls acc.add(wi, g·dω) for every grid point with wi.z > 0, on per-thread copies of `zero`
// merged at the end: Acc provides add(const glm::dvec3& wi, const double gdw[3]) and merge(const Acc&).
template <typename Acc>
Acc bruteForce(const Bsdf& bsdf, const Vec3& wo, int nu, int nphi, const Acc& zero) {
  const Vec3 r = glm::normalize(Vec3(-wo.x, -wo.y, wo.z));
  // Orthonormal frame (a, b, r).
  const Vec3 helper = std::fabs(r.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const glm::dvec3 rr(r), a = glm::normalize(glm::cross(glm::dvec3(helper), rr)), b = glm::cross(rr, a);
  std::mutex lock;
  Acc total = zero;
  parallelFor(static_cast<size_t>(nu), 16, [&](size_t begin, size_t end) {
    Acc acc = zero;
    for (size_t iu = begin; iu < end; ++iu) {
      const double u = (iu + 0.5) / nu, theta = kPiD * u * u;
      const double dA = std::sin(theta) * (2.0 * kPiD * u / nu) * (2.0 * kPiD / nphi);
      for (int k = 0; k < nphi; ++k) {
        const double phi = 2.0 * kPiD * (k + 0.5) / nphi;
        const glm::dvec3 w = std::sin(theta) * (std::cos(phi) * a + std::sin(phi) * b) + std::cos(theta) * rr;
        if (w.z <= 0) continue;
        const Vec3 wi(w);
        const Color g = bsdf.eval(wo, wi);
        const double gdw[3] = {g.r * dA, g.g * dA, g.b * dA};
        acc.add(w, gdw);
      }
    }
    std::lock_guard<std::mutex> guard(lock);
    total.merge(acc);
  });
  return total;
}

}  // namespace rc::test
