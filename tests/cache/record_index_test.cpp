// Record weights, the in-front test, neighbour clamping and the octree against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "cache/radiance_cache.h"
#include "cache/record_octree.h"
#include "cache/record_weights.h"
#include "core/parallel.h"
#include "core/rng.h"

namespace rc {
namespace {

TEST(RecordWeights, WardFormula) {
  const Vec3 n(0, 0, 1);
  // Distance R/2 along the plane, same normal: w = 1/(0.5 + 0) = 2.
  EXPECT_FLOAT_EQ(recordWeight(Vec3(0.5f, 0, 0), n, Vec3(0.0f), n, 1.0f), 2.0f);
  // Normals 60° apart at the record's position: √(1 − cos 60°) = √0.5.
  const Vec3 n60(std::sin(kPi / 3), 0, std::cos(kPi / 3));
  EXPECT_NEAR(recordWeight(Vec3(0.0f), n60, Vec3(0.0f), n, 1.0f), 1.0f / std::sqrt(0.5f), 1e-5f);
}

TEST(RecordWeights, NoDivisionByZero) {
  const Vec3 n(0, 0, 1);
  // Exactly at the record: finite, huge.
  const float w0 = recordWeight(Vec3(1, 2, 3), n, Vec3(1, 2, 3), n, 0.5f);
  EXPECT_TRUE(std::isfinite(w0));
  EXPECT_GE(w0, 1e5f);
  // R = 0: finite and (away from the record) tiny, so it never contributes.
  const float wR = recordWeight(Vec3(1, 0, 0), n, Vec3(0.0f), n, 0.0f);
  EXPECT_TRUE(std::isfinite(wR));
  EXPECT_EQ(contributionWeight(Vec3(1, 0, 0), n, Vec3(0.0f), n, 0.0f, 0.3f), 0.0f);
  // Opposite normals: w = 1/(0 + √2) and never contributes.
  EXPECT_NEAR(recordWeight(Vec3(0.0f), -n, Vec3(0.0f), n, 1.0f), 1.0f / std::sqrt(2.0f), 1e-6f);
  EXPECT_EQ(contributionWeight(Vec3(0.0f), -n, Vec3(0.0f), n, 1.0f, 10.0f), 0.0f);
  // a = 0.3: contributes inside 0.3·R on a plane, not outside.
  EXPECT_GT(contributionWeight(Vec3(0.29f, 0, 0), n, Vec3(0.0f), n, 1.0f, 0.3f), 0.0f);
  EXPECT_EQ(contributionWeight(Vec3(0.31f, 0, 0), n, Vec3(0.0f), n, 1.0f, 0.3f), 0.0f);
}

TEST(RecordWeights, InFrontTest) {
  const Vec3 n(0, 0, 1);
  // Record above p (on a step, its surface in front of p along the normal): rejected.
  EXPECT_TRUE(recordInFront(Vec3(0.0f), n, Vec3(0, 0, 0.2f), n, 1.0f));
  EXPECT_EQ(contributionWeight(Vec3(0.0f), n, Vec3(0.1f, 0, 0.2f), n, 1.0f, 1.0f), 0.0f);
  // Record below p (behind): allowed.
  EXPECT_FALSE(recordInFront(Vec3(0, 0, 0.2f), n, Vec3(0.0f), n, 1.0f));
  // Coplanar: allowed (the ε absorbs rounding).
  EXPECT_FALSE(recordInFront(Vec3(0.1f, 0, -1e-7f), n, Vec3(0.0f), n, 1.0f));
}

TEST(NeighbourClamping, LipschitzBound) {
  float rNew = 10.0f, rj = 1.0f;
  clampNeighbourRadii(Vec3(0.0f), rNew, Vec3(2, 0, 0), rj);
  EXPECT_FLOAT_EQ(rNew, 3.0f);  // 1 + 2
  EXPECT_FLOAT_EQ(rj, 1.0f);
  float rNew2 = 0.5f, rk = 10.0f;
  clampNeighbourRadii(Vec3(0.0f), rNew2, Vec3(0, 3, 0), rk);
  EXPECT_FLOAT_EQ(rNew2, 0.5f);
  EXPECT_FLOAT_EQ(rk, 3.5f);  // 0.5 + 3
}

TEST(NeighbourClamping, AppliedOnInsert) {
  RadianceCache cache(1, Vec3(-1), Vec3(1));
  const std::vector<float> z(3, 0.0f), none;
  RecordInfo a;
  a.p = Vec3(0.0f);
  a.R = 0.1f;
  a.a = 1.0f;
  cache.insert({a}, z, z, z, none, none, none);
  RecordInfo b = a;
  b.p = Vec3(0.5f, 0, 0);
  b.R = 5.0f;  // influence sphere 5 overlaps a's; clamp to 0.1 + 0.5
  cache.insert({b}, z, z, z, none, none, none);
  EXPECT_FLOAT_EQ(cache.info(1).R, 0.6f);
  EXPECT_FLOAT_EQ(cache.info(0).R, 0.1f);
  // A record facing the other way (other side of a wall) is not a neighbour.
  RecordInfo c = b;
  c.frame = Frame::fromNormal(Vec3(0, 0, -1));
  c.R = 5.0f;
  cache.insert({c}, z, z, z, none, none, none);
  EXPECT_FLOAT_EQ(cache.info(2).R, 5.0f);
}

TEST(SkippedRecords, LookupsPassOverThemAndLaterRecordsCount) {
  const std::vector<float> z(3, 0.0f), none;
  const RecordInfo coarse{Vec3(0.0f), Frame(), 1.0f, 0.5f};  // influence radius 0.5, normal +z
  RadianceCache cache(1, Vec3(-1), Vec3(1));
  cache.insert({coarse}, z, z, z, none, none, none);
  Lookup lk;
  cache.lookup(Vec3(0.1f, 0, 0), Vec3(0, 0, 1), lk);
  ASSERT_TRUE(lk.covered());
  cache.setSkipped({1});
  cache.lookup(Vec3(0.1f, 0, 0), Vec3(0, 0, 1), lk);
  EXPECT_FALSE(lk.covered());
  cache.lookupBruteForce(Vec3(0.1f, 0, 0), Vec3(0, 0, 1), lk);
  EXPECT_FALSE(lk.covered());
  cache.lookup(Vec3(0.1f, 0, 0), Vec3(0, 0, 1), lk, 3.0f);  // relaxed lookups skip it too
  EXPECT_FALSE(lk.covered());
  // A finer record inserted after the mask was set is looked up; the skipped one stays stored.
  const RecordInfo fine{Vec3(0.1f, 0, 0), Frame(), 0.1f, 0.5f};
  cache.insert({fine}, z, z, z, none, none, none);
  cache.lookup(Vec3(0.1f, 0, 0), Vec3(0, 0, 1), lk);
  ASSERT_EQ(lk.entries.size(), 1u);
  EXPECT_EQ(lk.entries[0].record, 1);
  EXPECT_EQ(cache.size(), 2u);
}

TEST(RecordOctree, EqualsBruteForceOnRandomRecords) {
  Rng rng(7);
  RadianceCache cache(1, Vec3(0.0f), Vec3(1.0f));
  std::vector<RecordInfo> infos;
  for (int i = 0; i < 1000; ++i) {
    RecordInfo r;
    // Some records outside the initial bounds exercise root growth.
    r.p = Vec3(rng.nextFloat() * 3 - 1, rng.nextFloat() * 3 - 1, rng.nextFloat() * 0.2f);
    Vec3 n(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 1.0f);
    r.frame = Frame::fromNormal(glm::normalize(n));
    // Radii over three orders of magnitude, including ones bigger than the root.
    r.R = std::pow(10.0f, rng.nextFloat() * 3 - 2.5f) * (i % 97 == 0 ? 100.0f : 1.0f);
    r.a = 0.5f + rng.nextFloat() * 2.5f;
    infos.push_back(r);
  }
  const std::vector<float> z(3 * infos.size(), 0.0f), none;
  cache.insert(infos, z, z, z, none, none, none);
  size_t total = 0, totalRelaxed = 0;
  for (int q = 0; q < 2000; ++q) {
    const Vec3 p(rng.nextFloat() * 3.4f - 1.2f, rng.nextFloat() * 3.4f - 1.2f, rng.nextFloat() * 0.2f);
    const Vec3 n = glm::normalize(Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 1.0f));
    // scale 1: the point query (one root-to-leaf path); scale 2: the relaxed lookup of the final
    // pass (a sphere query bounded by the largest reach). Both must equal brute force exactly.
    for (float scale : {1.0f, 2.0f}) {
      Lookup a, b;
      cache.lookup(p, n, a, scale);
      cache.lookupBruteForce(p, n, b, scale);
      ASSERT_EQ(a.entries.size(), b.entries.size()) << "query " << q << " scale " << scale;
      for (size_t i = 0; i < a.entries.size(); ++i) {
        EXPECT_EQ(a.entries[i].record, b.entries[i].record);
        EXPECT_EQ(a.entries[i].weight, b.entries[i].weight);
      }
      (scale == 1.0f ? total : totalRelaxed) += b.entries.size();
    }
  }
  EXPECT_GT(total, 2000u);  // the test exercises real overlaps, not empty lookups
  EXPECT_GT(totalRelaxed, total);  // relaxed lookups reach more records
}

// Relaxed lookups keep, per thread, which records a query has met (RadianceCache's
// VisitedRecords, shared by every cache the thread looks up): queries alternating between two
// caches whose record ids overlap must each still find exactly brute force's records, once each.
TEST(RecordOctree, RelaxedLookupsAlternatingBetweenCachesEqualBruteForce) {
  Rng rng(11);
  auto randomCache = [&](int records) {
    auto cache = std::make_unique<RadianceCache>(1, Vec3(0.0f), Vec3(1.0f));
    std::vector<RecordInfo> infos;
    for (int i = 0; i < records; ++i) {
      RecordInfo r;
      r.p = Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat() * 0.1f);
      r.frame = Frame::fromNormal(glm::normalize(Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 1.0f)));
      r.R = 0.02f + 0.1f * rng.nextFloat();
      r.a = 0.5f + rng.nextFloat();
      infos.push_back(r);
    }
    const std::vector<float> z(3 * infos.size(), 0.0f), none;
    cache->insert(infos, z, z, z, none, none, none);
    return cache;
  };
  const auto small = randomCache(150), large = randomCache(600);
  size_t found = 0;
  for (int q = 0; q < 1000; ++q) {
    const RadianceCache& cache = q % 3 == 0 ? *small : *large;
    const Vec3 p(rng.nextFloat(), rng.nextFloat(), rng.nextFloat() * 0.1f);
    const Vec3 n = glm::normalize(Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 1.0f));
    Lookup a, b;
    cache.lookup(p, n, a, 2.0f);
    cache.lookupBruteForce(p, n, b, 2.0f);
    ASSERT_EQ(a.entries.size(), b.entries.size()) << "query " << q;
    for (size_t i = 0; i < a.entries.size(); ++i) EXPECT_EQ(a.entries[i].record, b.entries[i].record);
    EXPECT_EQ(a.weightSum, b.weightSum);
    EXPECT_EQ(a.sameNormal, b.sameNormal);
    found += a.entries.size();
  }
  EXPECT_GT(found, 1000u);  // real overlaps, not empty lookups
}

// Neighbour clamping of batches (RadianceCache::insert finds candidates among the existing records
// in parallel and among the batch in its serial pass) equals the rule applied record by record with
// brute-force neighbours, and does not depend on the thread count.
TEST(NeighbourClamping, BatchesEqualBruteForceForAnyThreadCount) {
  Rng rng(11);
  std::vector<std::vector<RecordInfo>> batches(4);
  for (auto& batch : batches)
    for (int i = 0; i < 300; ++i) {
      RecordInfo r;
      r.p = Vec3(rng.nextFloat() * 2 - 0.5f, rng.nextFloat() * 2 - 0.5f, rng.nextFloat() * 0.1f);
      r.frame = Frame::fromNormal(glm::normalize(Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 0.6f)));
      r.R = std::pow(10.0f, rng.nextFloat() * 2 - 2.0f);
      r.a = 0.5f + rng.nextFloat();
      batch.push_back(r);
    }
  // Reference: every record in turn against all earlier ones (ARCHITECTURE.md §Conventions order).
  std::vector<RecordInfo> ref;
  for (const auto& batch : batches)
    for (RecordInfo r : batch) {
      std::vector<size_t> with;
      for (size_t q = 0; q < ref.size(); ++q)
        if (glm::dot(ref[q].frame.n, r.frame.n) > 0.0f &&
            glm::length(ref[q].p - r.p) <= ref[q].a * ref[q].R + r.a * r.R)
          with.push_back(q);
      for (size_t q : with) {
        float unused = ref[q].R;
        clampNeighbourRadii(r.p, r.R, ref[q].p, unused);
      }
      for (size_t q : with) {
        float rNew = r.R;
        clampNeighbourRadii(r.p, rNew, ref[q].p, ref[q].R);
      }
      ref.push_back(r);
    }
  size_t clamped = 0;
  for (size_t i = 0, k = 0; i < batches.size(); ++i)
    for (size_t j = 0; j < batches[i].size(); ++j, ++k) clamped += ref[k].R < batches[i][j].R ? 1 : 0;
  EXPECT_GT(clamped, 100u);  // the batches overlap: clamping really happens
  for (int threads : {1, 3}) {
    setThreadCount(threads);
    RadianceCache cache(1, Vec3(0.0f), Vec3(1.0f));
    for (const auto& batch : batches) {
      const std::vector<float> z(3 * batch.size(), 0.0f), none;
      cache.insert(batch, z, z, z, none, none, none);
    }
    ASSERT_EQ(cache.size(), ref.size());
    for (size_t k = 0; k < ref.size(); ++k) ASSERT_EQ(cache.info(static_cast<uint32_t>(k)).R, ref[k].R) << k;
  }
  setThreadCount(0);
}

}  // namespace
}  // namespace rc
