// Material planning (technique, SH order) and the disk cache of tables.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>

#include "brdf/material_plan.h"
#include "brdf/order_selection.h"
#include "brdf/table_cache.h"
#include "brdf/table_layout.h"
#include "test_bsdfs.h"

namespace rc {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test, removed at the end.
struct TempDir {
  std::string path;
  TempDir() {
    char tmpl[] = "/tmp/rc_brdf_test_XXXXXX";
    path = mkdtemp(tmpl);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// Small, fast settings: the machinery is the same at any resolution.
BrdfTableOptions smallOptions(const std::string& dir, std::vector<std::string>* notices) {
  BrdfTableOptions o;
  o.cacheDir = dir;
  o.isotropicRes = 8;
  o.anisotropicRes = 5;
  o.maxOrder = 12;
  o.tableQuadrature = LobeQuadrature{512, 256};
  o.planQuadrature = LobeQuadrature{1024, 512};
  o.notice = [notices](const std::string& m) {
    if (notices) notices->push_back(m);
  };
  return o;
}

std::vector<BsdfPtr> mixedScene() {
  std::vector<BsdfPtr> v;
  v.push_back(std::make_shared<test::TestLambert>(Color(0.7f, 0.2f, 0.2f)));
  v.push_back(test::ggx(0.5f));
  v.push_back(std::make_shared<test::TestMirror>());
  v.push_back(std::make_shared<test::TestMicrofacet>(true, 0.4f, 0.8f));
  v.push_back(test::ggx(0.01f));  // far too sharp for order 12
  return v;
}

TEST(BrdfPlan, TechniquesPerMaterial) {
  TempDir dir;
  std::vector<std::string> notices;
  BrdfTableSet set;
  set.build(mixedScene(), smallOptions(dir.path, &notices));
  const auto& p = set.plans();
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[0].technique, Technique::IrradianceCache);
  EXPECT_EQ(p[0].shOrder, 3);
  EXPECT_EQ(p[1].technique, Technique::RadianceCache);
  EXPECT_GE(p[1].shOrder, 3);
  EXPECT_EQ(p[1].tableKind, RC_TABLE_ISOTROPIC_1D);
  EXPECT_LE(p[1].truncationError, 0.10);
  EXPECT_EQ(p[2].technique, Technique::ImportanceSampling);
  EXPECT_EQ(p[2].tableIndex, -1);
  EXPECT_EQ(p[3].technique, Technique::RadianceCache);
  EXPECT_EQ(p[3].tableKind, RC_TABLE_ANISOTROPIC_2D);
  EXPECT_EQ(p[4].technique, Technique::ImportanceSampling);
  EXPECT_EQ(p[4].tableIndex, -1);
  ASSERT_EQ(set.tables().size(), 3u);
  size_t floats = 0;
  for (int m : {0, 1, 3}) {
    const RcBrdfTable& t = set.tables()[p[m].tableIndex];
    EXPECT_EQ(t.order, p[m].shOrder);
    EXPECT_EQ(static_cast<size_t>(t.offset), floats);
    floats += tableFloatCount(t.kind, t.order, t.res);
  }
  EXPECT_EQ(set.data().size(), floats);
  EXPECT_TRUE(notices.empty());
  const std::string json = set.materialsJson();
  EXPECT_NE(json.find("\"technique\": \"irradiance cache\""), std::string::npos);
  EXPECT_NE(json.find("\"table_cache_hit\": false"), std::string::npos);
  EXPECT_EQ(std::count(json.begin(), json.end(), '{'), 5);
}

TEST(BrdfPlan, NothingCachedBuildsNothing) {
  TempDir dir;
  const std::string sub = dir.path + "/never";
  BrdfTableSet set;
  set.build({std::make_shared<test::TestMirror>()}, smallOptions(sub, nullptr));
  EXPECT_TRUE(set.tables().empty());
  EXPECT_TRUE(set.data().empty());
  EXPECT_EQ(set.plans().at(0).technique, Technique::ImportanceSampling);
  EXPECT_FALSE(fs::exists(sub));  // not even the cache directory is created
}

// Sharper lobe → higher order, or importance sampling; never lower. Checked for GGX and Beckmann
// at the default tolerance/angle range, plus a tighter tolerance (which may only raise orders).
TEST(BrdfPlan, OrderIsMonotoneInRoughness) {
  const float alphas[] = {1.0f, 0.5f, 0.3f, 0.2f, 0.1f, 0.05f};  // rough → sharp
  for (bool isGgx : {true, false}) {
    for (double tol : {0.10, 0.05}) {
      int previous = 1;
      std::vector<int> orders;
      for (float a : alphas) {
        const auto bsdf = isGgx ? test::ggx(a) : test::beckmann(a);
        const OrderChoice c = selectShOrder(*bsdf, tol, 16, LobeQuadrature{1536, 512});
        const int order = c.order == 0 ? 17 : c.order;  // importance sampling ranks above any order
        EXPECT_GE(order, previous) << (isGgx ? "ggx" : "beckmann") << " tol " << tol << " alpha " << a;
        previous = order;
        orders.push_back(order);
        // The reported curve is non-increasing in the order (more bands never lose energy).
        for (size_t n = 1; n < c.worstError.size(); ++n) EXPECT_LE(c.worstError[n], c.worstError[n - 1] + 1e-9);
      }
      // The range is not degenerate: α = 1 is cached at a low order, α = 0.05 is sampled.
      EXPECT_LE(orders.front(), 10);
      EXPECT_EQ(orders.back(), 17);
    }
  }
}

TEST(BrdfCache, SecondBuildIsAHitAndEqual) {
  TempDir dir;
  std::vector<std::string> notices;
  const auto scene = mixedScene();
  BrdfTableSet a, b;
  a.build(scene, smallOptions(dir.path, &notices));
  b.build(scene, smallOptions(dir.path, &notices));
  EXPECT_TRUE(notices.empty());
  for (size_t m = 0; m < scene.size(); ++m) {
    if (m == 2) continue;  // the delta material has nothing to cache
    EXPECT_FALSE(a.plans()[m].tableCacheHit) << m;
    EXPECT_TRUE(b.plans()[m].tableCacheHit) << m;
    EXPECT_EQ(a.plans()[m].shOrder, b.plans()[m].shOrder);
  }
  EXPECT_EQ(a.data(), b.data());  // bit-identical
  // Force rebuild ignores the files and gives the same numbers (the quadrature is deterministic).
  BrdfTableOptions force = smallOptions(dir.path, &notices);
  force.forceRebuild = true;
  BrdfTableSet c;
  c.build(scene, force);
  EXPECT_FALSE(c.plans()[1].tableCacheHit);
  EXPECT_EQ(a.data(), c.data());
}

std::vector<std::string> cacheFiles(const std::string& dir) {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(BrdfCache, CorruptOrTruncatedFileIsDetectedAndRebuilt) {
  TempDir dir;
  std::vector<std::string> notices;
  const std::vector<BsdfPtr> scene{test::ggx(0.5f)};
  BrdfTableSet ref;
  ref.build(scene, smallOptions(dir.path, &notices));
  const std::vector<std::string> files = cacheFiles(dir.path);
  ASSERT_EQ(files.size(), 2u);  // the order choice and the table
  enum Damage { FlipPayloadByte, Truncate, BadMagic, Empty };
  for (Damage damage : {FlipPayloadByte, Truncate, BadMagic, Empty}) {
    for (const std::string& f : files) {
      std::string bytes;
      {
        std::ifstream in(f, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
      }
      if (damage == FlipPayloadByte) bytes[bytes.size() - 12] ^= 0x40;
      if (damage == Truncate) bytes.resize(bytes.size() - 7);
      if (damage == BadMagic) bytes[0] = 'X';
      if (damage == Empty) bytes.clear();
      std::ofstream(f, std::ios::binary | std::ios::trunc).write(bytes.data(), bytes.size());
    }
    notices.clear();
    BrdfTableSet rebuilt;
    rebuilt.build(scene, smallOptions(dir.path, &notices));
    EXPECT_EQ(notices.size(), 2u) << "damage " << damage;  // one line per bad file
    for (const std::string& n : notices) {
      EXPECT_NE(n.find("rebuilding"), std::string::npos) << n;
      EXPECT_EQ(n.find('\n'), std::string::npos);
    }
    EXPECT_FALSE(rebuilt.plans()[0].tableCacheHit);
    EXPECT_EQ(rebuilt.data(), ref.data());
    // The rebuilt files are valid again: the next build is a silent hit.
    notices.clear();
    BrdfTableSet again;
    again.build(scene, smallOptions(dir.path, &notices));
    EXPECT_TRUE(notices.empty());
    EXPECT_TRUE(again.plans()[0].tableCacheHit);
  }
}

TEST(BrdfCache, FileOfAnotherKeyIsRejected) {
  TempDir dir;
  std::vector<std::string> notices;
  BrdfDiskCache cache(dir.path, [&](const std::string& m) { notices.push_back(m); });
  ASSERT_TRUE(cache.enabled());
  CachedBlob blob;
  blob.kind = 0;
  blob.order = 2;
  blob.res = 2;
  blob.payload.assign(24, 1.5f);
  cache.store("key A", blob);
  fs::rename(cache.pathFor("key A"), cache.pathFor("key B"));
  CachedBlob out;
  EXPECT_FALSE(cache.load("key B", out));
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_NE(notices[0].find("another"), std::string::npos);
  cache.store("key A", blob);
  EXPECT_TRUE(cache.load("key A", out));
  EXPECT_EQ(out.payload, blob.payload);
}

TEST(BrdfCache, UnwritableDirectoryWorksWithoutCache) {
  TempDir dir;
  // A regular file where the directory should be: cannot be created, whoever runs the test
  // (a chmod-based test would pass as root).
  const std::string blocker = dir.path + "/file";
  std::ofstream(blocker) << "x";
  std::vector<std::string> notices;
  BrdfTableSet set;
  set.build({test::ggx(0.5f)}, smallOptions(blocker + "/cache", &notices));
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_NE(notices[0].find("without the disk cache"), std::string::npos);
  EXPECT_EQ(set.plans()[0].technique, Technique::RadianceCache);
  EXPECT_FALSE(set.tables().empty());
  EXPECT_TRUE(set.cacheDirectory().empty());
}

TEST(BrdfCache, DirectoryFromEnvironment) {
  const char* old = std::getenv("RC_CACHE_DIR");
  const std::string saved = old ? old : "";
  setenv("RC_CACHE_DIR", "/tmp/rc_env_dir", 1);
  EXPECT_EQ(resolveBrdfCacheDir(""), "/tmp/rc_env_dir");
  EXPECT_EQ(resolveBrdfCacheDir("/explicit"), "/explicit");
  unsetenv("RC_CACHE_DIR");
  setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  EXPECT_EQ(resolveBrdfCacheDir(""), "/tmp/xdg/rcache");
  unsetenv("XDG_CACHE_HOME");
  if (old) setenv("RC_CACHE_DIR", saved.c_str(), 1);
}

}  // namespace
}  // namespace rc
