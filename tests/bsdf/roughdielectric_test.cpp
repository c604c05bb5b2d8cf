// roughdielectric: values against Mitsuba 3.9.1 (scalar_rgb eval/pdf of the same configuration),
// sampling against pdf() over the whole sphere, generalized reciprocity of the transmission lobe,
// the albedo against Mitsuba's eval_reflectance + eval_transmittance quadratures, the smooth limit
// against the dielectric's Fresnel split, textured roughness per point, and parameter errors.
#include <gtest/gtest.h>

#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "bsdf/rough_textures.h"
#include "bsdf_test_util.h"
#include "core/error.h"
#include "texture/texture.h"

namespace rc {
namespace {

using namespace rc::test;

BsdfPtr ggx03() { return make("roughdielectric", {str("distribution", "ggx"), num("alpha", 0.3)}); }
BsdfPtr beckWater() { return make("roughdielectric", {num("alpha", 0.2), str("int_ior", "water")}); }
BsdfPtr ggxAniso() {
  return make("roughdielectric", {str("distribution", "ggx"), num("alpha_u", 0.1), num("alpha_v", 0.4),
                                  num("int_ior", 1.7), num("ext_ior", 1.2)});
}
BsdfPtr beckAllNormals() {
  return make("roughdielectric", {num("alpha", 0.25), boolean("sample_visible", false), num("int_ior", 1.33)});
}

// Mitsuba 3.9.1 scalar_rgb: BSDF.eval / BSDF.pdf with si.wi = our wo, wo = our wi, unit frame
// (bench/mitsuba_bsdf_values.py prints them).
struct MitsubaValue {
  BsdfPtr (*make)();
  double cosO, phiO, cosI, phiI, eval, pdf;
};
const MitsubaValue kMitsuba[] = {
    {ggx03, 0.8, 0.2, 0.6, 3.0, 0.02430698648, 0.02524320595},          // reflection
    {ggx03, 0.8, 0.2, -0.7, 2.9, 0.06155975536, 0.1424718350},          // refraction into glass
    {beckWater, -0.5, 1.0, -0.9, 4.5, 0.01985939220, 0.01985939406},    // reflection inside water
    {beckWater, -0.5, 1.0, 0.4, 4.0, 7.850299300e-10, 4.420450395e-10}, // refraction out of water
    {ggxAniso, 0.3, 0.5, -0.8, 3.5, 1.232896447, 2.484217644},          // anisotropic, η = 1.7/1.2
};

TEST(RoughDielectric, MatchesMitsubaEvalAndPdf) {
  for (const MitsubaValue& v : kMitsuba) {
    const BsdfPtr b = v.make();
    const Vec3 wo = dirFrom(v.cosO, v.phiO), wi = dirFrom(v.cosI, v.phiI);
    const Color f = b->eval(wo, wi);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], v.eval, 2e-4 * v.eval + 1e-12) << v.cosO << " → " << v.cosI;
    EXPECT_NEAR(b->pdf(wo, wi), v.pdf, 2e-4 * v.pdf + 1e-12) << v.cosO << " → " << v.cosI;
  }
}

struct Case {
  const char* name;
  BsdfPtr (*make)();
  float cosO, phiO;
};
const Case kCases[] = {
    {"ggx_outside", ggx03, 0.7f, 0.4f},     {"ggx_inside", ggx03, -0.6f, 2.0f},
    {"ggx_grazing", ggx03, 0.08f, 1.0f},    {"beckmann_water_inside", beckWater, -0.9f, 0.3f},
    {"aniso", ggxAniso, 0.5f, 0.8f},        {"all_normals", beckAllNormals, 0.6f, 5.0f},
    {"all_normals_inside", beckAllNormals, -0.5f, 1.0f},
};
constexpr int kNumCases = sizeof(kCases) / sizeof(kCases[0]);

class RoughDielectricSampling : public ::testing::TestWithParam<int> {};

TEST_P(RoughDielectricSampling, ChiSquareOverTheSphere) {
  const Case& c = kCases[GetParam()];
  const Chi2Result r = chi2ForBsdf(*c.make(), dirFrom(c.cosO, c.phiO), 500 + GetParam());
  const double alpha = 1.0 - std::pow(1.0 - 1e-3, 1.0 / kNumCases);
  EXPECT_FALSE(r.observedWhereImpossible) << c.name;
  EXPECT_GT(r.pValue, alpha) << c.name << ": chi2 " << r.statistic << ", dof " << r.dof << ", expected "
                             << r.expectedTotal << ", observed " << r.observedTotal;
}

TEST_P(RoughDielectricSampling, WeightAndPdfAgreeWithEval) {
  const Case& c = kCases[GetParam()];
  const BsdfPtr b = c.make();
  const Vec3 wo = dirFrom(c.cosO, c.phiO);
  Rng rng(91 + GetParam(), 5);
  int reflected = 0, refracted = 0;
  for (int k = 0; k < 4000; ++k) {
    const auto s = b->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
    if (!s) continue;
    ASSERT_FALSE(s->lobe & kLobeDelta);
    const bool transmitted = (s->lobe & kLobeTransmission) != 0;
    ASSERT_EQ(transmitted, s->wi.z * wo.z < 0.0f) << c.name;
    (transmitted ? refracted : reflected)++;
    const float pdf = b->pdf(wo, s->wi);
    const Color f = b->eval(wo, s->wi);
    ASSERT_NEAR(s->pdf, pdf, 2e-3f * pdf) << c.name;
    for (int ch = 0; ch < 3; ++ch) ASSERT_NEAR(s->weight[ch], f[ch] / pdf, 2e-3f * f[ch] / pdf + 1e-7f) << c.name;
    // The relative IOR crossed: η for refraction from outside, 1/η from inside, 1 for reflection.
    if (!transmitted) ASSERT_EQ(s->eta, 1.0f);
  }
  EXPECT_GT(reflected, 0) << c.name;
  EXPECT_GT(refracted, 0) << c.name;
}

INSTANTIATE_TEST_SUITE_P(All, RoughDielectricSampling, ::testing::Range(0, kNumCases),
                         [](const ::testing::TestParamInfo<int>& info) { return kCases[info.param].name; });

// Radiance-mode BTDFs obey f(wo,wi)/η_o² = f(wi,wo)/η_i² (η of each direction's medium); the
// reflection lobe is symmetric.
TEST(RoughDielectric, GeneralizedReciprocity) {
  const float eta = 1.7f / 1.2f;
  const BsdfPtr b = ggxAniso();
  Rng rng(3);
  int tested = 0;
  for (int k = 0; k < 2000; ++k) {
    Vec3 wo = uniformSphere(rng), wi = uniformSphere(rng);
    if (std::fabs(wo.z) < 0.05f || std::fabs(wi.z) < 0.05f) continue;
    const float fOI = b->eval(wo, wi).r / std::fabs(wi.z), fIO = b->eval(wi, wo).r / std::fabs(wo.z);
    if (fOI < 1e-4f && fIO < 1e-4f) continue;
    const float etaO = wo.z > 0 ? 1.0f : eta, etaI = wi.z > 0 ? 1.0f : eta;
    ASSERT_NEAR(fOI / (etaO * etaO), fIO / (etaI * etaI), 1e-3f * fOI / (etaO * etaO)) << wo.z << " " << wi.z;
    ++tested;
  }
  EXPECT_GT(tested, 500);
}

// Importance-transport albedo (sample weights with the η² of radiance compression removed) equals
// the share of light that is not lost to masking: Mitsuba's eval_reflectance + eval_transmittance
// (microfacet.h's quadratures), for light from outside and from inside.
TEST(RoughDielectric, AlbedoMatchesMitsubaQuadratures) {
  const float eta = 1.5046f / 1.000277f;
  for (const float alpha : {0.1f, 0.5f})
    for (const float cosO : {0.9f, 0.4f, -0.7f}) {
      const BsdfPtr b = make("roughdielectric", {str("distribution", "ggx"), num("alpha", alpha)});
      const Vec3 wo = dirFrom(cosO, 0.3);
      Rng rng(17);
      const int n = 200000;
      double sum = 0.0, sum2 = 0.0;
      for (int k = 0; k < n; ++k) {
        const auto s = b->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
        if (!s) continue;
        const double w = s->weight.r * s->eta * s->eta;
        sum += w;
        sum2 += w * w;
      }
      const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
      const Microfacet distr(MicrofacetType::GGX, alpha, alpha, true);
      const Vec3 up = cosO > 0 ? wo : -wo;  // the quadratures take the incident side as "outside"
      const float etaSide = cosO > 0 ? eta : 1.0f / eta;
      const double expected = microfacetReflectance(distr, up, etaSide) + microfacetTransmittance(distr, up, etaSide);
      EXPECT_LE(mean, 1.0 + 4 * se);
      EXPECT_NEAR(mean, expected, 4 * se + 2e-3) << "alpha " << alpha << " cos " << cosO;
    }
}

// As α → 0 the reflected share is the smooth dielectric's Fresnel reflectance.
TEST(RoughDielectric, SmoothLimitSplitsLikeFresnel) {
  const BsdfPtr b = make("roughdielectric", {num("alpha", 0.001), str("distribution", "ggx")});
  for (const float cosO : {0.95f, 0.3f, -0.8f, -0.75f}) {
    const Vec3 wo = dirFrom(cosO, 1.0);
    Rng rng(5);
    int reflected = 0, total = 0;
    for (int k = 0; k < 50000; ++k) {
      const auto s = b->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
      if (!s) continue;
      ++total;
      reflected += (s->lobe & kLobeTransmission) == 0;
    }
    const double F = fresnelDielectric(cosO, 1.5046f / 1.000277f).r, share = double(reflected) / total;
    EXPECT_NEAR(share, F, 4 * std::sqrt(F * (1 - F) / total) + 2e-3) << cosO;
  }
}

// A texture on alpha: at(uv) is the untextured BSDF with the texture's value there.
TEST(RoughDielectric, TexturedAlphaPerPoint) {
  Properties props;
  props.pluginType = "roughdielectric";
  props.set("distribution", str("distribution", "ggx").value);
  props.set("alpha", num("alpha", 0.3).value);  // the texture's mean, as the loader sets it
  const TexturePtr checker = makeCheckerboard(Color(0.05f), Color(0.55f), UvTransform());
  const BsdfPtr textured = createBsdf(props, {}, "glass", {{"alpha", checker}});
  ASSERT_TRUE(textured->spatiallyVarying());
  EXPECT_EQ(textured->lobes(), uint32_t(kLobeGlossy | kLobeTransmission));
  const Vec3 wo = dirFrom(0.7, 0.2), wi = dirFrom(-0.6, 3.0);
  // α is a scalar parameter (Mitsuba's eval_1): colour0 where frac(u) > ½ and frac(v) > ½ disagree.
  for (const auto& [uv, alpha] : {std::pair{Vec2(0.75f, 0.25f), 0.05}, std::pair{Vec2(0.25f, 0.25f), 0.55}}) {
    const BsdfPtr here = textured->at(TexturePoint(uv));
    ASSERT_TRUE(here);
    EXPECT_FALSE(here->spatiallyVarying());
    const BsdfPtr plain = make("roughdielectric", {str("distribution", "ggx"), num("alpha", alpha)});
    EXPECT_NEAR(here->eval(wo, wi).g, plain->eval(wo, wi).g, 1e-6f * plain->eval(wo, wi).g);
    EXPECT_NEAR(here->pdf(wo, wi), plain->pdf(wo, wi), 1e-6f * plain->pdf(wo, wi));
  }
  // A uniform BSDF is its own point BSDF.
  const BsdfPtr uniform = ggx03();
  BsdfPtr holder;
  EXPECT_EQ(&bsdfAt(*uniform, TexturePoint(Vec2(0.5f)), holder), uniform.get());
  EXPECT_FALSE(holder);
  // Keys differ with the texture's content.
  const BsdfPtr other = createBsdf(props, {}, "glass2", {{"alpha", makeCheckerboard(Color(0.05f), Color(0.6f), UvTransform())}});
  EXPECT_NE(textured->parameterKey(), other->parameterKey());
}

TEST(RoughDielectric, RejectsBadParameters) {
  EXPECT_THROW(make("roughdielectric", {num("int_ior", 1.3), num("ext_ior", 1.3)}), Error);
  EXPECT_THROW(make("roughdielectric", {num("alpha", 0.0)}), Error);
  EXPECT_THROW(make("roughdielectric", {num("alpha_u", 0.1)}), Error);
  EXPECT_THROW(make("roughdielectric", {str("distribution", "phong")}), Error);
  EXPECT_THROW(make("roughdielectric", {str("int_ior", "unobtainium")}), Error);
}

}  // namespace
}  // namespace rc
