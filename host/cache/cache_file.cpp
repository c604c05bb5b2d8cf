#include "cache/cache_file.h"

#include <cmath>
#include <cstring>

#include "bsdf/rough_textures.h"
#include "brdf/table_cache.h"
#include "cache/cache_file_validation.h"
#include "cache/world_frame.h"
#include "core/atomic_file.h"
#include "core/binary_writer.h"
#include "core/error.h"
#include "core/regular_file.h"

namespace rc {

namespace {

constexpr char kMagic[8] = {'R', 'C', 'C', 'A', 'C', 'H', 'E', '1'};

struct Reader {
  const std::string& data;
  const std::string& path;
  size_t pos = 0;
  template <typename T>
  T get() {
    T v;
    need(sizeof(T));
    std::memcpy(&v, data.data() + pos, sizeof(T));
    pos += sizeof(T);
    return v;
  }
  void floats(std::vector<float>& v, size_t n) {
    need(n * sizeof(float));
    v.resize(n);
    if (n == 0) return;  // memcpy into an empty vector's null data() is undefined (found by fuzzing)
    std::memcpy(v.data(), data.data() + pos, n * sizeof(float));
    pos += n * sizeof(float);
  }
  void need(size_t n) const {
    if (n > data.size() || pos + n > data.size()) throw Error(path + ": cache file is truncated");
  }
  size_t left() const { return data.size() - pos; }
};

void hashFloats(uint64_t& h, const float* v, size_t n) { h = fnv1a64(v, n * sizeof(float), h); }

}  // namespace

uint64_t cacheSceneHash(const Scene& scene, int maxDepth, bool tlMode) {
  uint64_t h = fnv1a64("rcache-scene", 12);
  for (const Mesh& m : scene.meshes) {
    hashFloats(h, &m.positions[0].x, 3 * m.positions.size());
    if (!m.normals.empty()) hashFloats(h, &m.normals[0].x, 3 * m.normals.size());
    if (!m.triangles.empty()) h = fnv1a64(m.triangles.data(), m.triangles.size() * sizeof(m.triangles[0]), h);
    const int ids[2] = {m.bsdf, m.emitter};
    h = fnv1a64(ids, sizeof(ids), h);
  }
  for (const Sphere& s : scene.spheres) {
    const float v[4] = {s.center.x, s.center.y, s.center.z, s.radius};
    hashFloats(h, v, 4);
    const int ids[3] = {s.bsdf, s.emitter, s.flipNormals ? 1 : 0};
    h = fnv1a64(ids, sizeof(ids), h);
  }
  for (const Cylinder& c : scene.cylinders) {
    hashFloats(h, &c.toWorld[0][0], 16);
    const int ids[2] = {c.bsdf, c.flipNormals ? 1 : 0};
    h = fnv1a64(ids, sizeof(ids), h);
  }
  for (const Curve& c : scene.curves) {
    hashFloats(h, &c.points[0].x, 4 * c.points.size());
    h = fnv1a64(c.segments.data(), c.segments.size() * sizeof(c.segments[0]), h);
    const int ids[2] = {c.bsdf, static_cast<int>(c.basis)};
    h = fnv1a64(ids, sizeof(ids), h);
  }
  for (const SdfGrid& g : scene.sdfGrids) {
    h = fnv1a64(g.res, sizeof(g.res), h);
    hashFloats(h, g.values->data(), g.values->size());
    hashFloats(h, &g.toWorld[0][0], 16);
    const int ids[2] = {g.bsdf, g.smoothNormals ? 1 : 0};
    h = fnv1a64(ids, sizeof(ids), h);
  }
  for (const auto& b : scene.bsdfs) {
    const std::string key = b->parameterKey();
    h = fnv1a64(key.data(), key.size(), h);
  }
  for (const Emitter& e : scene.emitters) {
    const int type = static_cast<int>(e.type);
    h = fnv1a64(&type, sizeof(type), h);
    const float v[13] = {e.radiance.r, e.radiance.g, e.radiance.b, e.intensity.r, e.intensity.g, e.intensity.b,
                         e.irradiance.r, e.irradiance.g, e.irradiance.b, e.position.x, e.position.y, e.position.z,
                         e.scale};
    hashFloats(h, v, 13);
    hashFloats(h, &e.direction.x, 3);
    hashFloats(h, &e.toWorld[0][0], 16);
    if (e.type == EmitterType::Spot) {
      const float spot[2] = {e.spotCutoffRad, e.spotBeamRad};
      hashFloats(h, spot, 2);
    }
    if (e.type == EmitterType::Projector) {
      const float projector[2] = {e.projectorCot, e.projectorAspect};
      hashFloats(h, projector, 2);
    }
    if (e.projection) {
      const std::string key = textureFingerprint(*e.projection);
      h = fnv1a64(key.data(), key.size(), h);
    }
    // The envmap by its pixels, not its path: an edited image must not reuse a stale cache, and
    // the same scene run from another directory must still find its cache.
    const int size[2] = {e.envWidth, e.envHeight};
    h = fnv1a64(size, sizeof(size), h);
    if (!e.envPixels.empty()) hashFloats(h, &e.envPixels[0].x, 3 * e.envPixels.size());
  }
  const int extra[2] = {maxDepth, tlMode ? 1 : 0};
  return fnv1a64(extra, sizeof(extra), h);
}

void saveCacheFile(const std::string& path, uint64_t sceneHash, const std::vector<CacheFileEntry>& entries) {
  std::string s;
  s.append(kMagic, 8);
  put(s, kCacheFileVersion);
  put(s, sceneHash);
  put(s, static_cast<uint32_t>(entries.size()));
  for (const CacheFileEntry& e : entries) {
    put(s, static_cast<int32_t>(e.key.level));
    put(s, static_cast<int32_t>(e.key.depth));
    put(s, static_cast<int32_t>(e.key.order));
    put(s, static_cast<uint32_t>(e.infos.size()));
    for (const RecordInfo& r : e.infos) {
      const float v[14] = {r.p.x, r.p.y, r.p.z, r.frame.t.x, r.frame.t.y, r.frame.t.z, r.frame.b.x,
                           r.frame.b.y, r.frame.b.z, r.frame.n.x, r.frame.n.y, r.frame.n.z, r.R, r.a};
      s.append(reinterpret_cast<const char*>(v), sizeof(v));
    }
    putFloats(s, e.lambda);
    putFloats(s, e.gradT);
    putFloats(s, e.gradB);
  }
  put(s, fnv1a64(s.data(), s.size()));
  writeFileAtomically(path, s);
}

std::vector<CacheFileEntry> loadCacheFile(const std::string& path, uint64_t expectedSceneHash) {
  return loadCacheFile(path, &expectedSceneHash, nullptr);
}

std::vector<CacheFileEntry> loadCacheFile(const std::string& path, const uint64_t* expectedSceneHash,
                                          uint64_t* sceneHash) {
  const std::string data = readRegularFile(path, "cache file");
  if (data.size() < 8 + 4 + 8 + 4 + 8 || std::memcmp(data.data(), kMagic, 8) != 0)
    throw Error(path + ": not an rcache cache file (bad magic)");
  uint64_t stored;
  std::memcpy(&stored, data.data() + data.size() - 8, 8);
  if (fnv1a64(data.data(), data.size() - 8) != stored) throw Error(path + ": cache file is corrupt (checksum mismatch)");
  Reader r{data, path, 8};
  const uint32_t version = r.get<uint32_t>();
  if (version != kCacheFileVersion)
    throw Error(path + ": cache file version " + std::to_string(version) + ", this build reads version " +
                std::to_string(kCacheFileVersion));
  const uint64_t fileSceneHash = r.get<uint64_t>();
  if (sceneHash) *sceneHash = fileSceneHash;
  if (expectedSceneHash && fileSceneHash != *expectedSceneHash)
    throw Error(path + ": cache file was made for another scene (geometry, materials, lights or max_depth differ)");
  const uint32_t count = r.get<uint32_t>();
  // Counts are checked against the bytes left before anything is allocated: a damaged (or
  // hostile) count must give a message, not a multi-gigabyte allocation.
  constexpr size_t kCacheHeaderBytes = 16, kRecordInfoBytes = 14 * sizeof(float);
  if (count > r.left() / kCacheHeaderBytes) throw Error(path + ": cache file is truncated (cache count " + std::to_string(count) + ")");
  std::vector<CacheFileEntry> entries(count);
  for (CacheFileEntry& e : entries) {
    e.key.level = r.get<int32_t>();
    e.key.depth = r.get<int32_t>();
    e.key.order = r.get<int32_t>();
    if (e.key.order < 1 || e.key.order > 20 || e.key.level < 0) throw Error(path + ": cache file has an invalid cache header");
    const uint32_t n = r.get<uint32_t>();
    const size_t perRecord = kRecordInfoBytes + 3 * 3 * sizeof(float) * static_cast<size_t>(e.key.order) * e.key.order;
    if (n > r.left() / perRecord) throw Error(path + ": cache file is truncated (record count " + std::to_string(n) + ")");
    e.infos.resize(n);
    for (RecordInfo& info : e.infos) {
      float v[14];
      for (float& x : v) x = r.get<float>();
      info.p = Vec3(v[0], v[1], v[2]);
      info.frame = Frame(Vec3(v[3], v[4], v[5]), Vec3(v[6], v[7], v[8]), Vec3(v[9], v[10], v[11]));
      info.R = v[12];
      info.a = v[13];
    }
    const size_t k = static_cast<size_t>(n) * 3 * e.key.order * e.key.order;
    r.floats(e.lambda, k);
    r.floats(e.gradT, k);
    r.floats(e.gradB, k);
  }
  if (r.pos + 8 != data.size()) throw Error(path + ": cache file has trailing bytes");
  validateCacheEntries(entries, path);
  return entries;
}

size_t loadCachesInto(CacheEngine& engine, const std::string& path, uint64_t sceneHash, bool worldFrame,
                      ShBackend& backend) {
  size_t loaded = 0;
  for (CacheFileEntry& e : loadCacheFile(path, sceneHash)) {
    RadianceCache& cache = engine.cacheFor(e.key);
    WorldCopies world;
    if (worldFrame && !e.infos.empty()) world = rotateToWorld(backend, e.key.order, e.infos, e.lambda, e.gradT, e.gradB);
    loaded += e.infos.size();
    cache.insert(e.infos, e.lambda, e.gradT, e.gradB, world.lambda, world.gradT, world.gradB, false);
  }
  return loaded;
}

void saveCaches(CacheEngine& engine, const std::string& path, uint64_t sceneHash) {
  std::vector<CacheFileEntry> entries;
  for (auto& [key, cache] : engine.caches()) {
    CacheFileEntry e;
    e.key = key;
    cache->snapshot(e.infos, e.lambda, e.gradT, e.gradB);
    entries.push_back(std::move(e));
  }
  saveCacheFile(path, sceneHash, entries);
}

}  // namespace rc
