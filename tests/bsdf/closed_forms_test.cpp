// eval() against formulas written out independently in double precision: Lambert, GGX and Beckmann
// D·G at normal viewing (F ≡ 1), anisotropic D, conductor/dielectric Fresnel from complex
// arithmetic, the diffuse Fresnel fit, plastic, and the rough-plastic tables in the smooth limit.
#include <complex>

#include <gtest/gtest.h>

#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "bsdf_test_util.h"

namespace rc {
namespace {

using namespace rc::test;

TEST(ClosedForm, DiffuseIsRhoOverPiTimesCos) {
  BsdfPtr b = make("diffuse", {rgb("reflectance", 0.1f, 0.5f, 0.9f)});
  Rng rng(1);
  for (int k = 0; k < 200; ++k) {
    const Vec3 wo = uniformSphere(rng), wi = uniformSphere(rng);
    const Color f = b->eval(wo, wi);
    const Color expect = (wo.z > 0 && wi.z > 0) ? Color(0.1f, 0.5f, 0.9f) * (wi.z / kPi) : Color(0.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], expect[c], 1e-6f);
  }
}

// Viewer on the normal (wo = z, so G1(wo) = 1 and h has θh = θi/2): eval = D(h)·G1(wi)/4.
double ggxD(double alpha, double cosH) {
  const double c2 = cosH * cosH, t2 = (1.0 - c2) / c2, a2 = alpha * alpha;
  return a2 / (kPiD * c2 * c2 * (a2 + t2) * (a2 + t2));
}
double ggxG1(double alpha, double cosT) {
  const double t2 = (1.0 - cosT * cosT) / (cosT * cosT);
  return 2.0 / (1.0 + std::sqrt(1.0 + alpha * alpha * t2));
}
double beckmannD(double alpha, double cosH) {
  const double c2 = cosH * cosH, t2 = (1.0 - c2) / c2;
  return std::exp(-t2 / (alpha * alpha)) / (kPiD * alpha * alpha * c2 * c2);
}
double beckmannG1Exact(double alpha, double cosT) {
  const double a = 1.0 / (alpha * std::sqrt(1.0 - cosT * cosT) / cosT);
  return 2.0 / (1.0 + std::erf(a) + std::exp(-a * a) / (a * std::sqrt(kPiD)));
}

TEST(ClosedForm, GgxAtNormalViewing) {
  for (double alpha : {0.05, 0.2, 0.6}) {
    BsdfPtr b = make("roughconductor", {str("distribution", "ggx"), num("alpha", alpha)});
    for (double theta = 0.0; theta < 1.5; theta += 0.1) {
      const Vec3 wi = dirFrom(std::cos(theta), 0.7);
      const double expect = ggxD(alpha, std::cos(theta / 2)) * ggxG1(alpha, std::cos(theta)) / 4.0;
      // Float evaluation of the same expression: relative 1e-4 (plus an absolute floor in the tail).
      EXPECT_NEAR(b->eval(Vec3(0, 0, 1), wi).g, expect, 1e-4 * expect + 1e-9) << alpha << " " << theta;
    }
  }
}

TEST(ClosedForm, BeckmannAtNormalViewing) {
  for (double alpha : {0.1, 0.3, 0.7}) {
    BsdfPtr b = make("roughconductor", {num("alpha", alpha)});  // beckmann is the default
    for (double theta = 0.0; theta < 1.5; theta += 0.1) {
      const Vec3 wi = dirFrom(std::cos(theta), 2.0);
      const double expect = beckmannD(alpha, std::cos(theta / 2)) * beckmannG1Exact(alpha, std::cos(theta)) / 4.0;
      // Mitsuba's rational G1 fit is within 0.35 % of the exact Smith G1; 0.4 % + float rounding.
      EXPECT_NEAR(b->eval(Vec3(0, 0, 1), wi).g, expect, 4e-3 * expect + 1e-9) << alpha << " " << theta;
    }
  }
}

TEST(ClosedForm, AnisotropicDUsesTangentForAlphaU) {
  const double au = 0.1, av = 0.4;
  const Microfacet ggx(MicrofacetType::GGX, au, av), beck(MicrofacetType::Beckmann, au, av);
  for (double cosT : {0.99, 0.9, 0.7})
    for (double phi : {0.0, 0.5, 1.5707963, 2.5}) {
      const Vec3 m = dirFrom(cosT, phi);
      const double c2 = cosT * cosT, t2 = (1 - c2) / c2;
      const double e = t2 * (std::cos(phi) * std::cos(phi) / (au * au) + std::sin(phi) * std::sin(phi) / (av * av));
      const double dGgx = 1.0 / (kPiD * au * av * c2 * c2 * (1 + e) * (1 + e));
      const double dBeck = std::exp(-e) / (kPiD * au * av * c2 * c2);
      EXPECT_NEAR(ggx.D(m), dGgx, 1e-4 * dGgx + 1e-9);
      EXPECT_NEAR(beck.D(m), dBeck, 1e-4 * dBeck + 1e-9);
    }
  // Wider along b (α_v): a half vector tilted toward y is more likely than one tilted toward x.
  EXPECT_GT(ggx.D(dirFrom(0.9, 1.5707963)), 10.0f * ggx.D(dirFrom(0.9, 0.0)));
}

// Exact Fresnel reflectance for complex relative IOR (s and p amplitudes from Snell's law).
double fresnelComplex(double cosI, std::complex<double> eta) {
  const double sin2 = 1.0 - cosI * cosI;
  const std::complex<double> cosT_eta = std::sqrt(eta * eta - sin2);  // η·cos θt
  const std::complex<double> rs = (cosI - cosT_eta) / (cosI + cosT_eta);
  const std::complex<double> rp = (eta * eta * cosI - cosT_eta) / (eta * eta * cosI + cosT_eta);
  return 0.5 * (std::norm(rs) + std::norm(rp));
}

TEST(ClosedForm, ConductorFresnelGoldAndOblique) {
  // Gold (pbrt's RGB fit): F0 = ((n−1)² + k²)/((n+1)² + k²) per channel.
  const Color eta(0.143119f, 0.374957f, 1.44248f), k(3.98316f, 2.38572f, 1.60322f);
  BsdfPtr gold = make("conductor", {rgb("eta", eta.r, eta.g, eta.b), rgb("k", k.r, k.g, k.b)});
  const auto s = gold->sample(Vec3(0, 0, 1), 0.5f, Vec2(0.5f));
  ASSERT_TRUE(s.has_value());
  for (int c = 0; c < 3; ++c) {
    const double n = eta[c], kk = k[c];
    const double f0 = ((n - 1) * (n - 1) + kk * kk) / ((n + 1) * (n + 1) + kk * kk);
    EXPECT_NEAR(s->weight[c], f0, 1e-5);
  }
  EXPECT_GT(s->weight.r, s->weight.b);  // gold is yellow
  for (double cosI : {0.95, 0.7, 0.4, 0.1, 0.02})
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(fresnelConductor(cosI, eta[c], k[c]), fresnelComplex(cosI, {eta[c], k[c]}), 1e-5) << cosI;
  // material "none" (eta 0, k 1) is an exact mirror at every angle.
  for (double cosI : {1.0, 0.5, 0.01}) EXPECT_EQ(fresnelConductor(cosI, 0.0f, 1.0f), 1.0f);
}

TEST(ClosedForm, DielectricFresnel) {
  const float eta = 1.5f;
  EXPECT_NEAR(fresnelDielectric(1.0f, eta).r, 0.04f, 1e-6f);
  for (double cosI : {0.9, 0.6, 0.3, 0.05}) {
    EXPECT_NEAR(fresnelDielectric(cosI, eta).r, fresnelComplex(cosI, eta), 1e-6) << cosI;
    // From inside: the same formula with 1/η, below the critical angle.
    const double sinI = std::sqrt(1 - cosI * cosI);
    const double expectInside = sinI > 1 / 1.5 ? 1.0 : fresnelComplex(cosI, 1.0 / 1.5);
    EXPECT_NEAR(fresnelDielectric(-cosI, eta).r, expectInside, 1e-6) << cosI;
  }
  // Brewster angle: the p-polarised part vanishes, F = r_s²/2.
  const double thetaB = std::atan(1.5), ci = std::cos(thetaB), ct = std::sqrt(1 - std::pow(std::sin(thetaB) / 1.5, 2));
  const double rs = (ci - 1.5 * ct) / (ci + 1.5 * ct);
  EXPECT_NEAR(fresnelDielectric(ci, eta).r, 0.5 * rs * rs, 1e-6);
}

TEST(ClosedForm, DiffuseFresnelFitMatchesQuadrature) {
  for (float eta : {1.33f, 1.5f, 1.0f / 1.5f, 1.0f / 1.33f}) {
    // Fdr = 2 ∫₀¹ F(μ) μ dμ (midpoint rule, 20000 steps).
    double sum = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const double mu = (i + 0.5) / n;
      sum += 2.0 * fresnelDielectric(static_cast<float>(mu), eta).r * mu / n;
    }
    // The fits are within 0.6 % (Egan–Hilgeman) / 0.1 % (d'Eon–Irving) for these η.
    EXPECT_NEAR(fresnelDiffuseReflectance(eta), sum, 0.01 * sum) << eta;
  }
}

TEST(ClosedForm, PlasticDiffuseLobe) {
  const float rho = 0.6f, eta = 1.49f / 1.000277f;
  BsdfPtr b = make("plastic", {num("diffuse_reflectance", rho)});
  const double fdrInt = fresnelDiffuseReflectance(1.0f / eta);
  for (double co : {1.0, 0.5, 0.1})
    for (double ci : {0.9, 0.3}) {
      const Vec3 wo = dirFrom(co, 0.0), wi = dirFrom(ci, 2.0);
      const double fo = fresnelComplex(co, eta), fi = fresnelComplex(ci, eta);
      const double expect = rho / (1 - fdrInt) * (1 - fo) * (1 - fi) / (eta * eta) * ci / kPiD;
      EXPECT_NEAR(b->eval(wo, wi).r, expect, 1e-4 * expect);
    }
  // Specular part: delta, weight·P(spec) = F(θo).
  const auto s = b->sample(dirFrom(0.5, 0.0), 0.0f, Vec2(0.5f));
  ASSERT_TRUE(s && (s->lobe & kLobeDelta));
  EXPECT_NEAR(s->wi.z, 0.5f, 1e-6f);
  EXPECT_NEAR(s->wi.x, -dirFrom(0.5, 0.0).x, 1e-6f);
}

TEST(ClosedForm, RoughInterfaceTablesApproachSmoothLimit) {
  const float eta = 1.49f;
  const Microfacet smooth(MicrofacetType::GGX, 0.005f, 0.005f);
  for (float mu : {1.0f, 0.7f, 0.4f, 0.2f}) {
    const Vec3 w(std::sqrt(1 - mu * mu), 0.0f, mu);
    const double t = microfacetTransmittance(smooth, w, eta), r = microfacetReflectance(smooth, w, eta);
    EXPECT_NEAR(t, 1.0 - fresnelComplex(mu, eta), 2e-3) << mu;
    EXPECT_NEAR(r, fresnelComplex(mu, eta), 2e-3) << mu;
  }
  // Rough interfaces lose energy to masking: R + T < 1 at grazing angles, never > 1.
  const Microfacet rough(MicrofacetType::Beckmann, 0.5f, 0.5f);
  for (float mu : {1.0f, 0.5f, 0.1f}) {
    const Vec3 w(std::sqrt(1 - mu * mu), 0.0f, mu);
    const double sum = microfacetTransmittance(rough, w, eta) + microfacetReflectance(rough, w, eta);
    EXPECT_LE(sum, 1.0 + 1e-3) << mu;
    EXPECT_GT(sum, 0.5) << mu;
  }
}

TEST(ClosedForm, RoughPlasticDiffuseApproachesSmoothLimit) {
  // With a nearly smooth coating, roughplastic's diffuse lobe (numerical tables) must reduce to
  // ρ/(1 − R_int)·(1 − F(θo))(1 − F(θi))/η²·cosθi/π with smooth Fresnel terms. R_int follows
  // Mitsuba's discretisation: 2·mean over μ_i = i/63 (i = 0..63) of R(μ_i)·μ_i, which is 63/64 of
  // a trapezoid rule and so ≈ 1.7 % below 2∫R(μ)μdμ = Fdr (0.590 vs 0.579 here) — reproduced on
  // purpose, so this test also pins that quirk (plastic's analytic Fdr would miss by 2.5 %).
  const float eta = 1.49f / 1.000277f, rho = 0.5f;
  BsdfPtr rough = make("roughplastic", {str("distribution", "ggx"), num("alpha", 0.005)});
  double rInt = 0.0;
  for (int i = 0; i < 64; ++i) {
    const double mu = std::max(1e-6, i / 63.0);
    rInt += fresnelComplex(mu, 1.0 / eta) * mu;
  }
  rInt = rInt / 64.0 * 2.0;
  for (double co : {0.9, 0.5})
    for (double ci : {0.8, 0.3}) {
      // Directions far from the mirror configuration, so the specular lobe is exactly zero.
      const Vec3 wo = dirFrom(co, 0.0), wi = dirFrom(ci, 1.0);
      const double expect = rho / (1 - rInt) * (1 - fresnelComplex(co, eta)) * (1 - fresnelComplex(ci, eta)) /
                            (eta * eta) * ci / kPiD;
      // α = 0.005 vs smooth: transmittance within 2e-3 (see above), table interpolation ~1e-4.
      EXPECT_NEAR(rough->eval(wo, wi).r, expect, 5e-3 * expect) << co << " " << ci;
    }
}

// Thin sheet: R = 2r/(1 + r) with r the first face's Fresnel reflectance, T = 1 − R straight through.
TEST(ClosedForm, ThinDielectricSumsInternalReflections) {
  BsdfPtr sheet = make("thindielectric", {num("int_ior", 1.5)});
  const float eta = 1.5f / 1.000277f;
  for (const double cosTheta : {1.0, 0.6, 0.2}) {
    const Vec3 wo = dirFrom(cosTheta, std::sqrt(1 - cosTheta * cosTheta));
    const float r = fresnelDielectric(float(cosTheta), eta).r, R = 2 * r / (1 + r);
    int reflected = 0;
    const int n = 40000;
    Rng rng(5);
    for (int k = 0; k < n; ++k) {
      const auto s = sheet->sample(k % 2 ? wo : -wo, rng.nextFloat(), Vec2(0.5f));  // both sides alike
      ASSERT_TRUE(s.has_value());
      EXPECT_NEAR(s->weight.r, 1.0f, 1e-6f);
      EXPECT_EQ(s->eta, 1.0f);
      const Vec3 w = k % 2 ? wo : -wo;
      if (s->lobe & kLobeTransmission) {
        EXPECT_NEAR(glm::length(s->wi + w), 0.0f, 1e-6f);  // straight through
      } else {
        ++reflected;
        EXPECT_NEAR(s->wi.z, w.z, 1e-6f);
      }
    }
    // Binomial: 4σ of the reflected fraction.
    EXPECT_NEAR(double(reflected) / n, R, 4 * std::sqrt(R * (1 - R) / n) + 1e-4) << cosTheta;
  }
}

TEST(ClosedForm, DielectricSamplesSnellAndFresnel) {
  BsdfPtr glass = make("dielectric");  // bk7 in air
  const float eta = 1.5046f / 1.000277f;
  const Vec3 wo = dirFrom(0.6, 0.8);
  const float F = fresnelDielectric(0.6f, eta).r;
  int reflected = 0;
  const int n = 20000;
  Rng rng(3);
  for (int k = 0; k < n; ++k) {
    const auto s = glass->sample(wo, rng.nextFloat(), Vec2(0.5f));
    ASSERT_TRUE(s.has_value());
    if (s->lobe & kLobeTransmission) {
      // Snell: sinθt = sinθo/η, opposite side, same plane; radiance scaled by 1/η².
      EXPECT_NEAR(std::sqrt(s->wi.x * s->wi.x + s->wi.y * s->wi.y), 0.8f / eta, 1e-5f);
      EXPECT_LT(s->wi.z, 0.0f);
      EXPECT_NEAR(s->wi.x * wo.y - s->wi.y * wo.x, 0.0f, 1e-6f);
      EXPECT_NEAR(s->weight.r, 1.0f / (eta * eta), 1e-5f);
      EXPECT_NEAR(s->eta, eta, 1e-6f);
    } else {
      ++reflected;
      EXPECT_NEAR(s->wi.z, wo.z, 1e-6f);
      EXPECT_NEAR(s->weight.r, 1.0f, 1e-6f);
    }
  }
  // Binomial: 4σ of n·F.
  EXPECT_NEAR(reflected, n * F, 4.0 * std::sqrt(n * F * (1 - F)));
  // From inside beyond the critical angle: always reflected (total internal reflection).
  const auto tir = glass->sample(dirFrom(-0.3, 0.0), 0.999f, Vec2(0.5f));
  ASSERT_TRUE(tir.has_value());
  EXPECT_FALSE(tir->lobe & kLobeTransmission);
}

}  // namespace
}  // namespace rc
