#pragma once
// What every phase of one rcache render reads (cache_fill, final_pass, adaptive_rounds,
// rcache_stats): the render context, the SH backend, the cache files, the parameters, the material tables, the
// camera, the engine that owns the caches and the primary-hit tracer. Built once by
// RcacheIntegrator::render; the phases keep their own outputs in their own result structs.
#include <atomic>
#include <cstdint>

#include "brdf/material_plan.h"
#include "cache/cache_engine.h"
#include "cache/cache_params.h"
#include "cache/primary_hits.h"
#include "cache/rcache_options.h"
#include "render/camera.h"
#include "render/integrator.h"

namespace rc {

struct RcacheRun {
  const RenderContext& ctx;
  ShBackend& backend;
  const CacheFiles& files;
  const RcacheParams& params;
  const BrdfTableSet& tables;
  const CameraModel& camera;
  CacheEngine& engine;
  const PrimaryHits& primaries;
  int width = 0, height = 0;
  int spp = 0;
  uint64_t seed = 0;  // the scene sampler's seed + --seed
  bool lowDiscrepancy = false;

  bool cancelled() const { return ctx.cancel && ctx.cancel->load(std::memory_order_relaxed); }
  size_t totalRecords() const {
    size_t n = 0;
    for (auto& [key, cache] : engine.caches()) n += cache->size();
    return n;
  }
};

}  // namespace rc
