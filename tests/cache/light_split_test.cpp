// The environment split (cache/light_split.h): the threshold's choice on synthetic maps, the
// two parts adding up to the envmap exactly, and rcache with the environment in its records
// agreeing with the path tracer per 16-px block.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cache/light_split.h"
#include "core/rng.h"
#include "test_scene.h"

namespace rc {
namespace {

using test::kEnvH;
using test::kEnvW;
using test::skyEmitter;
using test::skyTexels;
using test::statText;

TEST(LightSplit, UniformMapIsCachedWholeAndSunIsSplitOff) {
  const std::vector<Color> uniform(static_cast<size_t>(kEnvW) * kEnvH, Color(2.0f));
  EXPECT_TRUE(std::isinf(environmentSplitThreshold(kEnvW, kEnvH, uniform, 1.0f / 3.0f)));
  // The sky alone (zenith 1.5× the horizon, dark ground) passes the variance bound whole.
  EXPECT_TRUE(std::isinf(environmentSplitThreshold(kEnvW, kEnvH, skyTexels(0.0f), 1.0f / 3.0f)));
  // With a sun the threshold lies between the sky's brightest texel and the sun.
  const float tau = environmentSplitThreshold(kEnvW, kEnvH, skyTexels(5000.0f), 1.0f / 3.0f);
  const float skyMax = luminance(Color(0.6f, 0.8f, 1.2f)) * 1.5f;
  std::printf("sun map: tau = %g (sky max %g)\n", tau, skyMax);
  EXPECT_GT(tau, skyMax);
  EXPECT_LT(tau, 5000.0f);
  // A smaller κ never raises the threshold.
  EXPECT_LE(environmentSplitThreshold(kEnvW, kEnvH, skyTexels(5000.0f), 0.05f), tau);
}

TEST(LightSplit, PartsAddUpToTheEnvmapInEveryDirection) {
  Scene s;
  s.emitters.push_back(skyEmitter(5000.0f));
  s.emitters.back().scale = 0.7f;
  Emitter c;
  c.type = EmitterType::Constant;
  c.radiance = Color(0.2f, 0.3f, 0.4f);
  s.emitters.push_back(c);
  const LightSampler full(s);
  const LightSplit split(s, true, 1.0f / 3.0f);
  ASSERT_TRUE(split.active());
  EXPECT_GT(split.summary().cachedFraction, 0.05);
  EXPECT_GT(split.summary().sampledFraction, 0.05);
  EXPECT_NEAR(split.summary().cachedFraction + split.summary().sampledFraction, 1.0, 1e-12);
  Rng rng(7, 0);
  for (int i = 0; i < 2000; ++i) {
    const Vec2 u = rng.next2D();
    const float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;
    const Vec3 d(r * std::cos(phi), r * std::sin(phi), z);
    const Color whole = full.environment(d);
    const Color parts = split.cached(d) + split.residualLights().environment(d);
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(parts[k], whole[k], 1e-4f * (1.0f + whole[k])) << "direction " << i;
    // The cached part never exceeds τ by more than interpolation between clamped texels can.
    EXPECT_LE(luminance(split.cached(d)), split.summary().threshold + luminance(c.radiance) + 1e-3f);
  }
  // The residual sampler still samples the residual by importance: its pdf is positive on the
  // sun and zero where the residual is zero (the sky below τ).
  const Vec3 sunDir = envDirection(21.0f / kEnvW, 10.5f / (kEnvH - 1));
  EXPECT_GT(split.residualLights().environmentPdf(sunDir), 0.0f);
  EXPECT_EQ(split.residualLights().environmentPdf(Vec3(0, 1, 0)), 0.0f);
}

TEST(LightSplit, DisabledWithoutEnvironmentOrWhenOff) {
  const Scene box = test::boxScene(0.3f);
  EXPECT_FALSE(LightSplit(box, true, 1.0f / 3.0f).active());
  Scene sky;
  sky.emitters.push_back(skyEmitter(5000.0f));
  EXPECT_FALSE(LightSplit(sky, false, 1.0f / 3.0f).active());
}

// A diffuse floor, a glossy (radiance-cached) sphere and a diffuse sphere under the sun sky.
Scene skyScene(int res) {
  Scene s;
  s.bsdfs.push_back(test::diffuse(0.5f, 0.45f, 0.4f));  // 0 floor
  s.bsdfs.push_back(test::glossy(0.3f));                // 1 glossy sphere
  s.bsdfs.push_back(test::diffuse(0.2f, 0.5f, 0.7f));   // 2 diffuse sphere
  return test::twoSpheresUnderSky(s, "glossy", "diffuse", res);
}

using test::BlockStats;
using test::blockMeans;

TEST(LightSplit, CachedEnvironmentAgreesWithPathTracerPerBlock) {
  const Scene s = skyScene(48);
  const auto ref = test::renderScene(s, test::pathSettings(s), 512, 11);
  const auto cached = test::renderScene(s, test::rcacheSettings(s), 16, 3);
  const auto sampled = test::renderScene(s, test::rcacheSettings(s, {{"env_cache", "false"}}), 16, 3);
  EXPECT_EQ(statText(cached.stats, "env_cache"), "split");
  EXPECT_GT(cached.stats.get("env_cached_fraction"), 0.1);
  EXPECT_GT(cached.stats.get("env_sampled_fraction"), 0.1);
  EXPECT_EQ(statText(sampled.stats, "env_cache"), "off (disabled)");
  const test::BlockStats r = test::blockMeans(ref.image, 16), a = test::blockMeans(cached.image, 16),
                        b = test::blockMeans(sampled.image, 16);
  // Tolerance: 4 % of the block mean + 0.01 per channel. Half of it is the reference's own noise:
  // two 512-spp references with different seeds differ by up to 2.0 % in their worst block and
  // channel (measured). The other half is the cache's record noise, correlated over a block rather
  // than averaged by it (records a few pixels apart on a 48² image). Leaving the cached sky out
  // (≥ 10 % of the sky's power) or counting it twice (records and direct light: measured 8.1× the
  // tolerance) moves the blocks by far more.
  const double worstCached = test::worstBlockError(r, a, 0.04, 0.01),
               worstSampled = test::worstBlockError(r, b, 0.04, 0.01);
  std::printf("worst block error / tolerance: env cached %.3f, env sampled %.3f\n", worstCached, worstSampled);
  EXPECT_LT(worstCached, 1.0);
  EXPECT_LT(worstSampled, 1.0);
}

// area_cache=true: records carry the emission their rays find on the area light and cached points
// stop light-sampling it. On a large dim panel (most of the ceiling, the box's light power) the
// image has the path tracer's expectation, block by block (tolerance and reason as above);
// double counting the light or dropping it is far outside. (A small bright light is what records
// estimate badly: bench/RESULTS.md, which is why area_cache is off by default.)
TEST(LightSplit, CachedLargeAreaLightAgreesWithPathTracerPerBlock) {
  Scene s = test::boxScene(0.3f, 48, 32);
  Mesh& panel = s.meshes.back();
  ASSERT_EQ(panel.emitter, 0);
  panel.positions = {{-0.9f, 1.98f, -0.9f}, {0.9f, 1.98f, -0.9f}, {0.9f, 1.98f, 0.9f}, {-0.9f, 1.98f, 0.9f}};
  s.emitters[0].radiance = Color(12.0f * 0.36f / 3.24f);
  const auto ref = test::renderScene(s, test::pathSettings(s), 512, 11);
  const auto cached = test::renderScene(s, test::rcacheSettings(s, {{"area_cache", "true"}}), 16, 3);
  EXPECT_EQ(statText(cached.stats, "area_cache"), "area emitters cached");
  EXPECT_EQ(statText(cached.stats, "env_cache"), "off (no environment emitter)");
  const test::BlockStats r = test::blockMeans(ref.image, 16), a = test::blockMeans(cached.image, 16);
  const double worst = test::worstBlockError(r, a, 0.04, 0.01);
  std::printf("worst block error / tolerance: area light cached %.3f\n", worst);
  EXPECT_LT(worst, 1.0);
}

// The pilot (cache/path_fallback.h): a scene of sharp materials only gives the cache nothing to
// serve, so rcache hands the image to the path tracer — the very image `path` renders, bit for
// bit — and says so; with fallback=false it caches anyway; the sky scene's cached materials keep
// the cache.
TEST(PathFallback, SharpSceneIsPathTracedAndSaysSo) {
  Scene s = skyScene(32);
  for (auto& b : s.bsdfs) b = test::glossy(0.02f);
  const auto path = test::renderScene(s, test::pathSettings(s), 4, 5);
  const auto auto_ = test::renderScene(s, test::rcacheSettings(s), 4, 5);
  EXPECT_EQ(statText(auto_.stats, "fallback").rfind("path traced", 0), 0u) << statText(auto_.stats, "fallback");
  EXPECT_LT(auto_.stats.get("pilot_served_share", 1.0), 0.25);
  ASSERT_EQ(auto_.image.pixels.size(), path.image.pixels.size());
  for (size_t i = 0; i < path.image.pixels.size(); ++i) ASSERT_EQ(auto_.image.pixels[i], path.image.pixels[i]) << i;
  const auto forced = test::renderScene(s, test::rcacheSettings(s, {{"fallback", "false"}}), 4, 5);
  EXPECT_EQ(statText(forced.stats, "fallback"), "not considered");
  const Scene sky = skyScene(32);
  const auto cached = test::renderScene(sky, test::rcacheSettings(sky), 2, 5);
  EXPECT_EQ(statText(cached.stats, "fallback").rfind("cached", 0), 0u) << statText(cached.stats, "fallback");
  EXPECT_GT(cached.stats.get("records"), 0.0);
}

}  // namespace
}  // namespace rc
