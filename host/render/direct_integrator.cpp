#include "render/direct_integrator.h"

#include "core/error.h"
#include "geometry/shading_frame.h"
#include "render/direct_light.h"
#include "render/hidden_emitters.h"
#include "render/light_sampler.h"
#include "render/path_integrator.h"

namespace rc {

void readDirectParams(ParamReader& in, IntegratorSettings& s) {
  s.hideEmitters = in.flag("hide_emitters", false);
  const bool shading = in.given("shading_samples");
  const int both = in.integer("shading_samples", 1, 0, 1 << 20);
  if (shading && (in.given("emitter_samples") || in.given("bsdf_samples")))
    throw Error("direct: 'shading_samples' sets both counts; give it or 'emitter_samples'/'bsdf_samples', not both");
  s.emitterSamples = in.integer("emitter_samples", both, 0, 1 << 20);
  s.bsdfSamples = in.integer("bsdf_samples", both, 0, 1 << 20);
  if (s.emitterSamples + s.bsdfSamples == 0) throw Error("direct: needs at least one emitter or BSDF sample");
  // Two segments (camera ray, one bounce to an emitter), no Russian roulette within them.
  s.maxDepth = 2;
  s.rrDepth = 3;
}

Color directRadiance(const RenderContext& ctx, const IntegratorSettings& settings, const Ray& ray, Rng& rng,
                     const Hit* cameraHit) {
  const Scene& scene = ctx.scene;
  Hit hit = cameraHit ? *cameraHit : ctx.accel.intersect(ray);
  if (settings.hideEmitters) hit = behindAreaEmitters(ctx, ray, hit);

  // ---- Visible emitters ----
  Color L(0.0f);
  if (!settings.hideEmitters) L += hit.valid() ? emitted(scene, hit, -ray.d) : ctx.lights.environment(ray.d);
  if (!hit.valid() || hit.bsdf < 0 || hit.bsdf >= static_cast<int>(scene.bsdfs.size()) || !scene.bsdfs[hit.bsdf])
    return L;
  const Frame frame = shadingFrame(*scene.bsdfs[hit.bsdf], hit, -ray.d);
  BsdfPtr pointBsdf;
  const Bsdf& bsdf = bsdfAt(*scene.bsdfs[hit.bsdf], hit, frame, hit.ns, pointBsdf);
  const Vec3 wo = frame.toLocal(-ray.d);
  const Color tint = bsdf.tinted() ? bsdf.tint(hit.uv, wo) : Color(1.0f);
  const int lightSamples = settings.emitterSamples, bsdfSamples = settings.bsdfSamples;

  // ---- Emitter sampling ----
  if (lightSamples > 0) L += tint * lightStrategyMis(ctx, hit, frame, wo, bsdf, rng, lightSamples, bsdfSamples);

  // ---- BSDF sampling ----
  for (int k = 0; k < bsdfSamples; ++k) {
    const Vec2 u = rng.next2D();
    const float uLobe = rng.nextFloat();
    const std::optional<BsdfSample> bs = bsdf.sample(wo, uLobe, u);
    if (!bs) continue;
    const Color weight = tint * bs->weight;
    if (!(maxComponent(weight) > 0.0f) || !isFinite(weight)) continue;
    const Vec3 dir = frame.toWorld(bs->wi);
    const Hit next = ctx.accel.intersect(Accel::spawnRay(hit, dir));
    const Color found = weight * emitterMis(ctx, hit.p, dir, next, bs->pdf, (bs->lobe & kLobeDelta) != 0,
                                            lightSamples, bsdfSamples);
    L += bsdfSamples > 1 ? found / static_cast<float>(bsdfSamples) : found;
  }
  return L;
}

std::unique_ptr<Integrator> makeDirectIntegrator(const IntegratorSettings& settings) {
  return makeEstimatorIntegrator("direct", settings, directRadiance);
}

}  // namespace rc
