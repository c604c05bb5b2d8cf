// Sampling routines against their own pdf(): a chi-square goodness-of-fit test per configuration
// (cosθ × φ histogram of 100k samples vs pdf integrated over each bin, Šidák-corrected 1e-3 level
// over all configurations, as Mitsuba's chi2 tests), plus sample()'s weight and pdf == eval/pdf and
// pdf() for every continuous sample, and evalPdf() == (eval(), pdf()) exactly.
#include <gtest/gtest.h>

#include "bsdf_test_util.h"

namespace rc {
namespace {

using namespace rc::test;

struct SamplingCase {
  std::string name;
  BsdfPtr (*make)();
  float cosThetaO;  // negative: the viewer is behind the surface
  float phiO;
};

BsdfPtr ggxIso() { return make("roughconductor", {str("distribution", "ggx"), num("alpha", 0.3)}); }
BsdfPtr ggxRough() { return make("roughconductor", {str("distribution", "ggx"), num("alpha", 0.8)}); }
BsdfPtr ggxAniso() {
  return make("roughconductor", {str("distribution", "ggx"), num("alpha_u", 0.1), num("alpha_v", 0.5)});
}
BsdfPtr beckIso() { return make("roughconductor", {str("distribution", "beckmann"), num("alpha", 0.3)}); }
BsdfPtr beckRough() { return make("roughconductor", {str("distribution", "beckmann"), num("alpha", 0.8)}); }
BsdfPtr beckAniso() {
  return make("roughconductor", {str("distribution", "beckmann"), num("alpha_u", 0.5), num("alpha_v", 0.15)});
}
BsdfPtr ggxAllNormals() {
  return make("roughconductor", {str("distribution", "ggx"), num("alpha_u", 0.2), num("alpha_v", 0.4),
                                 boolean("sample_visible", false)});
}
BsdfPtr beckAllNormals() {
  return make("roughconductor", {str("distribution", "beckmann"), num("alpha", 0.3), boolean("sample_visible", false)});
}
BsdfPtr diffuse() { return make("diffuse", {rgb("reflectance", 0.2f, 0.5f, 0.8f)}); }
BsdfPtr roughPlasticGgx() {
  return make("roughplastic", {str("distribution", "ggx"), num("alpha", 0.2), rgb("diffuse_reflectance", 0.3f, 0.4f, 0.5f)});
}
BsdfPtr roughPlasticBeck() { return make("roughplastic", {num("alpha", 0.4)}); }
BsdfPtr plastic() { return make("plastic", {num("diffuse_reflectance", 0.6)}); }
BsdfPtr blend() {
  return make("blendbsdf", {num("weight", 0.3)}, {diffuse(), ggxIso()});
}
BsdfPtr twosided() { return make("twosided", {}, {ggxAniso(), diffuse()}); }
BsdfPtr twosidedOne() { return make("twosided", {}, {beckAniso()}); }

const float kGrazing = 0.05f;  // θ ≈ 87°
const SamplingCase kCases[] = {
    {"diffuse_normal", diffuse, 1.0f, 0.0f},
    {"diffuse_oblique", diffuse, 0.5f, 1.0f},
    {"diffuse_grazing", diffuse, kGrazing, 2.0f},
    {"ggx_normal", ggxIso, 1.0f, 0.0f},
    {"ggx_oblique", ggxIso, 0.6f, 0.3f},
    {"ggx_grazing", ggxIso, kGrazing, 0.0f},
    {"ggx_rough_oblique", ggxRough, 0.4f, 4.0f},
    {"ggx_rough_grazing", ggxRough, kGrazing, 1.0f},
    {"ggx_aniso_normal", ggxAniso, 1.0f, 0.0f},
    {"ggx_aniso_oblique", ggxAniso, 0.5f, 0.7f},
    {"ggx_aniso_grazing", ggxAniso, kGrazing, 2.2f},
    {"beckmann_normal", beckIso, 1.0f, 0.0f},
    {"beckmann_oblique", beckIso, 0.6f, 0.3f},
    {"beckmann_grazing", beckIso, kGrazing, 5.0f},
    {"beckmann_rough_oblique", beckRough, 0.4f, 4.0f},
    {"beckmann_rough_grazing", beckRough, kGrazing, 1.0f},
    {"beckmann_aniso_normal", beckAniso, 1.0f, 0.0f},
    {"beckmann_aniso_oblique", beckAniso, 0.5f, 0.7f},
    {"beckmann_aniso_grazing", beckAniso, kGrazing, 2.2f},
    {"ggx_all_normals_oblique", ggxAllNormals, 0.6f, 1.1f},
    {"ggx_all_normals_grazing", ggxAllNormals, kGrazing, 0.4f},
    {"beckmann_all_normals_oblique", beckAllNormals, 0.6f, 1.1f},
    {"roughplastic_ggx_normal", roughPlasticGgx, 1.0f, 0.0f},
    {"roughplastic_ggx_oblique", roughPlasticGgx, 0.5f, 1.0f},
    {"roughplastic_ggx_grazing", roughPlasticGgx, kGrazing, 3.0f},
    {"roughplastic_beckmann_oblique", roughPlasticBeck, 0.7f, 2.0f},
    {"plastic_oblique", plastic, 0.5f, 0.0f},
    {"blend_oblique", blend, 0.7f, 1.0f},
    {"blend_grazing", blend, kGrazing, 1.0f},
    {"twosided_front", twosided, 0.6f, 0.5f},
    {"twosided_back", twosided, -0.6f, 0.5f},
    {"twosided_one_back", twosidedOne, -0.4f, 2.5f},
};
constexpr int kNumCases = sizeof(kCases) / sizeof(kCases[0]);

// Each test's case, its BSDF and its viewer direction.
class BsdfSampling : public ::testing::TestWithParam<int> {
 protected:
  const SamplingCase& c = kCases[GetParam()];
  const BsdfPtr bsdf = c.make();
  const Vec3 wo = dirFrom(c.cosThetaO, c.phiO);
};

TEST_P(BsdfSampling, ChiSquare) {
  const Chi2Result r = chi2ForBsdf(*bsdf, wo, 1000 + GetParam());
  // Šidák: every configuration at level α' so that the whole suite has false-alarm rate 1e-3.
  const double alpha = 1.0 - std::pow(1.0 - 1e-3, 1.0 / kNumCases);
  EXPECT_FALSE(r.observedWhereImpossible) << c.name << ": samples where pdf() is zero";
  EXPECT_GT(r.pValue, alpha) << c.name << ": chi2 = " << r.statistic << ", dof = " << r.dof
                             << ", expected total " << r.expectedTotal << ", observed " << r.observedTotal;
}

TEST_P(BsdfSampling, WeightIsEvalOverPdf) {
  Rng rng(77 + GetParam(), 3);
  int continuous = 0;
  for (int k = 0; k < 2000; ++k) {
    const auto s = bsdf->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
    if (!s) continue;
    ASSERT_TRUE(isFinite(s->weight)) << c.name;
    ASSERT_NEAR(glm::length(s->wi), 1.0f, 1e-4f) << c.name;
    if (s->lobe & kLobeDelta) {
      EXPECT_EQ(s->pdf, 0.0f);
      continue;
    }
    ++continuous;
    const float pdf = bsdf->pdf(wo, s->wi);
    const Color f = bsdf->eval(wo, s->wi);
    // Same float formulas on both paths; 1e-3 relative covers re-normalised half vectors.
    ASSERT_NEAR(s->pdf, pdf, 1e-3f * pdf) << c.name;
    for (int ch = 0; ch < 3; ++ch) ASSERT_NEAR(s->weight[ch], f[ch] / pdf, 1e-3f * f[ch] / pdf + 1e-7f) << c.name;
  }
  EXPECT_GT(continuous, 0) << c.name;
}

// evalPdf (one call where eval and pdf share work) gives eval's and pdf's values bit for bit: for
// sampled directions and for directions all over the sphere (below the surface, grazing).
TEST_P(BsdfSampling, EvalPdfIsEvalAndPdfExactly) {
  Rng rng(91 + GetParam(), 5);
  int nonZero = 0;
  for (int k = 0; k < 4000; ++k) {
    Vec3 wi = uniformSphere(rng);
    if (k % 2 == 0)
      if (const auto s = bsdf->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()))) wi = s->wi;
    const BsdfValue both = bsdf->evalPdf(wo, wi);
    const Color f = bsdf->eval(wo, wi);
    const float pdf = bsdf->pdf(wo, wi);
    for (int ch = 0; ch < 3; ++ch) ASSERT_EQ(both.f[ch], f[ch]) << c.name << " wi " << wi.x << " " << wi.y << " " << wi.z;
    ASSERT_EQ(both.pdf, pdf) << c.name << " wi " << wi.x << " " << wi.y << " " << wi.z;
    if (pdf > 0.0f && maxComponent(f) > 0.0f) ++nonZero;
  }
  EXPECT_GT(nonZero, 100) << c.name;
}

INSTANTIATE_TEST_SUITE_P(All, BsdfSampling, ::testing::Range(0, kNumCases),
                         [](const ::testing::TestParamInfo<int>& info) { return kCases[info.param].name; });

}  // namespace
}  // namespace rc
