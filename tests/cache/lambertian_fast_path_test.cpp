// RadianceCache::cosineIrradiance (the Lambertian fast path of the cache engine) against the
// kernels' contract: interpolate (rotation into the point's frame, gradient adjustment, weighted
// average; scalar reference) followed by the clamped-cosine integral ∫ L(ω) max(cos θ, 0) dω of
// the interpolated SH function, done by brute-force quadrature.
#include <gtest/gtest.h>

#include <cmath>

#include "cache/radiance_cache.h"
#include "core/rng.h"
#include "sh/reference.h"
#include "sh/sh_basis.h"

namespace rc {
namespace {

void frameRows(const Frame& f, float* out) {
  const Vec3 rows[3] = {f.t, f.b, f.n};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[3 * r + c] = rows[r][c];
}

// ∫_{z>0} Σ_i Λ_c,i y_i(ω) cos θ dω by a midpoint rule in (cos θ, φ): exact to ~1e-6 for order 3.
Color clampedCosineIntegral(const float* lambda) {
  const int nt = 400, np = 400;
  double acc[3] = {0, 0, 0};
  double y[9];
  for (int i = 0; i < nt; ++i) {
    const double z = (i + 0.5) / nt, s = std::sqrt(1 - z * z);
    for (int j = 0; j < np; ++j) {
      const double phi = 2 * kPiD * (j + 0.5) / np;
      sh::evalBasis(3, s * std::cos(phi), s * std::sin(phi), z, y);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 9; ++k) acc[c] += lambda[9 * c + k] * y[k] * z;
    }
  }
  const double dA = (1.0 / nt) * (2 * kPiD / np);
  return Color(float(acc[0] * dA), float(acc[1] * dA), float(acc[2] * dA));
}

TEST(LambertianFastPath, EqualsInterpolateThenCosineIntegral) {
  Rng rng(17, 4);
  auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * rng.nextFloat(); };
  for (bool gradients : {true, false}) {
    RadianceCache cache(3, Vec3(-2), Vec3(2));
    // Records around the origin with normals tilted up to ~25° from +z, random Λ and gradients.
    std::vector<RecordInfo> infos;
    std::vector<float> lambda, gradT, gradB;
    for (int r = 0; r < 12; ++r) {
      RecordInfo info;
      info.p = Vec3(uniform(-0.3f, 0.3f), uniform(-0.3f, 0.3f), uniform(-0.02f, 0.02f));
      info.frame = Frame::fromNormal(glm::normalize(Vec3(uniform(-0.4f, 0.4f), uniform(-0.4f, 0.4f), 1.0f)));
      info.R = 2.0f;
      info.a = 0.5f;
      infos.push_back(info);
      for (int k = 0; k < 27; ++k) {
        lambda.push_back(k % 9 == 0 ? uniform(1.0f, 3.0f) : uniform(-0.5f, 0.5f));
        gradT.push_back(uniform(-1.0f, 1.0f));
        gradB.push_back(uniform(-1.0f, 1.0f));
      }
    }
    cache.insert(infos, lambda, gradT, gradB, {}, {}, {}, false);
    int tested = 0;
    for (int q = 0; q < 20; ++q) {
      const Vec3 p(uniform(-0.2f, 0.2f), uniform(-0.2f, 0.2f), 0.0f);
      const Frame f = Frame::fromNormal(glm::normalize(Vec3(uniform(-0.3f, 0.3f), uniform(-0.3f, 0.3f), 1.0f)));
      Lookup lk;
      cache.lookup(p, f.n, lk);
      if (lk.entries.size() < 2) continue;
      ++tested;
      InterpolateBatch ib;
      ib.order = 3;
      ib.worldFrame = false;
      ib.gradients = gradients;
      ib.records = static_cast<int>(infos.size());
      ib.lambda = lambda;
      if (gradients) ib.gradT = gradT, ib.gradB = gradB;
      ib.recordFrames.resize(9 * infos.size());
      for (size_t r = 0; r < infos.size(); ++r) frameRows(infos[r].frame, &ib.recordFrames[9 * r]);
      ib.points = 1;
      ib.pointFrames.resize(9);
      frameRows(f, ib.pointFrames.data());
      ib.offsets = {0, static_cast<int32_t>(lk.entries.size())};
      ib.entries = lk.entries;
      std::vector<float> interpolated;
      ref::interpolate(ib, interpolated);
      const Color expect = clampedCosineIntegral(interpolated.data());
      const Color got = cache.cosineIrradiance(lk, f.n, gradients);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], expect[c], 1e-3f * (std::fabs(expect[c]) + 1.0f)) << "gradients " << gradients << " query " << q;
    }
    EXPECT_GE(tested, 10);
  }
  // No contributions: zero, never a division by zero.
  RadianceCache empty(3, Vec3(-1), Vec3(1));
  Lookup none;
  empty.lookup(Vec3(0.0f), Vec3(0, 0, 1), none);
  EXPECT_EQ(empty.cosineIrradiance(none, Vec3(0, 0, 1), true), Color(0.0f));
}

}  // namespace
}  // namespace rc
