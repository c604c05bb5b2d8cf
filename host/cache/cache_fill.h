#pragma once
// Phase 2 of an rcache render (docs/ARCHITECTURE.md §Pipeline): fills the level-0 caches over the
// image before the final pass, in coarse-to-fine pixel grids (strides 16, 8, 4, 2, 1; Křivánek's
// implementation fills in the same spirit: big records land first, later passes fill the gaps).
// Skipped when a cache file was loaded.
#include <cstddef>
#include <string>

#include "cache/rcache_run.h"
#include "core/phase_cpu.h"

namespace rc {

struct FillReport {
  std::string passesJson = "[]";  // per pass: stride, points looked up, records created, time
  size_t edgePixels = 0;          // pixels whose quadrants the last pass looked up
  bool interrupted = false;
  double seconds = 0.0;
  PhaseCpu cpu;
};

FillReport fillCache(const RcacheRun& run);

}  // namespace rc
