#pragma once
// The cost-aware pilot: which technique renders this image to the path tracer's error soonest —
// the path tracer, rcache, or rcache with the lobe split (Technique::LobeSplit) — measured, not
// guessed. After the share pilot (cache/path_fallback.h) has found that records would serve
// enough of the image, each candidate renders the image at a reduced resolution (about 1/64 of
// the pixels, between 24² and 48²) with its own fill and final pass, and the pilot reads from
// those renders and their timings:
//   V  the variance of one sample per pixel, as relMSE × spp between two renders with independent
//      samples (rcache: two final passes over one cache);
//   B  rcache's floor: the error more final-pass samples leave (the records' own noise), as the
//      relMSE between renders over two independently filled caches, less the final passes' part;
//   F  the image's fill: records grow with the pixels as pixels^γ (γ = 1 where the pixel clamps
//      r_min/r_max bound every record, 0 where the scene's geometry does, about ½ for records
//      along edges), and a fill costs a fixed part plus a part per record; γ and both parts come
//      from a third fill at a quarter of the pilot's pixels; t the seconds per sample per pixel,
//      scaled by the ratio of the image's pixels to the pilot's.
// The pilot itself is held to 5 % of the path tracer's predicted render time: a candidate whose
// pilot would not fit is not tried (and not chosen); where none is tried, the caller asks
// cache/fill_payoff.h whether the fill can pay at all.
// The target is the path tracer's error at the user's spp N, E* = V_path / N; a candidate needs
// N_c = V_c / (E* − B_c) samples per pixel to reach it (none when B_c ≥ E*) and F_c + t_c·N_c
// seconds. The fastest is chosen; the path tracer costs t_path·N. Assumed, not measured: relMSE
// per pixel and seconds per sample per pixel do not depend on the resolution, so what 1/64 of the
// pixels shows holds for the image. Images below
// 16 × 24² pixels are not piloted this way (the pilot would cost about as much as the render), nor
// crop windows (its choice follows timings, and the tiles of one image must choose alike).
#include <string>
#include <vector>

#include "brdf/material_plan.h"
#include "cache/cache_params.h"
#include "core/math.h"
#include "render/integrator.h"
#include "scene/scene.h"

namespace rc {

class ShBackend;

enum class CandidateKind { PathTracer, Rcache, RcacheLobeSplit };
const char* candidateName(CandidateKind k);  // "path tracer", "rcache", "rcache + lobe split"

struct TechniqueEstimate {
  CandidateKind kind = CandidateKind::PathTracer;
  double variance = 0.0;  // V: relMSE of one sample per pixel
  double floor = 0.0;     // B: error that more samples do not remove (0 for the path tracer)
  double fixedS = 0.0;    // F: seconds before the first sample (the fill), at the image's size
  double perSppS = 0.0;   // t: seconds per sample per pixel, at the image's size
  double sppToTarget = 0.0;       // N_c (INFINITY: the floor is above the target)
  double secondsToTarget = 0.0;   // F + t·N_c (INFINITY: cannot reach it)
};

struct CostChoice {
  std::vector<TechniqueEstimate> candidates;
  int chosen = -1;             // index into candidates; -1: no decision
  double targetError = 0.0;    // E*
};

// The choice for `spp` samples per pixel among candidates whose first is the path tracer:
// fills sppToTarget/secondsToTarget and picks the fastest (the path tracer on ties).
CostChoice chooseByCost(std::vector<TechniqueEstimate> candidates, int spp);

struct CostPilotInputs {
  const RenderContext& ctx;
  const IntegratorSettings& settings;
  const RcacheParams& params;
  const BrdfTableSet& tables;
  ShBackend& backend;
  Vec3 sceneLo, sceneHi;
  int spp = 0;
  uint64_t seed = 0;
  bool lowDiscrepancy = false;
  std::vector<CandidateKind> rcacheCandidates;  // which rcache variants to try
};

struct CostPilotReport {
  bool ran = false;
  CostChoice choice;
  int pilotWidth = 0, pilotHeight = 0, pilotSpp = 0;
  double seconds = 0.0;  // the pilot's own cost
  // Not tried: their pilot would not fit its budget (all of them, with ran false, where that was
  // known before the path tracer's pilot images).
  std::vector<CandidateKind> skipped;
  std::string reason;    // why it did not run, or the decision
  std::string json() const;  // the candidates' estimates, for --stats
};

CostPilotReport runCostPilot(const CostPilotInputs& in);

// Statistics: cost_pilot (the decision or why there was none), and where it ran
// cost_pilot_candidates (JSON: each candidate's V, B, F, t and predicted time), cost_pilot_target_relmse,
// cost_pilot_s, cost_pilot_film.
void reportCostPilot(const CostPilotReport& report, RenderStats& stats);

}  // namespace rc
