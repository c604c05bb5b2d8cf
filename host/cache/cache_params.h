#pragma once
// Parameters of the rcache integrator, read from <integrator type="rcache"> (IntegratorSettings::
// params; -D name=value overrides arrive there too). Defaults are chosen from the literature, not
// from the shipped scenes:
//   a            0.3    accuracy of primary-hit caches (Ward's a; Křivánek 2005 uses 0.1–0.5)
//   rays         1024   hemisphere rays per record (M×N, N = 4M; the notes use 500–8000)
//   order        0      SH order override for glossy records (0 = the per-material order from brdf)
//   weber        0.025  adaptive caching threshold: relative luminance difference (Weber law, 2–3 %)
//   adaptive     true   shrink a_i where overlapping records disagree (EGSR 2006)
//   min_a_scale  0.125  adaptive caching never shrinks a_i below a·min_a_scale
//   gradients    true   translational gradients in records and interpolation
//   rmin, rmax   3, 20  clamp of the record radius R_i, in pixel footprints at the record (T&L 2004)
//   secondary_a_scale 2 a at secondary hits = a·2^level (coarser caches at deeper bounces)
//   secondary_rays  256 rays per record at secondary levels (level ≥ 1)
//   cache_depth  2      cache levels (bounces served by caches); deeper bounces are path traced
//   frame        world  interpolation mode: world (records stored world-aligned) | record
//   mode         radiance  radiance | tl (Tabellion–Lamorlette dominant-direction approximation)
//   batch        256    records sampled and projected together
//   share_pixel  true   samples of one pixel on the same surface share one cache lookup
//   final_pass   true   false: stop after the cache fill (image = fill-pass estimate)
#include <map>
#include <string>

namespace rc {

struct RcacheParams {
  float a = 0.3f;
  int rays = 1024;
  int order = 0;
  float weber = 0.025f;
  bool adaptive = true;
  float minAScale = 0.125f;
  bool gradients = true;
  float rMinPx = 3.0f, rMaxPx = 20.0f;
  float secondaryAScale = 2.0f;
  int secondaryRays = 256;
  int cacheDepth = 2;
  bool worldFrame = true;
  bool tlMode = false;
  int batch = 256;
  bool sharePixel = true;
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
