#pragma once
// Phase 0 of an rcache render (docs/ARCHITECTURE.md §Pipeline): whether caching can pay at all,
// measured before any record is made. A pilot traces the camera rays of a sparse grid of pixel
// centres (about kPilotPoints, over the whole sensor even when a crop window is rendered, so a tile
// decides as the full image does) and one BSDF continuation below each point rendered by importance
// sampling; a point counts as served by the cache when its own material is cached, or when its
// continuation lands on a cached material (its reflected light then comes from records); a
// lobe-split material counts for its base's share of the light it reflects. The
// cache only lowers the noise of that share s of the image, at a fill cost and a per-sample
// overhead o of the batched final pass over the path tracer, so at equal time it wins at most
// (1 − s + s·r)(1 + o) ≥ (1 − s)(1 + o) of the path tracer's error (r: its remaining error
// ratio on the served points): with o ≈ 0.3–0.8 (bench/RESULTS.md) it cannot win below
// s ≈ o / (1 + o) ≈ 0.25–0.45. Below fallback_share (0.25) the whole image is path traced by
// the path integrator (same max_depth, same estimator), and the statistics say so. Where the
// share passes, the coherence test (cache/record_coherence.h) asks whether a record can serve more
// than its own pixel; where it cannot (geometry finer than the pixels), the image is path traced
// too.
#include <cstddef>
#include <string>

#include "cache/rcache_run.h"

namespace rc {

// o: the batched final pass's overhead per sample over the path tracer, the lenient end of the
// 0.3–0.8 measured (bench/RESULTS.md), as fallback_share takes it.
constexpr double kFinalPassOverhead = 0.3;

struct FallbackDecision {
  bool pathTrace = false;
  double servedShare = 0.0;  // s: pilot points (with a surface hit) the cache would serve
  double lobeSplitShare = 0.0;  // the part of s served through lobe-split materials' bases
  size_t gridPoints = 0;     // pilot camera rays
  size_t pilotPoints = 0;    // pilot camera rays that hit a surface
  // The coherence test (cache/record_coherence.h), where the share passed: q, the upper end of its
  // interval, and the points it tested (own material cached).
  double neighbourServedShare = 0.0, neighbourServedBound = 0.0;
  size_t coherencePoints = 0;
  double neighbourOffsetPx = 0.0;  // δ
  std::string reason;        // for the statistics
};

// Never falls back when params.fallback is false, when a cache is loaded or is to be saved (the
// user asked for the cache itself), or when nothing is hit.
FallbackDecision decideFallback(const RcacheRun& run);

// Statistics: fallback (the decision and its figures), and where the pilot hit anything
// pilot_served_share and pilot_lobe_split_share; where the coherence test ran,
// pilot_neighbour_served_share (q), pilot_neighbour_served_bound (its upper end) and
// pilot_coherence_points.
void reportFallback(const FallbackDecision& d, RenderStats& stats);

}  // namespace rc
