#pragma once
// The share pilot's second question (cache/path_fallback.h): can a record serve more than its own
// pixel? The share pilot only asks whether records would serve a point's light; on geometry finer
// than a pixel (bricks, studs and bevels of a 2 M-triangle model, bench/RESULTS.md "records denser
// than pixels") every pixel holds several normal directions, a record serves none of its
// neighbours (the normal term of the interpolation criterion), and the fill makes records denser
// than pixels at ~1000 rays each.
//
// The test, deterministic: at every pilot point whose own material is cached, a second camera ray
// δ = r_min/3 pixels away (half a pixel at the base budget; it shrinks with r_min as the budget
// shrinks every radius) in a hashed direction, and whether a level-0 record at the first hit with
// the floor radius (a·R = r_min footprints) serves the second hit: same cache, contributionWeight
// on geometric normals, as the fill's lookups do. q is the share of such neighbours served.
//
// Threshold, from cost: sharing is the cache's only gain. A record that serves m pixels spends its
// S rays (and about as many again shading their hits) on an S-ray estimate of those pixels' first
// bounce; the path tracer, for the same rays, gives each of the m pixels S/m samples of about the
// same cost each, so at equal rays the record's error is lower only for m > 1, and the batched
// final pass's overhead o over the path tracer (cache/path_fallback.h: 0.3–0.8 measured; 0.3 as
// fallback_share takes it, the lenient end) raises that to m > 1 + o = 1.3 pixels. Where a record
// serves a patch of radius ρ (in pixels) around a uniform point of it, a step of δ in a random
// direction leaves the patch with probability 2δ/(πρ) (Crofton: the patch's perimeter over π
// times its area, times δ; a strip of width ρ gives the same), so q = 1 − 2δ/(πρ), and πρ² ≥ 1.3
// means q ≥ 1 − 2δ/√(1.3π) ≈ 0.505 at δ = ½ px. At other budgets r_min, δ and the record's rays
// change together so that the fill costs per pixel what the final pass does (budget_params.h):
// the same q holds. The cost pilot (cache/cost_pilot.h), where it runs, then judges the images
// that pass with measured timings.
//
// A small image must not flip on noise: the pilot path traces only when the upper end of a
// 3-sigma Wilson interval of q is below the threshold: 9 tested points with no neighbour served,
// 25 at q̂ = 0.2, 54 at q̂ = 0.3.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cache/path_fallback.h"
#include "cache/primary_hits.h"
#include "cache/rcache_run.h"
#include "core/math.h"

namespace rc {

// The neighbour's distance as a fraction of r_min (pixels).
constexpr float kNeighbourOffsetOfFloor = 1.0f / 3.0f;
// 1 + o: the pixels a record must serve to beat the path tracer at equal rays (above).
constexpr double kMinPixelsPerRecord = 1.0 + kFinalPassOverhead;
// The q of a record serving kMinPixelsPerRecord pixels, at δ = ½ px (above): 1 − 2δ/√(π·1.3).
inline double minNeighbourServed() { return 1.0 - 1.0 / std::sqrt(kPiD * kMinPixelsPerRecord); }
// z of the one-sided bound on q the decision uses.
constexpr double kCoherenceBoundZ = 3.0;

struct RecordCoherence {
  size_t points = 0;  // pilot points whose own material is cached (the tested ones)
  size_t served = 0;  // whose neighbour a floor record at the point serves
  float offsetPx = 0.0f;  // δ
  double share() const { return points > 0 ? double(served) / double(points) : 1.0; }
  // Upper end of the Wilson score interval of q at kCoherenceBoundZ (1 with no points).
  double upperBound() const;
  // Records could not serve their neighbours: the upper bound of q is below minNeighbourServed().
  bool tooIncoherent() const { return points > 0 && upperBound() < minNeighbourServed(); }
};

// The test above over the pilot's primaries `prim` (traced from filmPos with seeds), at the points
// where `tested` is non-zero.
RecordCoherence measureRecordCoherence(const RcacheRun& run, const std::vector<Vec2>& filmPos,
                                       const std::vector<uint64_t>& seeds, const std::vector<Primary>& prim,
                                       const std::vector<char>& tested);

}  // namespace rc
