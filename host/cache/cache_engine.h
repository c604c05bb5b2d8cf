#pragma once
// The radiance-caching engine (ARCHITECTURE.md §Pipeline): GetOutRadiance of the course notes, batched.
//   radianceOut(points)  = direct light (render/direct_light.h, the path tracer's estimator) +
//                          indirect(points)                       [emission of the points excluded]
//   indirect(points)     = cached materials: ensure the cache covers the points (new records are
//                          sampled and projected in batches), interpolate Λ (gradients, rotation),
//                          dot with the BRDF×cos table;
//                          importance-sampled materials (delta, too sharp) and levels past
//                          cache_depth: BSDF sampling, recursing into radianceOut at the next hit.
// A record at a point of depth d stores the radiance arriving from its hemisphere's hits
// without their own emission (that light is direct light, computed exactly), i.e. the
// radianceOut of depth d+1 points, so the sum equals the path tracer's estimate of the same
// integral (same max_depth).
// Environment light (cache/light_split.h): a record ray that escapes carries the cached
// part of the environment, so points whose indirect light comes from records take their direct
// light from directLightContext() — the scene's lights with only the environment's residual.
// Caches are keyed by (level, order) — and by depth when max_depth is finite, because then
// records at different depths hold different integrals. Level 0 caches use a; level l uses
// a·secondary_a_scale^l and secondary_rays.
// All control flow is serial; per-item work runs under parallelFor with per-item RNG streams, so
// images depend only on the seed.
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

#include "brdf/material_plan.h"
#include "cache/cache_params.h"
#include "cache/light_split.h"
#include "cache/radiance_cache.h"
#include "cache/shade_point.h"
#include "render/camera.h"
#include "render/integrator.h"

namespace rc {

struct CacheKey {
  int level = 0, depth = 0, order = 0;
  bool operator<(const CacheKey& o) const {
    return std::tie(level, depth, order) < std::tie(o.level, o.depth, o.order);
  }
};

struct EngineStats {
  std::atomic<uint64_t> recordRays{0}, pathRays{0}, lookups{0}, contributions{0}, droppedSamples{0};
  std::atomic<uint64_t> recordFrameLookups{0};  // lookups interpolated in record frames (no full rotation)
  std::atomic<uint64_t> relaxedLookups{0};      // final-pass points covered only at the relaxed radius
  std::atomic<uint64_t> lambertianLookups{0};   // shaded by the Lambertian fast path (no kernels)
  std::atomic<uint64_t> adaptiveShrinks{0}, uncoveredRounds{0};
  double sampling_s = 0, projection_s = 0, interpolation_s = 0, dot_s = 0, adaptive_s = 0;
};

// Per-point extras for AOVs (primary points only).
struct LookupAov {
  int contributors = 0;
  float meanA = 0, meanRadiusPx = 0;
};

class ShBackend;  // cl/sh_backend.h: the records' batched SH math

class CacheEngine {
 public:
  CacheEngine(const RenderContext& ctx, ShBackend& backend, const RcacheParams& params, const BrdfTableSet& tables,
              const CameraModel& camera, int maxDepth, int rrDepth, Vec3 sceneLo, Vec3 sceneHi);

  // L_o(p, ω_o) without p's own emission. out.size() == points.size().
  void radianceOut(PointView points, std::vector<Color>& out, float relaxedScale = 1.0f);
  // Indirect part only; `aov` (optional, same size) receives lookup details.
  // relaxedScale > 1 (the final pass): a point no record covers at a_i may use the records that
  // cover it at relaxedScale·a_i before a new record is made for it.
  // withCoat = false leaves out the coat of lobe-split points (the caller adds coatIndirect).
  void indirect(PointView points, std::vector<Color>& out, std::vector<LookupAov>* aov = nullptr,
                float relaxedScale = 1.0f, bool withCoat = true);
  // The coat's indirect light of lobe-split points (technique LobeSplit): one coat BSDF sample,
  // the path continued at its hit (also the coat's MIS BSDF sample for lobeSplitDirect).
  void coatIndirect(PointView points, std::vector<Color>& out, float relaxedScale = 1.0f);
  // Direct light of a lobe-split point: the base by light sampling alone over
  // directLightContext(sp) (its cached share of the environment comes with the records), the coat
  // by lightStrategyMis over the scene's lights. Consumes 3·lightSamples + 3 numbers.
  Color lobeSplitDirect(const ShadePoint& sp, Rng& rng, int lightSamples) const;
  // Fill pass at level 0: make the caches cover `points`; with adaptive caching, `baseLum`
  // (luminance of the points' direct light + emission) scales the Weber threshold.
  void fill(const std::vector<ShadePoint>& points, const std::vector<float>& baseLum, bool adaptive);

  // makeShadePoint with the BSDF's two-sidedness looked up once per material.
  ShadePoint shadePointOf(const Hit& hit, const Vec3& dir, int depth, int level, uint64_t seed) const {
    const bool known = hit.valid() && hit.bsdf >= 0;
    const bool two = known && twoSided_[static_cast<size_t>(hit.bsdf)];
    return makeShadePoint(hit, dir, depth, level, seed, two, known ? ctx_.scene.bsdfs[static_cast<size_t>(hit.bsdf)].get() : nullptr);
  }
  // Technique of a point: its material's (irradiance/radiance cache, importance sampling, lobe
  // split), None for points without indirect light, and importance sampling for cached materials
  // past cache_depth and for lobe-split materials below the camera's hits (level > 0: the whole
  // BSDF is sampled there, as in the path tracer; records average that noise).
  Technique technique(const ShadePoint& sp) const;
  // false: lobe-split materials are importance-sampled whole (the cost pilot's choice).
  void setLobeSplit(bool on) { lobeSplitOn_ = on; }
  // Whether indirect() continues a path from sp by BSDF sampling (importance sampling within the
  // depth limits). Such a point takes only the light half of its direct light (lightStrategyMis): the
  // continuation ray is also its MIS BSDF sample and adds the emitter it hits, as in the path
  // tracer, so one ray serves both.
  bool continuesPath(const ShadePoint& sp) const;
  // Whether indirect() gives sp any indirect light at all (max_depth and the hard depth limit).
  bool hasIndirect(const ShadePoint& sp) const;
  CacheKey keyFor(const ShadePoint& sp) const;
  // The lights sp's direct light samples: the residual ones where its indirect light comes from
  // records that carry the cached environment, else the scene's.
  const RenderContext& directLightContext(const ShadePoint& sp) const;
  const LightSplit& lightSplit() const;
  int maxDepth() const { return maxDepth_; }

  std::map<CacheKey, std::unique_ptr<RadianceCache>>& caches() { return caches_; }
  RadianceCache& cacheFor(const CacheKey& key);
  EngineStats& stats() { return stats_; }
  const EngineStats& stats() const { return stats_; }
  // Pixels whose primary hit created a record (AOV "records").
  std::vector<int> recordPixels() const { return recordPixels_; }
  // World size of the pixel that bounds a record's reach at p: primary records (level 0) follow
  // the film's pixels; deeper records, whose points lie anywhere in the scene and are seen only
  // through other records, follow the square film of equal pixel count (camera.h), so thin films
  // do not multiply them.
  float footprint(const Vec3& p, int level) const;
  float aForLevel(int level) const;

 private:
  const RenderContext& ctx_;
  ShBackend& backend_;
  RcacheParams params_;
  const BrdfTableSet& tables_;
  const CameraModel& camera_;
  int maxDepth_, rrDepth_;
  Vec3 lo_, hi_;
  std::vector<Technique> planTech_;  // per bsdf: a cached technique with a table, else sampling
  std::vector<int> planOrder_;  // per bsdf: record order
  bool lobeSplitOn_ = true;     // setLobeSplit
  std::vector<bool> twoSided_;
  std::map<CacheKey, std::unique_ptr<RadianceCache>> caches_;
  bool splitEnvironment_ = false, splitArea_ = false;  // what the light split is to take into records
  mutable std::once_flag splitBuilt_;
  mutable std::unique_ptr<LightSplit> envSplit_;  // lightSplit(), built on first use
  mutable std::unique_ptr<RenderContext> residualCtx_;  // ctx_ with envSplit_'s residual lights
  EngineStats stats_;
  std::vector<int> recordPixels_;
  uint64_t recordCounter_ = 0;

  void ensureCoverage(const CacheKey& key, PointView pts, std::vector<Lookup>& lookups,
                      const std::vector<float>* baseLum, bool adaptive, float relaxedScale = 1.0f);
  // The steps of ensureCoverage: look up points `todo`; which points to look up again after
  // insertions shrank records; which uncovered points become the next batch's candidates.
  void lookUp(RadianceCache& cache, PointView pts, const std::vector<size_t>& todo,
              std::vector<Lookup>& lookups, float relaxedScale);
  std::vector<size_t> pointsToRecheck(const std::vector<Lookup>& lookups, std::vector<uint32_t>& shrunk,
                                      float relaxedScale);
  std::vector<ShadePoint> recordCandidates(PointView pts, const std::vector<size_t>& uncovered,
                                           float sepPx) const;
  // Returns the ids of older records whose radius the new ones' neighbour clamping lowered.
  std::vector<uint32_t> buildRecords(const CacheKey& key, const std::vector<ShadePoint>& cands);
  // The steps of buildRecords: the projection batch of the candidates (stratified ray pattern,
  // per-record azimuth), their rays traced and shaded into it, one record's radius clamped.
  ProjectBatch recordBatch(const CacheKey& key, const std::vector<ShadePoint>& cands);
  void traceRecordRays(const std::vector<ShadePoint>& cands, ProjectBatch& rayBatch, ParallelArray<Hit>& hits);
  // R_i from the harmonic mean distance of its S ray hits, bounded by the gradient limit and
  // r_min/r_max; scales the record's gradients (in place) when r_min overrides the limit.
  RecordInfo clampRecord(const CacheKey& key, const ShadePoint& cand, const Hit* hits, int S, float minDistance,
                         float* lambda, float* gradT, float* gradB) const;
  void interpolateAndShade(const CacheKey& key, PointView pts, const std::vector<Lookup>& lookups,
                           std::vector<Color>& out);
  // The batched path of interpolateAndShade: interpolate and brdf_dot kernels.
  void interpolateWithKernels(const CacheKey& key, PointView pts,
                              const std::vector<Lookup>& lookups, std::vector<Color>& out);
  bool adaptiveCheck(const CacheKey& key, PointView pts, const std::vector<Lookup>& lookups,
                     const std::vector<float>& baseLum);
  std::vector<Color> recordPredictions(const CacheKey& key, PointView pts,
                                       const std::vector<size_t>& pairPoint, const std::vector<RcContribution>& pairEntry);
  // Lowers a_i of records (id → new a_i) within their floors; true when any changed.
  bool shrinkRecords(const CacheKey& key, const std::map<uint32_t, float>& shrink);
  // An interpolate batch's header for `points` points (frames and offsets sized, zero) and the
  // coefficients (and, in record-frame mode, frames) of records `ids` of `cache`.
  InterpolateBatch interpolateBatch(int order, bool world, size_t points) const;
  void addRecords(const RadianceCache& cache, const std::vector<uint32_t>& ids, InterpolateBatch& interp) const;
  void continuePaths(PointView pts, std::vector<Color>& out, float relaxedScale);
  void shadeLambda(PointView pts, size_t begin, size_t count, int order,
                   std::vector<float> lambda, std::vector<Color>& out, const std::vector<size_t>* outIndex);
};

}  // namespace rc
