#include <gtest/gtest.h>

#include <chrono>

#include "core/image_metrics.h"
#include "test_scene.h"

namespace rc {
namespace {

TEST(RcacheSmoke, RendersBoxAndMatchesPathTracerRoughly) {
  const Scene s = test::boxScene(0.2f);
  auto t0 = std::chrono::steady_clock::now();
  auto rc = test::renderScene(s, test::rcacheSettings(s), 4);
  double trc = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  t0 = std::chrono::steady_clock::now();
  auto pt = test::renderScene(s, test::pathSettings(s), 256);
  double tpt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const ImageError e = compareImages(rc.image.pixels, pt.image.pixels);
  std::printf("rcache %.2fs records %.0f  path %.2fs  relmse %.5f rmse %.5f\n", trc, rc.stats.get("records"), tpt,
              e.relmse, e.rmse);
  for (auto& [k, v] : rc.stats.numbers) std::printf("  %s = %g\n", k.c_str(), v);
  for (auto& [k, v] : rc.stats.json) std::printf("  %s = %s\n", k.c_str(), v.c_str());
  for (auto& [k, v] : rc.stats.texts) std::printf("  %s = %s\n", k.c_str(), v.c_str());
  EXPECT_LT(e.relmse, 0.05);
}

}  // namespace
}  // namespace rc
