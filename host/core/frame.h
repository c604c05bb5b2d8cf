#pragma once
// Local shading frame (t, b, n), right-handed, z = normal (ARCHITECTURE.md §Conventions).
#include "core/math.h"

namespace rc {

struct Frame {
  Vec3 t{1, 0, 0}, b{0, 1, 0}, n{0, 0, 1};

  Frame() = default;
  Frame(const Vec3& t_, const Vec3& b_, const Vec3& n_) : t(t_), b(b_), n(n_) {}

  // Duff et al. 2017, "Building an Orthonormal Basis, Revisited": continuous except at n.z = -0 sign flip.
  static Frame fromNormal(const Vec3& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    Frame f;
    f.t = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.b = Vec3(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
  }

  // Frame from a normal and a (not necessarily orthogonal) tangent, e.g. the mesh's dp/du.
  static Frame fromNormalTangent(const Vec3& n, const Vec3& tangent) {
    Vec3 t = tangent - n * glm::dot(n, tangent);
    const float len = glm::length(t);
    if (!(len > 1e-6f)) return fromNormal(n);
    t /= len;
    return Frame(t, glm::cross(n, t), n);
  }

  Vec3 toLocal(const Vec3& v) const { return Vec3(glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)); }
  Vec3 toWorld(const Vec3& v) const { return t * v.x + b * v.y + n * v.z; }

  // The rows t, b, n of the world-to-local rotation, row-major (the kernels' frame layout).
  void rows(float* out) const {
    const Vec3 r[3] = {t, b, n};
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) out[3 * i + c] = r[i][c];
  }
};

}  // namespace rc
