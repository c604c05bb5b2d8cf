#pragma once
// Phase 6 of an rcache render (docs/ARCHITECTURE.md §Pipeline): the statistics block (--stats
// JSON, printed after the render) from what the phases report.
#include <string>

#include "cache/cache_fill.h"
#include "cache/final_pass.h"
#include "cache/rcache_run.h"

namespace rc {

struct RcacheReport {
  double totalS = 0, tablesS = 0, finalS = 0;
  const FillReport& fill;
  const FinalPass& pass;
  const AdaptivePixels& adaptive;
  size_t recordsLoaded = 0;
  bool interrupted = false;
};

void reportRcacheStats(const RcacheRun& run, const RcacheReport& report, RenderStats& stats);

}  // namespace rc
