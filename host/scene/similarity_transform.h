#pragma once
// Whether an affine map keeps a sphere a sphere (and a round tube round): the shape builder's
// spheres and the instance placement of spheres and curves ask it.
#include <cmath>

#include "core/math.h"

namespace rc {

// True when the linear part of m is a rotation (or mirror) times a uniform scale and the projective
// row is (0 0 0 1); scale is then that factor. Tolerance 1e-4 relative: far above float rounding
// of composed rotate/scale ops (~1e-6), far below any intended anisotropy.
inline bool similarity(const Mat4& m, float& scale) {
  if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f) return false;
  const Vec3 c[3] = {Vec3(m[0]), Vec3(m[1]), Vec3(m[2])};
  const float s = glm::length(c[0]);
  if (!(s > 0.0f)) return false;
  for (int i = 0; i < 3; ++i) {
    if (std::fabs(glm::length(c[i]) - s) > 1e-4f * s) return false;
    for (int j = i + 1; j < 3; ++j)
      if (std::fabs(glm::dot(c[i], c[j])) > 1e-4f * s * s) return false;
  }
  scale = s;
  return true;
}

}  // namespace rc
