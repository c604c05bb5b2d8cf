// The lobe split (brdf/material_plan.h Technique::LobeSplit): layered BSDFs split into a base and a
// coat that add up to the whole, the plan choosing the split where the coat is too sharp for the
// cache, and rcache serving the base from records while sampling the coat — with the path
// tracer's expectation per 16-px block, and the pilot counting the base as served.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "brdf/material_plan.h"
#include "bsdf/warp.h"
#include "core/rng.h"
#include "test_scene.h"

namespace rc {
namespace {

BsdfPtr plastic(const std::string& type, float alpha, Color base) { return test::layeredPlastic(type, alpha, base); }

Vec3 hemisphereDirection(Rng& rng) {
  const Vec2 u = rng.next2D();
  const float z = std::max(1e-3f, u.x), r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;
  return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// base.eval + coat.eval = eval everywhere; each layer's sample weight is its own eval/pdf (a delta
// coat: s·F(θo), what the whole BSDF's delta sample carries times its lobe probability).
TEST(LobeSplit, LayersAddUpToTheWholeBsdf) {
  for (const BsdfPtr& b : {plastic("roughplastic", 0.1f, Color(0.5f, 0.4f, 0.3f)),
                           plastic("roughplastic", 0.4f, Color(0.2f)), plastic("plastic", 0.0f, Color(0.6f))}) {
    ASSERT_NE(b->baseLayer(), nullptr) << b->typeName();
    ASSERT_NE(b->coatLayer(), nullptr) << b->typeName();
    EXPECT_EQ(b->baseLayer()->lobes(), kLobeDiffuse);
    Rng rng(3, 0);
    for (int i = 0; i < 500; ++i) {
      const Vec3 wo = hemisphereDirection(rng), wi = hemisphereDirection(rng);
      const Color whole = b->eval(wo, wi), parts = b->baseLayer()->eval(wo, wi) + b->coatLayer()->eval(wo, wi);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(parts[c], whole[c], 1e-5f * (1.0f + whole[c])) << b->typeName() << " " << i;
      for (const Bsdf* layer : {b->baseLayer(), b->coatLayer()}) {
        const auto s = layer->sample(wo, rng.nextFloat(), rng.next2D());
        if (!s) continue;
        if (s->lobe & kLobeDelta) {
          EXPECT_EQ(s->pdf, 0.0f);
          continue;
        }
        EXPECT_NEAR(s->pdf, layer->pdf(wo, s->wi), 1e-4f * s->pdf);
        const Color w = layer->eval(wo, s->wi) / s->pdf;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->weight[c], w[c], 1e-4f * (1.0f + w[c]));
      }
    }
  }
  EXPECT_EQ(test::diffuse(0.5f, 0.5f, 0.5f)->baseLayer(), nullptr);
}

// A coat too sharp for order 16 (α 0.05) or a delta coat → lobe split with the base's order-3
// table; a coat the cache can hold (α 0.6) → the whole material radiance-cached as before.
TEST(LobeSplit, PlanSplitsSharpCoats) {
  const std::string dir = (std::filesystem::temp_directory_path() / "rcache_lobe_split_plan").string();
  BrdfTableOptions o;
  o.cacheDir = dir;
  o.notice = [](const std::string&) {};
  BrdfTableSet set;
  set.build({plastic("roughplastic", 0.05f, Color(0.5f)), plastic("plastic", 0.0f, Color(0.5f)),
             plastic("roughplastic", 0.6f, Color(0.5f))},
            o);
  const auto& p = set.plans();
  EXPECT_EQ(p[0].technique, Technique::LobeSplit);
  EXPECT_EQ(p[0].shOrder, 3);
  EXPECT_GE(p[0].tableIndex, 0);
  EXPECT_EQ(p[1].technique, Technique::LobeSplit);
  EXPECT_GE(p[1].tableIndex, 0);
  EXPECT_EQ(p[2].technique, Technique::RadianceCache);
  EXPECT_NE(set.materialsJson().find("\"technique\": \"lobe split\""), std::string::npos);
  // The table is the base's f·cos alone: its band-0 coefficient at ω_o is the base's albedo /
  // (2√π), the coat left out (quadrature and table interpolation ≲ 1 %).
  const BsdfPtr sharp = plastic("roughplastic", 0.05f, Color(0.5f));
  const Vec3 wo = glm::normalize(Vec3(0.5f, 0.0f, 1.0f));
  Rng rng(9, 0);
  double baseAlbedo = 0.0, wholeAlbedo = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const Vec3 wi = squareToCosineHemisphere(rng.next2D());
    const float pdf = wi.z / kPi;
    baseAlbedo += sharp->baseLayer()->eval(wo, wi).g / pdf / n;
    if (auto st = sharp->coatLayer()->sample(wo, rng.nextFloat(), rng.next2D())) wholeAlbedo += st->weight.g / n;
  }
  wholeAlbedo += baseAlbedo;
  std::vector<double> f;
  set.lookup(p[0].tableIndex, wo, f);
  const double tableAlbedo = f[p[0].shOrder * p[0].shOrder] * 2.0 * std::sqrt(kPi);  // green channel
  std::printf("base albedo %.4f, from the table %.4f, whole %.4f\n", baseAlbedo, tableAlbedo, wholeAlbedo);
  EXPECT_NEAR(tableAlbedo, baseAlbedo, 0.02 * baseAlbedo);
  EXPECT_GT(wholeAlbedo, baseAlbedo * 1.02);
  std::filesystem::remove_all(dir);
}

// A rough-plastic floor (α 0.1: too sharp for the cache), a rough-plastic and a smooth-plastic
// sphere under the sun sky: the pilot keeps the cache, counting the bases as served, the final pass splits the lobes,
// and every 16-px block agrees with the path tracer.
TEST(LobeSplit, RoughPlasticUnderSkyAgreesWithPathTracerPerBlock) {
  Scene s;
  s.bsdfs.push_back(plastic("roughplastic", 0.1f, Color(0.5f, 0.45f, 0.4f)));  // 0 floor
  s.bsdfs.push_back(plastic("roughplastic", 0.05f, Color(0.2f, 0.5f, 0.7f)));  // 1 sphere
  s.bsdfs.push_back(plastic("plastic", 0.0f, Color(0.6f, 0.6f, 0.6f)));        // 2 sphere (delta coat)
  s = test::twoSpheresUnderSky(s, "plastic", "smooth plastic", 48);
  const auto ref = test::renderScene(s, test::pathSettings(s), 512, 11);
  const auto split = test::renderScene(s, test::rcacheSettings(s, {{"lobe_split", "true"}}), 16, 3);
  EXPECT_EQ(test::statText(split.stats, "fallback").rfind("cached", 0), 0u) << test::statText(split.stats, "fallback");
  EXPECT_GT(split.stats.get("pilot_lobe_split_share"), 0.25);
  EXPECT_GT(split.stats.get("lobe_split_fraction"), 0.3);
  EXPECT_GT(split.stats.get("records"), 0.0);
  EXPECT_EQ(test::statText(split.stats, "env_cache"), "split");
  // The whole environment light-sampled by the bases (no environment in the records) too.
  const auto sampled =
      test::renderScene(s, test::rcacheSettings(s, {{"env_cache", "false"}, {"lobe_split", "true"}}), 16, 3);
  EXPECT_GT(sampled.stats.get("lobe_split_fraction"), 0.3);
  const test::BlockStats r = test::blockMeans(ref.image, 16), m = test::blockMeans(split.image, 16),
                         n = test::blockMeans(sampled.image, 16);
  // Tolerance as in LightSplit.CachedEnvironmentAgreesWithPathTracerPerBlock: 4 % of the block
  // mean + 0.01 per channel (half the 512-spp reference's own noise, half the records').
  const double worst = test::worstBlockError(r, m, 0.04, 0.01),
               worstSampled = test::worstBlockError(r, n, 0.04, 0.01);
  std::printf("worst block error / tolerance: lobe split %.3f, env sampled %.3f\n", worst, worstSampled);
  EXPECT_LT(worst, 1.0);
  EXPECT_LT(worstSampled, 1.0);
}

}  // namespace
}  // namespace rc
