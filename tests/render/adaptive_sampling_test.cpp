// Adaptive sampling: the per-pixel error estimate and its neighbourhood, the doubling rounds and
// their cap (unit), and whole images from the path tracer (the rcache side: tests/cache).
#include <gtest/gtest.h>

#include <cstring>

#include "core/image_metrics.h"
#include "core/parallel.h"
#include "render/adaptive_sampling.h"
#include "render/path_integrator.h"
#include "render_test_scenes.h"

namespace rc {
namespace {

AdaptiveSettings on(float threshold, int maxSpp = 0) {
  AdaptiveSettings s;
  s.threshold = threshold;
  s.maxSpp = maxSpp;
  return s;
}

// Feeds every pixel's current range with f(pixel, sample).
template <class F>
void feed(AdaptivePixels& a, F f) {
  for (size_t p = 0; p < a.ranges().size(); ++p)
    for (int s = a.ranges()[p].first; s < a.ranges()[p].end; ++s) a.add(p, s, f(p, s));
}

TEST(AdaptivePixels, OffTakesNoSecondRound) {
  AdaptivePixels a(8, 8, 4, AdaptiveSettings{});
  feed(a, [](size_t, int s) { return Color(float(s % 2) * 100.0f); });  // very noisy
  EXPECT_FALSE(a.nextRound());
  for (size_t p = 0; p < 64; ++p) EXPECT_EQ(a.ranges()[p].count(), 0);
  EXPECT_EQ(a.totalSamples(), 64u * 4u);
}

TEST(AdaptivePixels, ConvergedPixelsStop) {
  AdaptivePixels a(8, 8, 4, on(0.01f));
  feed(a, [](size_t p, int) { return Color(0.1f * float(p)); });  // constant per pixel: error 0
  EXPECT_FALSE(a.nextRound());
  EXPECT_EQ(a.pixelsAboveSpp(), 0u);
}

TEST(AdaptivePixels, NoisyPixelAndItsNeighbourhoodDouble) {
  const int W = 16, H = 16;
  AdaptivePixels a(W, H, 4, on(0.05f));
  const size_t noisy = 8 * W + 8;
  // First half 0, second half 1: mean 0.5, half-mean 0: e² = 0.25 / 0.26 ≈ 0.96 ≫ 0.05².
  feed(a, [&](size_t p, int s) { return Color(p == noisy && s >= 2 ? 1.0f : 0.0f); });
  EXPECT_FLOAT_EQ(a.errorSquared(noisy), float(0.25 / 0.26));
  EXPECT_EQ(a.errorSquared(noisy + 1), 0.0f);
  ASSERT_TRUE(a.nextRound());
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const bool near = std::abs(x - 8) <= kAdaptiveWindow && std::abs(y - 8) <= kAdaptiveWindow;
      const SampleRange r = a.ranges()[size_t(y) * W + x];
      if (near) {
        EXPECT_EQ(r.first, 4) << x << "," << y;  // samples 4…7: the doubled set
        EXPECT_EQ(r.end, 8) << x << "," << y;
      } else {
        EXPECT_EQ(r.count(), 0) << x << "," << y;
      }
    }
  EXPECT_EQ(a.pixelsAboveSpp(), uint64_t((2 * kAdaptiveWindow + 1) * (2 * kAdaptiveWindow + 1)));
}

TEST(AdaptivePixels, HalvesFollowTheDoublingAndTheCapHolds) {
  AdaptivePixels a(1, 1, 4, on(0.01f, 24));
  // Sample s has radiance s: the mean of the first half always trails the mean of all.
  std::vector<int> counts;
  do {
    feed(a, [](size_t, int s) { return Color(float(s)); });
    counts.push_back(a.samplesOf(0));
  } while (a.nextRound());
  // 4 → 8 → 16 → 24 (capped), never more.
  EXPECT_EQ(counts, (std::vector<int>{4, 8, 16, 24}));
  EXPECT_EQ(a.maxSamples(), 24);
  // A pixel with one sample has no estimate yet: it always takes a second round.
  AdaptivePixels one(2, 2, 1, on(10.0f));
  feed(one, [](size_t, int) { return Color(1.0f); });
  EXPECT_TRUE(std::isinf(one.errorSquared(0)));
  ASSERT_TRUE(one.nextRound());
  EXPECT_EQ(one.ranges()[3].first, 1);
  EXPECT_EQ(one.ranges()[3].end, 2);
}

TEST(AdaptivePixels, RestartForgetsAPixel) {
  AdaptivePixels a(4, 1, 2, on(0.01f));
  feed(a, [](size_t, int s) { return Color(float(s) * 5.0f); });
  ASSERT_TRUE(a.nextRound());
  feed(a, [](size_t, int s) { return Color(float(s) * 5.0f); });
  a.restart(0, 4);
  for (size_t p = 0; p < 4; ++p) {
    EXPECT_EQ(a.samplesOf(p), 2);
    EXPECT_EQ(a.ranges()[p].first, 0);
    EXPECT_EQ(a.ranges()[p].end, 2);
  }
  feed(a, [](size_t, int) { return Color(1.0f); });
  EXPECT_FALSE(a.nextRound());
}

Image renderPath(const test::World& w, int spp, uint64_t seed, AdaptiveSettings adaptive, RenderStats* stats = nullptr) {
  RenderOptions o;
  o.spp = spp;
  o.seed = seed;
  o.sampler = "ldsampler";
  o.adaptive = adaptive;
  return w.renderPath(o, stats);
}

// The visible light's edge is where a 16-spp image errs most; adaptive sampling spends its extra
// samples there and beats the plain image of the same base spp, keeps the image mean (it is
// consistent, and its bias is far below the noise), and stays independent of the thread count.
TEST(AdaptiveSampling, PathTracerSpendsSamplesWhereTheErrorIs) {
  Scene s = test::cornellLike(32, 32);
  s.camera.toWorld = test::lookAt({0, 1, 3.6f}, {0, 1.6f, 0}, {0, 1, 0});  // the light in view
  const test::World w(std::move(s));
  setThreadCount(2);
  const Image ref = renderPath(w, 1024, 99, AdaptiveSettings{});
  RenderStats st;
  const Image plain = renderPath(w, 16, 1, AdaptiveSettings{});
  const Image adaptive = renderPath(w, 16, 1, on(0.15f, 256), &st);
  setThreadCount(1);
  const Image oneThread = renderPath(w, 16, 1, on(0.15f, 256));
  setThreadCount(0);
  EXPECT_EQ(0, std::memcmp(adaptive.pixels.data(), oneThread.pixels.data(), adaptive.pixels.size() * sizeof(Color)));
  const double mean = st.get("samples_per_pixel_mean");
  EXPECT_GT(mean, 16.0);
  EXPECT_LT(mean, 256.0);
  EXPECT_GT(st.get("adaptive_pixels_fraction"), 0.0);
  EXPECT_LT(st.get("adaptive_pixels_fraction"), 1.0);
  EXPECT_EQ(st.get("samples_per_pixel_max"), 256.0);
  const double ePlain = compareImages(plain.pixels, ref.pixels).relmse;
  const double eAdaptive = compareImages(adaptive.pixels, ref.pixels).relmse;
  std::printf("relMSE plain 16 spp %.4g, adaptive (mean %.1f spp) %.4g\n", ePlain, mean, eAdaptive);
  EXPECT_LT(eAdaptive, ePlain);
  double mRef = 0, mAd = 0;
  for (size_t i = 0; i < ref.pixels.size(); ++i) mRef += luminance(ref.pixels[i]), mAd += luminance(adaptive.pixels[i]);
  EXPECT_NEAR(mAd / mRef, 1.0, 0.02);
}

}  // namespace
}  // namespace rc
