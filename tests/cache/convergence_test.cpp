// Convergence: the rcache image approaches a high-spp path-traced reference of the same scene
// and max_depth as records get more rays and a smaller a (denser records).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "core/image_metrics.h"
#include "test_scene.h"

namespace rc {
namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(Convergence, ErrorFallsWithRaysAndAccuracy) {
  Scene s = test::boxScene(0.4f, 32, 24);
  s.integrator.maxDepth = 4;  // two indirect bounces: exercises the level-1 (secondary) caches
  auto t0 = std::chrono::steady_clock::now();
  const auto ref = test::renderScene(s, test::pathSettings(s), 2048, 99);
  const double tRef = seconds(t0);
  struct Setting { const char* a; const char* rays; };
  const Setting settings[] = {{"0.6", "128"}, {"0.3", "512"}, {"0.15", "2048"}};
  double err[3];
  for (int i = 0; i < 3; ++i) {
    t0 = std::chrono::steady_clock::now();
    // 16 spp so that the (exact, but noisy) direct light does not hide the cache's error.
    const auto r = test::renderScene(
        s, test::rcacheSettings(s, {{"a", settings[i].a}, {"rays", settings[i].rays}, {"order", "8"}}), 16, 1);
    const double t = seconds(t0);
    err[i] = compareImages(r.image.pixels, ref.image.pixels).relmse;
    std::printf("rcache a=%s rays=%s: relMSE %.5f, %.2f s, %g records\n", settings[i].a, settings[i].rays, err[i], t,
                r.stats.get("records"));
  }
  // Equal-time path tracing for the record (printed, not asserted: timings vary on CI).
  t0 = std::chrono::steady_clock::now();
  const auto pt = test::renderScene(s, test::pathSettings(s), 64, 7);
  std::printf("path 64 spp: relMSE %.5f, %.2f s (reference 2048 spp: %.2f s)\n",
              compareImages(pt.image.pixels, ref.image.pixels).relmse, seconds(t0), tRef);
  EXPECT_LT(err[1], err[0]);
  EXPECT_LT(err[2], err[1]);
  // Bound: measured 0.0013 (a 64-spp path tracer: 0.0015); the reference's own noise is
  // ~0.00005. 0.005 leaves room for other seeds/backends while still catching a biased cache
  // (before the gradient limit on R this setting gave 0.027 from one extrapolated pixel).
  EXPECT_LT(err[2], 0.005);
}

}  // namespace
}  // namespace rc
