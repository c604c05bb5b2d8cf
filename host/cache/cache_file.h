#pragma once
// The view-independent cache file (--cache-save / --cache-load): every record of every cache
// (position, frame, R_i, a_i, Λ and gradients in the record's own frame). Layout, host byte order:
//   "RCCACHE1" | u32 version | u64 scene hash | u32 cache count |
//   per cache: i32 level, depth, order | u32 records | per record 14 floats (p, t, b, n, R, a) |
//              floats Λ[records][3][n²], ∂Λ/∂t, ∂Λ/∂b |
//   u64 FNV-1a of every preceding byte.
// Written to a temporary sibling and renamed (a reader sees a whole file or none). Loading checks
// magic, version, scene hash (geometry, materials, emitters, max_depth, record mode: whatever
// changes what a record holds — not the camera; meshes and images by their contents, never by
// their paths) and the checksum, and names what is wrong.
#include <cstdint>
#include <string>
#include <vector>

#include "cache/cache_engine.h"
#include "cache/radiance_cache.h"
#include "scene/scene.h"

namespace rc {

class ShBackend;

constexpr uint32_t kCacheFileVersion = 1;

struct CacheFileEntry {
  CacheKey key;
  std::vector<RecordInfo> infos;
  std::vector<float> lambda, gradT, gradB;  // record frame, [records][3][n²]
};

uint64_t cacheSceneHash(const Scene& scene, int maxDepth, bool tlMode);
void saveCacheFile(const std::string& path, uint64_t sceneHash, const std::vector<CacheFileEntry>& entries);
// Throws rc::Error("<path>: ...") on any problem.
std::vector<CacheFileEntry> loadCacheFile(const std::string& path, uint64_t expectedSceneHash);
// The same without a scene (rcache cache merge): any scene hash is accepted (null expected) and
// returned in *sceneHash.
std::vector<CacheFileEntry> loadCacheFile(const std::string& path, const uint64_t* expectedSceneHash,
                                          uint64_t* sceneHash);

// Phase 1b of an rcache render (--cache-load): inserts every record of the file into the engine's
// caches as it is (the file holds final, already clamped radii), with world-frame copies when
// `worldFrame`. Returns the number of records loaded.
size_t loadCachesInto(CacheEngine& engine, const std::string& path, uint64_t sceneHash, bool worldFrame,
                      ShBackend& backend);
// Phase 5 (--cache-save): writes every record of the engine's caches.
void saveCaches(CacheEngine& engine, const std::string& path, uint64_t sceneHash);

}  // namespace rc
