#pragma once
// Direct light of a run of secondary shade points (record-ray hits, path continuations) with
// their shadow rays and BSDF rays traced as Embree packets (issue 16: the fill on the batched
// core). Each point names the estimator of render/direct_light.h it takes; the result equals that
// scalar function's, bit for bit, whenever the batched queries answer as the single-ray ones
// (same draws from the point's RNG, same additions in the same order).
#include <cstdint>
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

}  // namespace rc
