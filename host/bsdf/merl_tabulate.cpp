#include "bsdf/merl_tabulate.h"

#include <cmath>

#include "core/error.h"
#include "core/parallel.h"

namespace rc {

MerlData tabulateMerl(const BrdfFunction& f, int thetaHalfRes, int thetaDiffRes, int phiDiffRes) {
  if (thetaHalfRes < 1 || thetaDiffRes < 1 || phiDiffRes < 1 || thetaHalfRes > kMerlMaxAxis ||
      thetaDiffRes > kMerlMaxAxis || phiDiffRes > kMerlMaxAxis)
    throw Error("tabulateMerl: dimensions outside 1.." + std::to_string(kMerlMaxAxis));
  MerlData d;
  d.thetaHalfRes = thetaHalfRes;
  d.thetaDiffRes = thetaDiffRes;
  d.phiDiffRes = phiDiffRes;
  d.values.assign(3 * d.nodeCount(), 0.0f);
  parallelFor(size_t(thetaHalfRes), 1, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
      for (int j = 0; j < thetaDiffRes; ++j)
        for (int k = 0; k < phiDiffRes; ++k) {
          Vec3 wi, wo;
          directionsFromHalfDiff(d.nodeThetaHalf(int(i)), d.nodeThetaDiff(j), d.nodePhiDiff(k), &wi, &wo);
          if (!(wi.z > 0.0f && wo.z > 0.0f)) continue;
          const Color v = f(wi, wo);
          for (int c = 0; c < 3; ++c) d.values[d.index(c, int(i), j, k)] = std::isfinite(v[c]) && v[c] > 0 ? v[c] : 0.0f;
        }
  });
  return d;
}

BrdfFunction brdfOf(const Bsdf& bsdf) {
  if (!bsdf.isotropic()) throw Error("MERL tables hold isotropic BRDFs; '" + bsdf.id + "' is anisotropic");
  return [&bsdf](const Vec3& wi, const Vec3& wo) { return bsdf.eval(wo, wi) / wi.z; };
}

Color RetroReflectiveLobe::operator()(const Vec3& wi, const Vec3& wo) const {
  const double cosAngle = std::fmax(-1.0, std::fmin(1.0, double(glm::dot(wi, wo))));
  const double thetaDiff = 0.5 * std::acos(cosAngle);
  const double t = thetaDiff / width;
  return diffuse * kInvPi + retro * float(std::exp(-t * t));
}

}  // namespace rc
