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
// Threshold, from cost: sharing is the cache's only gain. A record that serves one pixel spends its
// ~1000 rays on an S-ray estimate of that pixel's first bounce, which the path tracer buys for the
// same rays at no interpolation error; so a record must serve at least the area of one pixel (at
// the base budget 1/(π·1.5²) of its floor disk, the same fraction at every budget) for the cache to
// be able to win. Where a record serves a patch of radius ρ (in pixels) around a uniform point of
// it, a step of δ in a random direction leaves the patch with probability 2δ/(πρ) (Crofton: the
// patch's perimeter over π times its area, times δ; a strip of width ρ gives the same), so
// q = 1 − 2δ/(πρ), and ρ ≥ 1/√π pixels (a patch of one pixel) means q ≥ 1 − 2δ√π/π = 1 − 1/√π
// ≈ 0.436 at δ = ½ px. The cost pilot (cache/cost_pilot.h), where it runs, then judges the
// images that pass with measured timings.
//
// A small image must not flip on noise: the pilot path traces only when the upper end of a
// 3-sigma Wilson interval of q is below the threshold: 12 tested points with no neighbour served,
// 40 at q̂ = 0.2, 120 at q̂ = 0.3.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cache/primary_hits.h"
#include "cache/rcache_run.h"

namespace rc {

// The neighbour's distance as a fraction of r_min (pixels).
constexpr float kNeighbourOffsetOfFloor = 1.0f / 3.0f;
// 1 − 1/√π: below it a floor record serves less than one pixel's area (above).
constexpr double kMinNeighbourServed = 0.4358104164;
// z of the one-sided bound on q the decision uses.
constexpr double kCoherenceBoundZ = 3.0;

struct RecordCoherence {
  size_t points = 0;  // pilot points whose own material is cached (the tested ones)
  size_t served = 0;  // whose neighbour a floor record at the point serves
  float offsetPx = 0.0f;  // δ
  double share() const { return points > 0 ? double(served) / double(points) : 1.0; }
  // Upper end of the Wilson score interval of q at kCoherenceBoundZ (1 with no points).
  double upperBound() const;
  // Records could not serve their neighbours: the upper bound of q is below kMinNeighbourServed.
  bool tooIncoherent() const { return points > 0 && upperBound() < kMinNeighbourServed; }
};

// The test above over the pilot's primaries `prim` (traced from filmPos with seeds), at the points
// where `tested` is non-zero.
RecordCoherence measureRecordCoherence(const RcacheRun& run, const std::vector<Vec2>& filmPos,
                                       const std::vector<uint64_t>& seeds, const std::vector<Primary>& prim,
                                       const std::vector<char>& tested);

}  // namespace rc
