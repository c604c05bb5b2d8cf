// pplastic and polarizer in RGB mode: values against Mitsuba 3.9.1 scalar_rgb (eval/pdf of the same
// configuration, bench/mitsuba_bsdf_values.py prints them), pplastic's sampling against its pdf, and
// the polarizer's pass-through weight t/2 (Mitsuba's sample weight and eval_null_transmission).
#include <gtest/gtest.h>

#include "bsdf_test_util.h"
#include "core/error.h"

namespace rc {
namespace {

using namespace rc::test;

BsdfPtr docsPplastic() { return make("pplastic", {rgb("diffuse_reflectance", 0.05f, 0.03f, 0.1f), num("alpha", 0.06)}); }
BsdfPtr ggxColoured() {
  return make("pplastic", {str("distribution", "ggx"), num("alpha", 0.3), num("int_ior", 1.7),
                           rgb("diffuse_reflectance", 0.6f, 0.4f, 0.2f), rgb("specular_reflectance", 0.8f, 0.9f, 1.0f)});
}
BsdfPtr anisoAllNormals() {
  return make("pplastic", {num("alpha_u", 0.1), num("alpha_v", 0.3), num("eta", 1.33), boolean("sample_visible", false)});
}

struct MitsubaValue {
  BsdfPtr (*make)();
  double cosO, phiO, cosI, phiI;
  double eval[3];
  double pdf;
};
// si.wi = our wo, wo = our wi, unit frame.
const MitsubaValue kMitsuba[] = {
    {docsPplastic, 0.8, 0.2, 0.75, 3.3, {0.7355433106, 0.7311790586, 0.7464540005}, 15.63415241},  // near mirror
    {docsPplastic, 0.5, 0.2, 0.9, 1.0, {0.01255558245, 0.007533349097, 0.0251111649}, 0.0162157733},  // off-specular
    {ggxColoured, 0.6, 0.4, 0.5, 3.9, {0.1124853417, 0.09167633951, 0.07086734474}, 0.382044822},
    {anisoAllNormals, 0.7, 0.3, 0.4, 3.0, {0.05690945685, 0.05690945685, 0.05690945685}, 0.06160897762},
};

TEST(PolarizedPlastic, MatchesMitsubaEvalAndPdf) {
  for (const MitsubaValue& v : kMitsuba) {
    const BsdfPtr b = v.make();
    const Vec3 wo = dirFrom(v.cosO, v.phiO), wi = dirFrom(v.cosI, v.phiI);
    const Color f = b->eval(wo, wi);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], v.eval[c], 2e-4 * v.eval[c] + 1e-9) << v.cosO << " → " << v.cosI;
    EXPECT_NEAR(b->pdf(wo, wi), v.pdf, 2e-4 * v.pdf + 1e-9) << v.cosO << " → " << v.cosI;
  }
}

TEST(PolarizedPlastic, BlackBelowTheSurface) {
  const BsdfPtr b = docsPplastic();
  EXPECT_EQ(b->eval(dirFrom(-0.5, 0.0), dirFrom(0.5, 2.0)), Color(0.0f));
  EXPECT_EQ(b->eval(dirFrom(0.5, 0.0), dirFrom(-0.5, 2.0)), Color(0.0f));
  EXPECT_FALSE(b->sample(dirFrom(-0.5, 0.0), 0.3f, Vec2(0.4f, 0.6f)));
}

TEST(PolarizedPlastic, ChiSquareAndWeights) {
  int index = 0;
  for (BsdfPtr (*makeFn)() : {docsPplastic, ggxColoured, anisoAllNormals}) {
    const BsdfPtr b = makeFn();
    const Vec3 wo = dirFrom(0.55, 0.7);
    const Chi2Result r = chi2ForBsdf(*b, wo, 70 + index++);
    EXPECT_FALSE(r.observedWhereImpossible) << b->parameterKey();
    EXPECT_GT(r.pValue, 1e-3 / 3) << b->parameterKey() << ": chi2 " << r.statistic << ", dof " << r.dof;
    Rng rng(5, index);
    for (int k = 0; k < 2000; ++k) {
      const auto s = b->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
      if (!s) continue;
      const float pdf = b->pdf(wo, s->wi);
      ASSERT_NEAR(s->pdf, pdf, 1e-4f * pdf);
      const Color f = b->eval(wo, s->wi);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(s->weight[c], f[c] / pdf, 1e-4f * f[c] / pdf + 1e-9f);
    }
  }
}

TEST(PolarizedPlastic, RejectsEtaTogetherWithIors) {
  EXPECT_THROW(make("pplastic", {num("eta", 1.5), num("int_ior", 1.5)}), Error);
  EXPECT_THROW(make("pplastic", {num("int_ior", 1.5), num("ext_ior", 1.5)}), Error);
  EXPECT_THROW(make("pplastic", {str("distribution", "phong")}), Error);
}

TEST(Polarizer, PassesRaysWithHalfTheTransmittance) {
  // Mitsuba 3.9.1 scalar_rgb: sample weight and eval_null_transmission 0.5 (default) and
  // (0.4, 0.25, 0.1) for transmittance (0.8, 0.5, 0.2), any theta; eval 0.
  struct Case {
    std::vector<Param> params;
    Color weight;
  };
  const Case cases[] = {{{}, Color(0.5f)},
                        {{num("theta", 30.0), rgb("transmittance", 0.8f, 0.5f, 0.2f)}, Color(0.4f, 0.25f, 0.1f)}};
  for (const Case& c : cases) expectPassThrough(*make("polarizer", c.params), c.weight, 2, 50);
  EXPECT_THROW(make("polarizer", {str("theta", "north")}), Error);
}

}  // namespace
}  // namespace rc
