#pragma once
// Finer records for closer cameras (walk-throughs, caches loaded from other views; issue 20).
// A record's radius is clamped to [r_min, r_max] pixel footprints at its distance from the camera
// of the view that made it (cache_engine.cpp clampRecord); the clamped radius is then a property
// of the record, in world units, so every view interpolates it the same way. Both clamps are
// view-dependent: a camera that comes closer has smaller pixel footprints at the record and would
// have made the record smaller. Before its fill, a view that loaded records skips those whose
// influence radius a_i·R_i exceeds kCoarseRecordTolerance × its own r_max bound there: lookups
// pass over them, the fill finds those points uncovered and adds records at this view's radii,
// and the skipped records stay in the cache (and its file) for the farther views they serve.
// The tolerance is hysteresis: a record is replaced once the camera has come about twice as
// close as its maker was (the fill's coarse-to-fine grids halve their stride for the same
// reason), not on every frame of a dolly; a static camera skips nothing (its own records meet
// its bound), so reuse across frames costs nothing where the view does not change.
// Not detected: a record held up by the r_min floor (corners) whose maker was farther away —
// the record does not store the footprint it was floored to, so it is replaced only when it
// also exceeds the r_max test (a camera kCoarseRecordTolerance·r_max/r_min ≈ 13× closer).
#include <cstddef>

#include "cache/cache_engine.h"

namespace rc {

constexpr float kCoarseRecordTolerance = 2.0f;

// Marks the engine's loaded records that are too coarse for its camera as skipped (see above);
// returns how many.
size_t skipCoarseRecords(CacheEngine& engine, const RcacheParams& params);

}  // namespace rc
