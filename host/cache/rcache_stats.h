#pragma once
// Phase 6 of an rcache render (docs/ARCHITECTURE.md §Pipeline): the statistics block (--stats
// JSON, printed after the render) from what the phases report.
#include <string>

#include "cache/cache_fill.h"
#include "cache/final_pass.h"
#include "cache/rcache_run.h"

namespace rc {

// What the final passes did, summed over the passes of a render.
struct FinalPassTotals {
  uint64_t cameraRays = 0, nanSamples = 0, directLightOnly = 0, lobeSplitSamples = 0, samples = 0, pixelsAboveSpp = 0;
  int bandsReshaded = 0, maxPixelSamples = 0;
  PhaseCpu cpu;
  void add(const FinalPass& pass, const AdaptivePixels& adaptive);
};

struct RcacheReport {
  double totalS = 0, tablesS = 0, finalS = 0;
  const FillReport& fill;
  const FinalPassTotals& passes;
  size_t recordsLoaded = 0;
  bool interrupted = false;
};

void reportRcacheStats(const RcacheRun& run, const RcacheReport& report, RenderStats& stats);

}  // namespace rc
