// Physical sanity: reciprocity f(wo,wi) = f(wi,wo), one-sidedness, albedo ≤ 1 (Monte Carlo),
// albedo ≈ 1 for an F ≡ 1 nearly smooth conductor, and ∫pdf dω = 1 − P(sample rejected) ≤ 1.
#include <gtest/gtest.h>

#include "bsdf_test_util.h"

namespace rc {
namespace {

using namespace rc::test;

std::vector<std::pair<std::string, BsdfPtr>> reciprocalBsdfs() {
  BsdfPtr diffuse = make("diffuse", {rgb("reflectance", 0.3f, 0.6f, 0.9f)});
  BsdfPtr ggx = make("roughconductor", {str("distribution", "ggx"), num("alpha_u", 0.15), num("alpha_v", 0.45),
                                        rgb("eta", 0.2f, 0.9f, 1.1f), rgb("k", 3.9f, 2.4f, 1.6f)});
  BsdfPtr beck = make("roughconductor", {num("alpha", 0.35)});
  return {
      {"diffuse", diffuse},
      {"ggx_aniso_fresnel", ggx},
      {"beckmann", beck},
      {"beckmann_aniso", make("roughconductor", {num("alpha_u", 0.4), num("alpha_v", 0.1)})},
      {"plastic", make("plastic", {rgb("diffuse_reflectance", 0.2f, 0.4f, 0.8f)})},
      {"roughplastic", make("roughplastic", {str("distribution", "ggx"), num("alpha", 0.3)})},
      {"blend", make("blendbsdf", {num("weight", 0.25)}, {diffuse, ggx})},
      {"twosided", make("twosided", {}, {ggx, beck})},
  };
}

TEST(BsdfPhysics, Reciprocity) {
  Rng rng(11);
  for (const auto& [name, b] : reciprocalBsdfs()) {
    for (int k = 0; k < 500; ++k) {
      Vec3 wo = uniformSphere(rng), wi = uniformSphere(rng);
      if (name != "twosided") {  // same side; the two-sided one is tested on both sides
        wo.z = std::fabs(wo.z);
        wi.z = std::fabs(wi.z);
      } else if (wo.z * wi.z < 0) {
        wi.z = -wi.z;
      }
      if (std::fabs(wo.z) < 1e-3f || std::fabs(wi.z) < 1e-3f) continue;
      // eval includes |cos θi|: compare the BSDF values themselves.
      const Color a = b->eval(wo, wi) / std::fabs(wi.z), c = b->eval(wi, wo) / std::fabs(wo.z);
      for (int ch = 0; ch < 3; ++ch)
        ASSERT_NEAR(a[ch], c[ch], 2e-4f * std::fmax(a[ch], c[ch]) + 1e-7f) << name << " wo " << wo.z << " wi " << wi.z;
    }
  }
}

TEST(BsdfPhysics, OneSidedAreBlackFromBehind) {
  Rng rng(12);
  for (const auto& [name, b] : reciprocalBsdfs()) {
    if (name == "twosided") continue;
    for (int k = 0; k < 200; ++k) {
      Vec3 wo = uniformSphere(rng), wi = uniformSphere(rng);
      wo.z = -std::fabs(wo.z);
      EXPECT_EQ(b->eval(wo, wi), Color(0.0f)) << name;
      EXPECT_EQ(b->pdf(wo, wi), 0.0f) << name;
      EXPECT_FALSE(b->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat())).has_value()) << name;
    }
  }
  // A two-sided wrapper sees its second BSDF from behind, mirrored through the tangent plane.
  BsdfPtr front = make("diffuse", {num("reflectance", 0.2)}), back = make("diffuse", {num("reflectance", 0.7)});
  BsdfPtr two = make("twosided", {}, {front, back});
  const Vec3 wo = dirFrom(-0.5, 1.0), wi = dirFrom(-0.8, 2.0);
  EXPECT_NEAR(two->eval(wo, wi).r, 0.7f * 0.8f / kPi, 1e-6f);
  EXPECT_EQ(two->eval(wo, dirFrom(0.8, 2.0)), Color(0.0f));  // transmission stays black
}

struct Albedo {
  Color mean{0.0f};
  Color stderr_{0.0f};
  double rejected = 0.0;  // fraction of sample() calls that returned nothing
};

Albedo albedo(const Bsdf& b, const Vec3& wo, int n, uint64_t seed) {
  Rng rng(seed, 5);
  glm::dvec3 sum(0.0), sum2(0.0);
  int rejected = 0;
  for (int k = 0; k < n; ++k) {
    const auto s = b.sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
    if (!s) {
      ++rejected;
      continue;
    }
    const glm::dvec3 w(s->weight);
    sum += w;
    sum2 += w * w;
  }
  Albedo a;
  const glm::dvec3 mean = sum / double(n), var = sum2 / double(n) - mean * mean;
  a.mean = Color(mean);
  a.stderr_ = Color(glm::sqrt(glm::max(var, glm::dvec3(0.0)) / double(n)));
  a.rejected = double(rejected) / n;
  return a;
}

TEST(BsdfPhysics, AlbedoAtMostOne) {
  auto bsdfs = reciprocalBsdfs();
  bsdfs.push_back({"conductor", make("conductor")});
  bsdfs.push_back({"ggx_very_rough", make("roughconductor", {str("distribution", "ggx"), num("alpha", 1.0)})});
  bsdfs.push_back({"plastic_white", make("plastic", {num("diffuse_reflectance", 1.0)})});
  bsdfs.push_back({"roughplastic_white", make("roughplastic", {num("diffuse_reflectance", 1.0), num("alpha", 0.5)})});
  bsdfs.push_back({"plastic_nonlinear_white",
                   make("plastic", {num("diffuse_reflectance", 1.0), boolean("nonlinear", true)})});
  for (const auto& [name, b] : bsdfs)
    for (double cosO : {1.0, 0.7, 0.3, 0.05}) {
      const Albedo a = albedo(*b, dirFrom(cosO, 0.4), 20000, 99);
      for (int c = 0; c < 3; ++c) {
        // 4σ of the Monte Carlo error, plus 1 % for the polynomial Fdr fit in plastic (≤ 0.6 %)
        // and the 64-point transmittance table of roughplastic.
        EXPECT_LE(a.mean[c], 1.0f + 4.0f * a.stderr_[c] + 0.01f) << name << " cosθo " << cosO;
        EXPECT_GE(a.mean[c], 0.0f) << name;
      }
    }
}

TEST(BsdfPhysics, MirrorLikeConductorConservesEnergy) {
  // F ≡ 1 (material none), α = 0.02, normal incidence: G1 ≈ 1 for all sampled directions, so the
  // albedo is 1 up to a masking loss below 0.1 % (Smith G1 at tanθ ~ 2α).
  for (const char* distr : {"ggx", "beckmann"}) {
    BsdfPtr b = make("roughconductor", {str("distribution", distr), num("alpha", 0.02)});
    const Albedo a = albedo(*b, Vec3(0, 0, 1), 20000, 5);
    EXPECT_NEAR(a.mean.r, 1.0f, 2e-3f) << distr;
    EXPECT_LT(a.rejected, 1e-3) << distr;
  }
  // Exact mirror: every sample has weight 1.
  const auto s = make("conductor")->sample(dirFrom(0.3, 1.0), 0.5f, Vec2(0.5f));
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->weight, Color(1.0f));
}

TEST(BsdfPhysics, BlendAlbedoIsWeightedSum) {
  // blend(diffuse ρ = 0.5, ideal mirror) with w = 0.3: albedo = 0.7·0.5 + 0.3·1 = 0.65 exactly in
  // expectation; the delta branch must neither be divided by nor multiplied with its probability.
  BsdfPtr b = make("blendbsdf", {num("weight", 0.3)}, {make("diffuse"), make("conductor")});
  const Albedo a = albedo(*b, dirFrom(0.6, 0.2), 40000, 8);
  EXPECT_NEAR(a.mean.r, 0.65f, 4.0f * a.stderr_.r + 1e-4f);
  // Same with the mirror first (weight now selects the diffuse one): 0.7·1 + 0.3·0.5 = 0.85.
  BsdfPtr c = make("blendbsdf", {num("weight", 0.3)}, {make("conductor"), make("diffuse")});
  const Albedo a2 = albedo(*c, dirFrom(0.6, 0.2), 40000, 9);
  EXPECT_NEAR(a2.mean.r, 0.85f, 4.0f * a2.stderr_.r + 1e-4f);
}

TEST(BsdfPhysics, PdfIntegratesToAcceptanceRate) {
  std::vector<std::pair<std::string, BsdfPtr>> bsdfs = {
      {"diffuse", make("diffuse")},
      {"ggx", make("roughconductor", {str("distribution", "ggx"), num("alpha", 0.4)})},
      {"ggx_aniso", make("roughconductor", {str("distribution", "ggx"), num("alpha_u", 0.6), num("alpha_v", 0.2)})},
      {"beckmann", make("roughconductor", {num("alpha", 0.4)})},
      {"beckmann_all_normals", make("roughconductor", {num("alpha", 0.4), boolean("sample_visible", false)})},
      {"roughplastic", make("roughplastic", {num("alpha", 0.4)})},
      {"plastic", make("plastic")},
      {"blend", make("blendbsdf", {}, {make("diffuse"), make("roughconductor", {num("alpha", 0.5)})})},
  };
  for (const auto& [name, b] : bsdfs)
    for (double cosO : {1.0, 0.5, 0.1}) {
      const Vec3 wo = dirFrom(cosO, 0.9);
      const double integral = integrateSphere([&](const Vec3& wi) { return double(b->pdf(wo, wi)); });
      // Fraction of samples that are continuous (not rejected, not delta).
      Rng rng(21, 1);
      const int n = 40000;
      int continuous = 0;
      for (int k = 0; k < n; ++k) {
        const auto s = b->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
        if (s && !(s->lobe & kLobeDelta)) ++continuous;
      }
      const double p = double(continuous) / n, sigma = std::sqrt(std::max(p * (1 - p), 1e-6) / n);
      EXPECT_LE(integral, 1.0 + 2e-3) << name << " cosθo " << cosO;
      // 4σ binomial + 2e-3 quadrature error (64² cells × 5² Gauss points over the sphere).
      EXPECT_NEAR(integral, p, 4 * sigma + 2e-3) << name << " cosθo " << cosO;
      if (name == "diffuse") EXPECT_NEAR(integral, 1.0, 1e-3);
    }
}

}  // namespace
}  // namespace rc
