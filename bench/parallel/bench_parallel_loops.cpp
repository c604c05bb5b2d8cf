// What one parallel loop costs beyond its work: waking the pool's workers and waiting for its last
// chunk. Times `loops` parallelFor calls of `chunks` chunks, each a fixed amount of arithmetic, at
// 1 thread and at `threads`, interleaved `reps` times (minimum of each), with `gap` steps of the
// same arithmetic on the calling thread alone between loops (the serial code between a render's
// loops, during which the workers wait); prints µs per loop and the overhead over a perfect split
// (the 1-thread time / threads, plus the gap). bench/RESULTS.md, tenth and twelfth sessions.
// Usage: rcache-bench-parallel-loops [threads=2] [loops=2000] [chunks=8] [work-per-chunk=20000] [reps=5] [gap=0]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "core/parallel.h"

namespace {

volatile float gSink = 0.0f;

void work(int steps) {
  float x = 1.0f;
  for (int i = 0; i < steps; ++i) x = x * 0.999999f + 1e-7f;
  gSink = gSink + x;
}

double secondsFor(int threads, int loops, int chunks, int steps, int gap) {
  rc::setThreadCount(threads);
  const auto t0 = std::chrono::steady_clock::now();
  for (int l = 0; l < loops; ++l) {
    rc::parallelFor(static_cast<size_t>(chunks), 1, [&](size_t b, size_t e) {
      for (size_t c = b; c < e; ++c) work(steps);
    });
    if (gap > 0) work(gap);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  auto arg = [&](int i, int fallback) { return argc > i ? std::atoi(argv[i]) : fallback; };
  const int threads = arg(1, 2), loops = arg(2, 2000), chunks = arg(3, 8), steps = arg(4, 20000), reps = arg(5, 5), gap = arg(6, 0);
  double one = 1e30, many = 1e30;
  for (int r = 0; r < reps; ++r) {
    one = std::min(one, secondsFor(1, loops, chunks, steps, gap));
    many = std::min(many, secondsFor(threads, loops, chunks, steps, gap));
  }
  const double usOne = 1e6 * one / loops, usMany = 1e6 * many / loops;
  // The gap's share of the 1-thread time, which no thread count divides.
  const double usGap = gap > 0 ? usOne * double(gap) / (double(gap) + double(chunks) * steps) : 0.0;
  std::printf("%d loops of %d chunks, gap %d: 1 thread %.1f us/loop, %d threads %.1f us/loop, speed-up %.2fx, "
              "overhead over a perfect split %.1f us/loop\n",
              loops, chunks, gap, usOne, threads, usMany, one / many, usMany - usGap - (usOne - usGap) / threads);
  return 0;
}
