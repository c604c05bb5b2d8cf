// null and mask: pass-through as a Dirac transmission with weight 1, the mask's o·f_nested value
// against Mitsuba 3.9.1, its pass-through share 1 − o, nested samples consistent with pdf(), and a
// textured opacity / textured nested BSDF evaluated per point (Bsdf::at).
#include <gtest/gtest.h>

#include "bsdf/textured.h"
#include "bsdf_test_util.h"
#include "texture/texture.h"

namespace rc {
namespace {

using namespace rc::test;

TEST(NullBsdf, PassesEveryRayThroughUnchanged) {
  expectPassThrough(*make("null"), Color(1.0f), 1, 100);
}

BsdfPtr rough02() { return make("roughconductor", {num("alpha", 0.2)}); }

// Mitsuba 3.9.1 scalar_rgb (bench/mitsuba_bsdf_values.py): mask(opacity 0.3) over
// roughconductor(α 0.2), wo = (0.7, φ 0.1), wi = (0.6, φ 3.3): eval = pdf = 0.7510256.
TEST(MaskBsdf, MatchesMitsubaValue) {
  const BsdfPtr m = make("mask", {num("opacity", 0.3)}, {rough02()});
  const Vec3 wo = dirFrom(0.7, 0.1), wi = dirFrom(0.6, 3.3);
  EXPECT_NEAR(m->eval(wo, wi).r, 0.7510256f, 2e-4f);
  EXPECT_NEAR(m->pdf(wo, wi), 0.7510256f, 2e-4f);
}

TEST(MaskBsdf, PassThroughShareIsOneMinusOpacity) {
  const BsdfPtr nested = make("diffuse", {rgb("reflectance", 0.2f, 0.5f, 0.8f)});
  for (const double opacity : {0.0, 0.25, 0.8, 1.0}) {
    const BsdfPtr m = make("mask", {num("opacity", opacity)}, {nested});
    const Vec3 wo = dirFrom(0.6, 1.0);
    Rng rng(7);
    int through = 0, n = 20000;
    for (int k = 0; k < n; ++k) {
      const auto s = m->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
      ASSERT_TRUE(s);
      if (s->lobe & kLobeDelta) {
        ++through;
        EXPECT_EQ(s->wi, -wo);
        EXPECT_EQ(s->weight, Color(1.0f));
        continue;
      }
      // Nested sample: weight = eval/pdf of the mask (both scaled by o).
      const float pdf = m->pdf(wo, s->wi);
      EXPECT_NEAR(s->pdf, pdf, 1e-5f * pdf);
      const Color f = m->eval(wo, s->wi);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->weight[c], f[c] / pdf, 1e-4f * f[c] / pdf);
    }
    const double share = double(through) / n, p = 1.0 - opacity;
    EXPECT_NEAR(share, p, 4 * std::sqrt(p * (1 - p) / n) + 1e-9) << opacity;
  }
}

// The mask over a rough conductor passes the chi-square test of its continuous part (pdf
// integrates to the opacity).
TEST(MaskBsdf, ChiSquareOfTheNestedPart) {
  const BsdfPtr m = make("mask", {num("opacity", 0.6)}, {rough02()});
  const Chi2Result r = chi2ForBsdf(*m, dirFrom(0.5, 0.2), 33);
  EXPECT_FALSE(r.observedWhereImpossible);
  EXPECT_GT(r.pValue, 1e-3) << r.statistic << " dof " << r.dof;
  EXPECT_NEAR(r.expectedTotal / 100000.0, 0.6, 0.01);
}

TEST(MaskBsdf, TexturedOpacityAndTintedNestedPerPoint) {
  // Checkerboard on the opacity, a scalar parameter (Mitsuba's eval_1): colour0 (opacity 1) where
  // frac(u) > ½ and frac(v) > ½ disagree, colour1 (0) where they agree; on the tint, an RGB
  // parameter, the other way round: colour1 (0.2, 0.4, 0.6) where they disagree.
  const TexturePtr opacity = makeCheckerboard(Color(1.0f), Color(0.0f), UvTransform());
  const TexturePtr tint = makeCheckerboard(Color(0.9f), Color(0.2f, 0.4f, 0.6f), UvTransform());
  const BsdfPtr nested = makeTexturedBsdf(make("diffuse", {num("reflectance", 1.0)}), tint);
  Properties props;
  props.pluginType = "mask";
  props.set("opacity", num("opacity", 0.5).value);
  const BsdfPtr m = createBsdf(props, {nested}, "leaf", {{"opacity", opacity}});
  ASSERT_TRUE(m->spatiallyVarying());
  EXPECT_FALSE(m->tinted());  // the factor must not scale the pass-through
  const Vec3 wo = dirFrom(0.8, 0.0), wi = dirFrom(0.5, 2.0);
  const BsdfPtr solid = m->at(TexturePoint(Vec2(0.75f, 0.25f))), hole = m->at(TexturePoint(Vec2(0.25f, 0.25f)));
  ASSERT_TRUE(solid && hole);
  // Solid: the tinted diffuse, colour1 of the tint; hole: nothing but pass-through.
  const Color f = solid->eval(wo, wi);
  EXPECT_NEAR(f.r, 0.2f * 0.5f / kPi, 1e-6f);
  EXPECT_NEAR(f.b, 0.6f * 0.5f / kPi, 1e-6f);
  EXPECT_EQ(hole->eval(wo, wi), Color(0.0f));
  Rng rng(2);
  for (int k = 0; k < 100; ++k) {
    const auto s = hole->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
    ASSERT_TRUE(s);
    EXPECT_EQ(s->weight, Color(1.0f));
    const auto t = solid->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
    ASSERT_TRUE(t);
    EXPECT_NEAR(t->weight.g, 0.4f, 1e-5f);  // diffuse weight ρ, with the baked tint
  }
  // A plain constant mask does not vary.
  EXPECT_FALSE(make("mask", {num("opacity", 0.4)}, {rough02()})->spatiallyVarying());
}

}  // namespace
}  // namespace rc
