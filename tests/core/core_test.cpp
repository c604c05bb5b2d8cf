// Core utilities: error metrics, properties use-tracking, RNG determinism, parallelFor, atomic writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <utility>
#include <sys/stat.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/frame.h"
#include "core/image_metrics.h"
#include "core/math.h"
#include "core/parallel.h"
#include "core/parallel_sort.h"
#include "core/phase_cpu.h"
#include "core/properties.h"
#include "core/rng.h"

using namespace rc;

TEST(ImageMetrics, MatchesHandComputedValues) {
  std::vector<Color> ref = {Color(1, 0, 0), Color(0.5f, 0.5f, 0.5f)};
  std::vector<Color> test = {Color(1.1f, 0, 0), Color(0.5f, 0.5f, 0.3f)};
  const ImageError e = compareImages(test, ref);
  // Squared errors: 0.01 (r of pixel 0) and 0.04 (b of pixel 1) over 6 samples.
  EXPECT_NEAR(e.rmse, std::sqrt(0.05 / 6), 1e-6);
  EXPECT_NEAR(e.relmse, (0.01 / 1.01 + 0.04 / 0.26) / 6, 1e-6);
  EXPECT_NEAR(e.maxAbs, 0.2, 1e-6);
  EXPECT_EQ(compareImages(ref, ref).relmse, 0.0);
}

TEST(ImageMetrics, CountsNonFiniteAndRejectsSizeMismatch) {
  std::vector<Color> ref = {Color(1), Color(1)};
  std::vector<Color> test = {Color(NAN), Color(1)};
  EXPECT_EQ(compareImages(test, ref).nonFinite, 1u);
  EXPECT_EQ(compareImages(test, ref).relmse, 0.0);
  EXPECT_THROW(compareImages({Color(1)}, ref), Error);
}

TEST(Properties, TracksUseAndChecksTypes) {
  Properties p;
  Property f;
  f.type = Property::Type::Float;
  f.number = 0.25;
  f.line = 7;
  p.set("alpha", f);
  Property s;
  s.type = Property::Type::String;
  s.text = "ggx";
  p.set("distribution", s);
  EXPECT_EQ(p.unusedNames().size(), 2u);
  EXPECT_FLOAT_EQ(p.getFloat("alpha", 0.1f), 0.25f);
  EXPECT_EQ(p.getColor("alpha", Color(0)), Color(0.25f));
  EXPECT_THROW(p.getFloat("distribution", 0), Error);
  ASSERT_EQ(p.unusedNames().size(), 0u);
  EXPECT_EQ(p.lineOf("alpha"), 7);
  EXPECT_EQ(p.getInt("missing", 3), 3);
}

// maxComponent and the warps use fmaxInline in place of std::fmax: the images stay bit-identical
// only if it returns the very bits glibc's fmaxf does, signed zeros and NaNs included.
TEST(Math, FmaxInlineMatchesStdFmaxBitForBit) {
  const volatile float nan = std::nanf("");
  const float values[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 1e-38f, -1e-45f, INFINITY, -INFINITY, nan, 3.0e38f};
  for (float a : values)
    for (float b : values) {
      // Through a volatile pointer: glibc's fmaxf at run time, as the renderer called it (never a
      // compile-time folding, which need not order equal signed zeros the same way).
      float (*volatile libmFmax)(float, float) = ::fmaxf;
      const float expected = libmFmax(a, b), got = rc::fmaxInline(a, b);
      uint32_t e, g;
      std::memcpy(&e, &expected, 4);
      std::memcpy(&g, &got, 4);
      if (std::isnan(expected)) EXPECT_TRUE(std::isnan(got)) << a << " " << b;
      else EXPECT_EQ(e, g) << a << " " << b;
    }
}

TEST(Rng, DeterministicPerStreamAndInRange) {
  Rng a(42, 7), b(42, 7), c(42, 8);
  bool differs = false;
  for (int i = 0; i < 1000; ++i) {
    const float x = a.nextFloat();
    EXPECT_EQ(x, b.nextFloat());
    differs |= x != c.nextFloat();
    EXPECT_GE(x, 0.0f);
    EXPECT_LT(x, 1.0f);
  }
  EXPECT_TRUE(differs);
}

// Reseeding a used Rng (the sample loop reuses its per-row Rngs in place) gives exactly the stream
// of a fresh one, also after a low-discrepancy prefix was in use.
TEST(Rng, ReseedingAUsedRngEqualsAFreshOne) {
  Rng used(1, 2);
  used.useLowDiscrepancy(99, 5, 24);
  for (int i = 0; i < 3; ++i) used.nextFloat();
  used.seedWith(42, 7);
  Rng fresh(42, 7);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(used.nextUint(), fresh.nextUint());
  used.useLowDiscrepancy(3, 4, 24);
  for (int i = 0; i < 5; ++i) used.nextFloat();
  used.seedWith(8, 9);
  used.useLowDiscrepancy(11, 12, 24);
  fresh.seedWith(8, 9);
  fresh.useLowDiscrepancy(11, 12, 24);
  Rng brandNew(8, 9);
  brandNew.useLowDiscrepancy(11, 12, 24);
  for (int i = 0; i < 40; ++i) {
    const uint32_t x = brandNew.nextUint();
    EXPECT_EQ(used.nextUint(), x);
    EXPECT_EQ(fresh.nextUint(), x);
  }
}

TEST(Frame, DuffBasisIsOrthonormalAndRightHanded) {
  Rng rng(1);
  for (int i = 0; i < 1000; ++i) {
    Vec3 n(rng.nextFloat() * 2 - 1, rng.nextFloat() * 2 - 1, rng.nextFloat() * 2 - 1);
    if (i == 0) n = Vec3(0, 0, -1);
    if (i == 1) n = Vec3(0, 0, 1);
    if (glm::length(n) < 1e-3f) continue;
    n = glm::normalize(n);
    const Frame f = Frame::fromNormal(n);
    EXPECT_NEAR(glm::dot(f.t, f.b), 0, 1e-5);
    EXPECT_NEAR(glm::dot(f.t, f.n), 0, 1e-5);
    EXPECT_NEAR(glm::length(f.t), 1, 1e-5);
    EXPECT_NEAR(glm::length(f.b), 1, 1e-5);
    EXPECT_NEAR(glm::length(glm::cross(f.t, f.b) - f.n), 0, 1e-5);
    const Vec3 v = glm::normalize(Vec3(0.3f, -0.2f, 0.9f));
    EXPECT_NEAR(glm::length(f.toWorld(f.toLocal(v)) - v), 0, 1e-5);
  }
}

TEST(Parallel, CoversRangeOnceAndRethrows) {
  setThreadCount(2);
  std::vector<std::atomic<int>> hits(1000);
  parallelFor(hits.size(), 7, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) hits[i]++;
  });
  for (auto& h : hits) EXPECT_EQ(h.load(), 1);
  EXPECT_THROW(parallelFor(100, 1, [](size_t b, size_t) {
                 if (b == 50) throw Error("boom");
               }),
               Error);
  setThreadCount(0);
}

// Loops shorter than a worker's wake-up: the caller takes every chunk and withdraws the job before
// the worker wakes, so a worker joins late or not at all; each index must still run once, and a
// worker waking late must not touch a loop that has returned (the sanitizer pass checks that).
TEST(Parallel, ShortLoopsCoverEveryIndexOnceWhateverJoins) {
  for (int threads : {2, 3}) {
    setThreadCount(threads);
    for (int loop = 0; loop < 3000; ++loop) {
      std::vector<int> hits(3, 0);
      parallelFor(hits.size(), 1, [&](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) hits[i]++;
      });
      ASSERT_EQ(hits, std::vector<int>(3, 1)) << threads << " threads, loop " << loop;
    }
  }
  setThreadCount(0);
}

// The chunks a body gets: [0, n) once, none longer than the chunk, the last two chunks' worth in
// quarters, and the same ranges at any thread count (bodies may batch their range, e.g. as ray
// packets, so images must not depend on which ranges the thread count made).
TEST(Parallel, ChunksCoverTheRangeOnceAndDoNotDependOnThreads) {
  for (size_t n : {1u, 7u, 100u, 1000u, 1025u, 4099u}) {
    for (size_t chunk : {1u, 3u, 64u, 256u}) {
      std::vector<std::pair<size_t, size_t>> first;
      for (int threads : {1, 2, 3}) {
        setThreadCount(threads);
        std::mutex m;
        std::vector<std::pair<size_t, size_t>> ranges;
        parallelFor(n, chunk, [&](size_t b, size_t e) {
          std::lock_guard<std::mutex> lock(m);
          ranges.emplace_back(b, e);
        });
        std::sort(ranges.begin(), ranges.end());
        size_t at = 0;
        for (const auto& r : ranges) {
          ASSERT_EQ(r.first, at) << "n " << n << " chunk " << chunk;
          ASSERT_GT(r.second, r.first);
          ASSERT_LE(r.second - r.first, chunk);
          at = r.second;
        }
        ASSERT_EQ(at, n);
        if (chunk >= 4 && n >= 2 * chunk)  // the last of the quarters of the last 2·chunk items
          EXPECT_EQ(ranges.back().second - ranges.back().first, (2 * chunk - 1) % (chunk / 4) + 1);
        if (threads == 1) first = ranges;
        EXPECT_EQ(ranges, first) << threads << " threads";
      }
    }
  }
  setThreadCount(0);
}

namespace {
// Burns `seconds` of the calling thread's CPU time.
void burnCpu(double seconds) {
  const double end = threadCpuSeconds() + seconds;
  volatile double x = 0;
  while (threadCpuSeconds() < end) x = x + 1.0;
}
}  // namespace

TEST(Parallel, PhaseCpuTellsSerialWorkFromLoopsAtOneThread) {
  setThreadCount(1);
  const PhaseCpuMeter meter;
  burnCpu(0.02);  // serial
  parallelFor(4, 1, [](size_t, size_t) {
    burnCpu(0.01);
    parallelFor(3, 1, [](size_t, size_t) {});  // nested: part of the outer loop, not a loop of its own
  });
  parallelFor(1, 1, [](size_t, size_t) { burnCpu(0.01); });  // one chunk: nothing to share, serial
  const PhaseCpu cpu = meter.elapsed();
  EXPECT_EQ(cpu.loops, 1u);
  EXPECT_GE(cpu.loopsS, 0.04);
  EXPECT_LT(cpu.loopsS, 0.06);
  EXPECT_DOUBLE_EQ(cpu.loopsSpanAt2S, cpu.loopsS / 2);  // 4 chunks: 2 on each of 2 threads
  const PhaseCpuMeter odd;
  parallelFor(3, 1, [](size_t, size_t) { burnCpu(0.01); });
  EXPECT_NEAR(odd.elapsed().loopsSpanAt2S, odd.elapsed().loopsS * 2 / 3, 1e-9);  // 3 chunks: 2 on one thread
  EXPECT_GE(cpu.serialS, 0.03);
  EXPECT_LT(cpu.serialS, cpu.loopsS);
  EXPECT_LT(cpu.otherThreadsS, 0.01);  // no other thread worked
  setThreadCount(0);
}

TEST(Parallel, SortEqualsStdSortForAnyThreadCount) {
  // Several runs and an odd last one, so the merge rounds pair uneven runs; duplicate keys with
  // unique second members, as the record candidates' (hash, index) pairs.
  const size_t n = 5 * kSortRun + 123;
  std::vector<std::pair<uint64_t, size_t>> base(n);
  Rng rng(11, 3);
  for (size_t i = 0; i < n; ++i) base[i] = {static_cast<uint64_t>(rng.nextFloat() * 1000.0f), i};
  std::vector<std::pair<uint64_t, size_t>> expected = base;
  std::sort(expected.begin(), expected.end());
  for (int threads : {1, 2, 3}) {
    setThreadCount(threads);
    std::vector<std::pair<uint64_t, size_t>> v = base;
    parallelSort(v);
    EXPECT_EQ(v, expected) << threads << " threads";
  }
  std::vector<int> small = {3, 1, 2};
  parallelSort(small);
  EXPECT_EQ(small, (std::vector<int>{1, 2, 3}));
  setThreadCount(0);
}

TEST(AtomicFile, WritesWholeFileOrNothing) {
  const std::string dir = ::testing::TempDir() + "/rc_atomic";
  mkdir(dir.c_str(), 0755);
  const std::string path = dir + "/out.json";
  writeFileAtomically(path, "{\"a\": 1}\n");
  std::ifstream f(path);
  std::string text((std::istreambuf_iterator<char>(f)), {});
  EXPECT_EQ(text, "{\"a\": 1}\n");
  EXPECT_THROW(writeFileAtomically("/nonexistent-dir/x.json", "x"), Error);
}

// floorToInt is static_cast<int>(std::floor(x)) (the per-sample code relies on the same results):
// integers, just below and above them, negatives, and the halves a box filter's pixel edges give.
TEST(Math, FloorToIntIsFloor) {
  for (float x : {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, -0.5f, 1e-7f, -1e-7f, 0.99999994f, -0.99999994f, 255.5f, -3.25f,
                  1048575.9f, -1048575.9f, 8388607.5f, -8388607.5f, 2.0e9f, -2.0e9f})
    EXPECT_EQ(floorToInt(x), static_cast<int>(std::floor(x))) << x;
  Rng rng(3);
  for (int i = 0; i < 100000; ++i) {
    const float x = (rng.nextFloat() - 0.5f) * 4096.0f;
    ASSERT_EQ(floorToInt(x), static_cast<int>(std::floor(x))) << x;
  }
}
