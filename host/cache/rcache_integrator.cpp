#include "cache/rcache_integrator.h"

#include <cmath>
#include <cstring>

#include "brdf/material_plan.h"
#include "cache/adaptive_rounds.h"
#include "cache/cache_engine.h"
#include "cache/cache_file.h"
#include "cache/cache_fill.h"
#include "cache/cache_params.h"
#include "cache/final_pass.h"
#include "cache/final_pass_memory.h"
#include "cache/path_fallback.h"
#include "cache/primary_hits.h"
#include "cache/rcache_run.h"
#include "cache/rcache_stats.h"
#include "cl/sh_backend.h"
#include "core/error.h"
#include "core/rng.h"
#include "core/timing.h"
#include "geometry/scene_bounds.h"
#include "render/camera.h"
#include "render/film.h"
#include "render/path_integrator.h"
#include "render/render_loop.h"

namespace rc {

namespace {

// Phase 1 of a render: every material's technique, SH order and BRDF×cos table (nothing is built
// without cached materials).
void buildTables(const Scene& scene, const RcacheParams& params, RenderStats& stats, BrdfTableSet& tables) {
  BrdfTableOptions options;
  options.orderOverride = params.order;
  options.notice = [&](const std::string& msg) { stats.setText("brdf_notice", msg); };
  tables.build(scene.bsdfs, options);
}

// AOV "records": per pixel, the records whose primary hit lies there.
void addRecordsAov(const CacheEngine& engine, Image& img) {
  std::vector<Color> layer(static_cast<size_t>(img.width) * img.height, Color(0.0f));
  for (int p : engine.recordPixels())
    if (p >= 0 && p < img.width * img.height) layer[static_cast<size_t>(p)] += Color(1.0f);
  img.aovs["records"] = layer;
}

RcacheParams paramsOf(const IntegratorSettings& s) {
  ParamReader in(&s.props);
  return readRcacheParams(in);
}

class RcacheIntegrator : public Integrator {
 public:
  explicit RcacheIntegrator(const IntegratorSettings& s) : settings_(s), params_(paramsOf(s)) {}
  std::string name() const override { return "rcache"; }
  Image render(const RenderContext& ctx, RenderStats& stats) override;

 private:
  IntegratorSettings settings_;
  RcacheParams params_;
};

// The phases of docs/ARCHITECTURE.md §Pipeline, each in its own file of host/cache/.
Image RcacheIntegrator::render(const RenderContext& ctxIn, RenderStats& stats) {
  const auto start = SteadyClock::now();
  const Scene& scene = ctxIn.scene;
  const RcacheAovs aovs = parseRcacheAovs(ctxIn.options.aovs);
  std::unique_ptr<ShBackend> ownBackend = ctxIn.backend ? nullptr : makeScalarBackend();
  ShBackend& backend = ctxIn.backend ? *ctxIn.backend : *ownBackend;
  const RenderContext ctx{scene, ctxIn.accel, ctxIn.lights, ctxIn.options, &backend, ctxIn.cancel, ctxIn.progress};

  BrdfTableSet tables;
  buildTables(scene, params_, stats, tables);
  const double tablesS = secondsSince(start);

  Film film(scene.film);
  const int spp = ctx.options.spp > 0 ? ctx.options.spp : scene.sampleCount;
  // Before the fill, not after it: the final pass's smallest batch is one film row of spp samples.
  checkFinalPassMemory(static_cast<size_t>(film.width()) * static_cast<size_t>(spp), film.width(), spp);
  const CameraModel camera(scene.camera, scene.film);
  Vec3 lo, hi;
  finiteSceneBounds(scene, lo, hi);
  CacheEngine engine(ctx, params_, tables, camera, settings_.maxDepth, settings_.rrDepth, lo, hi);
  const PrimaryHits primaries(ctx, engine, camera, settings_.maxDepth, settings_.hideEmitters);
  const RcacheRun run{ctx, params_, tables, camera, engine, primaries, film.width(), film.height(),
                      spp, scene.samplerSeed + ctx.options.seed, usesLowDiscrepancy(ctx)};
  // Records hold the cached part of the scene's light: a cache saved under another split must not load.
  const LightSplitSummary& split = engine.lightSplit().summary();
  uint32_t thresholdBits = 0;
  std::memcpy(&thresholdBits, &split.threshold, sizeof(thresholdBits));
  const uint64_t splitKey = split.active ? (uint64_t(thresholdBits) << 2 | uint64_t(split.environmentCached) << 1 |
                                            uint64_t(split.areaCached)) + 1 : 0;
  const uint64_t sceneHash = hashMix(cacheSceneHash(scene, settings_.maxDepth, params_.tlMode), splitKey);

  // Phase 0: a pilot decides whether the cache can pay here at all (cache/path_fallback.h).
  const FallbackDecision fallback = decideFallback(run);
  if (fallback.pathTrace) {
    Image img = makePathIntegrator(settings_)->render(ctx, stats);
    stats.setText("fallback", fallback.reason);
    stats.set("pilot_served_share", fallback.servedShare);
    stats.set("pilot_lobe_split_share", fallback.lobeSplitShare);
    return img;
  }

  const size_t recordsLoaded = ctx.options.cacheLoad.empty() ? 0
      : loadCachesInto(engine, ctx.options.cacheLoad, sceneHash, params_.worldFrame, backend);
  // --cache-reuse (walk-throughs, distributed fills): the loaded records stay as they are and the
  // fill adds records only where this view finds none.
  const bool fillNeeded = ctx.options.cacheLoad.empty() || ctx.options.cacheReuse;
  const FillReport fill = fillNeeded ? fillCache(run) : FillReport{};
  bool interrupted = fill.interrupted;

  const auto finalStart = SteadyClock::now();
  AdaptivePixels adaptive(run.width, run.height, spp, ctx.options.adaptive);
  FinalPass pass(run, aovs, film, adaptive);
  pass.shadeBands(interrupted);
  const std::unique_ptr<Film> adaptiveFilm = runAdaptiveRounds(run, pass, adaptive, film, interrupted);
  pass.mergeBands();
  if (adaptiveFilm) film.add(*adaptiveFilm);
  const double finalS = secondsSince(finalStart);

  Image img = film.develop();
  if (aovs.records) addRecordsAov(engine, img);
  if (!ctx.options.cacheSave.empty() && !interrupted) {
    // A failed save (full disk) must not lose the image: the CLI writes it, then reports this.
    try {
      saveCaches(engine, ctx.options.cacheSave, sceneHash);
    } catch (const Error& e) {
      stats.setText("cache_save_error", e.what());
    }
  }

  reportRcacheStats(run, {secondsSince(start), tablesS, finalS, fill, pass, adaptive, recordsLoaded, interrupted},
                    stats);
  stats.setText("fallback", fallback.reason);
  if (fallback.pilotPoints > 0) stats.set("pilot_served_share", fallback.servedShare);
  if (fallback.pilotPoints > 0) stats.set("pilot_lobe_split_share", fallback.lobeSplitShare);
  return img;
}

}  // namespace

std::unique_ptr<Integrator> makeRcacheIntegrator(const IntegratorSettings& settings) {
  return std::make_unique<RcacheIntegrator>(settings);
}

}  // namespace rc
