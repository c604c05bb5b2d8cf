// ref::brdfDot: exact reproduction of tables linear in the lookup coordinates, an analytic mirror
// kernel (checks the parabolic maps and the φ_o rotation direction), 1-D isotropic == 2-D table
// of the same function, horizon, lower table order, validation, Range.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "sh/reference.h"
#include "sh_test_util.h"

namespace rc {
namespace {

using shtest::kPi;
using V3 = std::array<double, 3>;

// The mirror kernel: F_i(ω_o) = y_i(ω_r), ω_r = (−x, −y, z). Then Λ·F = Σ Λ_i y_i(ω_r): the
// radiance function seen in the mirror direction — analytic, and isotropic (turning ω_o about z
// turns F the same way), so it fits both table kinds.
std::vector<double> mirrorCoeffs(int order, const V3& wo) {
  std::vector<double> y(order * order);
  sh::evalBasis(order, -wo[0], -wo[1], wo[2], y.data());
  return y;
}

void appendIsotropicTable(BrdfDotBatch& b, int order, int T) {
  b.tables.push_back({RC_TABLE_ISOTROPIC_1D, order, T, static_cast<int>(b.tableData.size())});
  for (int t = 0; t < T; ++t) {
    const double theta = 2 * std::atan(double(t) / (T - 1));
    const auto y = mirrorCoeffs(order, {std::sin(theta), 0, std::cos(theta)});
    for (int c = 0; c < 3; ++c)
      for (double v : y) b.tableData.push_back(float(v * (1 + 0.5 * c)));  // channels differ
  }
}

void appendAnisotropicTable(BrdfDotBatch& b, int order, int S) {
  b.tables.push_back({RC_TABLE_ANISOTROPIC_2D, order, S, static_cast<int>(b.tableData.size())});
  for (int iy = 0; iy < S; ++iy)
    for (int ix = 0; ix < S; ++ix) {
      const double px = -1 + 2.0 * ix / (S - 1), py = -1 + 2.0 * iy / (S - 1), r2 = px * px + py * py;
      V3 w;
      if (r2 < 1) {  // inverse parabolic map: ω = (2px, 2py, 1 − r²) / (1 + r²)
        w = {2 * px / (1 + r2), 2 * py / (1 + r2), (1 - r2) / (1 + r2)};
      } else {  // outside the disk: the horizon direction of the same azimuth
        const double r = std::sqrt(r2);
        w = {px / r, py / r, 0};
      }
      const auto y = mirrorCoeffs(order, w);
      for (int c = 0; c < 3; ++c)
        for (double v : y) b.tableData.push_back(float(v * (1 + 0.5 * c)));
    }
}

BrdfDotBatch randomPoints(int order, int P, uint64_t seed, double minZ) {
  Rng rng(seed);
  BrdfDotBatch b;
  b.order = order;
  b.points = P;
  for (int i = 0; i < 3 * order * order * P; ++i) b.lambda.push_back(2 * rng.nextFloat() - 1);
  for (int p = 0; p < P; ++p) {
    V3 w;
    do w = shtest::randomDirection(rng);
    while (w[2] < minZ);
    for (double v : w) b.wo.push_back(float(v));
    b.material.push_back(0);
  }
  return b;
}

double mirrorDot(const BrdfDotBatch& b, int p, int c, int tableOrder) {
  const V3 w = {b.wo[3 * p], b.wo[3 * p + 1], b.wo[3 * p + 2]};
  const auto y = mirrorCoeffs(tableOrder, w);
  const int n2 = b.order * b.order, common = std::min(b.order, tableOrder);
  double s = 0;
  for (int i = 0; i < common * common; ++i) s += b.lambda[3 * n2 * p + c * n2 + i] * y[i];
  return s * (1 + 0.5 * c);
}

// Lookup error of the analytic kernel: linear interpolation in x = tan(θ/2) on T nodes errs by
// ≤ Δx²/8 · |∂²F/∂x²|, with |dθ/dx| ≤ 2 and |∂²y/∂θ²| ≲ l² |y|: for T = 256, l ≤ 5:
// (1/255)²/8 · 4 · 25 ≈ 2e-4 per coefficient; the dot with 36 coefficients |Λ_i| ≤ 1 (mean ½)
// and channel factor ≤ 2: ≲ 7e-3. Bilinear 2-D on S = 257 nodes spaced 2/256 is the same order
// (the horizon nodes only matter within one cell of the disk's edge, excluded by ω_o.z ≥ 0.1).
// Measured max: 1.9e-3. A wrong map or rotation direction gives O(1) errors.
constexpr double kLookupTol = 8e-3;

TEST(RefBrdfDot, IsotropicTableReproducesMirrorKernel) {
  constexpr int order = 6;
  BrdfDotBatch b = randomPoints(order, 200, 61, 0.1);
  appendIsotropicTable(b, order, 256);
  std::vector<float> out;
  ref::brdfDot(b, out);
  for (int p = 0; p < b.points; ++p)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[3 * p + c], mirrorDot(b, p, c, order), kLookupTol) << p;
}

TEST(RefBrdfDot, AnisotropicTableReproducesMirrorKernel) {
  constexpr int order = 6;
  BrdfDotBatch b = randomPoints(order, 200, 67, 0.1);
  appendAnisotropicTable(b, order, 257);
  std::vector<float> out;
  ref::brdfDot(b, out);
  for (int p = 0; p < b.points; ++p)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[3 * p + c], mirrorDot(b, p, c, order), kLookupTol) << p;
}

TEST(RefBrdfDot, IsotropicEqualsAnisotropicTableOfSameFunction) {
  constexpr int order = 6;
  BrdfDotBatch b = randomPoints(order, 200, 71, 0.1);
  appendIsotropicTable(b, order, 256);
  appendAnisotropicTable(b, order, 257);
  std::vector<float> iso, aniso;
  ref::brdfDot(b, iso);
  for (int32_t& m : b.material) m = 1;
  ref::brdfDot(b, aniso);
  for (size_t i = 0; i < iso.size(); ++i) EXPECT_NEAR(iso[i], aniso[i], 2 * kLookupTol) << i;
}

// Tables linear in the lookup coordinates are reproduced exactly by linear/bilinear lookup, which
// pins the coordinate maps and the grid scaling (x_t = t/(T−1); x_i = −1 + 2i/(S−1)) to float
// rounding: 1e-5 for sums of ~100 unit-size products.
TEST(RefBrdfDot, LinearTablesAreExact) {
  constexpr int order = 4, n2 = order * order, T = 9, S = 7;
  BrdfDotBatch b = randomPoints(order, 50, 73, 0.0);
  Rng rng(74);
  std::vector<double> a(3 * n2), g(3 * n2), h(3 * n2);
  for (int i = 0; i < 3 * n2; ++i) {
    a[i] = rng.nextDouble() - 0.5;
    g[i] = rng.nextDouble() - 0.5;
    h[i] = rng.nextDouble() - 0.5;
  }
  b.tables.push_back({RC_TABLE_ISOTROPIC_1D, order, T, 0});
  for (int t = 0; t < T; ++t)
    for (int i = 0; i < 3 * n2; ++i) b.tableData.push_back(float(a[i] + g[i] * t / (T - 1)));
  b.tables.push_back({RC_TABLE_ANISOTROPIC_2D, order, S, static_cast<int>(b.tableData.size())});
  for (int iy = 0; iy < S; ++iy)
    for (int ix = 0; ix < S; ++ix)
      for (int i = 0; i < 3 * n2; ++i)
        b.tableData.push_back(float(a[i] + g[i] * (-1 + 2.0 * ix / (S - 1)) + h[i] * (-1 + 2.0 * iy / (S - 1))));
  std::vector<float> iso, aniso;
  ref::brdfDot(b, iso);
  for (int32_t& m : b.material) m = 1;
  ref::brdfDot(b, aniso);
  for (int p = 0; p < b.points; ++p) {
    const double wx = b.wo[3 * p], wy = b.wo[3 * p + 1], wz = b.wo[3 * p + 2];
    const double x = std::sqrt(wx * wx + wy * wy) / (1 + wz), px = wx / (1 + wz), py = wy / (1 + wz);
    // 1-D: F(x) at φ = 0, turned about z by φ_o with the general rotation (independent path).
    std::vector<double> F(3 * n2), Fr(3 * n2), bands;
    for (int i = 0; i < 3 * n2; ++i) F[i] = a[i] + g[i] * x;
    const auto Rz = shtest::axisAngle({0, 0, 1}, std::atan2(wy, wx));
    sh::rotationMatrix(order, Rz.data(), bands);
    for (int c = 0; c < 3; ++c) sh::applyRotation(order, bands, F.data() + c * n2, Fr.data() + c * n2);
    for (int c = 0; c < 3; ++c) {
      double e1 = 0, e2 = 0;
      for (int i = 0; i < n2; ++i) {
        const double lam = b.lambda[3 * n2 * p + c * n2 + i];
        e1 += lam * Fr[c * n2 + i];
        e2 += lam * (a[c * n2 + i] + g[c * n2 + i] * px + h[c * n2 + i] * py);
      }
      if (wz > 0) {
        EXPECT_NEAR(iso[3 * p + c], e1, 1e-5) << p;
        EXPECT_NEAR(aniso[3 * p + c], e2, 1e-5) << p;
      } else {
        EXPECT_EQ(iso[3 * p + c], 0.0f);
        EXPECT_EQ(aniso[3 * p + c], 0.0f);
      }
    }
  }
}

TEST(RefBrdfDot, BelowHorizonLowerTableOrderValidationAndRange) {
  constexpr int order = 6;
  BrdfDotBatch b = randomPoints(order, 20, 79, 0.1);
  appendIsotropicTable(b, 3, 64);  // table order 3 < batch order 6: the rest counts as zero
  b.wo[2] = -0.5f;                 // point 0 below the horizon
  std::vector<float> out;
  ref::brdfDot(b, out);
  EXPECT_EQ(out[0], 0.0f);
  for (int p = 1; p < b.points; ++p)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[3 * p + c], mirrorDot(b, p, c, 3), 0.02) << p;

  std::vector<float> part(3 * b.points, -7.0f);
  ref::brdfDotRange(b, part, 5, 9);
  for (int i = 0; i < 3 * b.points; ++i) EXPECT_EQ(part[i] == -7.0f, i < 15 || i >= 27);

  BrdfDotBatch bad = b;
  bad.material[3] = 1;
  EXPECT_THROW(ref::brdfDot(bad, out), Error);
  bad = b;
  bad.tables[0].res = 65;  // runs past tableData
  EXPECT_THROW(ref::brdfDot(bad, out), Error);
  bad = b;
  bad.tables[0].kind = 7;
  EXPECT_THROW(ref::brdfDot(bad, out), Error);
  bad = b;
  bad.wo.pop_back();
  EXPECT_THROW(ref::brdfDot(bad, out), Error);
}

}  // namespace
}  // namespace rc
