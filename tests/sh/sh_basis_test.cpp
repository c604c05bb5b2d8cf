// SH basis evaluation: orthonormality by exact quadrature, closed forms, an independent
// evaluation via std::sph_legendre, poles, and order validation.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "sh_test_util.h"

namespace rc {
namespace {

using shtest::kPi;

// Gram matrix G_ij = ∫ y_i y_j dω by a quadrature exact for the band limit, so G − I is pure
// rounding: double ~ (number of nodes) · ε · max|y|² ≈ 1e-14 ≪ 1e-12; float: each y_i carries
// ~order·ε_f ≈ 20 · 6e-8 relative error from the recurrence ⇒ |ΔG| ≲ 2·20·6e-8 ≈ 2.4e-6 < 1e-5.
template <class T>
double orthonormalityError(int order) {
  const shtest::SphereQuadrature q(order);
  const int n2 = order * order;
  std::vector<double> G(n2 * n2, 0.0);
  std::vector<T> y(n2);
  for (size_t s = 0; s < q.dirs.size(); ++s) {
    const auto& d = q.dirs[s];
    sh::evalBasis(order, T(d[0]), T(d[1]), T(d[2]), y.data());
    for (int i = 0; i < n2; ++i)
      for (int j = 0; j <= i; ++j) G[i * n2 + j] += q.weights[s] * double(y[i]) * double(y[j]);
  }
  double err = 0;
  for (int i = 0; i < n2; ++i)
    for (int j = 0; j <= i; ++j) err = std::fmax(err, std::fabs(G[i * n2 + j] - (i == j ? 1.0 : 0.0)));
  return err;
}

TEST(ShBasis, OrthonormalDoubleToOrder20) {
  for (int order : {1, 2, 5, 10, 16, 20}) EXPECT_LT(orthonormalityError<double>(order), 1e-12) << order;
}

TEST(ShBasis, OrthonormalFloatToOrder20) {
  for (int order : {1, 10, 20}) EXPECT_LT(orthonormalityError<float>(order), 1e-5) << order;
}

TEST(ShBasis, ClosedFormsToBand2) {
  // Sloan, "Stupid SH tricks", Appendix A2 (Condon–Shortley phase included).
  const double c0 = std::sqrt(1 / (4 * kPi)), c1 = std::sqrt(3 / (4 * kPi));
  const double c2 = std::sqrt(15 / (4 * kPi)), c20 = std::sqrt(5 / (16 * kPi)), c22 = std::sqrt(15 / (16 * kPi));
  Rng rng(7);
  for (int t = 0; t < 100; ++t) {
    const auto d = shtest::randomDirection(rng);
    const double x = d[0], y = d[1], z = d[2];
    double v[9];
    sh::evalBasis(3, x, y, z, v);
    const double expect[9] = {c0,         -c1 * y,    c1 * z,     -c1 * x,    c2 * x * y,
                              -c2 * y * z, c20 * (3 * z * z - 1), -c2 * x * z, c22 * (x * x - y * y)};
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(v[i], expect[i], 1e-15) << i;
    float vf[9];
    sh::evalBasis(3, float(x), float(y), float(z), vf);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(vf[i], expect[i], 1e-6) << i;
  }
}

// Independent evaluation: std::sph_legendre(l, m, θ) = (−1)^m K_l^m P_l^m(cos θ) (libstdc++ C++17
// special functions, Condon–Shortley phase included); y = √2 · that · cos/sin(mφ).
TEST(ShBasis, MatchesStdSphLegendreToOrder20) {
  constexpr int order = 20;
  Rng rng(11);
  std::vector<double> v(order * order);
  double maxErr = 0;
  for (int t = 0; t < 200; ++t) {
    const auto d = shtest::randomDirection(rng);
    sh::evalBasis(order, d[0], d[1], d[2], v.data());
    const double theta = std::acos(d[2]), phi = std::atan2(d[1], d[0]);
    for (int l = 0; l < order; ++l)
      for (int m = -l; m <= l; ++m) {
        const double p = std::sph_legendre(l, std::abs(m), theta);
        const double e = m == 0 ? p : (m > 0 ? std::sqrt(2.0) * p * std::cos(m * phi) : std::sqrt(2.0) * p * std::sin(-m * phi));
        maxErr = std::fmax(maxErr, std::fabs(v[sh::index(l, m)] - e));
      }
  }
  // |y| ≤ √((2l+1)/4π) ≈ 1.2; both sides are accurate to ~1e-14 (libstdc++ uses a similar recurrence).
  EXPECT_LT(maxErr, 1e-12);
}

TEST(ShBasis, PolesAreExactAndFinite) {
  constexpr int order = 20;
  for (double z : {1.0, -1.0}) {
    std::vector<double> v(order * order);
    sh::evalBasis(order, 0.0, 0.0, z, v.data());
    for (int l = 0; l < order; ++l)
      for (int m = -l; m <= l; ++m) {
        const double val = v[sh::index(l, m)];
        ASSERT_TRUE(std::isfinite(val));
        if (m != 0) {
          EXPECT_EQ(val, 0.0);
        } else {  // y_l^0(pole) = √((2l+1)/4π) · (±1)^l
          EXPECT_NEAR(val, std::sqrt((2 * l + 1) / (4 * kPi)) * std::pow(z, l), 1e-13);
        }
      }
  }
}

TEST(ShBasis, RejectsBadOrder) {
  double v[4];
  EXPECT_THROW(sh::evalBasis(0, 0.0, 0.0, 1.0, v), Error);
  std::vector<double> big(21 * 21);
  EXPECT_THROW(sh::evalBasis(21, 0.0, 0.0, 1.0, big.data()), Error);
}

}  // namespace
}  // namespace rc
