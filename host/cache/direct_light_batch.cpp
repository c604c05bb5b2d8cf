#include "cache/direct_light_batch.h"

#include <algorithm>

#include "render/light_sampler.h"

namespace rc {

void directLightBatch(std::vector<DirectLightJob>& jobs, Color* out, DirectLightScratch& s) {
  s.shadowRays.clear();
  s.shadowValue.clear();
  s.shadowOwner.clear();
  s.bsdfRays.clear();
  s.bsdfWeight.clear();
  s.bsdfOwner.clear();
  s.bsdfPdf.clear();
  s.bsdfDelta.clear();
  const Accel* accel = nullptr;
  // The draws in the scalar order: the light samples (3 numbers each), then the BSDF sample's 3.
  for (size_t i = 0; i < jobs.size(); ++i) {
    DirectLightJob& j = jobs[i];
    accel = &j.lights->accel;
    const bool lightOnly = j.estimator == DirectEstimator::LightOnly;
    const int n = lightOnly ? 1 : std::max(1, j.lightSamples);
    for (int k = 0; k < n; ++k)
      if (const auto light = lightSampleUnshadowed(*j.lights, *j.hit, j.frame, j.wo, *j.bsdf, j.rng, lightOnly ? 0 : n)) {
        s.shadowRays.push_back(light->shadow);
        s.shadowValue.push_back(light->value);
        s.shadowOwner.push_back(static_cast<uint32_t>(i));
      }
    if (j.estimator != DirectEstimator::Full) continue;
    const Vec2 u = j.rng.next2D();
    const float uLobe = j.rng.nextFloat();
    // Black lights (all of the environment in the records): the BSDF ray could find no emission.
    if (!j.lights->lights.emitsLight()) continue;
    const std::optional<BsdfSample> bs = j.bsdf->sample(j.wo, uLobe, u);
    if (!bs || maxComponent(bs->weight) <= 0.0f) continue;
    s.bsdfRays.push_back(Accel::spawnRay(*j.hit, j.frame.toWorld(bs->wi)));
    s.bsdfWeight.push_back(bs->weight);
    s.bsdfPdf.push_back(bs->pdf);
    s.bsdfDelta.push_back((bs->lobe & kLobeDelta) ? 1 : 0);
    s.bsdfOwner.push_back(static_cast<uint32_t>(i));
  }
  std::fill(out, out + jobs.size(), Color(0.0f));
  if (!accel) return;
  s.blocked.resize(s.shadowRays.size());
  accel->occludedBatch(s.shadowRays.data(), s.blocked.data(), s.shadowRays.size(), BatchQuery::Packet16);
  s.bsdfHits.resize(s.bsdfRays.size());
  accel->intersectBatch(s.bsdfRays.data(), s.bsdfHits.data(), s.bsdfRays.size(), BatchQuery::Packet16);
  // Summed per point in light-sample order, averaged, then the BSDF sample's MIS-weighted
  // emission added: lightStrategyMis's and directLight's order of operations.
  for (size_t k = 0; k < s.shadowRays.size(); ++k)
    if (!s.blocked[k]) out[s.shadowOwner[k]] += s.shadowValue[k];
  for (size_t i = 0; i < jobs.size(); ++i) {
    const int n = jobs[i].estimator == DirectEstimator::LightOnly ? 1 : std::max(1, jobs[i].lightSamples);
    if (n > 1) out[i] /= static_cast<float>(n);
  }
  for (size_t k = 0; k < s.bsdfRays.size(); ++k) {
    const DirectLightJob& j = jobs[s.bsdfOwner[k]];
    const Color Le = emitterMis(*j.lights, j.hit->p, s.bsdfRays[k].d, s.bsdfHits[k], s.bsdfPdf[k], s.bsdfDelta[k] != 0,
                                j.lightSamples);
    out[s.bsdfOwner[k]] += s.bsdfWeight[k] * Le;
  }
}

}  // namespace rc
