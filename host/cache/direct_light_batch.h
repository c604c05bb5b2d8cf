#pragma once
// Direct light of a run of secondary shade points (record-ray hits, path continuations) with
// their shadow rays and BSDF rays traced as Embree packets (issue 16: the fill on the batched
// core). Each point names the estimator of render/direct_light.h it takes; the result equals that
// scalar function's, bit for bit, whenever the batched queries answer as the single-ray ones
// (same draws from the point's RNG, same additions in the same order).
#include <cstdint>
#include <deque>
#include <vector>

#include "render/direct_light.h"

namespace rc {

enum class DirectEstimator {
  LightOnly,      // directLightLightOnly
  LightStrategy,  // lightStrategyMis(…, lightSamples)
  Full,           // directLight(…, lightSamples)
};

struct DirectLightJob {
  const RenderContext* lights;
  const Hit* hit;
  Frame frame;
  Vec3 wo;
  const Bsdf* bsdf;
  Rng rng;
  DirectEstimator estimator;
  int lightSamples;
};

// Reused between calls (no allocation once sized).
struct DirectLightScratch {
  std::vector<Ray> shadowRays, bsdfRays;
  std::vector<uint8_t> blocked;
  std::vector<Hit> bsdfHits;
  std::vector<Color> shadowValue, bsdfWeight;
  std::vector<uint32_t> shadowOwner, bsdfOwner;
  std::vector<float> bsdfPdf;
  std::vector<uint8_t> bsdfDelta;
};

// out[i] = the direct light of jobs[i] (the RNGs advance as the scalar functions' would).
void directLightBatch(std::vector<DirectLightJob>& jobs, Color* out, DirectLightScratch& scratch);

// One parallel task's batch: its jobs, the caller's index of each, the BSDFs the jobs point at
// (spatially varying ones made per point, Bsdf::at; a deque keeps them in place as it grows) and
// the results. Kept per thread and reused, so a batch allocates nothing once sized.
struct DirectLightChunk {
  std::vector<DirectLightJob> jobs;
  std::vector<uint32_t> owner;
  std::deque<BsdfPtr> holders;
  std::vector<Color> L;
  DirectLightScratch scratch;

  void clear() {
    jobs.clear();
    owner.clear();
    holders.clear();
  }
  // L[k] = the direct light of jobs[k].
  void run() {
    L.resize(jobs.size());
    directLightBatch(jobs, L.data(), scratch);
  }
};

}  // namespace rc
