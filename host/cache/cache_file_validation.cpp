#include "cache/cache_file_validation.h"

#include <cmath>
#include <set>

#include "cache/radius_floor.h"
#include "core/error.h"

namespace rc {

namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string where(const std::string& path, size_t cache, size_t record) {
  return path + ": cache file has, in cache " + std::to_string(cache) + " record " + std::to_string(record) + ", ";
}

void checkKey(const CacheKey& k, const std::string& path, size_t cache) {
  const std::string at = path + ": cache file has, in cache " + std::to_string(cache) + ", ";
  if (k.level < 0 || k.level >= kMaxCacheLevel)
    throw Error(at + "level " + std::to_string(k.level) + " outside [0, " + std::to_string(kMaxCacheLevel - 1) + "]");
  if (k.depth < 0 || k.depth > kMaxCacheKeyDepth)
    throw Error(at + "depth " + std::to_string(k.depth) + " outside [0, " + std::to_string(kMaxCacheKeyDepth) + "]");
  if (k.order < 1 || k.order > kMaxCacheOrder)
    throw Error(at + "SH order " + std::to_string(k.order) + " outside [1, " + std::to_string(kMaxCacheOrder) + "]");
}

void checkRecord(const RecordInfo& r, const std::string& path, size_t cache, size_t record) {
  const Vec3 axes[3] = {r.frame.t, r.frame.b, r.frame.n};
  for (const Vec3& v : axes)
    if (!finite(v)) throw Error(where(path, cache, record) + "a non-finite frame");
  if (!finite(r.p)) throw Error(where(path, cache, record) + "a non-finite position");
  if (std::fabs(r.p.x) > kMaxRecordCoordinate || std::fabs(r.p.y) > kMaxRecordCoordinate ||
      std::fabs(r.p.z) > kMaxRecordCoordinate)
    throw Error(where(path, cache, record) + "a position beyond ±1e18");
  for (int i = 0; i < 3; ++i) {
    if (!(std::fabs(glm::length(axes[i]) - 1.0f) <= 1e-3f)) throw Error(where(path, cache, record) + "a frame axis that is not unit");
    if (!(std::fabs(glm::dot(axes[i], axes[(i + 1) % 3])) <= 1e-3f))
      throw Error(where(path, cache, record) + "frame axes that are not perpendicular");
  }
  if (!std::isfinite(r.R) || !std::isfinite(r.a)) throw Error(where(path, cache, record) + "a non-finite radius or a");
  if (!(r.R > 0.0f) || !(r.a > 0.0f)) throw Error(where(path, cache, record) + "radius or a ≤ 0");
  if (r.a < kMinRecordA || r.a > kMaxRecordA) throw Error(where(path, cache, record) + "a outside [1e-6, 1e16]");
  const float reach = r.a * r.R;
  if (!(reach <= kMaxRecordCoordinate)) throw Error(where(path, cache, record) + "an influence radius a·R beyond 1e18");
  if (reach < minimumReach(r.p, 0.0f))
    throw Error(where(path, cache, record) + "an influence radius a·R below float resolution at its position");
}

void checkCoefficients(const std::vector<float>& v, const char* name, const std::string& path, size_t cache) {
  for (size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]) || std::fabs(v[i]) > kMaxCoefficient)
      throw Error(path + ": cache file has, in cache " + std::to_string(cache) + ", a non-finite or huge " + name +
                  " coefficient (value " + std::to_string(i) + ")");
}

}  // namespace

void validateCacheEntries(const std::vector<CacheFileEntry>& entries, const std::string& path) {
  std::set<CacheKey> seen;
  for (size_t c = 0; c < entries.size(); ++c) {
    const CacheFileEntry& e = entries[c];
    checkKey(e.key, path, c);
    if (!seen.insert(e.key).second)
      throw Error(path + ": cache file has cache (level " + std::to_string(e.key.level) + ", depth " +
                  std::to_string(e.key.depth) + ", order " + std::to_string(e.key.order) + ") twice");
    for (size_t r = 0; r < e.infos.size(); ++r) checkRecord(e.infos[r], path, c, r);
    checkCoefficients(e.lambda, "radiance", path, c);
    checkCoefficients(e.gradT, "gradient", path, c);
    checkCoefficients(e.gradB, "gradient", path, c);
  }
}

}  // namespace rc
