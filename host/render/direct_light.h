#pragma once
// Direct illumination: next-event estimation with multiple importance sampling (light sampling +
// BSDF sampling, power heuristic). The path tracer and the radiance-cache integrator call the very
// same functions, so their direct light is the same estimator.
//
// The estimator is split in two so a caller that continues the path (the path tracer as Mitsuba's
// `path` does, rcache below importance-sampled surfaces) reuses its continuation ray for the BSDF
// strategy:
//   lightStrategyMis — light-sampling strategy, MIS-weighted against the BSDF pdf;
//   emitterMis       — what a BSDF-sampled ray that found `next` (or escaped) adds, MIS-weighted
//                      against the light pdf (weight 1 after a delta lobe).
// directLight() runs both (tracing its own BSDF ray) for callers that do not continue the path.
#include <optional>
#include <vector>

#include "bsdf/bsdf.h"
#include "core/frame.h"
#include "core/rng.h"
#include "geometry/accel.h"
#include "render/integrator.h"
#include "render/light_sampler.h"

namespace rc {

// Radiance emitted by an area emitter at `hit` toward direction wo (world, pointing away from the
// surface). Area emitters emit toward +ng only (Mitsuba 3).
Color emitted(const Scene& scene, const Hit& hit, const Vec3& wo);
// The same for an emitter list indexed like scene.emitters (a light sampler's, which may carry
// only part of the scene's light: emitterMis counts what the sampler's lights emit).
Color emitted(const std::vector<Emitter>& emitters, const Hit& hit, const Vec3& wo);

// Power heuristic (β = 2) weight of strategy a against b. Nested selects rather than early returns:
// the wave's vector pass (render/diffuse_shading.h) runs them as they are, scalar code still divides
// only where a > 0.
inline float powerHeuristic(float pdfA, float pdfB) {
  const float a = pdfA * pdfA, b = pdfB * pdfB;
  return a > 0.0f ? (std::isinf(a) ? 1.0f : a / (a + b)) : 0.0f;
}

// BSDF-sampling strategy's contribution once the sampled ray (from `from`, world direction `dirWorld`)
// found `next` (next.valid() false = escaped to the environment). `bsdfPdf` is the continuous pdf of
// the sample (ignored when `delta`). Returns the MIS-weighted emitted radiance (not multiplied by
// the sample's weight). The weight is the power heuristic of bsdfSamples·pdf_bsdf against
// lightSamples·pdf_light (Veach's multi-sample MIS: one of bsdfSamples BSDF samples beside
// lightSamples light samples; either count may be 0, which leaves the other technique weight 1).
Color emitterMis(const RenderContext& ctx, const Vec3& from, const Vec3& dirWorld, const Hit& next,
                 float bsdfPdf, bool delta, int lightSamples = 1, int bsdfSamples = 1);
// emitterMis of a ray that escaped, given what the environment sends along it (env, from
// LightSampler::environmentLookup or environmentLookups).
Color environmentMis(const LightSampler::EnvironmentLookup& env, float bsdfPdf, bool delta, int lightSamples = 1,
                     int bsdfSamples = 1);

// The light-sampling half of directLight: `lightSamples` light samples (one shadow ray each)
// averaged, MIS-weighted (power heuristic on lightSamples·pdf_light vs bsdfSamples·pdf_bsdf, Veach's
// multi-sample MIS) against the BSDF samples that the caller traces itself — the path tracer's and
// rcache's path continuation (one), Mitsuba's `direct` (bsdf_samples, 0 = light sampling alone) —
// and weights with emitterMis(…, lightSamples, bsdfSamples). Consumes 3·lightSamples numbers.
Color lightStrategyMis(const RenderContext& ctx, const Hit& hit, const Frame& frame, const Vec3& woLocal,
                       const Bsdf& bsdf, Rng& rng, int lightSamples, int bsdfSamples = 1);

// One light sample (MIS-weighted as one of misLightSamples beside misBsdfSamples BSDF samples;
// either 0 = light sampling alone, weight 1) before its shadow ray is traced: `value` counts only
// when `shadow` is unoccluded. Empty when the sample carries nothing (no ray needed). Consumes 3
// numbers. Lets a batched caller trace the shadow rays of many vertices in one occlusion query.
struct UnshadowedLight {
  Ray shadow;
  Color value{0.0f};
};
std::optional<UnshadowedLight> lightSampleUnshadowed(const RenderContext& ctx, const Hit& hit, const Frame& frame,
                                                     const Vec3& woLocal, const Bsdf& bsdf, Rng& rng,
                                                     int misLightSamples, int misBsdfSamples = 1);

// lightStrategyMis over a batch of shading points, their shadow rays traced in one occlusion query
// (BatchQuery): out[i] = lightStrategyMis(ctx, points[i]…, rngs[i], lightSamples), bit for bit
// when the batched query answers as the single-ray one. For integrators that shade many points at
// once (rcache's final pass). `scratch` is reused between calls (no allocation once sized).
struct LightStrategyPoint {
  const Hit* hit;
  Frame frame;
  Vec3 woLocal;
  const Bsdf* bsdf;
};
struct LightBatchScratch {
  std::vector<UnshadowedLight> lights;
  std::vector<uint32_t> owner;
  std::vector<Ray> rays;
  std::vector<uint8_t> blocked;
};
void lightStrategyMisBatch(const RenderContext& ctx, const LightStrategyPoint* points, Rng* rngs, size_t count,
                           int lightSamples, Color* out, LightBatchScratch& scratch,
                           BatchQuery query = BatchQuery::Packet16);

// Full direct light: `lightSamples` light samples (averaged) + one BSDF sample traced here +
// emitterMis, all MIS-weighted for that sample count. Consumes 3·lightSamples + 3 numbers; with one
// light sample it is exactly the path tracer's per-vertex estimator.
Color directLight(const RenderContext& ctx, const Hit& hit, const Frame& frame, const Vec3& woLocal,
                  const Bsdf& bsdf, Rng& rng, int lightSamples = 1);

// Direct light by light sampling alone (weight 1, one shadow ray, no BSDF ray): unbiased whenever
// the light sampler reaches every emitter with a non-zero pdf where it emits, which holds for all
// emitter types we load. For a Lambertian BSDF the BSDF strategy rarely helps (its samples almost
// never hit a small light) while costing a full ray; callers use this where the variance is
// averaged anyway (the hits of a record's hemisphere rays). Consumes 3 numbers.
Color directLightLightOnly(const RenderContext& ctx, const Hit& hit, const Frame& frame, const Vec3& woLocal,
                           const Bsdf& bsdf, Rng& rng);

// Solid angle (sr) below which all lights count as small from a point (LightSampler::solidAngleBound).
// With Ω ≤ 0.5 every emitter's bounding sphere has r/d ≤ 0.39, so over it the light estimator's
// f·cos·Le/pdf varies by at most ((1+0.39)/(1−0.39))² ≈ 5× (area sampling's 1/d² term), and a
// Lambertian BSDF strategy would carry at most Ω/(π+Ω) ≈ 14 % of the MIS weight.
constexpr float kSmallLightsSolidAngle = 0.5f;

// Direct light choosing its strategies per point: light sampling alone (one ray) on a
// Lambertian BSDF where the lights are small (kSmallLightsSolidAngle), else directLight (MIS,
// two rays). The choice depends only on the point, never on a sample, so the estimate stays
// unbiased. *lightOnly (optional) reports the choice.
Color directLightCheapest(const RenderContext& ctx, const Hit& hit, const Frame& frame, const Vec3& woLocal,
                          const Bsdf& bsdf, Rng& rng, int lightSamples, bool* lightOnly = nullptr);
// directLightCheapest's choice: true where it takes light sampling alone.
bool cheapestIsLightOnly(const RenderContext& ctx, const Hit& hit, const Bsdf& bsdf, int lightSamples);

// Shadow ray from a surface hit toward a light sample.
Ray shadowRay(const Hit& hit, const struct LightSample& ls);
// True when the light sample's point is visible from the hit (its shadow ray unoccluded).
bool visible(const Accel& accel, const Hit& hit, const struct LightSample& ls);

}  // namespace rc
