#pragma once
// Parameters of the rcache integrator, read from <integrator type="rcache"> (IntegratorSettings::
// params; -D name=value overrides arrive there too). Defaults are chosen from the literature, not
// from the shipped scenes:
//   a            0.4    accuracy of primary-hit caches (Ward's a; Křivánek 2005 uses 0.1–0.5)
//   rays         512    hemisphere rays per record (M×N, N = 4M; the notes use 500–8000)
//   order        0      SH order override for glossy records (0 = the per-material order from brdf)
//   weber        0.025  adaptive caching threshold: relative luminance difference (Weber law, 2–3 %)
//   adaptive     false  shrink a_i where overlapping records disagree (EGSR 2006). Off by default:
//                       with a few hundred rays per record the 2.5 % Weber test mostly fires on
//                       the records' own noise (27 k shrinks on the 512² Cornell box), doubling
//                       the records and the fill time for no lower error at equal time
//                       (bench/RESULTS.md "Defaults"); on with adaptive=true.
//   min_a_scale  0.125  adaptive caching never shrinks a_i below a·min_a_scale
//   gradients    true   translational gradients in records and interpolation
//   rmin, rmax   1.5, 10  bounds of a record's influence radius a·R_i, in pixel footprints at the
//                       record (secondary caches: × secondary_a_scale^level). Tabellion–Lamorlette
//                       clamp R_i to [3, 20] px under a weight whose influence radius is R_i/2,
//                       i.e. [1.5, 10] px of influence; applying [3, 20] to R_i under Ward's weight
//                       (influence a·R_i) would let records shrink to 0.9 px at a = 0.3.
//   secondary_a_scale 2 a at secondary hits = a·2^level (coarser caches at deeper bounces)
//   secondary_rays  256 rays per record at secondary levels (level ≥ 1)
//   secondary_order 8   SH order cap of glossy records at secondary levels (0 = none): 256 rays
//                       estimate 144 order-12 coefficients poorly, and the order-12 rotation of
//                       every secondary lookup was the largest cost of the fill (24 % in perf);
//                       measured on cornell_glossy 128², 64 spp: fill 2.9 → 2.3 s, relMSE
//                       0.00061 → 0.00058 (no loss)
//   cache_depth  2      cache levels (bounces served by caches); deeper bounces are path traced
//   frame        auto   interpolation mode: auto (per point: record frames where every contributing
//                       record differs from the point's frame by a z-rotation only, as on any flat
//                       surface, else world frame) | world (records stored world-aligned) | record
//   mode         radiance  radiance | tl (Tabellion–Lamorlette dominant-direction approximation)
//   batch        256    records sampled and projected together
//   share_pixel  true   samples of one pixel on the same surface share one cache lookup
//   light_samples 1     light samples per pixel sample for the direct light of the final pass
//                       (one BSDF sample beside them, MIS-weighted for the count). Measured on the
//                       256² Cornell box, 16 spp, loaded cache: relMSE 0.00127 / 0.00102 / 0.00089
//                       for 1 / 2 / 4 with 2.8 / 3.6 / 5.1 M rays — about what more spp would buy,
//                       so 1 by default
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
//                       serve less than fallback_share of the image, the image is path traced
//   fallback_share 0.25 that threshold (cache/path_fallback.h says why 0.25)
#include <map>
#include <string>

namespace rc {

struct RcacheParams {
  float a = 0.4f;
  int rays = 512;
  int order = 0;
  float weber = 0.025f;
  bool adaptive = false;
  float minAScale = 0.125f;
  bool gradients = true;
  float rMinPx = 1.5f, rMaxPx = 10.0f;
  float secondaryAScale = 2.0f;
  int secondaryRays = 256;
  int secondaryOrder = 8;
  int cacheDepth = 2;
  bool worldFrame = true;
  bool autoFrame = true;
  bool tlMode = false;
  int batch = 256;
  bool sharePixel = true;
  int lightSamples = 1;
  bool envCache = true;
  float envVariance = 1.0f / 3.0f;
  bool areaCache = false;
  bool fallback = true;
  float fallbackShare = 0.25f;
};

// Throws rc::Error("rcache parameter 'x': ...") for an unknown name or a malformed value.
RcacheParams parseRcacheParams(const std::map<std::string, std::string>& params);

// True for a name parseRcacheParams understands (its own and the path integrator's shared ones).
// The CLI forwards a -D name=value to the integrator only for these names: the others are scene
// parameters ($res, $spp, ...), as in Mitsuba.
bool isIntegratorParamName(const std::string& name);

// M×N with N = 4M and M·N ≥ rays (M ≥ 2).
void hemisphereCells(int rays, int& M, int& N);

}  // namespace rc
