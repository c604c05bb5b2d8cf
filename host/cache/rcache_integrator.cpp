#include "cache/rcache_integrator.h"

#include <cmath>
#include <cstring>

#include "brdf/material_plan.h"
#include "cache/adaptive_rounds.h"
#include "cache/budget_params.h"
#include "cache/cache_engine.h"
#include "cache/cache_file.h"
#include "cache/cache_fill.h"
#include "cache/cache_params.h"
#include "cache/cost_pilot.h"
#include "cache/fill_payoff.h"
#include "cache/final_pass.h"
#include "cache/final_pass_memory.h"
#include "cache/path_fallback.h"
#include "cache/primary_hits.h"
#include "cache/rcache_run.h"
#include "cache/rcache_stats.h"
#include "cache/view_refinement.h"
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
  options.lobeSplit = params.lobeSplit != RcacheParams::LobeSplitMode::Off;
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

// What a cache file must match to be loaded: the scene, and the light split its records were made
// under (they hold the cached part of the scene's light).
uint64_t cacheKeyOf(const Scene& scene, const IntegratorSettings& settings, const RcacheParams& params,
                    const CacheEngine& engine) {
  const LightSplitSummary& split = engine.lightSplit().summary();
  uint32_t thresholdBits = 0;
  std::memcpy(&thresholdBits, &split.threshold, sizeof(thresholdBits));
  const uint64_t splitKey = split.active ? (uint64_t(thresholdBits) << 2 | uint64_t(split.environmentCached) << 1 |
                                            uint64_t(split.areaCached)) + 1 : 0;
  return hashMix(cacheSceneHash(scene, settings.maxDepth, params.tlMode), splitKey);
}

// One rcache render as the phases of docs/ARCHITECTURE.md §Pipeline, each in its own file of
// host/cache/: the constructor runs what is done once (tables, pilot, cache load, fill), addPass
// the final pass and adaptive rounds over one pass of samples, finish the save and statistics.
// When the pilot decides for path tracing, the path integrator's passes render instead.
class RcachePasses final : public PassRender {
 public:
  RcachePasses(const RenderContext& ctx, const IntegratorSettings& settings, const RcacheParams& params,
               ShBackend* backend, const CacheFiles& files, RenderStats& stats);
  int passSpp() const override { return spp_; }
  bool addPass(Film& film, int firstSample) override;
  Image finish(const Film& film, int passes, bool stopped, RenderStats& stats) override;

 private:
  // Phase 0: the share pilot (cache/path_fallback.h), with and without the lobe split, then the
  // cost pilot (cache/cost_pilot.h) among the path tracer and the variants the share pilot keeps.
  void chooseTechnique(const Vec3& lo, const Vec3& hi);
  const RenderContext& ctx_;
  const IntegratorSettings& settings_;
  const int spp_;
  const RcacheParams params_;  // the integrator's, with the ray counts set for this render's budget
  const CacheFiles files_;
  const SteadyClock::time_point start_ = SteadyClock::now();
  const RcacheAovs aovs_;
  std::unique_ptr<ShBackend> ownBackend_;
  ShBackend& backend_;
  BrdfTableSet tables_;
  double tablesS_ = 0.0;
  CameraModel camera_;
  std::unique_ptr<CacheEngine> engine_;
  std::unique_ptr<PrimaryHits> primaries_;
  std::unique_ptr<RcacheRun> run_;
  FallbackDecision fallback_;
  CostPilotReport cost_;
  FillPayoff payoff_;  // where the cost pilot could afford no cache candidate
  std::unique_ptr<Integrator> pathIntegrator_;  // the pilot chose path tracing: it renders the passes
  std::unique_ptr<PassRender> pathPasses_;
  size_t recordsLoaded_ = 0;
  size_t recordsSkipped_ = 0;  // loaded records too coarse for this view
  FillReport fill_;
  FinalPassTotals totals_;
  double finalS_ = 0.0;
};

RcachePasses::RcachePasses(const RenderContext& ctx, const IntegratorSettings& settings, const RcacheParams& params,
                           ShBackend* backend, const CacheFiles& files, RenderStats& stats)
    : ctx_(ctx), settings_(settings), spp_(ctx.options.spp > 0 ? ctx.options.spp : ctx.scene.sampler.sampleCount),
      params_(paramsForBudget(params, spp_)), files_(files), aovs_(parseRcacheAovs(ctx.options.aovs)),
      ownBackend_(backend ? nullptr : makeScalarBackend()), backend_(backend ? *backend : *ownBackend_),
      camera_(ctx.scene.camera, ctx.scene.film) {
  const Scene& scene = ctx.scene;
  buildTables(scene, params_, stats, tables_);
  tablesS_ = secondsSince(start_);

  const Film film(scene.film);
  // Before the fill, not after it (final_pass_memory.h).
  checkFinalPassMemory(film.width(), spp_);
  Vec3 lo, hi;
  finiteSceneBounds(scene, lo, hi);
  engine_ = std::make_unique<CacheEngine>(ctx, backend_, params_, tables_, camera_, settings_.maxDepth,
                                          settings_.rrDepth, lo, hi);
  primaries_ = std::make_unique<PrimaryHits>(ctx, *engine_, camera_, settings_.maxDepth, settings_.hideEmitters);
  run_.reset(new RcacheRun{ctx, backend_, files_, params_, tables_, camera_, *engine_, *primaries_, film.width(),
                           film.height(), spp_, scene.sampler.seed + ctx.options.seed, usesLowDiscrepancy(ctx)});

  // Phase 0: a pilot decides whether the cache can pay here at all (cache/path_fallback.h).
  chooseTechnique(lo, hi);
  if (fallback_.pathTrace) {
    pathIntegrator_ = makePathIntegrator(settings_);
    pathPasses_ = pathIntegrator_->beginPasses(ctx, stats);
    return;
  }
  if (!files_.load.empty())
    recordsLoaded_ = loadCachesInto(*engine_, files_.load, cacheKeyOf(scene, settings_, params_, *engine_),
                                    params_.worldFrame, backend_);
  // Loaded records too coarse for this view are passed over (cache/view_refinement.h).
  if (recordsLoaded_ > 0) recordsSkipped_ = skipCoarseRecords(*engine_, params_);
  // --cache-reuse (walk-throughs, distributed fills): the loaded records stay as they are and the
  // fill adds records only where this view finds none.
  if (files_.load.empty() || files_.reuse) fill_ = fillCache(*run_);
}

// lobe_split=auto: the share pilot's verdict without the split is the default (the split loses at
// equal time where the fill does not pay, bench/RESULTS.md); the cost pilot may choose the split,
// rcache or the path tracer instead, among the variants whose pilot fits its budget.
void RcachePasses::chooseTechnique(const Vec3& lo, const Vec3& hi) {
  using Mode = RcacheParams::LobeSplitMode;
  const bool anySplit = params_.lobeSplit != Mode::Off && tables_.anyLobeSplit();
  engine_->setLobeSplit(params_.lobeSplit == Mode::On);
  fallback_ = decideFallback(*run_);
  FallbackDecision withSplit;
  if (params_.lobeSplit == Mode::Auto && anySplit) {
    engine_->setLobeSplit(true);
    withSplit = decideFallback(*run_);
    engine_->setLobeSplit(false);
  }
  if (!params_.costPilot || fallback_.pilotPoints == 0) return;
  std::vector<CandidateKind> kinds;
  if (!fallback_.pathTrace)
    kinds.push_back(params_.lobeSplit == Mode::On && anySplit ? CandidateKind::RcacheLobeSplit : CandidateKind::Rcache);
  if (withSplit.pilotPoints > 0 && !withSplit.pathTrace) kinds.push_back(CandidateKind::RcacheLobeSplit);
  if (kinds.empty()) return;
  cost_ = runCostPilot({ctx_, settings_, params_, tables_, backend_, lo, hi, spp_, run_->seed, run_->lowDiscrepancy,
                        kinds});
  if (!cost_.skipped.empty() && cost_.choice.candidates.size() < 2) {
    // No variant's pilot fit its budget: whether the fill can pay at all, predicted (cache/fill_payoff.h).
    if (fallback_.pathTrace || fallback_.coherencePoints == 0) return;
    payoff_ = measureFillPayoff(*run_, settings_, fallback_);
    if (!payoff_.pays) {
      fallback_.pathTrace = true;
      fallback_.reason = payoff_.reason + " (" + fallback_.reason + ")";
    }
    return;
  }
  // Not run (small image, crop window) or interrupted: the share pilot's verdict stands.
  if (!cost_.ran || cost_.choice.candidates.size() < 2) return;
  const CandidateKind chosen = cost_.choice.candidates[static_cast<size_t>(cost_.choice.chosen)].kind;
  if (chosen == CandidateKind::RcacheLobeSplit && params_.lobeSplit == Mode::Auto) {
    fallback_ = withSplit;
    engine_->setLobeSplit(true);
  }
  if (chosen == CandidateKind::PathTracer) {
    fallback_.pathTrace = true;
    fallback_.reason = "path traced by the cost pilot (" + fallback_.reason + ")";
  } else {
    fallback_.pathTrace = false;
  }
}

bool RcachePasses::addPass(Film& film, int firstSample) {
  if (pathPasses_) return pathPasses_->addPass(film, firstSample);
  if (fill_.interrupted) return false;
  const auto passStart = SteadyClock::now();
  const PhaseCpuMeter cpu;
  bool interrupted = false;
  AdaptivePixels adaptive(run_->width, run_->height, spp_, ctx_.options.adaptive, firstSample);
  FinalPass pass(*run_, aovs_, film, adaptive);
  pass.shadeBands(interrupted);
  const std::unique_ptr<Film> adaptiveFilm = runAdaptiveRounds(*run_, pass, adaptive, film, interrupted);
  pass.mergeBands();
  if (adaptiveFilm) film.add(*adaptiveFilm);
  totals_.add(pass, adaptive);
  totals_.cpu.add(cpu.elapsed());
  finalS_ += secondsSince(passStart);
  return !interrupted;
}

Image RcachePasses::finish(const Film& film, int passes, bool stopped, RenderStats& stats) {
  if (pathPasses_) {
    Image img = pathPasses_->finish(film, passes, stopped, stats);
    reportFallback(fallback_, stats);
    reportCostPilot(cost_, stats);
    reportFillPayoff(payoff_, stats);
    return img;
  }
  Image img = film.develop();
  if (aovs_.records) addRecordsAov(*engine_, img);
  // A stopped render's caches lack what its unfinished phases would have added.
  stopped |= fill_.interrupted;
  if (!files_.save.empty() && !stopped) {
    // A failed save (full disk) must not lose the image: the CLI writes it, then reports this.
    try {
      saveCaches(*engine_, files_.save, cacheKeyOf(ctx_.scene, settings_, params_, *engine_));
    } catch (const Error& e) {
      stats.setText("cache_save_error", e.what());
    }
  }
  reportRcacheStats(*run_, {secondsSince(start_), tablesS_, finalS_, fill_, totals_, recordsLoaded_, stopped},
                    stats);
  reportFallback(fallback_, stats);
  reportCostPilot(cost_, stats);
  reportFillPayoff(payoff_, stats);
  if (recordsLoaded_ > 0) stats.set("records_too_coarse", double(recordsSkipped_));
  return img;
}

}  // namespace

RcacheIntegrator::RcacheIntegrator(const IntegratorSettings& s) : settings_(s), params_(paramsOf(s)) {}

std::unique_ptr<PassRender> RcacheIntegrator::beginPasses(const RenderContext& ctx, RenderStats& stats) {
  return std::make_unique<RcachePasses>(ctx, settings_, params_, backend_, files_, stats);
}

std::unique_ptr<Integrator> makeRcacheIntegrator(const IntegratorSettings& settings) {
  return std::make_unique<RcacheIntegrator>(settings);
}

}  // namespace rc
