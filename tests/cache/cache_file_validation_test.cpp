// Crafted cache files with a valid checksum and scene hash (issue 19, finding 8): every field out
// of the range the renderer produces is refused on load with a message naming it. Each case
// starts from a valid file written by saveCacheFile and changes one field.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>

#include "cache/cache_file.h"
#include "core/error.h"

namespace rc {
namespace {

constexpr uint64_t kHash = 0x5CE7E;

std::vector<CacheFileEntry> validEntries() {
  CacheFileEntry e;
  e.key = CacheKey{0, 1, 3};
  for (int i = 0; i < 2; ++i) {
    RecordInfo r;
    r.p = Vec3(0.1f * i, 0.5f, -2.0f);
    r.frame = Frame(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
    r.R = 0.2f;
    r.a = 0.4f;
    e.infos.push_back(r);
  }
  const size_t k = e.infos.size() * 3 * 9;
  e.lambda.assign(k, 0.25f);
  e.gradT.assign(k, 0.01f);
  e.gradB.assign(k, -0.01f);
  return {e};
}

class CacheFileValidation : public ::testing::Test {
 protected:
  std::string path = "/tmp/rc_validation_" + std::to_string(getpid()) + ".rcc";
  void TearDown() override { std::remove(path.c_str()); }
  // Saves the valid entries changed by `mutate` and expects the load to fail naming `why`.
  void expectRejected(const std::function<void(std::vector<CacheFileEntry>&)>& mutate, const std::string& why) {
    std::vector<CacheFileEntry> entries = validEntries();
    mutate(entries);
    saveCacheFile(path, kHash, entries);
    try {
      loadCacheFile(path, kHash);
      ADD_FAILURE() << "accepted a file with " << why;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
};

TEST_F(CacheFileValidation, ValidFileLoads) {
  saveCacheFile(path, kHash, validEntries());
  const auto loaded = loadCacheFile(path, kHash);
  ASSERT_EQ(loaded.size(), 1u);
  EXPECT_EQ(loaded[0].infos.size(), 2u);
}

TEST_F(CacheFileValidation, NonFiniteCoefficients) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  expectRejected([&](auto& e) { e[0].lambda[5] = nan; }, "non-finite or huge radiance coefficient");
  expectRejected([&](auto& e) { e[0].gradT[0] = inf; }, "non-finite or huge gradient coefficient");
  expectRejected([&](auto& e) { e[0].gradB[3] = -3e38f; }, "non-finite or huge gradient coefficient");
}

TEST_F(CacheFileValidation, RadiusAndAccuracyRanges) {
  expectRejected([](auto& e) { e[0].infos[1].R = 3e38f; }, "a·R beyond 1e18");
  expectRejected([](auto& e) { e[0].infos[0].R = 1e-38f, e[0].infos[0].a = 1e-38f; }, "a outside");
  expectRejected([](auto& e) { e[0].infos[0].R = 1e-30f; }, "below float resolution");
  expectRejected([](auto& e) { e[0].infos[0].a = 1e20f; }, "a outside");
  expectRejected([](auto& e) { e[0].infos[0].R = 0.0f; }, "radius or a ≤ 0");
}

TEST_F(CacheFileValidation, PositionsAndFrames) {
  expectRejected([](auto& e) { e[0].infos[0].p = Vec3(1e38f, 0, 0); }, "position beyond");
  expectRejected([](auto& e) { e[0].infos[1].frame.n = Vec3(0, 0, 2); }, "not unit");
  expectRejected([](auto& e) { e[0].infos[1].frame.b = Vec3(0.6f, 0.8f, 0); }, "not perpendicular");
}

TEST_F(CacheFileValidation, KeyRanges) {
  expectRejected([](auto& e) { e[0].key.level = 1000000; }, "level 1000000 outside");
  expectRejected([](auto& e) { e[0].key.depth = -7; }, "depth -7 outside");
  for (int order : {17, 20})
    expectRejected(
        [&](auto& e) {
          e[0].key.order = order;
          const size_t k = e[0].infos.size() * 3 * order * order;
          e[0].lambda.assign(k, 0.0f), e[0].gradT.assign(k, 0.0f), e[0].gradB.assign(k, 0.0f);
        },
        "SH order " + std::to_string(order) + " outside");
}

TEST_F(CacheFileValidation, DuplicateKeys) {
  expectRejected([](auto& e) { e.push_back(e[0]); }, "(level 0, depth 1, order 3) twice");
}

// Finding 6: the scene hash keys images (and meshes) by their contents, not their paths.
TEST(CacheSceneHash, EnvmapByPixelsNotPath) {
  Scene scene;
  Emitter env;
  env.type = EmitterType::Envmap;
  env.filename = "/one/dir/sky.exr";
  env.envWidth = 2;
  env.envHeight = 1;
  env.envPixels = {Color(1.0f), Color(0.5f)};
  scene.emitters.push_back(env);
  const uint64_t h0 = cacheSceneHash(scene, 4, false);
  scene.emitters[0].filename = "../elsewhere/sky.exr";
  EXPECT_EQ(cacheSceneHash(scene, 4, false), h0) << "the path must not matter";
  scene.emitters[0].envPixels[1] = Color(0.5f, 0.5f, 0.6f);
  EXPECT_NE(cacheSceneHash(scene, 4, false), h0) << "the pixels must";
}

}  // namespace
}  // namespace rc
