// SH rotation (Ivanic–Ruedenberg): direction convention pinned by quadrature, evaluation at
// rotated directions, inverse, energy, special angles, fast paths, float path, chained drift.
#include <gtest/gtest.h>

#include <cmath>

#include "sh_test_util.h"

namespace rc {
namespace {

using shtest::Mat3;

std::vector<double> rotated(int order, const Mat3& R, const std::vector<double>& c) {
  std::vector<double> bands, out(c.size());
  sh::rotationMatrix(order, R.data(), bands);
  sh::applyRotation(order, bands, c.data(), out.data());
  return out;
}

double maxAbsDiff(const std::vector<double>& a, const std::vector<double>& b) {
  double e = 0;
  for (size_t i = 0; i < a.size(); ++i) e = std::fmax(e, std::fabs(a[i] - b[i]));
  return e;
}

// The convention f'(ω) = f(R⁻¹ω), pinned independently of evaluation at points: project
// g(ω) = f(R⁻¹ω) by exact quadrature (g is band limited to the same order) and compare.
TEST(ShRotation, ConventionPinnedByQuadrature) {
  constexpr int order = 8;
  Rng rng(3);
  const shtest::SphereQuadrature q(order);
  for (int t = 0; t < 3; ++t) {
    const Mat3 R = shtest::randomRotation(rng);
    const Mat3 Rinv = shtest::transpose(R);
    const auto c = shtest::randomCoeffs(rng, order * order);
    std::vector<double> proj(order * order, 0.0), y(order * order);
    for (size_t s = 0; s < q.dirs.size(); ++s) {
      const double g = shtest::evalFunction(order, c, shtest::apply(Rinv, q.dirs[s]));
      sh::evalBasis(order, q.dirs[s][0], q.dirs[s][1], q.dirs[s][2], y.data());
      for (int i = 0; i < order * order; ++i) proj[i] += q.weights[s] * g * y[i];
    }
    EXPECT_LT(maxAbsDiff(proj, rotated(order, R, c)), 1e-12);
  }
}

// Σ c'_i y_i(ω) = Σ c_i y_i(R⁻¹ω) at random ω, orders up to 20. Rounding: the recurrence
// carries O(l·ε) relative error per entry; |f| ≲ Σ|c_i||y_i| ≈ 400 · 1 ⇒ 1e-10 has ample margin.
TEST(ShRotation, RotateThenEvaluateEqualsEvaluateAtRotatedDirection) {
  Rng rng(5);
  for (int order : {1, 2, 3, 5, 10, 16, 20}) {
    for (int t = 0; t < 5; ++t) {
      const Mat3 R = shtest::randomRotation(rng);
      const auto c = shtest::randomCoeffs(rng, order * order);
      const auto cr = rotated(order, R, c);
      for (int k = 0; k < 10; ++k) {
        const auto w = shtest::randomDirection(rng);
        const double expect = shtest::evalFunction(order, c, shtest::apply(shtest::transpose(R), w));
        EXPECT_NEAR(shtest::evalFunction(order, cr, w), expect, 1e-10) << "order " << order;
      }
    }
  }
}

TEST(ShRotation, InverseRestoresAndEnergyPerBandIsPreserved) {
  constexpr int order = 20;
  Rng rng(9);
  for (int t = 0; t < 5; ++t) {
    const Mat3 R = shtest::randomRotation(rng);
    const auto c = shtest::randomCoeffs(rng, order * order);
    const auto cr = rotated(order, R, c);
    EXPECT_LT(maxAbsDiff(rotated(order, shtest::transpose(R), cr), c), 1e-12);
    for (int l = 0; l < order; ++l) {
      double e0 = 0, e1 = 0;
      for (int m = -l; m <= l; ++m) {
        e0 += c[sh::index(l, m)] * c[sh::index(l, m)];
        e1 += cr[sh::index(l, m)] * cr[sh::index(l, m)];
      }
      EXPECT_NEAR(e1, e0, 1e-12 * (1 + e0)) << "band " << l;
    }
  }
}

// Awkward rotations: axis ≈ z, tiny angles about arbitrary axes, near-identity, exactly 180°.
TEST(ShRotation, SpecialRotations) {
  constexpr int order = 16;
  Rng rng(13);
  std::vector<Mat3> cases;
  for (double ang : {1e-12, 1e-8, 1e-5, 1e-3}) {
    cases.push_back(shtest::axisAngle({1e-9, 2e-9, 1}, 0.7));  // axis ≈ z (general path)
    cases.push_back(shtest::axisAngle({0.3, -0.2, 1}, ang));   // near identity
    cases.push_back(shtest::axisAngle({1, 0, 1e-6}, ang));
    cases.push_back(shtest::axisAngle({1e-7, 1e-7, 1}, shtest::kPi - ang));
  }
  for (auto axis : std::vector<std::array<double, 3>>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 2, 3}})
    cases.push_back(shtest::axisAngle(axis, shtest::kPi));
  for (const Mat3& R : cases) {
    const auto c = shtest::randomCoeffs(rng, order * order);
    const auto cr = rotated(order, R, c);
    for (double v : cr) ASSERT_TRUE(std::isfinite(v));
    for (int k = 0; k < 8; ++k) {
      const auto w = shtest::randomDirection(rng);
      EXPECT_NEAR(shtest::evalFunction(order, cr, w),
                  shtest::evalFunction(order, c, shtest::apply(shtest::transpose(R), w)), 1e-10);
    }
  }
}

TEST(ShRotation, ZFastPathEqualsGeneral) {
  constexpr int order = 20;
  Rng rng(17);
  for (double alpha : {0.0, 0.3, -1.2, shtest::kPi, 2.5}) {
    const Mat3 Rz = shtest::axisAngle({0, 0, 1}, alpha);
    const auto c = shtest::randomCoeffs(rng, order * order);
    std::vector<double> fast(c.size());
    sh::rotateZ(order, alpha, c.data(), fast.data());
    EXPECT_LT(maxAbsDiff(fast, rotated(order, Rz, c)), 1e-12) << alpha;
    double a = 0;
    EXPECT_TRUE(sh::isZRotation(Rz.data(), 1e-12, a));
    std::vector<double> viaChannels(c.size());
    sh::rotateChannels(order, Rz.data(), 1, c.data(), viaChannels.data());
    EXPECT_LT(maxAbsDiff(viaChannels, fast), 1e-12);
  }
  const Mat3 general = shtest::axisAngle({1, 0, 0}, 0.2);
  double a = 0;
  EXPECT_FALSE(sh::isZRotation(general.data(), 1e-7, a));
  EXPECT_FALSE(sh::isIdentityRotation(general.data(), 1e-7));
  const Mat3 I = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  EXPECT_TRUE(sh::isIdentityRotation(I.data(), 0.0));
}

// Float build/apply vs double: per entry of R^l the float recurrence accumulates ~ l·ε_f
// relative error on entries ≤ 1, and the apply sums 2l+1 terms of unit-size inputs ⇒
// |Δ| ≲ (2l+1) · l · 6e-8 ≈ 39·19·6e-8 ≈ 4.5e-5 at l = 19; measured far below, bound 1e-4.
TEST(ShRotation, FloatPathMatchesDouble) {
  constexpr int order = 20;
  Rng rng(19);
  std::vector<float> bandsF(sh::rotationMatrixSize(order));
  for (int t = 0; t < 10; ++t) {
    const Mat3 R = shtest::randomRotation(rng);
    float Rf[9];
    for (int i = 0; i < 9; ++i) Rf[i] = float(R[i]);
    double Rd[9];  // the same (float-rounded) rotation in double, so only arithmetic differs
    for (int i = 0; i < 9; ++i) Rd[i] = Rf[i];
    const auto c = shtest::randomCoeffs(rng, order * order);
    std::vector<float> cf(c.begin(), c.end()), outF(c.size());
    std::vector<double> cd(cf.begin(), cf.end()), outD(c.size()), bands;
    sh::rotationMatrix(order, Rf, bandsF.data());
    sh::applyRotation(order, bandsF.data(), cf.data(), outF.data());
    sh::rotationMatrix(order, Rd, bands);
    sh::applyRotation(order, bands, cd.data(), outD.data());
    for (size_t i = 0; i < c.size(); ++i) EXPECT_NEAR(outF[i], outD[i], 1e-4) << i;
    // The RGB path (three channels per matrix pass) equals per-channel application.
    std::vector<float> rgb(3 * c.size()), rgbOut(rgb.size()), one(c.size());
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = float(rng.nextDouble() - 0.5);
    sh::rotateChannels(order, Rf, 3, rgb.data(), rgbOut.data());
    for (int ch = 0; ch < 3; ++ch) {
      sh::applyRotation(order, bandsF.data(), rgb.data() + ch * c.size(), one.data());
      for (size_t i = 0; i < c.size(); ++i) EXPECT_NEAR(rgbOut[ch * c.size() + i], one[i], 1e-6);
    }
  }
}

// 10⁴ chained random rotations applied one after another vs the single rotation by their exactly
// composed product (double 3×3 product). Each apply is orthogonal up to rounding, so errors
// random-walk: per step ~ c·ε·√(2l+1) relative, after K steps ~ √K times that. Bounds: double
// 1e-10 relative to ‖c‖ (random walk predicts ~1e-12; linear worst case K·ε·√39 ≈ 1.4e-11);
// float (order 10, the renderer's path): random walk predicts ~√1e4 · 3e-7 ≈ 3e-5, bound 1e-3.
TEST(ShRotation, ChainedRotationsDriftBounded) {
  constexpr int K = 10000;
  Rng rng(23);
  {
    constexpr int order = 20;
    auto c = shtest::randomCoeffs(rng, order * order);
    const auto c0 = c;
    Mat3 total = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    std::vector<double> bands, tmp(c.size());
    for (int k = 0; k < K; ++k) {
      const Mat3 R = shtest::randomRotation(rng);
      sh::rotationMatrix(order, R.data(), bands);
      sh::applyRotation(order, bands, c.data(), tmp.data());
      c.swap(tmp);
      total = shtest::matMul(R, total);
    }
    const auto direct = rotated(order, total, c0);
    const double drift = maxAbsDiff(c, direct) / shtest::norm(c0);
    EXPECT_LT(drift, 1e-10);
    std::printf("[ drift    ] double order 20, %d chained rotations: max |Δ| / ‖c‖ = %.3g\n", K, drift);
  }
  {
    constexpr int order = 10;
    const auto c0d = shtest::randomCoeffs(rng, order * order);
    std::vector<float> c(c0d.begin(), c0d.end()), tmp(c.size()), bands(sh::rotationMatrixSize(order));
    Mat3 total = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int k = 0; k < K; ++k) {
      const Mat3 R = shtest::randomRotation(rng);
      float Rf[9];
      for (int i = 0; i < 9; ++i) Rf[i] = float(R[i]);
      sh::rotationMatrix(order, Rf, bands.data());
      sh::applyRotation(order, bands.data(), c.data(), tmp.data());
      c.swap(tmp);
      total = shtest::matMul(R, total);
    }
    const auto direct = rotated(order, total, c0d);
    double drift = 0;
    for (size_t i = 0; i < c.size(); ++i) drift = std::fmax(drift, std::fabs(c[i] - direct[i]));
    drift /= shtest::norm(c0d);
    EXPECT_LT(drift, 1e-3);
    std::printf("[ drift    ] float order 10, %d chained rotations: max |Δ| / ‖c‖ = %.3g\n", K, drift);
  }
}

}  // namespace
}  // namespace rc
