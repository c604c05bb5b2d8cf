// Accuracy of the BRDF×cos tables: coefficients against brute force, dot products against direct
// integrals of L·f_r·cos, the white furnace, continuity of the lookup, 1-D vs 2-D tables, and the
// analytic clamped-cosine lobe of a Lambertian.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "brdf/lobe_projector.h"
#include "brdf/table_builder.h"
#include "brdf/table_layout.h"
#include "brute_force.h"
#include "core/rng.h"
#include "sh/sh_basis.h"
#include "test_bsdfs.h"

namespace rc {
namespace {

// Brute-force SH projection of the lobe (accumulator for bruteForce).
struct CoeffAcc {
  int order = 1;
  std::vector<double> c;  // [3][n2]
  double energy[3] = {0, 0, 0};
  void add(const glm::dvec3& w, const double gdw[3]) {
    const int n2 = order * order;
    std::vector<double> y(n2);
    sh::evalBasis(order, w.x, w.y, w.z, y.data());
    for (int ch = 0; ch < 3; ++ch)
      for (int i = 0; i < n2; ++i) c[ch * n2 + i] += gdw[ch] * y[i];
  }
  void merge(const CoeffAcc& o) {
    for (size_t i = 0; i < c.size(); ++i) c[i] += o.c[i];
  }
};

CoeffAcc bruteCoeffs(const Bsdf& bsdf, const Vec3& wo, int order, int nu = 700, int nphi = 1400) {
  CoeffAcc zero;
  zero.order = order;
  zero.c.assign(3 * order * order, 0.0);
  return test::bruteForce(bsdf, wo, nu, nphi, zero);
}

Vec3 dirFromAngles(double thetaDeg, double phiDeg) {
  const double t = thetaDeg * kPiD / 180, p = phiDeg * kPiD / 180;
  return Vec3(float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t)));
}

double norm(const std::vector<double>& v, int ch, int n2) {
  double s = 0;
  for (int i = 0; i < n2; ++i) s += v[ch * n2 + i] * v[ch * n2 + i];
  return std::sqrt(s);
}

// Importance-sampled coefficients at order 10 match brute force over the whole roughness range,
// at normal, oblique and grazing view. Measure: ‖F_IS − F_bf‖ / ‖F_bf‖ per channel (‖·‖ over the
// 100 coefficients). 2.5%: the QMC estimate with 4096 samples has 0.03–0.5% error for α ≤ 0.3
// and up to 2.2% for α = 1 at grazing view (a broad lobe's small high-band coefficients are
// integrated like a uniform quadrature); a real mistake (wrong pdf weight, missing cosine
// samples, wrong lobe) is off by ≫ 5%.
TEST(BrdfProjection, CoefficientsMatchBruteForceAtOrder10) {
  const int order = 10, n2 = order * order;
  for (float alpha : {0.05f, 0.1f, 0.3f, 1.0f}) {
    for (bool isGgx : {true, false}) {
      const auto bsdf = isGgx ? test::ggx(alpha) : test::beckmann(alpha);
      for (double theta : {0.0, 45.0, 80.0}) {
        const Vec3 wo = dirFromAngles(theta, 30.0);
        LobeProjection proj;
        projectLobe(*bsdf, wo, order, LobeQuadrature{}, proj);
        const CoeffAcc bf = bruteCoeffs(*bsdf, wo, order);
        for (int ch = 0; ch < 3; ++ch) {
          std::vector<double> diff(n2);
          for (int i = 0; i < n2; ++i) diff[i] = proj.coeffs[ch * n2 + i] - bf.c[ch * n2 + i];
          const double rel = norm(diff, 0, n2) / norm(bf.c, ch, n2);
          EXPECT_LT(rel, 0.025) << (isGgx ? "ggx" : "beckmann") << " alpha " << alpha << " theta " << theta << " ch " << ch;
        }
      }
    }
  }
}

// Random smooth incoming radiance: L = 1 + order-4 perturbation of amplitude ~0.3 per coefficient
// (positive-ish and O(1), so errors relative to the lobe albedo are meaningful).
std::vector<double> randomRadiance(int order, uint64_t seed) {
  Rng rng(seed);
  std::vector<double> L(3 * order * order);
  for (int ch = 0; ch < 3; ++ch)
    for (int i = 0; i < order * order; ++i)
      L[ch * order * order + i] = i == 0 ? std::sqrt(4 * kPiD) : 0.3 * (2 * rng.nextDouble() - 1);
  return L;
}

struct RadianceAcc {
  const std::vector<double>* L = nullptr;
  int order = 4;
  double sum[3] = {0, 0, 0}, albedo[3] = {0, 0, 0};
  void add(const glm::dvec3& w, const double gdw[3]) {
    const int n2 = order * order;
    double y[64];
    sh::evalBasis(order, w.x, w.y, w.z, y);
    for (int ch = 0; ch < 3; ++ch) {
      double l = 0;
      for (int i = 0; i < n2; ++i) l += (*L)[ch * n2 + i] * y[i];
      sum[ch] += l * gdw[ch];
      albedo[ch] += gdw[ch];
    }
  }
  void merge(const RadianceAcc& o) {
    for (int ch = 0; ch < 3; ++ch) sum[ch] += o.sum[ch], albedo[ch] += o.albedo[ch];
  }
};

// The quantity the renderer computes: Λ·F(ω_o) with F looked up from the table (rotated by φ_o),
// against ∫ L·f_r·cos by brute force. Order-4 L is exactly representable, so a table of order 4
// gives the exact integral up to (a) quadrature error of the table, (b) linear interpolation in
// x = tan(θ_o/2) between nodes. At nodes only (a): tolerance 1% of the albedo·⟨L⟩ scale. Between
// nodes (b) adds h²/8·|∂²I/∂x²| with h = 1/63; for α = 0.05 the lobe moves 2·Δθ ≈ 0.06 rad per
// cell, and I(x) has curvature ≲ 50·albedo (band-3 L over that path) → ≲ 0.2%; tolerance 2%.
TEST(BrdfTable, DotProductMatchesDirectIntegral) {
  const int order = 4, n2 = order * order, T = 64;
  for (float alpha : {0.05f, 0.2f, 1.0f}) {
    const auto bsdf = test::ggx(alpha);
    const std::vector<float> table = buildBrdfTable(*bsdf, RC_TABLE_ISOTROPIC_1D, order, T, LobeQuadrature{});
    const RcBrdfTable desc{RC_TABLE_ISOTROPIC_1D, order, T, 0};
    const std::vector<double> L = randomRadiance(order, 7 + static_cast<uint64_t>(alpha * 100));
    // Nodes (φ_o = 0, then a rotated copy) and in-between directions, up to 89°.
    struct Case { double theta, phi; bool node; };
    std::vector<Case> cases;
    for (int t : {0, 20, 45, 60, 62}) {
      const double theta = 2 * std::atan(double(t) / (T - 1)) * 180 / kPiD;
      cases.push_back({theta, 0.0, true});
      cases.push_back({theta, 137.0, true});  // node in x, any φ_o: exact rotation
    }
    for (double theta : {10.3, 33.7, 71.1, 85.5, 89.0}) cases.push_back({theta, -61.0, false});
    for (const Case& c : cases) {
      const Vec3 wo = dirFromAngles(c.theta, c.phi);
      std::vector<double> F;
      lookupTable(desc, table.data(), wo, F);
      RadianceAcc zero;
      zero.L = &L;
      zero.order = order;
      const RadianceAcc direct = test::bruteForce(*bsdf, wo, 600, 1200, zero);
      for (int ch = 0; ch < 3; ++ch) {
        double dot = 0;
        for (int i = 0; i < n2; ++i) dot += L[ch * n2 + i] * F[ch * n2 + i];
        const double scale = direct.albedo[ch];
        EXPECT_NEAR(dot, direct.sum[ch], (c.node ? 0.01 : 0.02) * scale)
            << "alpha " << alpha << " theta " << c.theta << " phi " << c.phi << " ch " << ch;
      }
    }
  }
}

// White furnace: L ≡ 1 (Λ = √(4π)·δ_i0) gives √(4π)·F_00 = directional albedo. Compared with an
// independent Monte Carlo albedo (mean of sample().weight, pseudo-random): tolerance 4 standard
// errors of that estimate plus 0.5% for the table's quadrature.
TEST(BrdfTable, WhiteFurnaceGivesAlbedo) {
  const int order = 3, T = 9;
  for (float alpha : {0.05f, 0.3f, 1.0f}) {
    const auto bsdf = test::ggx(alpha);
    const std::vector<float> table = buildBrdfTable(*bsdf, RC_TABLE_ISOTROPIC_1D, order, T, LobeQuadrature{});
    for (int t = 0; t < T; ++t) {
      const Vec3 wo = isotropicNodeDirection(t, T);
      Rng rng(1234, static_cast<uint64_t>(t));
      const int N = 200000;
      double s[3] = {0, 0, 0}, s2[3] = {0, 0, 0};
      for (int k = 0; k < N; ++k) {
        const auto bs = bsdf->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
        if (!bs || bs->wi.z <= 0) continue;
        for (int ch = 0; ch < 3; ++ch) s[ch] += bs->weight[ch], s2[ch] += double(bs->weight[ch]) * bs->weight[ch];
      }
      for (int ch = 0; ch < 3; ++ch) {
        const double mean = s[ch] / N, se = std::sqrt(std::max(0.0, s2[ch] / N - mean * mean) / N);
        const double tableAlbedo = std::sqrt(4 * kPiD) * table[(t * 3 + ch) * order * order];
        EXPECT_NEAR(tableAlbedo, mean, 4 * se + 0.005 * mean) << "alpha " << alpha << " node " << t << " ch " << ch;
      }
    }
  }
}

// Continuity: walking ω_o in tiny steps (θ over 0..89.9° at several φ, and φ across ±180° and
// around the pole) never jumps. A piecewise-linear lookup changes by at most
// (largest node-to-node change)·(step / node spacing) per step; a jump (wrong cell, wrong
// rotation branch, non-zonal pole) would exceed that bound.
TEST(BrdfTable, LookupIsContinuous) {
  const int order = 6, n2 = order * order, T = 32;
  const auto bsdf = test::ggx(0.2f);
  const std::vector<float> table = buildBrdfTable(*bsdf, RC_TABLE_ISOTROPIC_1D, order, T, LobeQuadrature{1024, 512});
  const RcBrdfTable desc{RC_TABLE_ISOTROPIC_1D, order, T, 0};
  double maxNodeStep = 0;  // in coefficient-vector norm, per unit x
  for (int t = 0; t + 1 < T; ++t) {
    double d = 0;
    for (int k = 0; k < 3 * n2; ++k) d += std::pow(table[(t + 1) * 3 * n2 + k] - table[t * 3 * n2 + k], 2);
    maxNodeStep = std::max(maxNodeStep, std::sqrt(d) * (T - 1));
  }
  // |∂F/∂φ| ≤ (order−1)·‖F‖ for a z-rotation (band l turns at rate ≤ l).
  double maxNorm = 0;
  for (int t = 0; t < T; ++t) {
    double d = 0;
    for (int k = 0; k < 3 * n2; ++k) d += double(table[t * 3 * n2 + k]) * table[t * 3 * n2 + k];
    maxNorm = std::max(maxNorm, std::sqrt(d));
  }
  auto dist = [&](const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0;
    for (size_t k = 0; k < a.size(); ++k) d += (a[k] - b[k]) * (a[k] - b[k]);
    return std::sqrt(d);
  };
  auto px = [](const Vec3& w) { return std::sqrt(double(w.x) * w.x + double(w.y) * w.y) / (1.0 + w.z); };
  std::vector<double> prev, cur;
  for (double phi : {0.0, 37.0, 179.9}) {
    const int steps = 3000;
    for (int s = 0; s <= steps; ++s) {
      const Vec3 wo = dirFromAngles(89.9 * s / steps, phi);
      lookupTable(desc, table.data(), wo, cur);
      if (s > 0) {
        const Vec3 wp = dirFromAngles(89.9 * (s - 1) / steps, phi);
        EXPECT_LE(dist(cur, prev), 1.05 * maxNodeStep * std::fabs(px(wo) - px(wp)) + 1e-6 * maxNorm) << "theta step " << s;
      }
      prev = cur;
    }
  }
  for (double theta : {0.01, 1.0, 45.0, 89.0}) {
    const int steps = 2000;
    for (int s = 0; s <= steps; ++s) {
      const double phi = -200.0 + 400.0 * s / steps;  // crosses ±180°
      lookupTable(desc, table.data(), dirFromAngles(theta, phi), cur);
      if (s > 0) {
        const double dphi = 400.0 / steps * kPiD / 180;
        EXPECT_LE(dist(cur, prev), 1.05 * (order - 1) * maxNorm * dphi + 1e-6 * maxNorm) << "theta " << theta << " phi step " << s;
      }
      prev = cur;
    }
  }
  // At the pole the lobe of an isotropic BSDF is zonal: every φ gives the same vector.
  std::vector<double> a, b;
  lookupTable(desc, table.data(), Vec3(0, 0, 1), a);
  lookupTable(desc, table.data(), dirFromAngles(1e-4, 123.0), b);
  EXPECT_LT(dist(a, b), 1e-3 * maxNorm);
}

// The 1-D isotropic table, z-rotated by φ_o, equals the full 2-D table of the same BSDF. At 2-D
// nodes the 2-D lookup is exact, so the difference is the 1-D table's interpolation in x plus both
// tables' quadrature error: ≤ 3% of ‖F‖ (measured ≲ 1% at α = 0.3 with T = 33, S = 17).
TEST(BrdfTable, Isotropic1DEqualsFull2D) {
  const int order = 5, n2 = order * order, T = 33, S = 17;
  for (float alpha : {0.3f, 0.6f}) {
    const auto bsdf = test::ggx(alpha);
    const LobeQuadrature quad{1024, 512};
    const std::vector<float> t1 = buildBrdfTable(*bsdf, RC_TABLE_ISOTROPIC_1D, order, T, quad);
    const std::vector<float> t2 = buildBrdfTable(*bsdf, RC_TABLE_ANISOTROPIC_2D, order, S, quad);
    const RcBrdfTable d1{RC_TABLE_ISOTROPIC_1D, order, T, 0}, d2{RC_TABLE_ANISOTROPIC_2D, order, S, 0};
    std::vector<double> f1, f2;
    int checked = 0;
    for (int iy = 0; iy < S; ++iy)
      for (int ix = 0; ix < S; ++ix) {
        const double px = -1.0 + 2.0 * ix / (S - 1), py = -1.0 + 2.0 * iy / (S - 1);
        if (px * px + py * py > 0.97) continue;  // keep clear of the clamped rim
        const Vec3 wo = anisotropicNodeDirection(ix, iy, S);
        lookupTable(d1, t1.data(), wo, f1);
        lookupTable(d2, t2.data(), wo, f2);
        for (int ch = 0; ch < 3; ++ch) {
          double d = 0, n = 0;
          for (int i = 0; i < n2; ++i) d += std::pow(f1[ch * n2 + i] - f2[ch * n2 + i], 2), n += f2[ch * n2 + i] * f2[ch * n2 + i];
          EXPECT_LT(std::sqrt(d), 0.03 * std::sqrt(n)) << "alpha " << alpha << " node " << ix << "," << iy;
        }
        ++checked;
      }
    EXPECT_GT(checked, 150);
  }
}

// An anisotropic BSDF's 2-D table against brute force at nodes away from the axes.
TEST(BrdfTable, AnisotropicTableMatchesBruteForce) {
  const int order = 6, n2 = order * order, S = 9;
  const auto bsdf = std::make_shared<test::TestMicrofacet>(true, 0.1f, 0.4f);
  ASSERT_FALSE(bsdf->isotropic());
  const std::vector<float> t2 = buildBrdfTable(*bsdf, RC_TABLE_ANISOTROPIC_2D, order, S, LobeQuadrature{});
  for (auto [ix, iy] : {std::pair{4, 4}, std::pair{6, 5}, std::pair{2, 7}, std::pair{7, 1}}) {
    const Vec3 wo = anisotropicNodeDirection(ix, iy, S);
    const CoeffAcc bf = bruteCoeffs(*bsdf, wo, order, 500, 1000);
    const float* node = t2.data() + (iy * S + ix) * 3 * n2;
    for (int ch = 0; ch < 3; ++ch) {
      double d = 0;
      for (int i = 0; i < n2; ++i) d += std::pow(node[ch * n2 + i] - bf.c[ch * n2 + i], 2);
      EXPECT_LT(std::sqrt(d), 0.015 * norm(bf.c, ch, n2)) << "node " << ix << "," << iy;
    }
  }
}

// A Lambertian's lobe is ρ/π·max(cos θ, 0), whose SH coefficients are known in closed form:
// zonal, c_0 = √π/2, c_1 = √(π/3), c_2 = √(5π)/8 (Ramamoorthi & Hanrahan 2001), times ρ/π.
TEST(BrdfTable, DiffuseTableIsClampedCosine) {
  const int order = 3, n2 = order * order;
  const Color rho(0.8f, 0.5f, 0.2f);
  test::TestLambert bsdf(rho);
  const std::vector<float> t = buildBrdfTable(bsdf, RC_TABLE_ISOTROPIC_1D, order, 2, LobeQuadrature{});
  const double c[3] = {std::sqrt(kPiD) / 2, std::sqrt(kPiD / 3), std::sqrt(5 * kPiD) / 8};
  for (int node = 0; node < 2; ++node)
    for (int ch = 0; ch < 3; ++ch)
      for (int l = 0; l < order; ++l)
        for (int m = -l; m <= l; ++m) {
          const double expected = m == 0 ? rho[ch] / kPiD * c[l] : 0.0;
          // QMC error of a smooth cosine-sampled integrand with 4096 points: ≪ 1e-3.
          EXPECT_NEAR(t[(node * 3 + ch) * n2 + sh::index(l, m)], expected, 1e-3) << "l " << l << " m " << m;
        }
}

}  // namespace
}  // namespace rc
