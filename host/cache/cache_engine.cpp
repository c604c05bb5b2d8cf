#include "cache/cache_engine.h"

#include <algorithm>
#include <cmath>

#include "bsdf/alpha_family.h"
#include "cache/cosine_match.h"
#include "cache/direct_light_batch.h"
#include "cache/interpolate_entries.h"
#include "cache/radius_floor.h"
#include "cache/record_octree.h"
#include "cache/rng_salts.h"
#include "cache/world_frame.h"
#include "cl/sh_backend.h"
#include "core/error.h"
#include "core/parallel.h"
#include "core/parallel_select.h"
#include "core/parallel_sort.h"
#include "core/rng.h"
#include "core/timing.h"
#include "render/direct_light.h"
#include "scene/integrator_params.h"
#include "sh/sh_basis.h"

namespace rc {

namespace {

// Interpolation/shading runs in chunks so that Λ of a chunk ([P][3][n²] floats) stays small
// (4096 points at order 16 = 12 MB) however many points a batch of records produced.
constexpr size_t kChunk = 4096;
// Paths longer than this are cut (only reachable through chains of delta lobes that Russian
// roulette has not yet ended; probability < 0.95^990).
constexpr int kHardDepthLimit = 1000;
// A record ray's hit starts its low-discrepancy dimensions at the second pair (ShadePoint::ldDim
// = 0 means "none"; the pairs are scrambled independently, so skipping one costs nothing).
constexpr uint32_t kRecordLowDiscrepancyFirstDim = 2;
// Adaptive-caching checks per ensureCoverage call: each may shrink records and uncover points.
constexpr int kMaxAdaptiveRounds = 4;

// The points of each cache key (tech[i] cached), in point order per key: one order-preserving
// parallel selection per distinct key (a handful per call).
std::map<CacheKey, std::vector<size_t>> groupByKey(const std::vector<Technique>& tech, const std::vector<CacheKey>& keys) {
  const size_t n = tech.size();
  const size_t blocks = (n + kSelectBlock - 1) / kSelectBlock;
  std::vector<std::vector<CacheKey>> blockKeys(blocks);
  parallelFor(blocks, 1, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b) {
      std::vector<CacheKey>& found = blockKeys[b];
      const size_t end = std::min(n, (b + 1) * kSelectBlock);
      for (size_t i = b * kSelectBlock; i < end; ++i) {
        if (!isCached(tech[i])) continue;
        const auto same = [&](const CacheKey& k) { return !(k < keys[i]) && !(keys[i] < k); };
        if (std::find_if(found.begin(), found.end(), same) == found.end()) found.push_back(keys[i]);
      }
    }
  });
  std::map<CacheKey, std::vector<size_t>> groups;
  for (const auto& found : blockKeys)
    for (const CacheKey& k : found) groups[k];
  for (auto& group : groups) {
    const CacheKey& key = group.first;
    group.second = parallelSelect(n, [&](size_t i) {
      return isCached(tech[i]) && !(keys[i] < key) && !(key < keys[i]);
    });
  }
  return groups;
}

// The points idx of pts (all of them in order: an empty array, the caller uses pts itself).
ParallelArray<ShadePoint> gather(PointView pts, const std::vector<size_t>& idx) {
  if (idx.size() == pts.size()) return {};
  return ParallelArray<ShadePoint>(idx.size(), [&](size_t j) { return pts[idx[j]]; });
}

// Frees the lookups' contribution lists on all threads: hundreds of thousands of small
// allocations per call, which the destructor would free one by one on the calling thread.
void releaseLookups(std::vector<Lookup>& lookups) {
  parallelFor(lookups.size(), 1024, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) std::vector<RcContribution>().swap(lookups[i].entries);
  });
  lookups.clear();
}

}  // namespace

CacheEngine::CacheEngine(const RenderContext& ctx, ShBackend& backend, const RcacheParams& params,
                         const BrdfTableSet& tables, const CameraModel& camera, int maxDepth, int rrDepth,
                         Vec3 sceneLo, Vec3 sceneHi)
    : ctx_(ctx), backend_(backend), params_(params), tables_(tables), camera_(camera), maxDepth_(maxDepth),
      rrDepth_(rrDepth), lo_(sceneLo), hi_(sceneHi) {
  const auto& bsdfs = ctx.scene.bsdfs;
  const auto& plans = tables.plans();
  planTech_.assign(bsdfs.size(), Technique::ImportanceSampling);
  planOrder_.assign(bsdfs.size(), 0);
  twoSided_.assign(bsdfs.size(), false);
  for (size_t i = 0; i < bsdfs.size(); ++i) {
    twoSided_[i] = bsdfs[i]->isTwoSided();
    const MaterialPlan* plan = i < plans.size() ? &plans[i] : nullptr;
    if (plan && plan->tableIndex >= 0 && isCached(plan->technique)) {
      planTech_[i] = plan->technique;
      // Records of a material have its table's order; the TL approximation needs only the
      // irradiance and the dominant direction (bands 0..2).
      planOrder_[i] = params.tlMode ? 3 : plan->shOrder;
    }
  }
  // Without a cached material no record exists to carry the environment; the TL approximation
  // treats a record's light as one direction, which a sky is not.
  bool anyCached = false;
  for (Technique t : planTech_) anyCached |= isCached(t);
  const bool split = anyCached && !params.tlMode;
  splitEnvironment_ = split && params.envCache;
  splitArea_ = split && params.areaCache;
}

// Built on first use, not with the engine: the environment's threshold costs several path-traced
// 256² frames on a large envmap, which a render the pilot path traces must not pay.
const LightSplit& CacheEngine::lightSplit() const {
  std::call_once(splitBuilt_, [this] {
    envSplit_ = std::make_unique<LightSplit>(ctx_.scene, splitEnvironment_, params_.envVariance, splitArea_);
    if (envSplit_->active())
      residualCtx_ = std::make_unique<RenderContext>(RenderContext{
          ctx_.scene, ctx_.accel, envSplit_->residualLights(), ctx_.options, ctx_.cancel, ctx_.progress});
  });
  return *envSplit_;
}

const RenderContext& CacheEngine::directLightContext(const ShadePoint& sp) const {
  lightSplit();
  return residualCtx_ && hasIndirect(sp) && isCached(technique(sp)) ? *residualCtx_ : ctx_;
}

float CacheEngine::footprint(const Vec3& p, int level) const {
  const float distance = std::max(glm::length(p - camera_.position()), 1e-6f);
  return level == 0 ? camera_.pixelFootprint(distance) : camera_.squareFilmPixelFootprint(distance);
}

float CacheEngine::aForLevel(int level) const { return params_.a * std::pow(params_.secondaryAScale, float(level)); }

Technique CacheEngine::technique(const ShadePoint& sp) const {
  if (!sp.active || sp.hit.bsdf < 0) return Technique::None;
  const Technique t = planTech_[static_cast<size_t>(sp.hit.bsdf)];
  if (isCached(t)) {
    if (sp.wo.z <= 0.0f) return Technique::None;  // back of a one-sided BSDF: black
    if (sp.level >= params_.cacheDepth) return Technique::ImportanceSampling;
    if (t == Technique::LobeSplit && (sp.level > 0 || !lobeSplitOn_)) return Technique::ImportanceSampling;
  }
  return t;
}

Color CacheEngine::lobeSplitDirect(const ShadePoint& sp, Rng& rng, int lightSamples) const {
  const Bsdf& bsdf = *ctx_.scene.bsdfs[static_cast<size_t>(sp.hit.bsdf)];
  const int n = std::max(1, lightSamples);
  Color base(0.0f);
  for (int k = 0; k < n; ++k) base += directLightLightOnly(directLightContext(sp), sp.hit, sp.frame, sp.wo, *bsdf.baseLayer(), rng);
  return base / float(n) + lightStrategyMis(ctx_, sp.hit, sp.frame, sp.wo, *bsdf.coatLayer(), rng, lightSamples);
}

bool CacheEngine::hasIndirect(const ShadePoint& sp) const {
  return withinMaxDepth(maxDepth_, sp.depth + 2) && sp.depth < kHardDepthLimit;
}

bool CacheEngine::continuesPath(const ShadePoint& sp) const {
  return hasIndirect(sp) && technique(sp) == Technique::ImportanceSampling;
}

CacheKey CacheEngine::keyFor(const ShadePoint& sp) const {
  CacheKey k;
  k.level = sp.level;
  k.depth = maxDepth_ < 0 ? 0 : sp.depth;
  k.order = planOrder_[static_cast<size_t>(sp.hit.bsdf)];
  if (sp.level > 0 && params_.secondaryOrder > 0) k.order = std::min(k.order, std::max(3, params_.secondaryOrder));
  return k;
}

RadianceCache& CacheEngine::cacheFor(const CacheKey& key) {
  auto it = caches_.find(key);
  if (it == caches_.end()) it = caches_.emplace(key, std::make_unique<RadianceCache>(key.order, lo_, hi_)).first;
  return *it->second;
}

void CacheEngine::radianceOut(PointView pts, std::vector<Color>& out, float relaxedScale) {
  out.assign(pts.size(), Color(0.0f));
  parallelFor(pts.size(), 256, [&](size_t b, size_t e) {
    // The chunk's estimators, their shadow and BSDF rays traced as packets.
    thread_local DirectLightChunk batch;
    batch.clear();
    for (size_t i = b; i < e; ++i) {
      const ShadePoint& sp = pts[i];
      if (!sp.active) continue;
      if (!withinMaxDepth(maxDepth_, sp.depth + 1)) continue;
      // Secondary hits (of record rays, or of continuations below importance-sampled surfaces):
      // a Lambertian hit skips the BSDF strategy and its ray (see directLightLightOnly); for
      // record rays its noise is averaged over the hemisphere anyway. A record ray's hit draws
      // its light sample from the record's low-discrepancy sequence (buildRecords), unless its
      // path continues: continuePaths starts that point's sequence afresh for the BSDF sample.
      const bool continues = continuesPath(sp);
      BsdfPtr& pointBsdf = batch.holders.emplace_back();  // a spatially varying BSDF at this point (Bsdf::at)
      const Bsdf& bsdf = bsdfAt(*ctx_.scene.bsdfs[sp.hit.bsdf], sp, pointBsdf);
      if (technique(sp) == Technique::LobeSplit) {  // a camera path's vertex behind delta bounces
        Rng rng = shadePointRng(sp, 1);
        const Color L = lobeSplitDirect(sp, rng, sp.lightSamples);
        if (isFinite(L)) out[i] = L;
        continue;
      }
      batch.jobs.push_back({&directLightContext(sp), &sp.hit, sp.frame, sp.wo, &bsdf,
                      continues ? Rng(sp.seed, 1) : shadePointRng(sp, 1),
                      continues               ? DirectEstimator::LightStrategy
                      : bsdf.isDiffuseOnly() ? DirectEstimator::LightOnly
                                             : DirectEstimator::Full,
                      continues ? sp.lightSamples : 1});
      batch.owner.push_back(static_cast<uint32_t>(i));
    }
    batch.run();
    for (size_t k = 0; k < batch.jobs.size(); ++k)
      if (isFinite(batch.L[k])) out[batch.owner[k]] = batch.L[k];
  });
  std::vector<Color> ind;
  indirect(pts, ind, nullptr, relaxedScale);
  parallelFor(pts.size(), 4096, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      out[i] += ind[i];
      // A textured factor scales everything the point reflects (Bsdf::tint), after the cache.
      const Bsdf* bsdf = pts[i].active ? ctx_.scene.bsdfs[pts[i].hit.bsdf].get() : nullptr;
      if (bsdf && bsdf->tinted()) out[i] *= bsdf->tint(pts[i].hit.uv, pts[i].wo);
    }
  });
}

void CacheEngine::indirect(PointView pts, std::vector<Color>& out, std::vector<LookupAov>* aov,
                           float relaxedScale, bool withCoat) {
  out.assign(pts.size(), Color(0.0f));
  if (aov) aov->assign(pts.size(), LookupAov{});
  // Classify in parallel (technique and cache key per point), then group by the few distinct keys
  // in point order (groupByKey): millions of record-ray hits pass through here in the fill.
  std::vector<Technique> tech(pts.size(), Technique::None);
  std::vector<CacheKey> keys(pts.size());
  parallelFor(pts.size(), 4096, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const ShadePoint& sp = pts[i];
      if (!hasIndirect(sp)) continue;
      tech[i] = technique(sp);
      if (isCached(tech[i])) keys[i] = keyFor(sp);
    }
  });
  const std::vector<size_t> sampled = parallelSelect(pts.size(), [&](size_t i) {
    return tech[i] == Technique::ImportanceSampling || (withCoat && tech[i] == Technique::LobeSplit);
  });
  const std::map<CacheKey, std::vector<size_t>> groups = groupByKey(tech, keys);
  for (auto& group : groups) {
    // Named references, not a structured binding: C++17 lambdas cannot capture those (clang).
    const CacheKey& key = group.first;
    const std::vector<size_t>& idx = group.second;
    const ParallelArray<ShadePoint> copy = gather(pts, idx);
    const PointView sub = idx.size() == pts.size() ? pts : PointView(copy);
    std::vector<Lookup> lookups;
    ensureCoverage(key, sub, lookups, nullptr, false, relaxedScale);
    std::vector<Color> L;
    interpolateAndShade(key, sub, lookups, L);
    parallelFor(idx.size(), 4096, [&](size_t b, size_t e) {
      for (size_t j = b; j < e; ++j) out[idx[j]] = L[j];
    });
    if (aov) {
      const RadianceCache& cache = cacheFor(key);
      parallelFor(idx.size(), 1024, [&](size_t b, size_t e) {
        const RadianceCache::Reader reader = cache.reader();
        for (size_t j = b; j < e; ++j) {
          LookupAov& a = (*aov)[idx[j]];
          a.contributors = static_cast<int>(lookups[j].entries.size());
          for (const auto& c : lookups[j].entries) {
            const RecordInfo& r = reader.info(static_cast<uint32_t>(c.record));
            a.meanA += r.a;
            a.meanRadiusPx += r.a * r.R / footprint(r.p, key.level);
          }
          if (a.contributors > 0) {
            a.meanA /= a.contributors;
            a.meanRadiusPx /= a.contributors;
          }
        }
      });
    }
    releaseLookups(lookups);
  }
  if (!sampled.empty()) {
    const ParallelArray<ShadePoint> copy = gather(pts, sampled);
    const PointView sub = sampled.size() == pts.size() ? pts : PointView(copy);
    std::vector<Color> L;
    // Paths continued below a sharp surface keep the relaxed lookups of the final pass.
    continuePaths(sub, L, relaxedScale);
    parallelFor(sampled.size(), 4096, [&](size_t b, size_t e) {
      for (size_t j = b; j < e; ++j) out[sampled[j]] += L[j];  // a lobe split's base is there already
    });
  }
}

void CacheEngine::coatIndirect(PointView pts, std::vector<Color>& out, float relaxedScale) {
  for (size_t i = 0; i < pts.size(); ++i)
    if (!hasIndirect(pts[i]) || technique(pts[i]) != Technique::LobeSplit)
      throw Error("coatIndirect: a point that is not lobe-split");
  continuePaths(pts, out, relaxedScale);
}

void CacheEngine::fill(const std::vector<ShadePoint>& pts, const std::vector<float>& baseLum, bool adaptive) {
  std::vector<Technique> tech(pts.size(), Technique::None);
  std::vector<CacheKey> keys(pts.size());
  parallelFor(pts.size(), 4096, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const Technique t = technique(pts[i]);
      if (!isCached(t) || !withinMaxDepth(maxDepth_, pts[i].depth + 2)) continue;
      tech[i] = t;
      keys[i] = keyFor(pts[i]);
    }
  });
  for (const auto& group : groupByKey(tech, keys)) {
    const std::vector<size_t>& idx = group.second;
    const ParallelArray<ShadePoint> copy = gather(pts, idx);
    const PointView sub = idx.size() == pts.size() ? PointView(pts) : PointView(copy);
    std::vector<float> lum(idx.size(), 0.0f);
    parallelFor(idx.size(), 4096, [&](size_t b, size_t e) {
      for (size_t j = b; j < e; ++j)
        if (idx[j] < baseLum.size()) lum[j] = baseLum[idx[j]];
    });
    std::vector<Lookup> lookups;
    ensureCoverage(group.first, sub, lookups, &lum, adaptive);
    releaseLookups(lookups);
  }
}

void CacheEngine::lookUp(RadianceCache& cache, PointView pts, const std::vector<size_t>& todo,
                         std::vector<Lookup>& lookups, float relaxedScale) {
  parallelFor(todo.size(), 64, [&](size_t b, size_t e) {
    const RadianceCache::Reader reader = cache.reader();
    for (size_t j = b; j < e; ++j) {
      const ShadePoint& sp = pts[todo[j]];
      Lookup& lk = lookups[todo[j]];
      reader.lookup(sp.hit.p, sp.geometryFrame.n, lk);
      if (!lk.covered() && relaxedScale > 1.0f) {
        reader.lookup(sp.hit.p, sp.geometryFrame.n, lk, relaxedScale);
        if (lk.covered()) ++stats_.relaxedLookups;
      }
    }
  });
}

// Neighbour clamping on insertion shrinks the radii of older records, which can uncover points
// found covered in an earlier round. In the final pass (relaxedScale > 1) every point is looked up
// again, so the image is a function of the final cache alone (what --cache-load reproduces). In
// the fill only the points one of whose records shrank are (the others keep lookups that miss the
// newest records, a valid interpolation of the cache as it was; re-checking all would cost a third
// of the fill's lookups).
std::vector<size_t> CacheEngine::pointsToRecheck(const std::vector<Lookup>& lookups, std::vector<uint32_t>& shrunk,
                                                 float relaxedScale) {
  const size_t n = lookups.size();
  std::vector<size_t> todo;
  std::sort(shrunk.begin(), shrunk.end());
  shrunk.erase(std::unique(shrunk.begin(), shrunk.end()), shrunk.end());
  if (relaxedScale > 1.0f) {
    todo.resize(n);
    for (size_t i = 0; i < n; ++i) todo[i] = i;
  } else if (!shrunk.empty()) {
    todo = parallelSelect(n, [&](size_t i) {
      for (const RcContribution& c : lookups[i].entries)
        if (std::binary_search(shrunk.begin(), shrunk.end(), static_cast<uint32_t>(c.record))) return true;
      return false;
    });
  }
  shrunk.clear();
  return todo;
}

std::vector<ShadePoint> CacheEngine::recordCandidates(PointView pts,
                                                      const std::vector<size_t>& uncovered, float sepPx) const {
  // Deterministic shuffle (by the points' seeds) so candidates spread over the batch; the keys
  // are hashed once each, in parallel, not twice per comparison, and sorted in parallel (the
  // point indices make every pair unique, so the order is std::sort's).
  std::vector<std::pair<uint64_t, size_t>> order(uncovered.size());
  parallelFor(order.size(), 4096, [&](size_t b, size_t e) {
    for (size_t j = b; j < e; ++j) order[j] = {hashMix(pts[uncovered[j]].seed, kSaltCandidateOrder), uncovered[j]};
  });
  parallelSort(order);
  RecordOctree accepted(lo_, hi_);
  std::vector<ShadePoint> cands;
  for (const auto& keyed : order) {
    const size_t i = keyed.second;
    const ShadePoint& sp = pts[i];
    bool near = false;
    accepted.query(sp.hit.p, [&](uint32_t id) {
      if (near) return;
      const ShadePoint& c = cands[id];
      const float sep = sepPx * footprint(c.hit.p, c.level);
      if (glm::length(c.hit.p - sp.hit.p) < sep && glm::dot(c.geometryFrame.n, sp.geometryFrame.n) > 0.5f) near = true;
    });
    if (near) continue;
    accepted.insert(static_cast<uint32_t>(cands.size()), sp.hit.p, sepPx * footprint(sp.hit.p, sp.level));
    cands.push_back(sp);
    if (static_cast<int>(cands.size()) >= params_.batch) break;
  }
  return cands;
}

// Rounds of: look up the points still to do; if all are covered, re-check those whose records
// shrank and run the adaptive check; else place a batch of records at spread-out uncovered points.
void CacheEngine::ensureCoverage(const CacheKey& key, PointView pts, std::vector<Lookup>& lookups,
                                 const std::vector<float>* baseLum, bool adaptive, float relaxedScale) {
  RadianceCache& cache = cacheFor(key);
  const size_t n = pts.size();
  lookups.assign(n, Lookup{});
  const float levelScale = aForLevel(key.level) / params_.a;
  // Candidate spacing starts at half the largest influence radius and halves every round down to
  // the smallest: like the coarse-to-fine image passes, big records are placed first and the
  // gaps are filled afterwards, so few records are wasted on overlap.
  const float minSepPx = params_.rMinPx * levelScale;
  float sepPx = std::max(minSepPx, 0.5f * params_.rMaxPx * levelScale);
  int adaptiveRounds = 0;
  bool created = false;
  std::vector<uint32_t> shrunk;  // records whose radius clamping lowered since the last check
  // Points off the float range (a hit on an overflowing sphere) cannot hold a record.
  const std::vector<size_t> all = parallelSelect(n, [&](size_t i) { return isFinite(pts[i].hit.p); });
  std::vector<size_t> todo = all;
  // Each creation round covers at least the points its records were made at (radius_floor.h), so
  // the loop ends within about 2n rounds; the bound and the cancel check are the last resort.
  const size_t maxRounds = 2 * n + 64;
  for (size_t round = 0; round < maxRounds && !(ctx_.cancel && ctx_.cancel->load(std::memory_order_relaxed));
       ++round) {
    lookUp(cache, pts, todo, lookups, relaxedScale);
    std::vector<size_t> uncovered = parallelSelectFrom(todo, [&](size_t i) { return !lookups[i].covered(); });
    if (uncovered.empty() && created) {
      created = false;
      todo = pointsToRecheck(lookups, shrunk, relaxedScale);
      if (!todo.empty()) continue;
    }
    if (uncovered.empty()) {
      if (adaptive && params_.adaptive && baseLum && adaptiveRounds < kMaxAdaptiveRounds) {
        ++adaptiveRounds;
        const auto t0 = SteadyClock::now();
        const bool changed = adaptiveCheck(key, pts, lookups, *baseLum);
        stats_.adaptive_s += secondsSince(t0);
        if (changed) {
          // Shrunk records may uncover points and change the weights of others: look up all again.
          todo = all;
          created = false;
          continue;
        }
      }
      break;
    }
    ++stats_.uncoveredRounds;
    for (uint32_t id : buildRecords(key, recordCandidates(pts, uncovered, sepPx))) shrunk.push_back(id);
    created = true;
    sepPx = std::max(minSepPx, 0.5f * sepPx);
    todo = uncovered;
  }
}

ProjectBatch CacheEngine::recordBatch(const CacheKey& key, const std::vector<ShadePoint>& cands) {
  const int B = static_cast<int>(cands.size());
  ProjectBatch rayBatch;
  hemisphereCells(key.level == 0 ? params_.rays : params_.secondaryRays, rayBatch.M, rayBatch.N);
  const int S = rayBatch.M * rayBatch.N;
  rayBatch.order = key.order;
  rayBatch.records = B;
  rayBatch.gradients = params_.gradients;
  rayBatch.pattern.resize(2 * static_cast<size_t>(S));
  Rng prng(hashMix(ctx_.options.seed, recordCounter_, static_cast<uint64_t>(key.level) * 1000 + key.depth),
           kStreamRecordPattern);
  for (auto& v : rayBatch.pattern) v = prng.nextFloat();
  rayBatch.phi0.resize(B);
  for (int b = 0; b < B; ++b) rayBatch.phi0[b] = 2.0f * kPi * Rng(cands[b].seed, kStreamRecordAzimuth).nextFloat();
  // Smallest distance the gradient formula sees: a thousandth of a pixel footprint keeps 1/r
  // finite when geometry touches the record, yet far below any R_min.
  float minFp = INFINITY;
  for (const auto& c : cands) minFp = std::min(minFp, footprint(c.hit.p, key.level));
  rayBatch.minDistance = std::max(1e-3f * minFp, 1e-12f);
  return rayBatch;
}

void CacheEngine::traceRecordRays(const std::vector<ShadePoint>& cands, ProjectBatch& rayBatch,
                                  ParallelArray<Hit>& hits) {
  const int M = rayBatch.M, N = rayBatch.N, S = M * N;
  const size_t total = cands.size() * S;
  // Ray s of record b: cell (j, k) = (s / N, s % N) of the stratified pattern, turned by the
  // record's azimuth.
  const ParallelArray<Ray> rays(total, [&](size_t i) {
    const size_t b = i / S, s = i % S;
    const ShadePoint& c = cands[b];
    const int j = static_cast<int>(s) / N, k = static_cast<int>(s) % N;
    const float ct = 1.0f - (j + rayBatch.pattern[2 * s]) / M;
    const float st = std::sqrt(std::max(0.0f, 1.0f - ct * ct));
    const float phi = 2.0f * kPi * (k + rayBatch.pattern[2 * s + 1]) / N + rayBatch.phi0[b];
    const Vec3 local(st * std::cos(phi), st * std::sin(phi), ct);
    return Accel::spawnRay(c.hit, c.geometryFrame.toWorld(local));
  });
  hits = ParallelArray<Hit>(total);
  parallelFor(total, 1024, [&](size_t b, size_t e) {
    ctx_.accel.intersectBatch(rays.data() + b, hits.data() + b, e - b, BatchQuery::Packet16);
  });
  stats_.recordRays += total;
  // The radiance arriving along each ray: the hit's outgoing radiance, shaded recursively.
  std::vector<Color> L;
  {
    const ParallelArray<ShadePoint> next(total, [&](size_t i) {
      const ShadePoint& c = cands[i / S];
      ShadePoint sp = shadePointOf(hits[i], rays[i].d, c.depth + 1, c.level + 1, hashMix(c.seed, i % S, kSaltRecordRayHit));
      // The light samples at a record's S hits are one padded Sobol sequence (index = ray): like
      // the ray directions they are stratified over the record, so the record's estimate of
      // direct light at its neighbours converges faster than with independent samples.
      sp.ldSeed = static_cast<uint32_t>(hashMix(c.seed, kSaltRecordLightSequence));
      sp.ldIndex = static_cast<uint32_t>(i % S);
      sp.ldDim = kRecordLowDiscrepancyFirstDim;
      return sp;
    });
    radianceOut(next, L);
  }
  rayBatch.radiance.resize(total * 3);
  rayBatch.distance.resize(total);
  const LightSplit& split = lightSplit();
  const bool carriesEnvironment = split.active();
  parallelFor(total, 16384, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      // An escaping ray brings the environment's cached part, a ray that hits a cached area
      // emitter its emission (the rest is the direct light of the points that use this record).
      if (carriesEnvironment)
        L[i] += hits[i].valid() ? split.cachedEmission(hits[i], rays[i].d) : split.cached(rays[i].d);
      for (int c = 0; c < 3; ++c) rayBatch.radiance[3 * i + c] = L[i][c];
      rayBatch.distance[i] = hits[i].valid() ? hits[i].t : 0.0f;
    }
  });
}

RecordInfo CacheEngine::clampRecord(const CacheKey& key, const ShadePoint& cand, const Hit* hits, int S,
                                    float minDistance, float* lambda, float* gradT, float* gradB) const {
  RecordInfo info;
  // Harmonic mean distance (Ward): misses count as infinitely far.
  double inv = 0.0;
  for (int s = 0; s < S; ++s)
    if (hits[s].valid()) inv += 1.0 / std::max(double(hits[s].t), double(minDistance));
  const float fp = footprint(cand.hit.p, key.level);
  const float R = inv > 0.0 ? static_cast<float>(S / inv) : INFINITY;
  info.p = cand.hit.p;
  info.frame = cand.geometryFrame;
  // Gradient limit R ≤ ‖Λ‖/‖∇Λ‖ (Křivánek et al. 2006; Mitsuba 0.5's irrcache clamps R by
  // E/|∇E| the same way): R is, like Ward's split-sphere distance, the length over which the
  // record's light changes by its own size, so a bounds the first-order change over the reach
  // a·R to a share a of it. Norms run over all coefficients and channels, so the higher bands of
  // a glossy record are held to the same bound as its mean. Where an object touches a surface the
  // light rises steeply and then levels off (occlusion, not linear in distance): a looser bound
  // (‖∇Λ‖·a·R ≤ ‖Λ‖) let records reach across the contact with a
  // slope valid only beside it, brightening the contact (bench/RESULTS.md, contact17).
  float Rg = INFINITY;
  const size_t coeffs = 3 * static_cast<size_t>(key.order) * key.order;
  if (params_.gradients) {
    double l2 = 0, g2 = 0;
    for (size_t o = 0; o < coeffs; ++o) {
      l2 += double(lambda[o]) * lambda[o];
      g2 += double(gradT[o]) * gradT[o] + double(gradB[o]) * gradB[o];
    }
    if (g2 > 0) Rg = static_cast<float>(std::sqrt(l2 / g2));
  }
  // r_min and r_max bound the influence radius a·R_i in pixel footprints (scaled like a at the
  // coarser secondary caches): a record never covers less than r_min pixels (below that a
  // cache only re-samples what a path tracer would, at 1000 rays a pixel) nor more than r_max.
  const float aL = aForLevel(key.level), levelScale = aL / params_.a;
  info.R = std::min(std::max(std::min(R, Rg), params_.rMinPx * levelScale * fp / aL), params_.rMaxPx * levelScale * fp / aL);
  info.R = std::max(info.R, minimumReach(cand.hit.p, maxComponent(hi_ - lo_)) / aL);
  // The pixel-footprint floor r_min can push R past the gradient limit (records in corners,
  // where R is tiny and the gradient ~Λ/R): scale the gradient down so the bound holds at the
  // radius actually used. Without this, a record 3 px wide extrapolates a gradient meant for a
  // sub-pixel neighbourhood and paints isolated pixels many times too bright (and at a contact,
  // where the floored records are the ones next to it, carries its steep slope past the contact).
  if (info.R > Rg) {
    const float s = Rg / info.R;
    for (size_t o = 0; o < coeffs; ++o) {
      gradT[o] *= s;
      gradB[o] *= s;
    }
  }
  info.a = aForLevel(key.level);
  return info;
}

// Sample → project → clamp → insert: one batch of new records at the candidates.
std::vector<uint32_t> CacheEngine::buildRecords(const CacheKey& key, const std::vector<ShadePoint>& cands) {
  if (cands.empty()) return {};
  RadianceCache& cache = cacheFor(key);
  const int B = static_cast<int>(cands.size());
  ProjectBatch rayBatch = recordBatch(key, cands);
  const int S = rayBatch.M * rayBatch.N;
  ParallelArray<Hit> hits;
  traceRecordRays(cands, rayBatch, hits);
  ProjectResult projected;
  auto t0 = SteadyClock::now();
  backend_.project(rayBatch, projected);
  // An irradiance cache's records: E at their own normal from the rays, not bands 0..2 alone.
  if (key.order == 3 && !params_.tlMode) matchCosineIrradianceAtNormal(rayBatch, projected);
  stats_.projection_s += secondsSince(t0);
  const size_t K = static_cast<size_t>(cache.coeffsPerRecord());
  if (!params_.gradients) {
    projected.gradT.assign(K * B, 0.0f);
    projected.gradB.assign(K * B, 0.0f);
  }
  std::vector<RecordInfo> infos(B);
  parallelFor(static_cast<size_t>(B), 16, [&](size_t b0, size_t b1) {
    for (size_t b = b0; b < b1; ++b)
      infos[b] = clampRecord(key, cands[b], &hits[b * S], S, rayBatch.minDistance, &projected.lambda[K * b],
                             &projected.gradT[K * b], &projected.gradB[K * b]);
  });
  for (int b = 0; b < B; ++b) {
    stats_.droppedSamples += projected.dropped.empty() ? 0 : static_cast<uint64_t>(projected.dropped[b]);
    if (key.level == 0 && cands[b].pixel >= 0) recordPixels_.push_back(cands[b].pixel);
  }
  WorldCopies world;
  if (params_.worldFrame) {
    t0 = SteadyClock::now();
    world = rotateToWorld(backend_, key.order, infos, projected.lambda, projected.gradT, projected.gradB);
    stats_.projection_s += secondsSince(t0);
  }
  std::vector<uint32_t> shrunk;
  cache.insert(std::move(infos), projected.lambda, projected.gradT, projected.gradB, world.lambda, world.gradT, world.gradB, true, &shrunk);
  recordCounter_ += static_cast<uint64_t>(B);
  return shrunk;
}

void CacheEngine::interpolateAndShade(const CacheKey& key, PointView pts,
                                      const std::vector<Lookup>& lookups, std::vector<Color>& out) {
  RadianceCache& cache = cacheFor(key);
  out.assign(pts.size(), Color(0.0f));
  // Lambertian points (all of an irradiance cache's, in practice) take the direct path: their
  // outgoing radiance is (ρ/π)·E(n), evaluated per point without batches, rotations or tables
  // (RadianceCache::cosineIrradiance; equal to the kernels' interpolate + brdf_dot, tested).
  // Everything else goes through the kernels below.
  if (!params_.tlMode && key.order == 3) {
    std::vector<char> lambertian(pts.size(), 0);
    const auto t0 = SteadyClock::now();
    parallelFor(pts.size(), 256, [&](size_t b, size_t e) {
      const RadianceCache::Reader reader = cache.reader();
      uint64_t contributions = 0, count = 0;
      for (size_t i = b; i < e; ++i) {
        BsdfPtr pointBsdf;  // a spatially varying BSDF at this point (Bsdf::at)
        const Bsdf& bsdf = bsdfAt(*ctx_.scene.bsdfs[static_cast<size_t>(pts[i].hit.bsdf)], pts[i], pointBsdf);
        if (!bsdf.isDiffuseOnly()) continue;
        lambertian[i] = 1;
        ++count;
        contributions += lookups[i].entries.size();
        const Color E = reader.cosineIrradiance(lookups[i], pts[i].frame.n, params_.gradients);
        const Color Lo = glm::max(bsdf.eval(pts[i].wo, Vec3(0, 0, 1)) * E, Color(0.0f));
        out[i] = isFinite(Lo) ? Lo : Color(0.0f);
      }
      stats_.lookups += count;
      stats_.contributions += contributions;
      stats_.lambertianLookups += count;
    });
    stats_.interpolation_s += secondsSince(t0);
    const std::vector<size_t> rest = parallelSelect(pts.size(), [&](size_t i) { return !lambertian[i]; });
    if (rest.empty()) return;
    if (rest.size() < pts.size()) {
      const ParallelArray<ShadePoint> subPts = gather(pts, rest);
      std::vector<Lookup> subLookups(rest.size());
      parallelFor(rest.size(), 1024, [&](size_t b, size_t e) {
        for (size_t j = b; j < e; ++j) subLookups[j] = lookups[rest[j]];
      });
      std::vector<Color> subOut;
      interpolateWithKernels(key, subPts, subLookups, subOut);
      releaseLookups(subLookups);
      parallelFor(rest.size(), 4096, [&](size_t b, size_t e) {
        for (size_t j = b; j < e; ++j) out[rest[j]] = subOut[j];
      });
      return;
    }
  }
  interpolateWithKernels(key, pts, lookups, out);
}

void CacheEngine::interpolateWithKernels(const CacheKey& key, PointView pts,
                                         const std::vector<Lookup>& lookups, std::vector<Color>& out) {
  RadianceCache& cache = cacheFor(key);
  out.assign(pts.size(), Color(0.0f));
  const size_t K = static_cast<size_t>(cache.coeffsPerRecord());
  RecordSlots slots(cache.size());
  // Interpolates the points idx (all in one frame mode) into lambda[(slot)·K...] at their
  // position in the chunk.
  auto interpolate = [&](size_t begin, const std::vector<uint32_t>& idx, bool world, std::vector<float>& lambda) {
    if (idx.empty()) return;
    InterpolateBatch interp = interpolateBatch(key.order, world, idx.size());
    const std::vector<uint32_t> used = fillInterpolateEntries(pts, lookups, begin, idx, slots, interp);
    stats_.lookups += idx.size();
    stats_.contributions += interp.entries.size();
    addRecords(cache, used, interp);
    std::vector<float> part;
    const auto t0 = SteadyClock::now();
    backend_.interpolate(interp, part);
    stats_.interpolation_s += secondsSince(t0);
    if (lambda.empty()) {  // the chunk's only frame mode: idx is the whole chunk, in order
      lambda = std::move(part);
      return;
    }
    parallelFor(idx.size(), 256, [&](size_t b, size_t e) {
      for (size_t j = b; j < e; ++j)
        std::copy(part.begin() + K * j, part.begin() + K * (j + 1), lambda.begin() + K * idx[j]);
    });
  };
  for (size_t begin = 0; begin < pts.size(); begin += kChunk) {
    const size_t count = std::min(kChunk, pts.size() - begin);
    std::vector<uint32_t> worldIdx, recordIdx;
    for (size_t j = 0; j < count; ++j) {
      // frame=auto: where every contributing record lies in the point's tangent plane (all of a
      // flat wall) the per-record path costs at most an O(n²) z-rotation per record, the world
      // path a full O(n³) rotation per point; both give the same Λ to float precision (ARCHITECTURE.md §Kernels).
      // The lookup tells (Lookup::sameNormal; contributions have n·n_i > 0).
      // A normal or bump map turns the point's frame off the records' plane: the world path.
      const ShadePoint& sp = pts[begin + j];
      const bool turned = sp.frame.n != sp.geometryFrame.n;
      const bool record = params_.autoFrame ? lookups[begin + j].sameNormal && !turned : !params_.worldFrame;
      (record ? recordIdx : worldIdx).push_back(static_cast<uint32_t>(j));
    }
    stats_.recordFrameLookups += recordIdx.size();
    std::vector<float> lambda;
    if (!worldIdx.empty() && !recordIdx.empty()) lambda.assign(K * count, 0.0f);
    interpolate(begin, worldIdx, true, lambda);
    interpolate(begin, recordIdx, false, lambda);
    shadeLambda(pts, begin, count, key.order, std::move(lambda), out, nullptr);
  }
}

void CacheEngine::shadeLambda(PointView pts, size_t begin, size_t count, int order,
                              std::vector<float> lambda, std::vector<Color>& out,
                              const std::vector<size_t>* outIndex) {
  const size_t n2 = static_cast<size_t>(order) * order;
  auto point = [&](size_t j) -> const ShadePoint& { return pts[outIndex ? (*outIndex)[j] : begin + j]; };
  auto slot = [&](size_t j) -> Color& { return out[outIndex ? j : begin + j]; };
  const auto t0 = SteadyClock::now();
  if (params_.tlMode) {
    // Tabellion–Lamorlette 2004: the record's irradiance as if it all came from the dominant
    // direction. E = ∫ L cos from the zonal clamped-cosine coefficients (√π/2, √(π/3), √(5π)/8);
    // the direction from band 1 (y₁₋₁ ∝ −y, y₁₀ ∝ z, y₁₁ ∝ −x with the Condon–Shortley phase).
    parallelFor(count, 64, [&](size_t b, size_t e) {
      for (size_t j = b; j < e; ++j) {
        const ShadePoint& sp = point(j);
        const float* L = &lambda[3 * n2 * j];
        const float c0 = std::sqrt(kPi) / 2, c1 = std::sqrt(kPi / 3), c2 = std::sqrt(5 * kPi) / 8;
        Color E(0.0f);
        Vec3 d(0.0f);
        for (int c = 0; c < 3; ++c) {
          const float* Lc = L + n2 * c;
          E[c] = c0 * Lc[0] + (order > 1 ? c1 * Lc[2] : 0.0f) + (order > 2 ? c2 * Lc[6] : 0.0f);
          const float wl = c == 0 ? 0.2126f : c == 1 ? 0.7152f : 0.0722f;
          if (order > 1) d += wl * Vec3(-Lc[3], -Lc[1], Lc[2]);
        }
        const float len = glm::length(d);
        d = len > 0.0f ? d / len : Vec3(0, 0, 1);
        if (d.z < 1e-2f) d = glm::normalize(Vec3(d.x, d.y, 1e-2f));
        BsdfPtr pointBsdf;  // a spatially varying BSDF at this point (Bsdf::at)
        const Color f = bsdfAt(*ctx_.scene.bsdfs[sp.hit.bsdf], sp, pointBsdf).eval(sp.wo, d) / d.z;
        const Color Lo = f * glm::max(E, Color(0.0f));
        slot(j) = isFinite(Lo) ? Lo : Color(0.0f);
      }
    });
    stats_.dot_s += secondsSince(t0);
    return;
  }
  BrdfDotBatch dotBatch;
  dotBatch.order = order;
  dotBatch.points = static_cast<int>(count);
  dotBatch.lambda = std::move(lambda);
  dotBatch.wo.resize(3 * count);
  dotBatch.material.resize(count);
  parallelFor(count, 1024, [&](size_t b, size_t e) {
    for (size_t j = b; j < e; ++j) {
      const ShadePoint& sp = point(j);
      for (int c = 0; c < 3; ++c) dotBatch.wo[3 * j + c] = sp.wo[c];
      const MaterialPlan& plan = tables_.plans()[static_cast<size_t>(sp.hit.bsdf)];
      dotBatch.material[j] = plan.tableIndex;
      if (!plan.alphaNodes.empty()) {  // a roughness texture: the table of the point's α
        const float alpha = alphaFamilyOf(*ctx_.scene.bsdfs[static_cast<size_t>(sp.hit.bsdf)])->alphaAt(sp.hit.uv);
        const float u = static_cast<float>(hashMix(sp.seed, 0, kSaltAlphaNode) >> 40) * 0x1p-24f;
        dotBatch.material[j] = plan.tableAt(alpha, u);
      }
    }
  });
  tables_.fillBatch(dotBatch);
  std::vector<float> res;
  backend_.brdfDot(dotBatch, res);
  parallelFor(count, 4096, [&](size_t b, size_t e) {
    for (size_t j = b; j < e; ++j) {
      // Extrapolation by gradients (or SH ringing) can dip below zero where light changes
      // abruptly; negative radiance is not physical and is clamped.
      const Color Lo = glm::max(Color(res[3 * j], res[3 * j + 1], res[3 * j + 2]), Color(0.0f));
      slot(j) = isFinite(Lo) ? Lo : Color(0.0f);
    }
  });
  stats_.dot_s += secondsSince(t0);
}

InterpolateBatch CacheEngine::interpolateBatch(int order, bool world, size_t points) const {
  InterpolateBatch interp;
  interp.order = order;
  interp.worldFrame = world;
  interp.gradients = params_.gradients;
  interp.points = static_cast<int>(points);
  interp.pointFrames.resize(9 * points);
  interp.offsets.resize(points + 1, 0);
  return interp;
}

void CacheEngine::addRecords(const RadianceCache& cache, const std::vector<uint32_t>& ids, InterpolateBatch& interp) const {
  const size_t K = static_cast<size_t>(cache.coeffsPerRecord());
  const bool world = interp.worldFrame;
  interp.records = static_cast<int>(ids.size());
  interp.lambda.resize(K * ids.size());
  if (interp.gradients) {
    interp.gradT.resize(K * ids.size());
    interp.gradB.resize(K * ids.size());
  }
  if (!world) interp.recordFrames.resize(9 * ids.size());
  parallelFor(ids.size(), 64, [&](size_t b, size_t e) {
    const RadianceCache::Reader reader = cache.reader();
    for (size_t r = b; r < e; ++r) {
      reader.copyCoefficients(ids[r], world, &interp.lambda[K * r], interp.gradients ? &interp.gradT[K * r] : nullptr,
                              interp.gradients ? &interp.gradB[K * r] : nullptr);
      if (!world) reader.info(ids[r]).frame.rows(&interp.recordFrames[9 * r]);
    }
  });
}

// Each contribution (point i, record) of the points covered by two or more records, as the
// record alone predicts the point's outgoing radiance (its Λ moved by its gradient, rotated,
// dotted with the BRDF).
std::vector<Color> CacheEngine::recordPredictions(const CacheKey& key, PointView pts,
                                                  const std::vector<size_t>& pairPoint,
                                                  const std::vector<RcContribution>& pairEntry) {
  RadianceCache& cache = cacheFor(key);
  std::vector<Color> pred(pairPoint.size());
  for (size_t begin = 0; begin < pairPoint.size(); begin += kChunk) {
    const size_t count = std::min(kChunk, pairPoint.size() - begin);
    InterpolateBatch interp = interpolateBatch(key.order, params_.worldFrame, count);
    std::vector<uint32_t> ids(count);
    for (size_t j = 0; j < count; ++j) {
      RcContribution c = pairEntry[begin + j];
      ids[j] = static_cast<uint32_t>(c.record);
      pts[pairPoint[begin + j]].frame.rows(&interp.pointFrames[9 * j]);
      c.record = static_cast<int>(j);
      c.weight = 1.0f;
      interp.entries.push_back(c);
      interp.offsets[j + 1] = static_cast<int32_t>(j + 1);
    }
    addRecords(cache, ids, interp);
    std::vector<float> lambda;
    auto t0 = SteadyClock::now();
    backend_.interpolate(interp, lambda);
    stats_.interpolation_s += secondsSince(t0);
    std::vector<size_t> idx(pairPoint.begin() + begin, pairPoint.begin() + begin + count);
    std::vector<Color> part(count);
    shadeLambda(pts, 0, count, key.order, std::move(lambda), part, &idx);
    std::copy(part.begin(), part.end(), pred.begin() + begin);
  }
  return pred;
}

// EGSR 2006: at a point covered by several records, each record's own prediction should agree; a
// disagreement above the Weber threshold would show as a visible seam, so the most deviant record
// gets a smaller a_i.
bool CacheEngine::adaptiveCheck(const CacheKey& key, PointView pts,
                                const std::vector<Lookup>& lookups, const std::vector<float>& baseLum) {
  std::vector<size_t> pairPoint;
  std::vector<RcContribution> pairEntry;
  for (size_t i = 0; i < pts.size(); ++i)
    if (lookups[i].entries.size() >= 2)
      for (const auto& e : lookups[i].entries) {
        pairPoint.push_back(i);
        pairEntry.push_back(e);
      }
  if (pairPoint.empty()) return false;
  const std::vector<Color> pred = recordPredictions(key, pts, pairPoint, pairEntry);
  std::map<uint32_t, float> shrink;  // record → the a_i that excludes the points it disagrees at
  for (size_t q = 0; q < pairPoint.size();) {
    const size_t i = pairPoint[q];
    size_t end = q;
    double wsum = 0, ysum = 0;
    while (end < pairPoint.size() && pairPoint[end] == i) {
      wsum += pairEntry[end].weight;
      ysum += pairEntry[end].weight * luminance(pred[end]);
      ++end;
    }
    const double mean = ysum / wsum;
    const double threshold = params_.weber * (std::max(0.0, mean) + std::max(0.0f, baseLum[i]));
    double worst = 0;
    size_t worstAt = q;
    for (size_t k = q; k < end; ++k) {
      const double dev = std::fabs(luminance(pred[k]) - mean);
      if (dev > worst) {
        worst = dev;
        worstAt = k;
      }
    }
    if (threshold > 0 && worst > threshold) {
      // Exclude p from the record's influence: contributes iff w > 1/a, so a ≤ 1/w (with margin).
      const uint32_t id = static_cast<uint32_t>(pairEntry[worstAt].record);
      const float newA = 0.95f / pairEntry[worstAt].weight;
      auto it = shrink.find(id);
      if (it == shrink.end()) shrink[id] = newA;
      else it->second = std::min(it->second, newA);
    }
    q = end;
  }
  return shrinkRecords(key, shrink);
}

bool CacheEngine::shrinkRecords(const CacheKey& key, const std::map<uint32_t, float>& shrink) {
  RadianceCache& cache = cacheFor(key);
  bool changed = false;
  const float aL = aForLevel(key.level), aMin = aL * params_.minAScale, levelScale = aL / params_.a;
  for (const auto& [id, newA] : shrink) {
    const RecordInfo r = cache.info(id);
    const float before = r.a;
    // Shrinking stops at a·min_a_scale and where the influence radius would fall below r_min.
    const float floorA = std::max(aMin, std::min(aL, params_.rMinPx * levelScale * footprint(r.p, key.level) / r.R));
    cache.shrinkA(id, newA, floorA);
    if (cache.info(id).a < before) {
      changed = true;
      ++stats_.adaptiveShrinks;
    }
  }
  return changed;
}

void CacheEngine::continuePaths(PointView pts, std::vector<Color>& out, float relaxedScale) {
  const size_t n = pts.size();
  out.assign(n, Color(0.0f));
  ParallelArray<Ray> rays(n);
  std::vector<Color> weight(n, Color(0.0f));
  std::vector<float> pdf(n, 0.0f);
  std::vector<char> alive(n, 0), delta(n, 0);
  parallelFor(n, 64, [&](size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) {
      const ShadePoint& sp = pts[i];
      Rng rng = shadePointRng(sp, 2);
      const Vec2 u = rng.next2D();
      const float uLobe = rng.nextFloat();
      BsdfPtr pointBsdf;  // a spatially varying BSDF at this point (Bsdf::at)
      const Bsdf& whole = bsdfAt(*ctx_.scene.bsdfs[sp.hit.bsdf], sp, pointBsdf);
      // A lobe-split point's base light came from records: only its coat continues.
      const Bsdf& sampled = technique(sp) == Technique::LobeSplit ? *whole.coatLayer() : whole;
      const auto s = sampled.sample(sp.wo, uLobe, u);
      if (!s || !isFinite(s->weight) || maxComponent(s->weight) <= 0.0f) continue;
      Color w = s->weight;
      if (sp.depth >= rrDepth_) {
        // Russian roulette on this vertex's throughput factor (unbiased: survivors divide by q).
        const float q = std::min(0.95f, maxComponent(w));
        if (rng.nextFloat() >= q) continue;
        w /= q;
      }
      weight[i] = w;
      pdf[i] = s->pdf;
      alive[i] = 1;
      delta[i] = (s->lobe & kLobeDelta) ? 1 : 0;
      rays[i] = Accel::spawnRay(sp.hit, sp.frame.toWorld(s->wi));
    }
  });
  const std::vector<size_t> live = parallelSelect(n, [&](size_t i) { return alive[i] != 0; });
  if (live.empty()) return;
  const ParallelArray<Ray> liveRays(live.size(), [&](size_t j) { return rays[live[j]]; });
  ParallelArray<Hit> hits(live.size());
  parallelFor(live.size(), 1024, [&](size_t b, size_t e) {
    ctx_.accel.intersectBatch(liveRays.data() + b, hits.data() + b, e - b, BatchQuery::Packet16);
  });
  stats_.pathRays += live.size();
  std::vector<Color> L;
  {
    const ParallelArray<ShadePoint> next(live.size(), [&](size_t j) {
      const ShadePoint& sp = pts[live[j]];
      ShadePoint hit = shadePointOf(hits[j], liveRays[j].d, sp.depth + 1, sp.level + (delta[live[j]] ? 0 : 1),
                                    hashMix(sp.seed, 0xC0471));
      hit.pixel = sp.pixel;
      return hit;
    });
    radianceOut(next, L, relaxedScale);
  }
  // The continuation ray is the point's MIS BSDF sample too (continuesPath): add the emitter it
  // found, weighted against the point's light samples.
  parallelFor(live.size(), 1024, [&](size_t b, size_t e) {
    for (size_t j = b; j < e; ++j) {
      const size_t i = live[j];
      const Color Le = emitterMis(ctx_, pts[i].hit.p, liveRays[j].d, hits[j], pdf[i], delta[i] != 0, pts[i].lightSamples);
      out[i] = weight[i] * (Le + L[j]);
    }
  });
}

}  // namespace rc
