#pragma once
// Minimal parallel-for over an index range with dynamic chunking. Results must not depend on
// which thread runs which chunk: callers seed RNGs by index, never by thread.
#include <cstddef>
#include <cstdint>
#include <functional>

namespace rc {

// Number of threads used by parallelFor; 0 = all hardware threads. Set once from the CLI (-t).
void setThreadCount(int threads);
int threadCount();

// Calls body(begin, end) for chunks of [0, n) of at most `chunk` items (the last two chunks' worth
// in quarters, so threads finish together; the same chunks at any thread count); blocks until done. Exceptions are rethrown on the
// calling thread (the first one wins).
void parallelFor(size_t n, size_t chunk, const std::function<void(size_t, size_t)>& body);

// The calling thread's own CPU time inside the parallel loops it started (the outermost ones of more
// than one chunk, at any thread count: at -t 1 they are the work that more threads would share), and
// how many it started. spanAt2S: what those loops would take on 2 threads if each chunk cost its
// loop's mean — ceil(chunks / 2) chunks on the busier thread — so a loop of few chunks shows the
// imbalance that its last chunk costs. Read by core/phase_cpu.h.
struct LoopAccount {
  double cpuS = 0.0, spanAt2S = 0.0;
  uint64_t loops = 0;
};
LoopAccount loopAccountOfThisThread();

}  // namespace rc
