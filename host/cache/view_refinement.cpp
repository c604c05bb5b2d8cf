#include "cache/view_refinement.h"

#include <vector>

namespace rc {

size_t skipCoarseRecords(CacheEngine& engine, const RcacheParams& params) {
  size_t skipped = 0;
  for (auto& [key, cache] : engine.caches()) {
    // r_max scales like a at the coarser secondary caches, as in clampRecord.
    const float levelScale = engine.aForLevel(key.level) / params.a;
    std::vector<uint8_t> mask(cache->size(), 0);
    for (size_t i = 0; i < mask.size(); ++i) {
      const RecordInfo r = cache->info(static_cast<uint32_t>(i));
      const float bound = params.rMaxPx * levelScale * engine.footprint(r.p, key.level);
      if (r.a * r.R > kCoarseRecordTolerance * bound) mask[i] = 1, ++skipped;
    }
    cache->setSkipped(std::move(mask));
  }
  return skipped;
}

}  // namespace rc
