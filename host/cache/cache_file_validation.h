#pragma once
// Range checks of a loaded cache file's contents. The checksum only proves the bytes are the
// ones written; a crafted (or buggy) writer can checksum anything. Every field is held to what
// the renderer itself can produce before a record reaches a cache:
//   key      level in [0, kMaxCacheLevel), depth in [0, kMaxCacheKeyDepth], order in [1, 16]
//            (the kernels' range), each (level, depth, order) once
//   record   position finite with |p| ≤ kMaxRecordCoordinate (squared distances stay finite),
//            frame orthonormal (t, b, n unit and perpendicular within 1e-3),
//            a in [kMinRecordA, kMaxRecordA], R > 0, influence a·R finite, at least the
//            float-resolution floor at p (radius_floor.h) and at most kMaxRecordCoordinate
//   Λ, ∇Λ    finite, |x| ≤ kMaxCoefficient (weighted sums of a few hundred stay finite in float)
#include <string>
#include <vector>

#include "cache/cache_file.h"

namespace rc {

constexpr int kMaxCacheLevel = 8;          // cache_depth ≤ 8
constexpr int kMaxCacheKeyDepth = 1000;    // the engine's hard path-depth limit
constexpr int kMaxCacheOrder = 16;
constexpr float kMaxRecordCoordinate = 1e18f;
constexpr float kMinRecordA = 1e-6f;       // a ≥ 1e-3 times min_a_scale ≥ 1e-3
constexpr float kMaxRecordA = 1e16f;       // a ≤ 10 times secondary_a_scale^level ≤ 100^7
constexpr float kMaxCoefficient = 1e30f;

// Throws rc::Error("<path>: cache file has ...") naming the cache, record and field.
void validateCacheEntries(const std::vector<CacheFileEntry>& entries, const std::string& path);

}  // namespace rc
