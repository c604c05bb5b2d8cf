// The cost pilot (cache/cost_pilot.h): the choice of the fastest technique to the path tracer's
// error from measured variance, floor, fixed and per-sample cost; and, on a scene rendered by
// rcache, that the pilot runs, reports its candidates and renders with the one it chose.
#include <gtest/gtest.h>

#include <cmath>

#include "cache/cost_pilot.h"
#include "test_scene.h"

namespace rc {
namespace {

TechniqueEstimate estimate(CandidateKind kind, double variance, double floor, double fixedS, double perSppS) {
  TechniqueEstimate e;
  e.kind = kind;
  e.variance = variance;
  e.floor = floor;
  e.fixedS = fixedS;
  e.perSppS = perSppS;
  return e;
}

// The path tracer at 64 spp: error 1/64 in 64 s. A cache with a tenth of its variance and no floor
// needs 6.4 spp: 10 + 7.68 s. The same cache with a floor at the target cannot reach it; with a
// fill of 100 s it is slower than the path tracer.
TEST(CostPilot, ChoosesTheFastestToThePathTracersError) {
  const TechniqueEstimate path = estimate(CandidateKind::PathTracer, 1.0, 0.0, 0.0, 1.0);
  CostChoice c = chooseByCost({path, estimate(CandidateKind::Rcache, 0.1, 0.0, 10.0, 1.2)}, 64);
  EXPECT_DOUBLE_EQ(c.targetError, 1.0 / 64.0);
  EXPECT_DOUBLE_EQ(c.candidates[0].secondsToTarget, 64.0);
  EXPECT_NEAR(c.candidates[1].sppToTarget, 6.4, 1e-9);
  EXPECT_NEAR(c.candidates[1].secondsToTarget, 17.68, 1e-9);
  EXPECT_EQ(c.chosen, 1);

  c = chooseByCost({path, estimate(CandidateKind::Rcache, 0.1, 1.0 / 64.0, 10.0, 1.2)}, 64);
  EXPECT_TRUE(std::isinf(c.candidates[1].secondsToTarget));
  EXPECT_EQ(c.chosen, 0);

  c = chooseByCost({path, estimate(CandidateKind::Rcache, 0.1, 0.0, 100.0, 1.2)}, 64);
  EXPECT_EQ(c.chosen, 0);

  // A floor below the target costs samples: V / (E* − B). Between two caches the faster wins.
  c = chooseByCost({path, estimate(CandidateKind::Rcache, 0.1, 0.0, 10.0, 1.2),
                    estimate(CandidateKind::RcacheLobeSplit, 0.05, 0.5 / 64.0, 12.0, 1.5)},
                   64);
  EXPECT_NEAR(c.candidates[2].sppToTarget, 6.4, 1e-9);
  EXPECT_NEAR(c.candidates[2].secondsToTarget, 12.0 + 1.5 * 6.4, 1e-9);
  EXPECT_EQ(c.chosen, 1);

  // Equal times: the path tracer (no fill to risk).
  c = chooseByCost({path, estimate(CandidateKind::Rcache, 1.0, 0.0, 0.0, 1.0)}, 64);
  EXPECT_EQ(c.chosen, 0);
  // No path tracer first: no decision.
  EXPECT_EQ(chooseByCost({estimate(CandidateKind::Rcache, 0.1, 0.0, 1.0, 1.0)}, 64).chosen, -1);
}

// A rough-plastic floor too sharp for the cache (α 0.1: lobe split), a diffuse wall behind and a
// diffuse sphere under a sky, 96² (the smallest image the cost pilot runs on): the share pilot
// caches it with and without the split.
Scene skyScene() {
  Scene s;
  s.bsdfs.push_back(test::layeredPlastic("roughplastic", 0.1f, Color(0.5f, 0.45f, 0.4f)));
  s.bsdfs.push_back(test::diffuse(0.6f, 0.5f, 0.4f));
  test::addQuad(s, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}, 0);
  test::addQuad(s, {-4, 0, -1}, {4, 0, -1}, {4, 4, -1}, {-4, 4, -1}, 1);
  test::addSphere(s, "ball", Vec3(0.0f, 0.5f, 0.0f), 0.5f, 1);
  s.emitters.push_back(test::skyEmitter(400.0f));
  test::setTestCamera(s, Vec3(0, 1.6f, 3.2f), Vec3(0, 0.3f, 0), 96, 96);
  return s;
}

std::string statJson(const RenderStats& st, const std::string& key) {
  for (const auto& [k, v] : st.json)
    if (k == key) return v;
  return "";
}

TEST(CostPilot, RendersWithTheCandidateItChose) {
  const Scene s = skyScene();
  // A budget that lets every candidate be tried (at 4 spp the path-traced render is far shorter
  // than one candidate's pilot).
  const auto r = test::renderScene(s, test::rcacheSettings(s, {{"cost_pilot", "true"}, {"cost_pilot_share", "1000"}}), 4, 1);
  const std::string choice = test::statText(r.stats, "cost_pilot");
  const std::string candidates = statJson(r.stats, "cost_pilot_candidates");
  std::printf("share pilot: %s\ncost pilot: %s\n%s\n", test::statText(r.stats, "fallback").c_str(), choice.c_str(),
              candidates.c_str());
  ASSERT_FALSE(candidates.empty()) << choice;
  for (const char* name : {"\"path tracer\"", "\"rcache\"", "\"rcache + lobe split\""})
    EXPECT_NE(candidates.find(name), std::string::npos) << name;
  EXPECT_EQ(test::statText(r.stats, "cost_pilot_film"), "24x24, 4 spp");
  EXPECT_GT(r.stats.get("cost_pilot_target_relmse"), 0.0);
  EXPECT_GT(r.stats.get("cost_pilot_s"), 0.0);
  // The render is the chosen candidate's.
  if (choice.rfind("path tracer", 0) == 0) {
    EXPECT_EQ(test::statText(r.stats, "fallback").rfind("path traced", 0), 0u);
  } else if (choice.rfind("rcache + lobe split", 0) == 0) {
    EXPECT_GT(r.stats.get("lobe_split_fraction"), 0.1);
  } else {
    ASSERT_EQ(choice.rfind("rcache:", 0), 0u) << choice;
    EXPECT_EQ(r.stats.get("lobe_split_fraction", -1.0), 0.0);
  }

  // lobe_split=false: no such candidate, no split; cost_pilot=false: no pilot, lobe_split=true
  // keeps the split, auto does not (the default without a measurement).
  const auto off =
      test::renderScene(s, test::rcacheSettings(s, {{"cost_pilot", "true"}, {"lobe_split", "false"}, {"cost_pilot_share", "1000"}}), 4, 1);
  EXPECT_NE(statJson(off.stats, "cost_pilot_candidates").find("\"rcache\""), std::string::npos);
  EXPECT_EQ(statJson(off.stats, "cost_pilot_candidates").find("lobe split"), std::string::npos);
  EXPECT_LE(off.stats.get("lobe_split_fraction", 0.0), 0.0);
  const auto kept =
      test::renderScene(s, test::rcacheSettings(s, {{"cost_pilot", "false"}, {"lobe_split", "true"}}), 4, 1);
  EXPECT_EQ(test::statText(kept.stats, "cost_pilot"), "");
  EXPECT_GT(kept.stats.get("lobe_split_fraction"), 0.1);
  const auto unmeasured = test::renderScene(s, test::rcacheSettings(s, {{"cost_pilot", "false"}}), 4, 1);
  EXPECT_LE(unmeasured.stats.get("lobe_split_fraction", 0.0), 0.0);
  // By default there is no cost pilot (its choice would follow timings).
  EXPECT_EQ(test::statText(test::renderScene(s, test::rcacheSettings(s), 4, 1).stats, "cost_pilot"), "");
  // At its default budget the pilot tries no cache for a 4-spp render (each candidate's pilot
  // would cost more than 5 % of it): the candidates are reported as not tried, the fill's predicted
  // payoff (cache/fill_payoff.h) decides, and where it caches the share pilot's verdict without the
  // split stands.
  const auto quick = test::renderScene(s, test::rcacheSettings(s, {{"cost_pilot", "true"}}), 4, 1);
  EXPECT_EQ(test::statText(quick.stats, "cost_pilot").rfind("no candidate", 0), 0u) << test::statText(quick.stats, "cost_pilot");
  EXPECT_NE(statJson(quick.stats, "cost_pilot_candidates").find("\"tried\": false"), std::string::npos);
  const std::string payoff = test::statText(quick.stats, "fill_payoff");
  const std::string share = test::statText(unmeasured.stats, "fallback");
  ASSERT_FALSE(payoff.empty());
  if (payoff.rfind("path traced", 0) == 0)
    EXPECT_EQ(test::statText(quick.stats, "fallback"), payoff + " (" + share + ")");
  else
    EXPECT_EQ(test::statText(quick.stats, "fallback"), share);
  EXPECT_LE(quick.stats.get("lobe_split_fraction", 0.0), 0.0);
}

}  // namespace
}  // namespace rc
