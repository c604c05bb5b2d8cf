#pragma once
// The radiance-caching integrator (`--integrator rcache`; docs/ARCHITECTURE.md §Pipeline): direct
// light exact (the path tracer's NEE with MIS), indirect light on diffuse/glossy surfaces
// interpolated from caches of incoming-radiance records (SH coefficients + translational
// gradients), filled coarse-to-fine over the image in batches; sharp/delta materials
// importance-sampled into the caches.
//
// Parameters (<integrator type="rcache">, or -D name=value; read in cache/cache_params.cpp with
// their ranges; max_depth, rr_depth, hide_emitters as for path, scene/integrator_params.h).
// Defaults come from the literature, not from the shipped scenes; measurements behind them are in
// bench/RESULTS.md.
// The values marked † are those for up to 16 spp: unless given, they follow the sample budget
// above it (cache/budget_params.h) — rays ×√(spp/16) (at most 8192), a, rmin, rmax
// ×(spp/16)^(-1/4), spp counted up to 4096 — so the records' noise and interpolation error fall
// with the spp instead of flooring the error.
// A given value is used as given at every spp; follow_budget=false keeps all of them at their
// base values (records independent of the spp: e.g. to time the final pass alone).
//   follow_budget true  the † values follow the sample budget
//   a            0.4 †  accuracy of primary-hit caches (Ward's a; Křivánek 2005 uses 0.1–0.5)
//   rays         512 †  hemisphere rays per record (M×N, N = 4M; the course notes use 500–8000;
//                       0 = the default, following the budget)
//   order        0      SH order of glossy records (0 = the per-material order the BRDF plan chose)
//   weber        0.025  adaptive caching threshold: relative luminance difference (Weber law, 2–3 %)
//   adaptive     false  shrink a_i where overlapping records disagree (EGSR 2006). Off by default:
//                       with a few hundred rays per record the 2.5 % test mostly fires on the
//                       records' own noise, so it multiplies records and fill time for no lower
//                       error at equal time (bench/RESULTS.md "Defaults")
//   min_a_scale  0.125  adaptive caching never shrinks a_i below a·min_a_scale
//   gradients    true   translational gradients in records and interpolation
//   rmin, rmax   1.5, 10 †  bounds of a record's influence radius a·R_i, in pixel footprints at the
//                       record (secondary caches: × secondary_a_scale^level). Tabellion–Lamorlette
//                       clamp R_i to [3, 20] px under a weight whose influence radius is R_i/2,
//                       i.e. [1.5, 10] px of influence; [3, 20] applied to R_i under Ward's weight
//                       (influence a·R_i) would let records shrink to 0.9 px at a = 0.3
//   secondary_a_scale 2 a at secondary hits = a·2^level (coarser caches at deeper bounces)
//   secondary_rays  256 † rays per record at secondary levels (level ≥ 1; 0 = the default)
//   secondary_order 8   SH order cap of glossy records at secondary levels (0 = none): 256 rays
//                       estimate 144 order-12 coefficients poorly, and an order-12 rotation per
//                       secondary lookup would dominate the fill, for no visible gain at a bounce
//                       already blurred by the primary lookup
//   cache_depth  2      cache levels (bounces served by caches); deeper bounces are path traced
//   frame        auto   interpolation frame: auto (per point: record frames where every contributing
//                       record differs from the point's frame by a z-rotation only, as on any flat
//                       surface, else world frame) | world (records stored world-aligned) | record
//   mode         radiance  radiance | tl (Tabellion–Lamorlette dominant-direction approximation)
//   batch        256    records sampled and projected together
//   share_pixel  true   samples of one pixel on the same surface share a cache lookup, in groups of
//                       ⌈√spp⌉ samples (one lookup per pixel would be an error floor; final_pass.cpp)
//   light_samples 1     light samples per pixel sample for the final pass's direct light (one BSDF
//                       sample beside them, MIS-weighted for the count); more buys about what more
//                       spp would, at a similar ray cost
//   env_cache    true   records carry the smooth part of the environment light (constant, envmap)
//                       and only its compact bright residual is light-sampled per pixel sample
//                       (cache/light_split.h); false: all of it light-sampled
//   env_variance 0.333  κ of that split: the cached part's variance over any hemisphere stays
//                       ≤ κ·(brightest hemisphere's mean)² (1/3: a diffuse record's own cosine
//                       weight under a uniform sky)
//   area_cache   false  records also carry the emission of the area lights their rays hit, and
//                       cached points no longer light-sample those (off: measured not to pay,
//                       bench/RESULTS.md "Environment light in the cache")
//   fallback     true   a pilot decides before the fill whether the cache can pay; if it would
//                       serve less than fallback_share of the image, or its records could not
//                       serve their neighbours (cache/record_coherence.h), the image is path traced
//   fallback_share 0.25 that threshold (cache/path_fallback.h says why 0.25)
//   cost_pilot   false  where the share pilot caches, a cost pilot at ~1/64 of the pixels chooses
//                       the fastest of path tracer, rcache and rcache + lobe split to the path
//                       tracer's error at the requested spp (cache/cost_pilot.h); off by default:
//                       a choice from timings is not reproducible run to run
//   cost_pilot_share 0.05 the cost pilot's budget: a candidate is tried only while the pilot's time
//                       stays below this share of the path tracer's predicted render; with none
//                       tried, the fill's predicted payoff decides (cache/fill_payoff.h)
//   lobe_split   auto   layered materials' base from records, coat sampled (Technique::LobeSplit):
//                       auto = the cost pilot may choose it (off where it does not
//                       run or tries no variant) | true | false
//
// Besides the parameters it takes its own options (cache/rcache_options.h) and the SH backend
// (--device), set by the CLI after the registry made it.
#include <memory>

#include "cache/cache_params.h"
#include "cache/rcache_options.h"
#include "render/integrator.h"
#include "scene/scene.h"

namespace rc {

class ShBackend;  // cl/sh_backend.h

class RcacheIntegrator : public Integrator {
 public:
  // Reads the parameters from settings.props; throws rc::Error naming a parameter with an invalid
  // value (the registry, app/integrator_registry.h, adds the location and reports unused ones).
  explicit RcacheIntegrator(const IntegratorSettings& settings);
  std::string name() const override { return "rcache"; }
  std::unique_ptr<PassRender> beginPasses(const RenderContext& ctx, RenderStats& stats) override;

  // Batched SH math for the records (owned by the caller, outliving the renders); null: the scalar
  // references, made per render.
  void setBackend(ShBackend* backend) { backend_ = backend; }
  void setCacheFiles(const CacheFiles& files) { files_ = files; }
  const CacheFiles& cacheFiles() const { return files_; }

 private:
  IntegratorSettings settings_;
  RcacheParams params_;
  ShBackend* backend_ = nullptr;
  CacheFiles files_;
};

std::unique_ptr<Integrator> makeRcacheIntegrator(const IntegratorSettings& settings);

}  // namespace rc
