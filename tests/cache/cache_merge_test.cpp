// rcache cache merge (cache/cache_merge.h): the union of the parts' records, de-duplicated, radii
// clamped across parts, byte-identical whatever the order of the parts; parts of another scene
// are refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cache/cache_merge.h"
#include "core/error.h"

namespace rc {
namespace {

// A part with records at the given x positions on the plane z = 0 (normal +z), order 2.
std::vector<CacheFileEntry> part(const std::vector<float>& xs, const std::vector<float>& radii) {
  CacheFileEntry e;
  e.key = CacheKey{0, 1, 2};
  const size_t k = 3 * 4;
  for (size_t i = 0; i < xs.size(); ++i) {
    RecordInfo r;
    r.p = Vec3(xs[i], 0.0f, 0.0f);
    r.frame = Frame(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
    r.R = radii[i];
    r.a = 0.5f;
    e.infos.push_back(r);
    for (size_t c = 0; c < k; ++c) {
      e.lambda.push_back(xs[i] + 0.01f * c);
      e.gradT.push_back(0.0f);
      e.gradB.push_back(0.0f);
    }
  }
  return {e};
}

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string tmp(const std::string& name) { return (std::filesystem::temp_directory_path() / name).string(); }

TEST(CacheMerge, DeduplicatesAndClampsAcrossParts) {
  // Record x=0 (R 0.4) is in both parts; part B's copy was shrunk to 0.3. B adds a fine record at
  // x=0.1 (R 0.05) next to A's coarse record at x=0.2 (R 4): 4 > 0.05 + 0.1 → clamped to 0.15.
  const auto a = part({0.0f, 0.2f}, {0.4f, 4.0f});
  const auto b = part({0.0f, 0.1f}, {0.3f, 0.05f});
  MergeReport rep;
  const auto merged = mergeCacheEntries({a, b}, &rep);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(rep.recordsIn, 4u);
  EXPECT_EQ(rep.duplicates, 1u);
  ASSERT_EQ(merged[0].infos.size(), 3u);
  EXPECT_EQ(merged[0].lambda.size(), 3u * 12u);
  for (const RecordInfo& r : merged[0].infos) {
    if (r.p.x == 0.0f) EXPECT_FLOAT_EQ(r.R, 0.15f);  // min(0.3, R(0.1) + 0.1): the smaller copy, then clamped
    if (r.p.x == 0.2f) EXPECT_FLOAT_EQ(r.R, 0.15f);
    if (r.p.x == 0.1f) EXPECT_FLOAT_EQ(r.R, 0.05f);
  }
  EXPECT_GE(rep.radiiClamped, 2u);
}

TEST(CacheMerge, SameFileWhateverTheOrder) {
  const auto a = part({0.0f, 0.5f, 1.0f}, {0.2f, 0.3f, 0.25f});
  const auto b = part({0.0f, 0.7f}, {0.2f, 0.1f});
  const auto c = part({2.0f, 0.6f}, {1.0f, 0.05f});
  const std::string pa = tmp("rc_merge_a.rcc"), pb = tmp("rc_merge_b.rcc"), pc = tmp("rc_merge_c.rcc");
  saveCacheFile(pa, 77, a);
  saveCacheFile(pb, 77, b);
  saveCacheFile(pc, 77, c);
  const std::string o1 = tmp("rc_merge_o1.rcc"), o2 = tmp("rc_merge_o2.rcc");
  const MergeReport r1 = mergeCacheFiles({pa, pb, pc}, o1);
  mergeCacheFiles({pc, pa, pb}, o2);
  EXPECT_EQ(r1.recordsOut, 6u);
  EXPECT_EQ(fileBytes(o1), fileBytes(o2));
  uint64_t hash = 0;
  EXPECT_EQ(loadCacheFile(o1, nullptr, &hash)[0].infos.size(), 6u);
  EXPECT_EQ(hash, 77u);
}

TEST(CacheMerge, RefusesPartsOfAnotherScene) {
  const std::string pa = tmp("rc_merge_s1.rcc"), pb = tmp("rc_merge_s2.rcc");
  saveCacheFile(pa, 1, part({0.0f}, {1.0f}));
  saveCacheFile(pb, 2, part({1.0f}, {1.0f}));
  try {
    mergeCacheFiles({pa, pb}, tmp("rc_merge_s3.rcc"));
    ADD_FAILURE() << "merged two scenes";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("rc_merge_s2.rcc: cache file was made for another scene"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(tmp("rc_merge_s3.rcc")));
}

}  // namespace
}  // namespace rc
