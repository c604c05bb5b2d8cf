// Whether the fill can pay (cache/fill_payoff.h): the prediction on figures worked by hand, the
// coherence test's q turned into pixels per record, and a scene the cost pilot cannot afford to
// try a cache on, at 1 spp under a sun, that is path traced.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cache/fill_payoff.h"
#include "cache/record_coherence.h"
#include "test_scene.h"

namespace rc {
namespace {

FillPayoffFigures figures(int spp, double pixelsPerRecord, double raysPerSample, double indirectShare) {
  FillPayoffFigures f;
  f.spp = spp;
  f.pixelsPerRecord = pixelsPerRecord;
  f.raysPerSample = raysPerSample;
  f.indirectShare = indirectShare;
  return f;  // h = c = s = 1, S = 512, o = 0.3
}

// 1 spp, records serving 4 px, half the variance indirect: the fill's 2·512/4 = 256 rays per pixel
// against the path tracer's 2 rays × 1/(0.5 + 0.5/512) spp = 3.99 at rcache's error.
TEST(FillPayoff, FillOfRecordsServingFewPixelsCannotPayAtOneSpp) {
  const FillPayoff p = predictFillPayoff(figures(1, 4.0, 2.0, 0.5));
  EXPECT_DOUBLE_EQ(p.fillRays, 256.0);
  EXPECT_DOUBLE_EQ(p.cacheRays, 256.0 + 1.3 * 2.0);
  EXPECT_NEAR(p.pathEqualSpp, 1.0 / (0.5 + 0.5 / 512.0), 1e-12);
  EXPECT_NEAR(p.pathRays, 2.0 / (0.5 + 0.5 / 512.0), 1e-12);
  EXPECT_FALSE(p.pays);
  EXPECT_EQ(p.reason.rfind("path traced, the fill cannot pay", 0), 0u) << p.reason;
}

// 64 spp, records serving 100 px, 90 % of the variance indirect, 4 rays per sample: 10.24 + 1.3·256
// = 343.04 rays per pixel against 4 × 64/(0.1 + 0.9·64/512) = 1204.7.
TEST(FillPayoff, FillOfWideRecordsPaysWhereIndirectNoiseDominates) {
  const FillPayoff p = predictFillPayoff(figures(64, 100.0, 4.0, 0.9));
  EXPECT_NEAR(p.cacheRays, 343.04, 1e-9);
  EXPECT_NEAR(p.pathRays, 4.0 * 64.0 / 0.2125, 1e-9);
  EXPECT_TRUE(p.pays);
  // Records serve only the served share: with none served, the path tracer's error is rcache's.
  FillPayoffFigures f = figures(64, 100.0, 4.0, 0.9);
  f.servedShare = 0.0;
  EXPECT_DOUBLE_EQ(predictFillPayoff(f).pathEqualSpp, 64.0);
  EXPECT_FALSE(predictFillPayoff(f).pays);
}

// No indirect noise: nothing for the records to remove, and the final pass costs 1 + o per sample.
TEST(FillPayoff, NoIndirectNoiseNeverPays) {
  const FillPayoff p = predictFillPayoff(figures(16, 300.0, 3.0, 0.0));
  EXPECT_DOUBLE_EQ(p.pathEqualSpp, 16.0);
  EXPECT_FALSE(p.pays);
}

// m = πρ², ρ = 2δ/(π(1 − q)): the coherence test's threshold is 1 + o pixels per record at δ = ½ px.
TEST(FillPayoff, PixelsPerRecordFromTheCoherenceTest) {
  EXPECT_NEAR(pixelsPerRecord(minNeighbourServed(), 0.5, 10.0), 1.0 + kFinalPassOverhead, 1e-9);
  EXPECT_NEAR(pixelsPerRecord(0.0, 0.5, 10.0), 1.0 / kPiD, 1e-12);
  EXPECT_NEAR(pixelsPerRecord(1.0, 0.5, 10.0), kPiD * 100.0, 1e-9);  // at most r_max's disk
  EXPECT_NEAR(pixelsPerRecord(0.999, 0.5, 10.0), kPiD * 100.0, 1e-9);
}

// Two diffuse spheres on a diffuse floor under a sky with a sun, 96² at 1 spp, records of 16384
// rays: the cost pilot cannot afford a cache candidate (its pilot would cost more than 5 % of a
// 1-spp render), the records would serve every point and serve their neighbours (smooth surfaces),
// but at 1 spp a fill of such records costs more rays per pixel than the path tracer needs to reach
// rcache's error: the path integrator's image, bit for bit. (At the budget's own record size the
// fill pays here: the envmap's bilinear sampling density leaves little of the sun's direct light as
// noise, so most of the path tracer's variance is indirect, which the records remove.)
TEST(FillPayoff, OneSppWithCostlyRecordsIsPathTracedWhenTheCostPilotCannotTry) {
  Scene base;
  for (int i = 0; i < 3; ++i) base.bsdfs.push_back(test::diffuse(0.6f, 0.55f, 0.5f));
  const Scene s = test::twoSpheresUnderSky(base, "left", "right", 96);
  const auto path = test::renderScene(s, test::pathSettings(s), 1, 3);
  const auto r = test::renderScene(s, test::rcacheSettings(s, {{"cost_pilot", "true"}, {"rays", "16384"}}), 1, 3);
  const std::string why = test::statText(r.stats, "fallback");
  std::printf("%s\n", why.c_str());
  EXPECT_NE(test::statText(r.stats, "cost_pilot").find("payoff decides"), std::string::npos);
  EXPECT_EQ(why.rfind("path traced, the fill cannot pay", 0), 0u) << why;
  EXPECT_GT(r.stats.get("pilot_neighbour_served_bound"), minNeighbourServed());  // coherence passed
  EXPECT_LE(r.stats.get("fill_payoff_indirect_share"), 1.0);
  EXPECT_GT(r.stats.get("fill_payoff_rays_per_pixel"), r.stats.get("fill_payoff_path_rays_per_pixel"));
  EXPECT_EQ(r.stats.get("records", 0.0), 0.0);
  ASSERT_EQ(r.image.pixels.size(), path.image.pixels.size());
  for (size_t i = 0; i < path.image.pixels.size(); ++i) ASSERT_EQ(r.image.pixels[i], path.image.pixels[i]) << i;
  // Without the cost pilot the share pilot's verdict stands (the default): cached.
  const auto plain = test::renderScene(s, test::rcacheSettings(s), 1, 3);
  EXPECT_EQ(test::statText(plain.stats, "fallback").rfind("cached", 0), 0u);
  EXPECT_EQ(plain.stats.get("fill_payoff_indirect_share", -1.0), -1.0);
}

}  // namespace
}  // namespace rc
