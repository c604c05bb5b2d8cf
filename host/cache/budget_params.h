#pragma once
// The cache's quality follows the sample budget. A record's error does not fall with pixel
// samples: the noise of its hemisphere estimate (interpolated into blotches) and the error of
// interpolating between records are fixed once the records are made, an error floor that more spp
// cannot remove. So, as progressive photon mapping lets its kernel's variance and bias fall
// together with the photon count (Hachisuka et al. 2008; Knaus and Zwicker 2011, whose radius
// shrinks as a power of the pass count), both follow the spp here:
// - rays per record grow as √(spp/16): a record's variance falls as 1/rays, so the cached noise
//   falls at least half as fast (in relMSE) as the pixel noise, which is what "the error at 4×
//   the spp at most half the error at 1×" (issue 17) asks of the whole image;
// - the influence radii (a, r_min, r_max, so every level's records) shrink as (spp/16)^(-1/4),
//   the radius of Knaus and Zwicker's α = 1/2: the interpolation error (at high spp most of what
//   is left, bench/RESULTS.md "The cache follows the budget") falls with the radius, and the
//   records' noise, averaged over fewer neighbours, still falls because the rays grow.
// The fill then costs rays/r² ∝ spp, as the final pass does: the cache's share of the time stays
// about constant as the budget grows, up to kBudgetMaxSpp (below). Below 16 spp the same laws
// run the other way, down to 1 spp (a quarter of the rays, twice the radii): a fill sized for 16
// spp costs there many times the final pass, while the error the final pass leaves at those few
// samples is far above what the coarser records add (bench/RESULTS.md "The loose end of the
// error ladder"), so the path tracer, paying no fill, was ahead at the loose end of the ladder. Only the values not given on the
// command line or in the file follow the budget (RcacheParams::follow); a given one is used as
// given.
#include "cache/cache_params.h"

namespace rc {

// The budget the base values (RcacheParams' defaults) are meant for.
constexpr int kBudgetBaseSpp = 16;
// The smallest budget the values follow (the fewest samples a render has): a quarter of the base
// rays, twice the base radii.
constexpr int kBudgetMinSpp = 1;
// The course notes' upper end of rays per record; the growth stops there.
constexpr int kBudgetMaxRays = 8192;
// The budget beyond which nothing grows further: there the primary rays reach kBudgetMaxRays and
// the radii a quarter of the base (r_min 0.375 px); finer records would multiply the cache's
// memory (∝ 1/r²) without bound as the spp grows.
constexpr int kBudgetMaxSpp = 4096;

// Rays per record for `spp` samples per pixel: base·√(spp / kBudgetBaseSpp) (spp clamped to
// [kBudgetMinSpp, kBudgetMaxSpp]: a quarter of the base at the least), and above the base at
// most kBudgetMaxRays (a base above that cap is not lowered for a large budget).
int budgetRays(int base, int spp);

// The factor of the influence radii for `spp`: (spp / kBudgetBaseSpp)^(-1/4), between 1/4 and 2
// (spp clamped to [kBudgetMinSpp, kBudgetMaxSpp]).
float budgetRadiusScale(int spp);

// `params` with the values that follow the budget set for a render of `spp` samples per pixel.
RcacheParams paramsForBudget(const RcacheParams& params, int spp);

}  // namespace rc
